#pragma once
// Off-screen 3D views with OSMesa (Mesa's software OpenGL: no display, no
// GPU), legacy fixed-function pipeline. Lines and risers are drawn as tubes
// whose thickness is set in pixels (the mooring spans kilometres, the hull
// ~100 m, a line ~0.1 m: at true scale the lines would be invisible); lines
// are drawn unlit in their exact colour-map colour so that they read true
// against the colour bar, the hull and seabed are lit. Anti-aliasing by
// supersampling and a box filter. Overlays (title, colour bar, scale bar,
// axes, depth scale) are drawn with cairo on the result.
//
// Deterministic: the same scene, camera and options give byte-identical
// pixels (no time, no randomness; Mesa's rasterization is deterministic).

#include "report/image.hpp"
#include "report/scene.hpp"

namespace spiral::report {

/// Renders one view. Throws std::runtime_error when no OSMesa context can be
/// created or the size is not in [16, 8192] px.
Image render_view(const Scene& scene, const Camera& camera, const ViewOptions& options);

}  // namespace spiral::report

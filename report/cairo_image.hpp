#pragma once
// Internal: between report::Image and cairo image surfaces (ARGB32, opaque).

#include <cairo.h>

#include <memory>

#include "report/image.hpp"

namespace spiral::report {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

/// A new opaque image surface holding `image`.
SurfacePtr to_surface(const Image& image);

/// The pixels of an image surface (alpha ignored: surfaces here are opaque).
Image from_surface(cairo_surface_t* surface);

}  // namespace spiral::report

#pragma once
// Motion RAOs of a free-floating (or linearly restrained) hull from its
// first-order excitation and radiation data, for a hull whose BEM set has a
// .3 but no .4: the frequency-domain equation of motion solved per frequency
// and heading (Faltinsen 1990, ch. 3; WAMIT user manual ch. 4, the RAO
// definition of the .4 file).

#include "engine/common/eigen_types.hpp"
#include "engine/hull/wamit_1.hpp"
#include "engine/hull/wamit_3.hpp"

namespace spiral::engine {

/// Motion RAOs (WAMIT e^{iwt} convention, per unit wave amplitude) from the
/// excitation X (.3) and A(w), B(w) (.1) on the excitation table's grid:
///   xi(w, beta) = [−w² (mass + A(w)) + i w (B(w) + linear_damping) + stiffness]^-1 X(w, beta)
/// (A, B interpolated in w, held outside the .1 table).
MotionRaoTable motion_raos_from_excitation(const ExcitationTable& excitation, const HydroCoefficients& radiation,
                                           const Matrix6d& mass, const Matrix6d& linear_damping,
                                           const Matrix6d& stiffness);

}  // namespace spiral::engine

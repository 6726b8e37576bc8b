#pragma once
// Readers for the WAMIT first-order wave transfer functions per unit wave
// amplitude: `.3` diffraction excitation (also `.2` Haskind excitation, same
// layout) and `.4` motion RAOs (WAMIT User Manual v7, ch. 4, numeric output
// files .2/.3/.4; the same layout is written by HAMS and NEMOH/Capytaine
// exporters).
//
// Format: free-format lines `PER BETA I MOD PHA RE IM`: column 1 the period in
// s (or the angular frequency in rad/s, WamitReadOptions::frequency_column),
// BETA the wave heading in degrees, I = 1..6 the DOF, MOD/PHA modulus and
// phase (deg), RE/IM real and imaginary parts. RE and IM are used; MOD/PHA are
// checked for format only. Limit codes (PER <= 0, OMEGA <= 0) are rejected:
// excitation has no meaning there. A first line whose first field is not a
// number is a title and is skipped; blank lines are skipped.
//
// Phase convention (WAMIT User Manual v7 ch. 4 and §2: time dependence e^{iwt}):
//   incident wave   eta(x, y, t) = Re{ A e^{i(w t - k (x cos b + y sin b))} }
//   load / motion   F_i(t)       = Re{ X_i A e^{i w t} }
// so PHA is the phase *lead* of the response over the wave elevation at the
// body origin (x = y = 0). Check on the HAMS cylinder (Buoy.3): the surge
// force of an inertia-dominated cylinder leads the crest by 90 deg (force
// ~ du/dt), and the file gives PHA(1) = +90 deg.
//
// Heading BETA: direction of wave propagation in the body frame, degrees CCW
// from body +x (0 deg: waves travelling towards +x). This is the same
// convention as DESIGN.md §4 for the global frame; the realization
// (wave_realization.hpp) converts global headings with the hull yaw.
//
// Dimensionalisation (WAMIT User Manual v7 §4.1; L = ULEN):
//   excitation (.2/.3):  X_i = rho g L^m Xbar_i,  m = 2 (forces, N/m), 3 (moments, N m/m)
//   motions (.4):        xi_i = L^-n xibar_i,     n = 0 (translations, m/m),
//                                                 1 (rotations, rad/m)
//   (rotations are non-dimensionalised by A/L: xibar = xi L / A.)
//
// Grid: the distinct frequencies x distinct headings found form the table;
// each DOF that appears anywhere must appear at every (frequency, heading)
// node (a gap is an error naming the node); a DOF that never appears is zero.
//
// Errors: FileFormatError with file and 1-based line (0: whole file);
// std::invalid_argument for options out of range and interpolation outside
// the heading range.

#include <Eigen/Core>
#include <array>
#include <complex>
#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "engine/common/file_format_error.hpp"
#include "engine/hull/wamit_format.hpp"

namespace spiral::engine {

using Vector6cd = Eigen::Matrix<std::complex<double>, 6, 1>;

enum class TransferQuantity {
  excitation,  ///< .2/.3: N/m (forces), N m/m (moments) per unit wave amplitude
  motion_rao,  ///< .4: m/m (translations), rad/m (rotations) per unit wave amplitude
};

/// Complex first-order transfer functions per unit wave amplitude, WAMIT phase
/// convention (see the header comment), body frame.
struct WaveTransferTable {
  TransferQuantity quantity = TransferQuantity::excitation;
  std::vector<double> omega_rad_per_s;  ///< strictly ascending, > 0
  std::vector<double> headings_rad;     ///< strictly ascending, as given in the file
  /// per DOF (surge..yaw): rows = headings, columns = frequencies; SI per m of amplitude
  std::array<Eigen::MatrixXcd, 6> values;
  std::array<bool, 6> dof_present{};  ///< false: the file had no rows for the DOF (zeros)
  std::string file;
};

using ExcitationTable = WaveTransferTable;
using MotionRaoTable = WaveTransferTable;

/// Parses `.3` (or `.2`) text into excitation per unit amplitude.
ExcitationTable parse_wamit_3(std::istream& text, const std::string& file_name, const WamitReadOptions& options);
ExcitationTable read_wamit_3(const std::filesystem::path& file, const WamitReadOptions& options);

/// Parses `.4` text into motion RAOs per unit amplitude (water density and
/// gravity are not used).
MotionRaoTable parse_wamit_4(std::istream& text, const std::string& file_name, const WamitReadOptions& options);
MotionRaoTable read_wamit_4(const std::filesystem::path& file, const WamitReadOptions& options);

/// X(w, beta): complex linear interpolation in w and in beta (bilinear on the
/// real and imaginary parts). Frequencies outside the table are held at the
/// end values. The heading is first wrapped into [beta_min, beta_min + 360 deg);
/// if it is then more than 0.5 deg above beta_max (or below beta_min) it is
/// outside the table and std::invalid_argument says "heading X deg outside the
/// database range [a, b] deg" (no symmetry is assumed: supply the headings the
/// sea state needs). Within 0.5 deg of an end the end value is used: the
/// hull's own equilibrium yaw (hundredths of a degree for a moored semi) must
/// not make a single-heading table unusable.
Vector6cd transfer_at(const WaveTransferTable& table, double omega_rad_per_s, double heading_rad);

}  // namespace spiral::engine

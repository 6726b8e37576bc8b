#pragma once
// Mean drift coefficients from a WAMIT difference-frequency QTF file `.12d`
// (WAMIT User Manual v7, ch. 4, second-order output files "numeric output
// .12d/.12s"; the same layout is written by NEMOH/HAMS exporters for OpenFAST).
//
// Format: free-format lines of 9 fields
//   PER1 PER2 BETA1 BETA2 I MOD PHS RE IM
// periods in s, headings in degrees (direction of propagation in the body
// frame, CCW from body +x), I = 1..6 the load component (surge, sway, heave,
// roll, pitch, yaw), MOD/PHS modulus and phase (deg), RE/IM the real and
// imaginary parts of the non-dimensional QTF. Only one triangle (w1 >= w2 in
// the OC4 file) is stored; rows come in any order. A first line whose first
// field is not a number is a title and is skipped (NEMOH-written files have
// one); blank lines are skipped; anything else that does not parse is an error.
//
// The mean drift coefficient in a regular wave of frequency w and heading beta
// is the diagonal PER1 = PER2, BETA1 = BETA2 (its imaginary part is round-off):
//   D_i(w, beta) = rho g ULEN^k RE_i,   k = 1 (forces, I = 1..3), 2 (moments, I = 4..6)
// (WAMIT manual normalisation of second-order forces F / (rho g A^2 ULEN^k);
// OpenFAST HydroDyn WAMIT2.f90 Read_DataFile4D dimensionalises with the same
// rho g ULEN^k), so that the mean load in a wave of amplitude A is A^2 D_i and
// in irregular seas 2 int S D dw (mean_environmental_loads.hpp).
// Off-diagonal rows are checked for format and then ignored. Every DOF that
// appears on the diagonal must be given at every (period, heading) pair of the
// diagonal; a gap is an error. Periods must be > 0 (WAMIT's PER = 0 / -1
// infinite / zero period codes are rejected on the diagonal). Headings are kept
// as given (converted to rad) and sorted; equal periods/headings are matched
// to 1e-6 relative / 1e-6 deg. Multi-body files (I > 6) are not supported.
// Output: MeanDriftTable, frequencies w = 2 pi / PER increasing.
//
// (WAMIT manual section numbers are recalled, not re-read.)
// Errors: spiral::engine::FileFormatError with file and 1-based line (line 0:
// the whole file, e.g. missing, empty, incomplete diagonal); std::invalid_argument
// for rho, g or ULEN <= 0.

#include <filesystem>
#include <istream>
#include <string>

#include "engine/common/file_format_error.hpp"
#include "engine/hull/mean_environmental_loads.hpp"

namespace spiral::engine {

/// Parses .12d text; `file_name` appears in error messages only.
/// `period_scale` (> 0) multiplies the file's periods (frequencies divided by
/// it): a Froude-scaled hull of scale lambda uses ULEN x lambda and
/// period_scale = sqrt(lambda) (the coefficients themselves are unchanged).
MeanDriftTable parse_wamit_12d_mean_drift(std::istream& text, const std::string& file_name, double rho_kg_per_m3,
                                          double g_m_per_s2, double ulen_m, double period_scale = 1.0);

/// Reads a .12d file.
MeanDriftTable read_wamit_12d_mean_drift(const std::filesystem::path& path, double rho_kg_per_m3, double g_m_per_s2,
                                         double ulen_m, double period_scale = 1.0);

}  // namespace spiral::engine

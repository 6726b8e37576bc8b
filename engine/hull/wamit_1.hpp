#pragma once
// Reader for the WAMIT added-mass and radiation-damping file `.1` (WAMIT User
// Manual v7, ch. 4 "numeric output files", file .1; written in the same form
// by HAMS, NEMOH/Capytaine exporters and used by OpenFAST HydroDyn).
//
// Format: free-format lines `PER I J Abar(I,J) Bbar(I,J)`, I, J = 1..6 (surge,
// sway, heave, roll, pitch, yaw). Column 1 is the period PER in s unless the
// caller says it is the angular frequency (WamitReadOptions::frequency_column;
// check the file: marin_semi.1 runs 628.3 ... 1.26 s, HAMS's Buoy.1 0.2 ... 6.0
// rad/s). Limit rows (the damping column may be absent there):
//   period column:     PER = 0  -> infinite frequency (zero period),
//                      PER < 0  -> zero frequency (infinite period; WAMIT writes -1);
//   frequency column:  w = 0    -> zero frequency; w < 0 is rejected (no code for
//                      infinite frequency is defined for this layout).
// Entries that a file omits (WAMIT drops coefficients below its print
// threshold) are zero. Blank lines are skipped; a first line whose first field
// is not a number is a title and is skipped; any other unparsable line is an error.
//
// Dimensionalisation (WAMIT User Manual v7 §4.1; L = ULEN, rho water density):
//   A_ij = rho L^k Abar_ij
//   B_ij = rho L^k w Bbar_ij
//   k = 3 for i, j in 1..3;  k = 4 for one index in 1..3 and one in 4..6;
//   k = 5 for i, j in 4..6.
// Units: A in kg, kg m, kg m^2; B in kg/s, kg m/s, kg m^2/s.
//
// Errors: FileFormatError with file and 1-based line (line 0: whole file —
// missing, empty, duplicate frequency sets); std::invalid_argument for
// options out of range.

#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "engine/common/eigen_types.hpp"
#include "engine/common/file_format_error.hpp"
#include "engine/hull/wamit_format.hpp"

namespace spiral::engine {

struct HydroCoefficients {
  std::vector<double> omega_rad_per_s;          ///< strictly ascending, > 0
  std::vector<Matrix6d> added_mass;             ///< SI, one per frequency
  std::vector<Matrix6d> damping;                ///< SI, one per frequency
  std::optional<Matrix6d> added_mass_infinite;  ///< infinite-frequency limit, if in the file
  std::optional<Matrix6d> added_mass_zero;      ///< zero-frequency limit, if in the file
  std::string file;                             ///< name used in messages
};

/// Length exponent k of the (i, j) added-mass / damping entry, 1-based i, j in
/// 1..6: 3 + (number of rotational indices). Throws std::invalid_argument outside.
int wamit_radiation_length_exponent(int i, int j);

/// Parses .1 text; `file_name` appears in error messages only.
HydroCoefficients parse_wamit_1(std::istream& text, const std::string& file_name, const WamitReadOptions& options);

/// Reads a .1 file.
HydroCoefficients read_wamit_1(const std::filesystem::path& file, const WamitReadOptions& options);

/// A(w) by linear interpolation in w between the tabulated frequencies, held
/// at the first/last value outside the table (the limit rows are not used:
/// call sites that need A(inf) read added_mass_infinite). Throws
/// std::invalid_argument for a non-finite w or an empty table.
Matrix6d added_mass_at(const HydroCoefficients& coefficients, double omega_rad_per_s);

/// B(w), same rule as added_mass_at.
Matrix6d damping_at(const HydroCoefficients& coefficients, double omega_rad_per_s);

}  // namespace spiral::engine

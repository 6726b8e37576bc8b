#pragma once
// Reader for the WAMIT hydrostatic restoring file `.hst` (WAMIT User Manual
// v7, §4.3 "Hydrostatic restoring coefficients"; written in the same form by
// HAMS, NEMOH/Capytaine exporters).
//
// Format: one coefficient per line, `I J C(I,J)`, free-format, I and J the
// 1-based DOF indices (1..6: surge, sway, heave, roll, pitch, yaw), C
// non-dimensional. Blank lines are skipped; anything else is an error. Only
// single-body files (I, J <= 6) are read. Entries not in the file are zero.
//
// Dimensionalisation (WAMIT User Manual v7, §4.1 normalisation of the output
// quantities, applied to .hst in §4.3):
//   C_ij = rho g ULEN^k  Cbar_ij,   k = 2 + (number of rotational indices among i, j)
// i.e. k = 2 for (3,3); k = 3 for (3,4), (3,5), (4,3), (5,3); k = 4 for
// (4,4), (4,5), (4,6), (5,4), (5,5), (5,6) (force per metre -> moment per radian
// adds one length per rotational index). The same rule is applied to every
// entry that the file holds.
//
// What the matrix contains: WAMIT writes the hydrostatic *and* gravity terms
// (-m g z_g etc.) of §3.1 with the mass and CG of its .frc input; the NREL/
// OpenFAST files (and the OC4 report values) hold the buoyancy part only. This
// reader returns the file's matrix as it is; see hydrostatics.hpp to add the
// gravity part to a buoyancy-only matrix.
//
// (WAMIT section numbers are recalled, not re-read.)
//
// Errors: spiral::engine::FileFormatError with the file name and the 1-based
// line (missing/unreadable file: line 0, message names the file).

#include <Eigen/Core>
#include <filesystem>
#include <istream>
#include <string>

#include "engine/common/file_format_error.hpp"
#include "engine/common/seawater.hpp"

namespace spiral::engine {

struct WamitHstScaling {
  double ulen_m = 1.0;  ///< WAMIT length scale ULEN of the run, > 0
  Seawater water;       ///< rho and g for dimensionalisation
};

struct WamitHstData {
  Eigen::Matrix<double, 6, 6> nondimensional = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> restoring_6x6 = Eigen::Matrix<double, 6, 6>::Zero();  ///< SI: N/m, N, N m/rad
  int entries_read = 0;                                                             ///< number of `I J C` lines
  std::string file;                                                                 ///< name used in messages
};

/// Length exponent k of the (i, j) entry (1-based indices 1..6); throws
/// std::invalid_argument outside that range.
int wamit_hst_length_exponent(int i, int j);

/// Parses .hst text; `file_name` is used in error messages only.
WamitHstData parse_wamit_hst(std::istream& text, const std::string& file_name, const WamitHstScaling& scaling);

/// Reads a .hst file.
WamitHstData read_wamit_hst(const std::filesystem::path& file, const WamitHstScaling& scaling);

}  // namespace spiral::engine

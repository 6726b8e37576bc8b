#pragma once
// Options shared by the WAMIT-format readers of frequency-dependent data
// (.1 added mass/damping, .3 excitation, .4 motion RAOs) and the small text
// helpers they use.
//
// WAMIT User Manual v7, ch. 4 (output files): every numeric output file is
// free-format text, one coefficient per line, column 1 the wave period PER in
// seconds. Other BEM codes write the same layout but may put the angular
// frequency in column 1 (HAMS does when its control file asks for frequency
// input; shared/data/hydro/cylinder-buoy/Buoy.1 is such a file): the caller says
// which with FrequencyColumn — the readers cannot tell reliably.
//
// Non-dimensional output (WAMIT User Manual v7 §4.1; L = ULEN, A = wave amplitude):
//   added mass      Abar_ij = A_ij / (rho L^k)
//   damping         Bbar_ij = B_ij / (rho L^k omega)
//       k = 3 (i, j <= 3), 4 (one of i, j >= 4), 5 (both >= 4)
//   excitation      Xbar_i  = X_i / (rho g A L^m),   m = 2 (forces), 3 (moments)
//   motions (RAO)   xibar_i = xi_i / (A / L^n),       n = 0 (translations), 1 (rotations)
// (the section number is recalled, not re-read; the OC4 numbers of
// shared/data/reference-platforms.md §1.5 check the added-mass rule.)

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "engine/common/seawater.hpp"

namespace spiral::engine {

/// What column 1 of a WAMIT-format file holds.
enum class FrequencyColumn {
  period_s,           ///< wave period in s (WAMIT); PER = 0 and PER < 0 are limit codes
  angular_frequency,  ///< angular frequency in rad/s (HAMS option); see each reader for limits
};

struct WamitReadOptions {
  FrequencyColumn frequency_column = FrequencyColumn::period_s;
  double ulen_m = 1.0;  ///< WAMIT length scale ULEN of the run, > 0
  /// Periods multiplied by period_scale (frequencies divided by it) before
  /// use: a Froude-scaled hull of scale lambda reuses the non-dimensional
  /// coefficients at equal w^2 L / g with ULEN x lambda and periods x sqrt(lambda)
  /// (shared/data/reference-platforms.md §2.4). > 0; 1 = the file as written.
  double period_scale = 1.0;
  Seawater water;  ///< rho (and g for excitation) used to dimensionalise
};

namespace detail {

/// Throws std::invalid_argument unless ULEN, rho and g are finite and > 0.
void validate_wamit_options(const WamitReadOptions& options, const char* reader);

/// Whitespace-separated tokens of one line (views into `line`).
std::vector<std::string_view> split_whitespace(std::string_view line, bool comma_separates = false);

/// Strict integer parse of the whole token (leading '+' allowed).
bool parse_int(std::string_view token, int& value);

/// Strict finite real parse of the whole token; Fortran 'D' exponents accepted.
bool parse_real(std::string_view token, double& value);

/// Sorted distinct values of `values`, merging neighbours closer than
/// rel_tol x |value| (+ abs_tol).
std::vector<double> distinct_sorted(std::vector<double> values, double rel_tol, double abs_tol);

/// Index of `value` in sorted distinct `grid` within the same tolerance; -1 if absent.
int index_in(const std::vector<double>& grid, double value, double rel_tol, double abs_tol);

}  // namespace detail
}  // namespace spiral::engine

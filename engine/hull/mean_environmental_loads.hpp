#pragma once
// Mean (static) environmental loads on the hull: wind and current by
// heading-dependent coefficients, and mean wave drift in irregular seas.
//
// Frames (DESIGN.md §4): global frame z up at mean water level; the hull body
// frame at the hull reference point, rotated by the hull yaw psi about z (roll
// and pitch are ignored for these mean loads). Loads are 6-vectors (surge, sway,
// heave, roll, pitch, yaw) = (Fx, Fy, Fz, Mx, My, Mz) in N and N m about the
// hull reference point, returned in the global frame (_g) and the body frame (_b).
// Body -> global: (Fx, Fy) and (Mx, My) rotate by psi; Fz and Mz are unchanged.
//
// Relative heading: beta = (flow or wave propagation direction) - psi, wrapped
// to [0, 2 pi): the direction the flow travels towards, seen in the hull frame,
// CCW from body +x (the WAMIT wave-heading convention, and the OCIMF one with
// "towards" instead of "from").
//
// 1) Wind and current coefficients (OCIMF, "Prediction of wind and current
//    loads on VLCCs", 2nd ed. 1994, form; DNV-RP-C205 §5.4 for wind on structures):
//      F_x,b = 1/2 rho CxA(beta) V^2,  F_y,b = 1/2 rho CyA(beta) V^2,
//      M_z,b = 1/2 rho CmzA(beta) V^2
//    V = |V| >= 0 the horizontal flow speed (the V|V| of the signed form: the
//    sign is carried by beta). CxA, CyA (m^2) and CmzA (m^3) are coefficient x
//    area (x length for the moment) as designers tabulate them. Sign
//    convention: a positive CxA at beta = 0 pushes the hull along the flow
//    (drag); CyA > 0 pushes towards body +y; CmzA > 0 is a CCW (about +z) yaw
//    moment. Heave, roll and pitch are zero (no coefficients for them: wind
//    heeling moments belong with the hull's stability model, not here).
//    Headings in [0, 2 pi), strictly increasing; linear interpolation in beta.
//    Heading rule (both kinds of table): the table is treated as periodic, i.e.
//    beta between the last and the first heading (+ 2 pi) is interpolated
//    between those two, when that wrap-around gap is no larger than the
//    largest gap between consecutive headings (true for any table covering
//    0-360 deg, e.g. 0, 15, ..., 345 deg). Otherwise (a half-circle table, a
//    single heading) a beta up to 0.5 deg beyond an end heading takes the end
//    value (the hull's own equilibrium yaw, typically hundredths of a degree
//    for a moored semi, must not make a single-heading database unusable),
//    and a beta further outside [first, last] throws std::invalid_argument:
//    no extrapolation; mirror the table for a symmetric hull before calling.
//    Current on the hull: the current velocity at a reference depth
//    (default z = 0, the surface current; e.g. half the draught for a
//    deep-draught hull if the coefficients were derived that way - state it
//    where the coefficients come from). Wind: the mean wind speed at the
//    coefficients' reference height (usually 10 m, 1-hour mean), see wind.hpp.
//
// 2) Mean wave drift in irregular seas (Faltinsen, "Sea Loads on Ships and
//    Offshore Structures", 1990, ch. 5, mean wave loads in irregular sea;
//    J. N. Newman, "Second-order, slowly-varying forces on vessels in
//    irregular waves", 1974; OpenFAST HydroDyn WAMIT2 MnDrift uses the same sum):
//      F_i = 2 sum_k w_k int_0^inf S(w) D_i(w, beta_k) dw
//    D_i (N/m^2 for forces, N m/m^2 for moments) is the mean load in a regular
//    wave of unit amplitude (the diagonal of the difference-frequency QTF),
//    w_k, beta_k the spreading directions (one direction, weight 1, if none).
//    Interpolation: linear in w and in beta. Outside the table's frequency
//    range D is HELD at the end values (conservative for the usual drift
//    curves, which do not vanish at the ends of a BEM frequency range); the
//    result reports the share of wave variance lying below / above the table
//    so the caller can warn. Headings follow the heading rule above. The
//    frequency integral uses spectrum_quadrature() with its upper limit raised
//    to the table's last frequency, so the analytic w^-5 tail lies where D is
//    held constant.

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "engine/common/rigid_body.hpp"
#include "engine/environment/current_profile.hpp"
#include "engine/environment/wave_spectrum.hpp"

namespace spiral::engine {

/// Heading-dependent coefficient x area table (hull frame), see header comment.
struct CoefficientTable {
  std::vector<double> headings_rad;  ///< strictly increasing, in [0, 2 pi)
  std::vector<double> Cx_m2;         ///< surge coefficient x area, m^2
  std::vector<double> Cy_m2;         ///< sway coefficient x area, m^2
  std::vector<double> Cmz_m3;        ///< yaw coefficient x area x length, m^3
};

/// Throws std::invalid_argument for an empty table, mismatched sizes, headings
/// not strictly increasing in [0, 2 pi), or non-finite values.
void validate_coefficient_table(const CoefficientTable& table);

struct CoefficientLoadInput {
  double fluid_density_kg_per_m3 = 0.0;                       ///< > 0 (air ~1.225, sea water 1025)
  Eigen::Vector3d flow_velocity_g = Eigen::Vector3d::Zero();  ///< m/s; z component ignored
  double hull_yaw_rad = 0.0;                                  ///< psi
};

struct CoefficientLoadResult {
  Vector6d load_g = Vector6d::Zero();  ///< N, N m, global frame
  Vector6d load_b = Vector6d::Zero();  ///< N, N m, hull frame
  double relative_heading_rad = 0.0;   ///< beta in [0, 2 pi)
  double speed_m_per_s = 0.0;          ///< horizontal |V|
  /// (CxA m^2, CyA m^2, CmzA m^3) at beta; left zero when the speed is zero
  Eigen::Vector3d coefficients = Eigen::Vector3d::Zero();
};

CoefficientLoadResult coefficient_load(const CoefficientTable& table, const CoefficientLoadInput& input);

/// Current load: the current velocity at reference_depth_z_m (global z, <= 0; default surface).
CoefficientLoadResult current_load(const CoefficientTable& table, const CurrentProfile& current,
                                   double water_density_kg_per_m3, double hull_yaw_rad, double reference_z_m = 0.0);

/// Wind load from the mean wind speed at the table's reference height (m/s)
/// travelling towards wind_heading_rad.
CoefficientLoadResult wind_load(const CoefficientTable& table, double wind_speed_m_per_s, double wind_heading_rad,
                                double hull_yaw_rad, double air_density_kg_per_m3 = 1.225);

/// Mean drift coefficients D_i(w, beta), hull frame, SI.
struct MeanDriftTable {
  std::vector<double> omega_rad_per_s;  ///< strictly increasing, > 0
  std::vector<double> headings_rad;     ///< strictly increasing, last - first <= 2 pi
  /// coefficient[i](k, j) at omega[k], heading[j]: N/m^2 (i = 0..2), N m/m^2 (i = 3..5)
  std::array<Eigen::MatrixXd, 6> coefficient;
  std::array<bool, 6> present{};  ///< DOFs for which data exist (others are zero)
  /// The widest gap between neighbouring headings the loads interpolate
  /// across, rad; a relative heading inside a wider gap (more than the
  /// heading rule's 0.5° from its ends) is a TableRangeError. Infinite for a
  /// table as read; a table extended by the hull's symmetry keeps its data's
  /// own gaps (mean_drift_headings.hpp), so the images do not silently widen
  /// what the data interpolate.
  double max_interpolation_gap_rad = std::numeric_limits<double>::infinity();
};

/// Throws std::invalid_argument for an inconsistent table.
void validate_mean_drift_table(const MeanDriftTable& table);

/// D(w, beta) for all six DOFs (absent ones 0), interpolated as described above.
Vector6d mean_drift_coefficients(const MeanDriftTable& table, double omega_rad_per_s, double relative_heading_rad);

struct MeanDriftInput {
  WaveSpectrum spectrum;
  double wave_heading_rad = 0.0;                  ///< mean direction of propagation, global
  double hull_yaw_rad = 0.0;                      ///< psi
  std::optional<DirectionalSpreading> spreading;  ///< none: long-crested
  int spreading_directions = 15;                  ///< N for discretise_spreading, >= 1
  SpectrumQuadratureOptions quadrature;           ///< frequency integration
};

struct MeanDriftResult {
  Vector6d load_g = Vector6d::Zero();          ///< N, N m, global frame
  Vector6d load_b = Vector6d::Zero();          ///< N, N m, hull frame
  double m0_m2 = 0.0;                          ///< variance of the spectrum as integrated
  double variance_fraction_below_table = 0.0;  ///< share of m0 at w < first table frequency
  double variance_fraction_above_table = 0.0;  ///< share of m0 at w > last table frequency
  std::vector<SpreadingDirection> directions;  ///< global headings and weights used
};

MeanDriftResult mean_wave_drift_load(const MeanDriftTable& table, const MeanDriftInput& input);

/// A sea's mean drift at any hull yaw without a quadrature per call: the
/// spectrum's integral of the coefficients at each of the table's headings,
/// F_j = 2 ∫ S(w) D(w, beta_j) dw. The coefficients are interpolated
/// linearly in heading, so the integral at a heading between beta_j0 and
/// beta_j1 is the same interpolation of F_j0 and F_j1 (exact, not an
/// approximation). An equilibrium evaluates the load at every Newton pose;
/// the quadrature (a JONSWAP's pow and exp at each node) was a quarter of the
/// every-line pretension optimization's profile.
class MeanDriftIntegral {
 public:
  /// input.hull_yaw_rad is not used. Throws as mean_wave_drift_load.
  MeanDriftIntegral(const MeanDriftTable& table, const MeanDriftInput& input);
  /// The load at this hull yaw (what mean_wave_drift_load returns for the
  /// table and input with input.hull_yaw_rad = hull_yaw_rad).
  MeanDriftResult load(double hull_yaw_rad) const;

 private:
  std::vector<double> headings_rad_;
  double max_interpolation_gap_rad_;
  Eigen::Matrix<double, 6, Eigen::Dynamic> at_heading_;  ///< F_j, hull frame, one column per table heading
  MeanDriftResult without_load_;                         ///< the spectrum's variance, fractions and directions
};

}  // namespace spiral::engine

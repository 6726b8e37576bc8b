#include "design/analysis/line_dynamic_reduction.hpp"

#include <array>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>

#include <fmt/format.h>

#include "design/analysis/line_dynamics.hpp"
#include "design/model/riser_model.hpp"
#include "engine/analysis/fairlead_velocity.hpp"
#include "engine/analysis/line_relaxation_fit.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/lines/fe_line_impedance.hpp"

namespace spiral::design {
namespace {

/// The low-frequency band of the fit: periods from 30 s to 1250 s (10
/// frequencies, evenly in log: 20 gave the default FPS's offset std to
/// 0.01 %, at twice the cost): the moored hull's surge, sway and yaw.
constexpr int kBandFrequencies = 10;
constexpr double kLowestFrequency_rad_per_s = 0.005;
constexpr double kHighestFrequency_rad_per_s = 0.2;

/// A fit whose residual is above this does not represent its group's
/// impedance. Within the band a line can have a resonance of its own (the
/// IEA 15 MW VolturnUS-S's 850 m chains in 200 m of water near 0.13 rad/s:
/// its damping peaks there and the fit left 84 %), which a dashpot and
/// relaxations cannot hold: the band is then shortened from the top,
/// one frequency at a time, down to kFewestBandFrequencies (the default
/// FPS's and OC4's fits leave 3–7 % over the whole band).
constexpr double kLargestFitResidual = 0.15;
constexpr std::size_t kFewestBandFrequencies = 6;
/// The band kept must reach this far above the hull's highest surge, sway
/// or yaw natural frequency, whose response the reduction is for.
constexpr double kBandMarginOverHullModes = 1.2;

/// The hull's highest natural frequency in surge, sway or yaw (rad/s) at
/// the static case (with the dynamic stiffness the S-C levels use).
double highest_horizontal_natural_frequency(const StaticCaseResult& statics) {
  const std::vector<NaturalMode>& modes =
      statics.dynamic_natural_modes.empty() ? statics.natural_modes : statics.dynamic_natural_modes;
  double highest = 0.0;
  for (const NaturalMode& mode : modes) {
    if ((mode.dominant_dof == "surge" || mode.dominant_dof == "sway" || mode.dominant_dof == "yaw") &&
        mode.period_s > 0.0)
      highest = std::max(highest, 2.0 * std::numbers::pi / mode.period_s);
  }
  return highest;
}

}  // namespace

DynamicLineReduction dynamic_line_reduction(const Project& project, const std::vector<LineTypeProperties>& types,
                                            const std::optional<engine::CurrentProfile>& current,
                                            const StaticCaseResult& statics, const std::string& damaged_line,
                                            const Eigen::Matrix<double, 6, Eigen::Dynamic>& hull_motion,
                                            double motion_step_s) {
  const engine::HullPose pose = engine::pose_from_offset(project.hull.reference_point_g, statics.offset);
  std::vector<double> omegas{0.0};
  for (int k = 0; k < kBandFrequencies; ++k) {
    omegas.push_back(kLowestFrequency_rad_per_s * std::pow(kHighestFrequency_rad_per_s / kLowestFrequency_rad_per_s,
                                                           static_cast<double>(k) / (kBandFrequencies - 1)));
  }
  std::vector<const MooringLine*> moorings;
  for (const MooringLine& line : project.mooring.lines)
    if (line.name != damaged_line) moorings.push_back(&line);
  const int count = static_cast<int>(moorings.size() + project.risers.size());

  // Each line's K_dyn over the band, mapped to the hull.
  std::vector<std::vector<engine::Matrix6cd>> mapped(static_cast<std::size_t>(count));
  engine::parallel_for(count, engine::worker_count(count), [&](int i) {
    Eigen::Vector3d attachment_b;
    DynamicLineSetup setup;
    if (i < static_cast<int>(moorings.size())) {
      const MooringLine& line = *moorings[static_cast<std::size_t>(i)];
      attachment_b = line.fairlead_b;
      setup = dynamic_mooring_line(project, line, types, current, pose.reference_point_g + pose.rotation * attachment_b,
                                   line_profile(statics.lines, line.name));
    } else {
      const RiserDesign design = riser_design(project, project.risers[static_cast<std::size_t>(i) - moorings.size()]);
      attachment_b = design.hang_off_b;
      // From the static case's own FE solution of the riser there.
      setup = dynamic_riser(project, design, current, pose.reference_point_g + pose.rotation * attachment_b,
                            riser_profile(statics.risers, design.name));
    }
    setup.environment.statics.seabed_axial_friction = 0.0;
    setup.environment.seabed_lateral_friction = 0.0;
    const std::array<Eigen::Vector3d, 1> attachments{attachment_b};
    const Eigen::Matrix3d velocity_covariance = engine::fairlead_velocity_covariance(
        attachments, project.hull.reference_point_g, hull_motion, motion_step_s)[0];
    const std::vector<engine::Matrix3cd> K =
        engine::end_B_dynamic_stiffness(setup.model, setup.environment, setup.statics, omegas, velocity_covariance);
    const Eigen::Matrix<std::complex<double>, 3, 6> Tc =
        engine::point_jacobian(pose.rotation * attachment_b).cast<std::complex<double>>();
    for (const engine::Matrix3cd& k : K) mapped[static_cast<std::size_t>(i)].push_back(Tc.transpose() * k * Tc);
  });

  // Mooring lines and risers fitted apart: their relaxations differ (a
  // mooring line's current-loaded bow against a riser's long steel catenary
  // and touchdown zone). Fitted together the two groups' residual was 70 %
  // and the lines' damping came out 20 % too high (lc5).
  DynamicLineReduction out;
  out.lines = count;
  out.frequencies = kBandFrequencies;
  out.lowest_frequency_rad_per_s = kLowestFrequency_rad_per_s;
  out.highest_frequency_rad_per_s = kHighestFrequency_rad_per_s;
  const int mooring_count = static_cast<int>(moorings.size());
  for (const auto& [first, last, group] :
       {std::tuple{0, mooring_count, "mooring lines"}, std::tuple{mooring_count, count, "risers"}}) {
    if (first == last) continue;
    std::vector<engine::Matrix6cd> total(omegas.size(), engine::Matrix6cd::Zero());
    for (int i = first; i < last; ++i)
      for (std::size_t k = 0; k < omegas.size(); ++k) total[k] += mapped[static_cast<std::size_t>(i)][k];
    std::vector<engine::Matrix6cd> increase;
    std::vector<double> band, weights;
    for (std::size_t k = 1; k < omegas.size(); ++k) {
      band.push_back(omegas[k]);
      increase.push_back(total[k] - total[0]);
      weights.push_back(1.0 / total[k].norm());
    }
    std::size_t kept = band.size();
    const auto fit_over = [&](std::size_t n) {
      return engine::fit_line_relaxation(std::span(band).first(n), std::span(increase).first(n),
                                         std::span(weights).first(n), 2);
    };
    engine::LineRelaxationFit fit = fit_over(kept);
    while (fit.relative_residual > kLargestFitResidual && kept > kFewestBandFrequencies) fit = fit_over(--kept);
    out.frequencies = std::min(out.frequencies, static_cast<int>(kept));
    out.highest_frequency_rad_per_s = std::min(out.highest_frequency_rad_per_s, band[kept - 1]);
    out.damping += fit.damping;
    out.added_mass += fit.added_mass;
    out.relaxations.insert(out.relaxations.end(), fit.relaxations.begin(), fit.relaxations.end());
    out.relative_residual = std::max(out.relative_residual, fit.relative_residual);
    if (!out.relaxation_summary.empty()) out.relaxation_summary += "; ";
    out.relaxation_summary += fmt::format("{:.3g} s, {:.3g} s ({})", fit.relaxations.front().time_constant_s,
                                          fit.relaxations.back().time_constant_s, group);
  }
  const double hull_mode_rad_per_s = highest_horizontal_natural_frequency(statics);
  if (out.relative_residual > kLargestFitResidual) {
    out.unusable_reason = fmt::format(
        "the lines' impedance is not a dashpot, an added mass and relaxations: the fit leaves {:.0f} % (at most "
        "{:.0f} %) over {:.3g}-{:.3g} rad/s",
        100.0 * out.relative_residual, 100.0 * kLargestFitResidual, out.lowest_frequency_rad_per_s,
        out.highest_frequency_rad_per_s);
  } else if (out.highest_frequency_rad_per_s < kBandMarginOverHullModes * hull_mode_rad_per_s) {
    out.unusable_reason = fmt::format(
        "the band the fit holds (up to {:.3g} rad/s; a resonance of the lines above it) does not reach {:g} x the "
        "hull's highest surge, sway or yaw natural frequency ({:.3g} rad/s)",
        out.highest_frequency_rad_per_s, kBandMarginOverHullModes, hull_mode_rad_per_s);
  }
  return out;
}

}  // namespace spiral::design

// The two reductions of the enhanced S-C give the same drag damping where
// they should: OC4's three chains at rest in still water, every fairlead
// swept by the same isotropic velocity. The quasi-static reduction
// (design/analysis/line_hydrodynamics: the elastic catenary's shape
// derivative, the normal drag linearized stochastically node by node) and
// the FE line's impedance with its drag linearized on that motion
// (engine/lines/fe_line_impedance: the FE statics' condensed transfer to
// each Gauss point) reach the same damping by different models — the
// catenary's closed form against the ANCF mesh with its seabed penalty.
// Tolerance 3 % (measured below): the two models' laid lengths and
// touchdown zones differ, and there the line barely moves.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "design/analysis/line_dynamics.hpp"
#include "design/analysis/line_hydrodynamics.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/validated_project.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/lines/fe_line_impedance.hpp"

namespace spiral::design {
namespace {

TEST(LineDragDampingModels, TheCatenaryAndTheFeLineDampTheSameMotionAlike) {
  const ValidatedProject validated =
      load_validated_project(std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml");
  const Project& project = validated.project;
  const std::vector<LineTypeProperties> types = resolve_line_types(project);
  LineArrayModel catenaries = build_mooring_model(project, types);
  const engine::HullPose rest = engine::pose_from_offset(catenaries.reference_point_g, engine::Vector6d::Zero());

  // The FE lines' dashpot at a frequency low enough for their response to be
  // quasi-static, Im K_dyn / ω, less that of the line at rest: its axial
  // and seabed damping, which the catenary has not (1.8e3 N·s/m in surge).
  const auto fe_damping = [&](const Eigen::Matrix3d& covariance) {
    const std::vector<double> omegas{1e-3};
    engine::Matrix6d B = engine::Matrix6d::Zero();
    for (const MooringLine& line : project.mooring.lines) {
      const Eigen::Vector3d arm_g = rest.rotation * line.fairlead_b;
      DynamicLineSetup setup = dynamic_mooring_line(project, line, types, std::nullopt, rest.reference_point_g + arm_g);
      setup.environment.statics.seabed_axial_friction = 0.0;
      setup.environment.seabed_lateral_friction = 0.0;
      const engine::Matrix3cd K =
          engine::end_B_dynamic_stiffness(setup.model, setup.environment, setup.statics, omegas, covariance).front();
      const Eigen::Matrix<double, 3, 6> T = engine::point_jacobian(arm_g);
      B += T.transpose() * (K.imag() / omegas.front()) * T;
    }
    return B;
  };
  const engine::Matrix6d fe_at_rest = fe_damping(Eigen::Matrix3d::Zero());

  // Measured: surge and sway +1.3 %, yaw +0.3 %, at 0.1 and 0.5 m/s.
  for (const double sigma_m_per_s : {0.1, 0.5}) {
    const Eigen::Matrix3d covariance = sigma_m_per_s * sigma_m_per_s * Eigen::Matrix3d::Identity();
    const std::vector<Eigen::Matrix3d> covariances(catenaries.lines.size(), covariance);
    const engine::Matrix6d quasi_static =
        line_hydrodynamics(catenaries, rest, covariances, project.site.water_density_kg_per_m3, nullptr).damping;
    const engine::Matrix6d fe = fe_damping(covariance) - fe_at_rest;
    for (int dof : {0, 1, 5}) {
      EXPECT_NEAR(fe(dof, dof), quasi_static(dof, dof), 0.03 * quasi_static(dof, dof))
          << "sigma " << sigma_m_per_s << " m/s, DOF " << dof << "\nFE:\n"
          << fe << "\nquasi-static:\n"
          << quasi_static;
    }
  }
}

}  // namespace
}  // namespace spiral::design

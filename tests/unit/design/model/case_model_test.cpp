// The case model (issue 13): one load case's hull, line types, environment and
// current, built once and shared by the analyses of the case. It must hold
// exactly what the analyses built for themselves before (the static case on
// it is bit-identical to the one that builds its own), and it must belong to
// the case it is used for.
#include "design/model/case_model.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "design/analysis/static_case.hpp"
#include "design/model/environment_loads.hpp"
#include "design/model/mooring_model.hpp"
#include "design/project/input_error.hpp"
#include "design/project/validated_project.hpp"

namespace spiral::design {
namespace {

const std::string kFps = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";
const std::string kOc4 = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/oc4-semisubmersible.yaml";

TEST(CaseModel, HoldsTheCaseEnvironmentCurrentHullAndTypes) {
  const ValidatedProject fps = load_validated_project(kFps);
  const CaseModel model = build_case_model(fps.project, std::string("lc1-survival-collinear-0deg"));
  ASSERT_NE(model.load_case, nullptr);
  ASSERT_NE(model.environment, nullptr);
  EXPECT_EQ(model.load_case->name, "lc1-survival-collinear-0deg");
  EXPECT_EQ(model.environment->name, "survival-100yr-0deg");
  EXPECT_TRUE(model.current.has_value());  // the survival environment has a current profile

  // The same hull and types as built on their own (same inputs, same code:
  // exact equality).
  const HullModel hull = build_hull_model(fps.project);
  EXPECT_EQ(model.hull->mass_matrix, hull.mass_matrix);
  EXPECT_EQ(model.hull->statics.hydrostatic_stiffness, hull.statics.hydrostatic_stiffness);
  EXPECT_EQ(model.hull->low_frequency_added_mass, hull.low_frequency_added_mass);
  const std::vector<LineTypeProperties> types = resolve_line_types(fps.project);
  ASSERT_EQ(model.line_types->size(), types.size());
  for (std::size_t i = 0; i < types.size(); ++i) {
    EXPECT_EQ((*model.line_types)[i].name, types[i].name);
    EXPECT_EQ((*model.line_types)[i].axial_stiffness_N, types[i].axial_stiffness_N);
  }
}

TEST(CaseModel, StillWaterHasNoCaseNorEnvironment) {
  const ValidatedProject oc4 = load_validated_project(kOc4);
  const CaseModel model = build_case_model(oc4.project, std::nullopt);
  EXPECT_EQ(model.load_case, nullptr);
  EXPECT_EQ(model.environment, nullptr);
  EXPECT_FALSE(model.current.has_value());
  EXPECT_TRUE(model.hull->radiation.has_value());  // the .1 file, read once here
}

TEST(CaseModel, DriftTableOnlyInWaves) {
  const ValidatedProject oc4 = load_validated_project(kOc4);
  const CaseModel sea = build_case_model(oc4.project, std::string("intact-raft-jonswap"));
  ASSERT_NE(sea.drift, nullptr);  // hull.mean_drift: marin_semi.12d
  const engine::MeanDriftTable alone = drift_table_of(oc4.project, *oc4.project.hull.mean_drift);
  EXPECT_EQ(sea.drift->omega_rad_per_s, alone.omega_rad_per_s);
  EXPECT_EQ(build_case_model(oc4.project, std::string("intact-still-water")).drift, nullptr);
}

TEST(CaseModel, UnknownCaseIsAnInputError) {
  const ValidatedProject oc4 = load_validated_project(kOc4);
  EXPECT_THROW(build_case_model(oc4.project, std::string("no-such-case")), InputError);
}

TEST(CaseModel, StaticCaseOnAPrebuiltModelIsTheSame) {
  const ValidatedProject fps = load_validated_project(kFps);
  StaticCaseRequest request{std::string("lc3-survival-45deg-damaged-L10"), std::nullopt, false};
  request.lines_carry_current = true;
  const StaticCaseResult own = run_static_case(fps, request);
  const StaticCaseResult shared = run_static_case(fps, build_case_model(fps.project, request.load_case), request);
  EXPECT_EQ(shared.offset, own.offset);
  EXPECT_EQ(shared.stiffness, own.stiffness);
  EXPECT_EQ(shared.damaged_line, own.damaged_line);
  EXPECT_EQ(shared.design_condition, own.design_condition);
  EXPECT_EQ(shared.notes, own.notes);
}

TEST(CaseModel, StaticCaseRefusesAnotherCasesModel) {
  const ValidatedProject fps = load_validated_project(kFps);
  const CaseModel lc1 = build_case_model(fps.project, std::string("lc1-survival-collinear-0deg"));
  const StaticCaseRequest lc2{std::string("lc2-survival-collinear-45deg"), std::nullopt, false};
  EXPECT_THROW(run_static_case(fps, lc1, lc2), std::invalid_argument);
  const StaticCaseRequest still_water{std::nullopt, std::nullopt, false};
  EXPECT_THROW(run_static_case(fps, lc1, still_water), std::invalid_argument);
}

}  // namespace
}  // namespace spiral::design

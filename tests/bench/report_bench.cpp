// Rendering cost of the stage report on the default scenario: one 3D view
// at 1600×1200 (target < 1 s) and the whole static-stage report, analyses
// included (target < 5 s).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>

#include "design/stages/static_stage.hpp"
#include "design/project/validated_project.hpp"
#include "report/render3d.hpp"
#include "report/report_writer.hpp"
#include "report/stage_scene.hpp"
#include "report/static_stage_report.hpp"

namespace {

using namespace spiral;

const std::string kScenario = std::string(SPIRAL_SOURCE_DIR) + "/scenarios/deepwater-fps.yaml";

void BM_RenderView_1600x1200_DefaultScenario(benchmark::State& state) {
  const auto project = design::load_validated_project(kScenario);
  const auto results = design::run_static_stage(project);
  const report::Scene scene =
      report::stage_scene(project.project, results.cases[0], results.strengths, results.checks[0].safety_factor);
  report::ViewOptions options;  // 1600×1200, 2× supersampling
  options.title = "Overview";
  const report::Camera camera = report::frame_view(scene, report::ViewKind::iso, 4.0 / 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(report::render_view(scene, camera, options).rgb.data());
}
BENCHMARK(BM_RenderView_1600x1200_DefaultScenario)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StaticStageReport_DefaultScenario(benchmark::State& state) {
  const auto project = design::load_validated_project(kScenario);
  const auto folder = std::filesystem::temp_directory_path() / ("spiral-bench-report-" + std::to_string(::getpid()));
  for (auto _ : state) {
    const auto results = design::run_static_stage(project);
    const auto document = report::static_stage_report(project, results, {kScenario, "bench", "bench", "0.1.0"});
    benchmark::DoNotOptimize(report::write_report(document, folder).pages);
  }
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_StaticStageReport_DefaultScenario)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

// libFuzzer harness: a hull motion history as `spiral lines --motion` takes it
// — the reader, then the C² spline the fairleads follow built on what it read.
// Documented rejection: design::InputError naming the file with a line and
// column. What it accepts must hold the reader's promises: one finite offset
// per strictly increasing finite time, at least two.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "design/import/motion_history.hpp"
#include "engine/numerics/sampled_trajectory.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spiral;
  const std::string source = "fuzz-input.csv";
  try {
    const design::MotionHistory m = design::parse_motion_history(fuzz::input_text(data, size), source);
    const std::size_t n = m.time_s.size();
    if (n < 2 || static_cast<std::size_t>(m.offset.cols()) != n) fuzz::fail("accepted fewer than 2 rows", source);
    if (!m.offset.allFinite()) fuzz::fail("accepted a non-finite offset", source);
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(m.time_s[k]) || (k > 0 && !(m.time_s[k] > m.time_s[k - 1])))
        fuzz::fail("accepted times that do not increase", source);
    }
    std::vector<Eigen::Vector3d> translation;
    for (Eigen::Index k = 0; k < m.offset.cols(); ++k) translation.emplace_back(m.offset.col(k).head<3>());
    const engine::SampledTrajectory spline(m.time_s, std::move(translation));
    (void)spline.at(0.5 * (m.time_s.front() + m.time_s.back()));
  } catch (const design::InputError& error) {
    fuzz::check_input_error(error, source);
  }
  return 0;
}

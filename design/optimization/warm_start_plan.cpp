#include "design/optimization/warm_start_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace spiral::design {

namespace {

double largest_distance_m(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double largest = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) largest = std::max(largest, (a[j] - b[j]).norm());
  return largest;
}

}  // namespace

std::vector<WarmStart> plan_warm_starts(const std::vector<WarmStartNode>& nodes) {
  const std::size_t n = nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (nodes[k].environment == nodes[i].environment &&
          nodes[k].predicted_tops_g.size() != nodes[i].predicted_tops_g.size())
        throw std::invalid_argument(
            fmt::format("warm-start plan: scenarios {} and {} share an environment but "
                        "not their riser count",
                        k, i));
    }
    if (!nodes[i].own_tops_g.empty() && nodes[i].own_tops_g.size() != nodes[i].predicted_tops_g.size())
      throw std::invalid_argument(fmt::format("warm-start plan: scenario {} has {} solved and {} predicted risers", i,
                                              nodes[i].own_tops_g.size(), nodes[i].predicted_tops_g.size()));
  }
  std::vector<WarmStart> plan(n);
  std::vector<bool> planned(n, false);
  // best[i]: the closest start of an unplanned node so far; updated as nodes
  // are planned (Prim's rule, O(n²) distance evaluations in all).
  std::vector<WarmStart> best(n);
  std::vector<double> best_distance(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i) {
    if (nodes[i].own_tops_g.empty()) continue;
    best_distance[i] = largest_distance_m(nodes[i].predicted_tops_g, nodes[i].own_tops_g);
    best[i] = {std::nullopt, 0, best_distance[i]};
  }
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t next = n;
    for (std::size_t i = 0; i < n; ++i) {
      // Ties go to the lower index: the plan does not depend on the order of
      // equal distances in memory.
      if (!planned[i] && (next == n || best_distance[i] < best_distance[next])) next = i;
    }
    if (best_distance[next] == std::numeric_limits<double>::infinity())
      throw std::invalid_argument(
          fmt::format("warm-start plan: scenario {} has no solved state to start from in its environment", next));
    planned[next] = true;
    plan[next] = best[next];
    for (std::size_t i = 0; i < n; ++i) {
      if (planned[i] || nodes[i].environment != nodes[next].environment) continue;
      const double d = largest_distance_m(nodes[i].predicted_tops_g, nodes[next].predicted_tops_g);
      if (d < best_distance[i]) {
        best_distance[i] = d;
        best[i] = {static_cast<int>(next), plan[next].wave + 1, d};
      }
    }
  }
  return plan;
}

std::vector<std::vector<int>> warm_start_waves(const std::vector<WarmStart>& plan) {
  int last = -1;
  for (const WarmStart& w : plan) last = std::max(last, w.wave);
  std::vector<std::vector<int>> waves(static_cast<std::size_t>(last + 1));
  for (std::size_t i = 0; i < plan.size(); ++i)
    waves[static_cast<std::size_t>(plan[i].wave)].push_back(static_cast<int>(i));
  return waves;
}

}  // namespace spiral::design

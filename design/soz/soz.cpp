// The riser offset evaluator and the zone search of soz.hpp. Past ~600 lines
// on purpose: the search (march, bracket, regula falsi, symmetry sharing) and
// the evaluator's warm-start and tolerance contract (march solves at 1e-5,
// re-solved at 1e-10 near utilization 1) are one algorithm whose invariants
// read best side by side; the offset check is in soz_check.cpp, the symmetry
// in soz_symmetry.cpp.
#include "design/project/request_error.hpp"
#include "design/soz/soz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <thread>

#include "design/model/environment_loads.hpp"
#include "design/project/input_error.hpp"
#include "design/soz/soz_symmetry.hpp"
#include "design/analysis/static_case.hpp"
#include "design/criteria/riser_checks.hpp"
#include "engine/common/rigid_body.hpp"
#include "engine/common/parallel_for.hpp"
#include "engine/lines/catenary.hpp"
#include "engine/common/stopwatch.hpp"

namespace spiral::design {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// A step "divides 360" when 360/step is an integer to this relative precision
// (5.0, 2.5, 0.1 … pass; 7.0 does not).
constexpr double kStepDivisionTolerance = 1e-9;
// Regula falsi keeps each new point this fraction of the tolerance inside the
// bracket, so that a converging one-sided sequence closes the bracket from the
// other side in one more solve.
constexpr double kFalsiInset = 0.4;
// Refinement iterations per bracket: bisection of a 20 %-of-depth bracket to
// 1 mm takes < 25; this only stops a pathological case.
constexpr int kMaxRefineIterations = 60;
// Newton tolerance of the march samples (RiserOffsetEvaluator::Precision):
// 1e-5 of the force scale instead of 1e-10 (Newton and chord steps stop
// earlier). Measured on the default SCRs, all 1,557 march points of the
// still-water zone solved both ways: governing utilization within 2.3e-4
// (mean 4.8e-6); at 1e-4 within 1.2e-3, at 1e-6 within 2.8e-5.
constexpr double kMarchForceTolerance = 1e-5;
// A march point whose governing utilization is this close to 1 — ten times
// the error above — is solved again at the final precision, so that no
// march point's pass/fail (which places the bracket) rests on that error.
constexpr double kMarchUtilizationMargin = 2.5e-3;
// Directions per parallel task: 72 directions × 12 risers give 144 tasks on
// any core count, fine enough to balance 2–64 threads.
constexpr int kDirectionsPerTask = 6;

/// Re-derives the governing criterion and pass flag after a check was added.
void regovern(RiserStaticsRow& row) {
  row.utilization = 0.0;
  row.governing_criterion.clear();
  row.passes = true;
  for (const RiserCriterionCheck& check : row.checks) {
    if (check.utilization >= row.utilization || row.governing_criterion.empty()) {
      row.utilization = check.utilization;
      row.governing_criterion = check.criterion;
    }
    row.passes = row.passes && check.passes;
  }
}

double normalize_deg(double deg) {
  deg = std::fmod(deg, 360.0);
  return deg < 0.0 ? deg + 360.0 : deg;
}

}  // namespace

const char* to_string(SozModel model) { return model == SozModel::fe ? "fe" : "catenary"; }

const char* to_string(OffsetCheckKind kind) { return kind == OffsetCheckKind::static_mean ? "static" : "extreme"; }

// ---------------------------------------------------------------------------
// Riser statics at an offset.

RiserOffsetEvaluator::RiserOffsetEvaluator(const Project& project, const RiserDesign& design,
                                           const SozConditions& conditions, SozModel model)
    : project_(project),
      design_(design),
      conditions_(conditions),
      model_(model),
      environment_(
          fe_environment(project, conditions.current, design.sections.front().properties.hydrodynamic_diameter_m)) {
  zero_ = model_ == SozModel::fe ? solve_fe(hang_off_g({0.0, 0.0}), nullptr, Precision::final)
                                 : solve_catenary(hang_off_g({0.0, 0.0}));
  if (!zero_.error.empty()) throw engine::SolverError(zero_.error);
  if (zero_.touchdown_g) {
    reference_touchdown_g_ = *zero_.touchdown_g;
    has_reference_touchdown_ = true;
  }
  // The zero-offset point itself has no excursion.
  add_touchdown_check(zero_, zero_.touchdown_g);
}

Eigen::Vector3d RiserOffsetEvaluator::hang_off_g(const Eigen::Vector2d& offset_xy_m) const {
  engine::Vector6d offset;
  offset << offset_xy_m.x(), offset_xy_m.y(), conditions_.heave_m, conditions_.rotation_rad;
  return engine::body_point_to_global(project_.hull.reference_point_g, offset, design_.hang_off_b);
}

RiserOffsetEvaluator::Evaluation RiserOffsetEvaluator::evaluate(const Eigen::Vector2d& offset_xy_m,
                                                                const engine::FeStaticsResult* warm,
                                                                Precision precision) const {
  const Eigen::Vector3d top = hang_off_g(offset_xy_m);
  Evaluation e;
  if (model_ == SozModel::catenary) {
    e = solve_catenary(top);
  } else {
    e = solve_fe(top, warm ? warm : zero_.solution.get(), precision);
  }
  if (!e.error.empty()) return e;
  add_touchdown_check(e, e.touchdown_g);
  return e;
}

void RiserOffsetEvaluator::add_touchdown_check(Evaluation& e, const std::optional<Eigen::Vector3d>& touchdown_g) const {
  const auto& limit = design_.criteria.max_touchdown_excursion_m;
  if (!limit || !e.error.empty()) return;
  // A riser that lifts off the seabed entirely has moved its TDP to the foot
  // or beyond: count the excursion as unbounded rather than silently zero.
  const double excursion_m = touchdown_g && has_reference_touchdown_
                                 ? (*touchdown_g - reference_touchdown_g_).head<2>().norm()
                                 : std::numeric_limits<double>::infinity();
  const double u = excursion_m / *limit;
  e.row.checks.push_back({"max_touchdown_excursion", excursion_m, *limit, "m", u, u <= 1.0});
  regovern(e.row);
}

RiserOffsetEvaluator::Evaluation RiserOffsetEvaluator::failed(std::string message) const {
  Evaluation e;
  e.error = std::move(message);
  e.row.name = design_.name;
  e.row.kind = design_.kind;
  e.row.governing_criterion = "no_static_solution";
  e.row.utilization = std::numeric_limits<double>::infinity();
  e.row.passes = false;
  return e;
}

RiserOffsetEvaluator::Evaluation RiserOffsetEvaluator::solve_fe(const Eigen::Vector3d& top,
                                                                const engine::FeStaticsResult* warm,
                                                                Precision precision) const {
  engine::FeStaticsOptions options;
  if (precision == Precision::march) {
    options.relative_force_tolerance = kMarchForceTolerance;
    // The touchdown node move sharpens the TDP curvature peak for the final
    // bracket; a march point's pass/fail does not hinge on it (5 % of the
    // Newton work, callgrind on the default SCR).
    options.snap_node_to_touchdown = false;
    options.polish_chord_steps = false;
  }
  options.compute_end_B_stiffness = false;  // the zone needs forces and stresses only
  if (warm) engine::warm_start_from(options, *warm);
  Evaluation e;
  try {
    auto solution = std::make_shared<engine::FeStaticsResult>(
        engine::solve_fe_line_statics(design_.fe_model, environment_, {design_.foot_g, top}, options));
    e.row = riser_statics_row(project_, design_, *solution, conditions_.condition,
                              engine::rotation_matrix(conditions_.rotation_rad));
    if (solution->touchdown) e.touchdown_g = solution->touchdown->position_m;
    e.solution = std::move(solution);
  } catch (const engine::SolverError& error) {
    e = failed(fmt::format("riser '{}' at hang-off ({:.2f}, {:.2f}, {:.2f}) m: {}", design_.name, top.x(), top.y(),
                           top.z(), error.what()));
  }
  return e;
}

// Screening model: the riser as a multi-segment elastic catenary in the
// vertical plane through its foot and hang-off (no current, no bending
// stiffness in the equilibrium). Curvature of the suspended part from the
// catenary, κ = w H / T² (Irvine 1981), which at the touchdown point is the
// boundary-layer peak w/H of Pesce et al. (1998) — the FE solution is within
// ≈ 1 % of it for these SCRs (fe_line_statics.hpp); the bending moment is
// EI κ. The result is packed as an FE result so the same criteria apply.
RiserOffsetEvaluator::Evaluation RiserOffsetEvaluator::solve_catenary(const Eigen::Vector3d& top) const {
  Evaluation e;
  engine::CatenaryLine line;
  for (const RiserSectionDesign& s : design_.sections) {
    line.segments.push_back({s.length_m, s.properties.effective_weight_N_per_m, s.properties.EA_N});
  }
  const Eigen::Vector2d span_xy = top.head<2>() - design_.foot_g.head<2>();
  const double span_m = span_xy.norm();
  const Eigen::Vector2d along = span_m > 0.0 ? Eigen::Vector2d(span_xy / span_m) : Eigen::Vector2d(1.0, 0.0);
  engine::CatenaryOptions options;
  options.profile_points_per_segment = 400;
  try {
    const engine::CatenarySolution c =
        engine::solve_catenary(line, {span_m, top.z() - design_.foot_g.z(), 0.0}, options);
    engine::FeStaticsResult r;
    const double H = c.fairlead_horizontal_N;
    for (const engine::CatenaryProfilePoint& p : c.profile) {
      const RiserSectionDesign& s = design_.sections[static_cast<std::size_t>(p.segment)];
      const double w = s.properties.effective_weight_N_per_m;
      const double kappa = p.on_seabed || !(p.tension_N > 0.0) ? 0.0 : std::abs(w) * H / (p.tension_N * p.tension_N);
      r.node_arc_length_m.push_back(p.arc_length_m);
      Eigen::Vector3d position = design_.foot_g;
      position.head<2>() += p.x_m * along;
      position.z() += p.z_m;
      r.node_position_m.push_back(position);
      r.node_tension_N.push_back(p.tension_N);
      r.node_curvature_per_m.push_back(kappa);
      r.node_bending_moment_Nm.push_back(s.properties.EI_N_m2 * kappa);
    }
    r.node_position_m.back() = top;
    r.end_B_force_N << -H * along.x(), -H * along.y(), -c.fairlead_vertical_N;
    if (c.laid_length_m > 0.0) {
      Eigen::Vector3d tdp = design_.foot_g;
      tdp.head<2>() += c.touchdown_x_m * along;
      r.touchdown = engine::FeTouchdown{c.laid_length_m, tdp};
    }
    e.row = riser_statics_row(project_, design_, r, conditions_.condition,
                              engine::rotation_matrix(conditions_.rotation_rad));
    if (r.touchdown) e.touchdown_g = r.touchdown->position_m;
  } catch (const engine::SolverError& error) {
    e = failed(fmt::format("riser '{}' (catenary screening) at hang-off ({:.2f}, {:.2f}, {:.2f}) m: {}", design_.name,
                           top.x(), top.y(), top.z(), error.what()));
  }
  return e;
}

// ---------------------------------------------------------------------------
// Zone search in one direction.

namespace {

struct Sample {
  double d_m = 0.0;
  RiserOffsetEvaluator::Evaluation evaluation;
  /// Governing utilization − 1: ≤ 0 passes. A failed solve counts as +1.
  double g() const {
    if (!evaluation.error.empty()) return 1.0;
    return evaluation.row.utilization - 1.0;
  }
};

class DirectionSearch {
 public:
  /// `chunk`: the searches of the earlier directions of the same task, in
  /// order (the direction before this one last); `index`: this direction's
  /// place in the task. Their samples are warm starts too — at offset d two
  /// neighbouring hang-offs are only d·step apart, closer than the march
  /// step — and cover the march where they are closer than one march step.
  DirectionSearch(const RiserOffsetEvaluator& evaluator, double direction_rad, const SozOptions& options,
                  double depth_m, const std::vector<std::unique_ptr<DirectionSearch>>& chunk, int index)
      : evaluator_(evaluator),
        chunk_(chunk),
        index_(index),
        step_rad_(options.step_deg * kDegToRad),
        unit_(std::cos(direction_rad), std::sin(direction_rad)),
        tolerance_m_(options.tolerance_m),
        step_m_(options.march_step_pct_depth * depth_m / 100.0),
        limit_m_(options.search_limit_pct_depth * depth_m / 100.0) {
    samples_.push_back({0.0, evaluator.zero_offset()});
  }

  SozDirection run(double direction_deg) {
    SozDirection result;
    result.direction_deg = direction_deg;
    const Sample* pass = &samples_.front();
    const Sample* fail = nullptr;
    double d = 0.0;
    // 1. Coarse march to the first failure. A march point is solved unless
    // the covering direction of the task (covering_index) passed at the same
    // offset: the march resolves the zone to one march step radially, and
    // that direction is within one march step of the point along the arc.
    while (d < limit_m_ - 1e-9) {
      d = std::min(d + step_m_, limit_m_);
      // The search limit is always solved: a direction that passes reports
      // it as its allowable offset, and the boundary may lie within the
      // last step although the neighbour passes there.
      if (d < limit_m_ - 1e-9 && covered(d, true)) continue;
      const Sample& s = evaluate(d, RiserOffsetEvaluator::Precision::march);
      if (s.g() > 0.0) {
        fail = &s;
        break;
      }
      pass = &s;
    }
    if (!fail) {
      result.allowable_offset_m = limit_m_;
      result.governing_criterion = "search_limit";
      result.governing_utilization = pass->evaluation.row.utilization;
      result.limited_by_search = true;
      result.solves = solves_;
      return result;
    }
    // The bracket's passing end must be a solve of this direction: march
    // points skipped below the failure are solved now, downwards, until one
    // passes (the failure moves down with them).
    for (double below = fail->d_m - step_m_; below > pass->d_m + 1e-9; below -= step_m_) {
      const Sample& s = evaluate(below, RiserOffsetEvaluator::Precision::march);
      if (s.g() <= 0.0) {
        pass = &s;
        break;
      }
      fail = &s;
    }
    // 2. Refine the first boundary.
    const auto [edge_pass, edge_fail] = refine(*pass, *fail);
    result.allowable_offset_m = edge_pass.d_m;
    result.governing_criterion = edge_fail.evaluation.row.governing_criterion;
    result.governing_utilization = edge_fail.evaluation.row.utilization;
    result.solver_message = edge_fail.evaluation.error;
    // 3. Continue the coarse march: does the riser pass again farther out?
    // Mirror of the coverage above: while this direction fails, a point whose
    // covering direction fails at the same offset is not solved (a band
    // narrower than one step is below the march's resolution either way).
    const Sample* previous = fail;
    std::optional<SozBand> open;
    while (d < limit_m_ - 1e-9) {
      d = std::min(d + step_m_, limit_m_);
      if (previous->g() > 0.0 && covered(d, false)) continue;
      const Sample& s = evaluate(d, RiserOffsetEvaluator::Precision::march);
      const bool passes = s.g() <= 0.0;
      const bool previous_passes = previous->g() <= 0.0;
      if (passes && !previous_passes) {
        open = SozBand{refine(s, *previous).first.d_m, limit_m_};
      } else if (!passes && previous_passes && open) {
        open->to_m = refine(*previous, s).first.d_m;
        result.reopened_bands.push_back(*open);
        open.reset();
      }
      previous = &s;
    }
    if (open) result.reopened_bands.push_back(*open);
    result.solves = solves_;
    return result;
  }

 private:
  /// The earlier direction of the task that covers this one's march point at
  /// offset d, or −1: directions are grouped in blocks of m (m divides
  /// kDirectionsPerTask) spanning at most one march step of arc at d, (m − 1)
  /// d Δθ ≤ step; a block's first direction covers the rest.
  int covering_index(double d) const {
    int m = 1;
    for (const int candidate : {2, 3, 6}) {
      if (kDirectionsPerTask % candidate == 0 && (candidate - 1) * d * step_rad_ <= step_m_) m = candidate;
    }
    const int first = index_ - index_ % m;
    return first == index_ ? -1 : first;
  }

  /// Whether the march point at d is covered by a solve of the covering
  /// direction at the same offset that passes (`passing`) or fails.
  bool covered(double d, bool passing) const {
    const int k = covering_index(d);
    if (k < 0 || k >= static_cast<int>(chunk_.size())) return false;
    for (const Sample& s : chunk_[static_cast<std::size_t>(k)]->samples_) {
      if (std::abs(s.d_m - d) <= 1e-9 * std::max(1.0, d)) return (s.g() <= 0.0) == passing;
    }
    return false;
  }

  /// Solves at offset d along the direction, warm-started from the sample
  /// (of this direction or an earlier one of the task) whose hull offset is nearest.
  const Sample& evaluate(double d, RiserOffsetEvaluator::Precision precision) {
    const Eigen::Vector2d x = d * unit_;
    const engine::FeStaticsResult* warm = nullptr;
    double nearest_m = std::numeric_limits<double>::infinity();
    const auto consider = [&](const DirectionSearch& search) {
      for (const Sample& s : search.samples_) {
        const double distance_m = (s.d_m * search.unit_ - x).norm();
        if (s.evaluation.solution && distance_m < nearest_m) {
          nearest_m = distance_m;
          warm = s.evaluation.solution.get();
        }
      }
    };
    consider(*this);
    for (const auto& search : chunk_) consider(*search);
    ++solves_;
    RiserOffsetEvaluator::Evaluation e = evaluator_.evaluate(x, warm, precision);
    if (precision == RiserOffsetEvaluator::Precision::march && e.error.empty() &&
        std::abs(e.row.utilization - 1.0) < kMarchUtilizationMargin) {
      ++solves_;
      e = evaluator_.evaluate(x, e.solution.get(), RiserOffsetEvaluator::Precision::final);
    }
    samples_.push_back({d, std::move(e)});
    return samples_.back();
  }

  /// Shrinks [pass, fail] (either order along d) to the tolerance by
  /// safeguarded regula falsi (Illinois): returns the final passing and
  /// failing samples.
  std::pair<Sample, Sample> refine(Sample pass, Sample fail) {
    double g_pass = pass.g(), g_fail = fail.g();  // Illinois-scaled copies
    int retained = 0;                             // +n: pass end moved n times in a row, −n: fail end
    for (int i = 0; i < kMaxRefineIterations && std::abs(fail.d_m - pass.d_m) > tolerance_m_; ++i) {
      const double lo = std::min(pass.d_m, fail.d_m), hi = std::max(pass.d_m, fail.d_m);
      double x = 0.5 * (lo + hi);
      if (std::isfinite(g_pass) && std::isfinite(g_fail) && g_fail > g_pass) {
        x = pass.d_m + (fail.d_m - pass.d_m) * (-g_pass) / (g_fail - g_pass);
      }
      const double inset = kFalsiInset * tolerance_m_;
      x = std::clamp(x, lo + inset, hi - inset);
      const Sample s = evaluate(x, RiserOffsetEvaluator::Precision::final);
      if (s.g() <= 0.0) {
        pass = s;
        g_pass = s.g();
        retained = retained > 0 ? retained + 1 : 1;
        if (retained >= 2) g_fail *= 0.5;  // the fail end is stale: Illinois step
      } else {
        fail = s;
        g_fail = s.g();
        retained = retained < 0 ? retained - 1 : -1;
        if (retained <= -2) g_pass *= 0.5;
      }
    }
    return {pass, fail};
  }

  const RiserOffsetEvaluator& evaluator_;
  const std::vector<std::unique_ptr<DirectionSearch>>& chunk_;
  int index_;
  double step_rad_;
  Eigen::Vector2d unit_;
  double tolerance_m_;
  double step_m_;
  double limit_m_;
  std::deque<Sample> samples_;  // stable addresses
  int solves_ = 0;
};

}  // namespace

// ---------------------------------------------------------------------------

double polygon_allowable(const std::vector<double>& directions_deg, const std::vector<double>& allowable_m,
                         double direction_deg) {
  const std::size_t n = directions_deg.size();
  const double step = 360.0 / static_cast<double>(n);
  const double x = normalize_deg(direction_deg - directions_deg.front()) / step;
  const std::size_t i = static_cast<std::size_t>(std::floor(x)) % n;
  const double t = x - std::floor(x);
  return (1.0 - t) * allowable_m[i] + t * allowable_m[(i + 1) % n];
}

void validate_soz_options(const Project& project, const SozOptions& o) {
  const double count = 360.0 / o.step_deg;
  if (!(o.step_deg > 0.0) || o.step_deg > 360.0 ||
      std::abs(count - std::round(count)) > kStepDivisionTolerance * count) {
    throw request_error(project, "step_deg",
                        fmt::format("the direction step must divide 360 deg, got {} deg", o.step_deg),
                        "soz_step_divides_360");
  }
  if (!(o.tolerance_m > 0.0)) {
    throw request_error(project, "tolerance_m", fmt::format("must be > 0, got {} m", o.tolerance_m),
                        "soz_tolerance_positive");
  }
  if (!(o.march_step_pct_depth > 0.0) || !(o.search_limit_pct_depth >= o.march_step_pct_depth)) {
    throw request_error(project, "search_limit_pct_depth",
                        fmt::format("need 0 < march step ({} %) <= search limit ({} %) of depth",
                                    o.march_step_pct_depth, o.search_limit_pct_depth),
                        "soz_search_range");
  }
  for (const std::string& name : o.exclude_risers) {
    if (std::none_of(project.risers.begin(), project.risers.end(), [&](const Riser& r) { return r.name == name; })) {
      throw request_error(project, "exclude_risers", fmt::format("no riser named \"{}\"", name));
    }
  }
  if (o.load_case) find_load_case(project, *o.load_case);
  if (o.extreme) {
    if (!(o.extreme->duration_s > 0.0)) {
      throw request_error(project, "duration_s", fmt::format("must be > 0 s, got {} s", o.extreme->duration_s),
                          "soz_duration_positive");
    }
    if ((!o.offset_check || o.zones_only) && !o.load_case) {
      throw request_error(project, "extreme",
                          "the extreme offsets are part of the offset check, which this request turns off",
                          "soz_extreme_needs_check");
    }
  }
}

SozResult compute_soz(const Project& project, const std::vector<RiserDesign>& risers, const SozConditions& conditions,
                      const SozOptions& options) {
  validate_soz_options(project, options);
  engine::Stopwatch start;
  SozResult result;
  result.project = project.name;
  result.depth_m = project.site.depth_m;
  result.options = options;
  result.conditions = conditions;
  const int n_directions = static_cast<int>(std::lround(360.0 / options.step_deg));
  for (int k = 0; k < n_directions; ++k) result.directions_deg.push_back(k * options.step_deg);
  result.threads = options.threads > 0 ? options.threads : engine::worker_count(std::numeric_limits<int>::max());

  // Risers whose zone is another's turned or mirrored are not solved; a
  // riser symmetric about its own plane is solved on one half.
  const std::vector<SozZoneMap> maps = soz_zone_maps(project, risers, conditions, options, n_directions);
  std::vector<int> solved;  // riser indices that are solved
  for (std::size_t r = 0; r < risers.size(); ++r) {
    if (maps[r].source < 0) solved.push_back(static_cast<int>(r));
  }

  // Zero-offset solves (cold), one riser per task.
  const int n_solved = static_cast<int>(solved.size());
  std::vector<std::unique_ptr<RiserOffsetEvaluator>> evaluators(risers.size());
  engine::parallel_for(n_solved, result.threads, [&](int i) {
    const auto r = static_cast<std::size_t>(solved[static_cast<std::size_t>(i)]);
    evaluators[r] = std::make_unique<RiserOffsetEvaluator>(project, risers[r], conditions, options.model);
  });
  result.risers.resize(risers.size());
  for (std::size_t r = 0; r < risers.size(); ++r) {
    RiserSoz& z = result.risers[r];
    z.name = risers[r].name;
    z.kind = risers[r].kind;
    z.azimuth_deg = normalize_deg(risers[r].azimuth_rad * kRadToDeg);
    if (maps[r].source >= 0) continue;  // filled from its source below
    const RiserStaticsRow& zero = evaluators[r]->zero_offset().row;
    z.zero_offset_governing_criterion = zero.governing_criterion;
    z.zero_offset_utilization = zero.utilization;
    z.fails_at_zero_offset = !zero.passes;
    z.zone_mirror_symmetric = maps[r].self_mirror_index >= 0;
    z.directions.resize(static_cast<std::size_t>(n_directions));
    z.solves = 1;
  }

  // Directions: tasks of kDirectionsPerTask consecutive directions of one
  // riser. A self-mirror riser's solved half runs from its mirror plane
  // anticlockwise, so that its directions stay consecutive.
  struct Task {
    std::size_t riser;
    std::vector<int> directions;
  };
  std::vector<Task> tasks;
  for (const int ri : solved) {
    const auto r = static_cast<std::size_t>(ri);
    const int m = maps[r].self_mirror_index;
    const int first = m < 0 ? 0 : (m + 1) / 2;  // the first grid direction at or after the plane
    std::vector<int> order;
    for (int i = 0; i < n_directions; ++i) {
      const int k = (first + i) % n_directions;
      if (soz_in_solved_half(k, m, n_directions)) order.push_back(k);
    }
    for (std::size_t i = 0; i < order.size(); i += kDirectionsPerTask) {
      tasks.push_back({r, std::vector<int>(order.begin() + static_cast<std::ptrdiff_t>(i),
                                           order.begin() + static_cast<std::ptrdiff_t>(
                                                               std::min(order.size(), i + kDirectionsPerTask)))});
    }
  }
  std::atomic<int> started{0};
  engine::parallel_for(static_cast<int>(tasks.size()), result.threads, [&](int t) {
    if (options.progress) options.progress(started++ / static_cast<double>(tasks.size()));
    const Task& task = tasks[static_cast<std::size_t>(t)];
    RiserSoz& z = result.risers[task.riser];
    // Directions of a task run in order, each warm-started from its
    // predecessor in the task; the tasks are fixed, so the result does not
    // depend on the thread count.
    std::vector<std::unique_ptr<DirectionSearch>> chunk;
    for (const int k : task.directions) {
      SozDirection& out = z.directions[static_cast<std::size_t>(k)];
      const double direction_deg = result.directions_deg[static_cast<std::size_t>(k)];
      if (z.fails_at_zero_offset) {
        out.direction_deg = direction_deg;
        out.governing_criterion = z.zero_offset_governing_criterion;
        out.governing_utilization = z.zero_offset_utilization;
        continue;
      }
      auto search = std::make_unique<DirectionSearch>(*evaluators[task.riser], direction_deg * kDegToRad, options,
                                                      project.site.depth_m, chunk, static_cast<int>(chunk.size()));
      out = search->run(direction_deg);
      chunk.push_back(std::move(search));
    }
  });

  // Copies: the mirrored half of a self-mirror riser, then the turned and
  // mirrored risers (their sources are complete by then).
  const auto copy = [&](const SozDirection& from, int k) {
    SozDirection d = from;
    d.direction_deg = result.directions_deg[static_cast<std::size_t>(k)];
    d.solves = 0;
    return d;
  };
  const auto wrap = [n_directions](int k) { return ((k % n_directions) + n_directions) % n_directions; };
  for (const int ri : solved) {
    const auto r = static_cast<std::size_t>(ri);
    const int m = maps[r].self_mirror_index;
    if (m < 0) continue;
    RiserSoz& z = result.risers[r];
    for (int k = 0; k < n_directions; ++k) {
      if (soz_in_solved_half(k, m, n_directions)) continue;
      z.directions[static_cast<std::size_t>(k)] = copy(z.directions[static_cast<std::size_t>(wrap(m - k))], k);
    }
  }
  for (std::size_t r = 0; r < risers.size(); ++r) {
    const SozZoneMap& map = maps[r];
    if (map.source < 0) continue;
    const RiserSoz& from = result.risers[static_cast<std::size_t>(map.source)];
    RiserSoz& z = result.risers[r];
    z.zero_offset_governing_criterion = from.zero_offset_governing_criterion;
    z.zero_offset_utilization = from.zero_offset_utilization;
    z.fails_at_zero_offset = from.fails_at_zero_offset;
    (map.mirrored ? z.zone_mirrored_from : z.zone_rotated_from) = from.name;
    z.directions.resize(from.directions.size());
    for (int k = 0; k < n_directions; ++k) {
      const int source_k = map.mirrored ? wrap(map.index - k) : wrap(k - map.index);
      z.directions[static_cast<std::size_t>(k)] = copy(from.directions[static_cast<std::size_t>(source_k)], k);
    }
  }
  std::string rotated, mirrored, halves;
  for (const RiserSoz& z : result.risers) {
    if (!z.zone_rotated_from.empty())
      rotated += fmt::format("{}{} = {}", rotated.empty() ? "" : ", ", z.name, z.zone_rotated_from);
    if (!z.zone_mirrored_from.empty())
      mirrored += fmt::format("{}{} = {}", mirrored.empty() ? "" : ", ", z.name, z.zone_mirrored_from);
    if (z.zone_mirror_symmetric) halves += fmt::format("{}{}", halves.empty() ? "" : ", ", z.name);
  }
  const char* exact = "same design and criteria, no current, no hull rotations: exact by symmetry";
  if (!rotated.empty()) {
    result.notes.push_back(
        fmt::format("zones turned about the vertical from an identical riser ({}): {}", exact, rotated));
  }
  if (!mirrored.empty()) {
    result.notes.push_back(
        fmt::format("zones mirrored in a vertical plane from an identical riser placed as its mirror image ({}): {}",
                    exact, mirrored));
  }
  if (!halves.empty()) {
    result.notes.push_back(fmt::format(
        "zones symmetric about the riser's own plane, one half solved and the other mirrored ({}): {}", exact, halves));
  }

  // Per-riser summaries and the platform intersection.
  result.platform.allowable_offset_m.assign(static_cast<std::size_t>(n_directions),
                                            std::numeric_limits<double>::infinity());
  result.platform.governing_riser.assign(static_cast<std::size_t>(n_directions), "");
  result.platform.governing_criterion.assign(static_cast<std::size_t>(n_directions), "");
  for (RiserSoz& z : result.risers) {
    std::vector<double> allowable;
    for (const SozDirection& d : z.directions) {
      allowable.push_back(d.allowable_offset_m);
      z.solves += d.solves;
      z.star_shaped = z.star_shaped && d.reopened_bands.empty();
    }
    z.near_m = polygon_allowable(result.directions_deg, allowable, z.azimuth_deg);
    z.far_m = polygon_allowable(result.directions_deg, allowable, z.azimuth_deg + 180.0);
    z.cross_left_m = polygon_allowable(result.directions_deg, allowable, z.azimuth_deg + 90.0);
    z.cross_right_m = polygon_allowable(result.directions_deg, allowable, z.azimuth_deg - 90.0);
    const auto nearest = [&](double deg) -> const std::string& {
      const double x = normalize_deg(deg) / options.step_deg;
      return z.directions[static_cast<std::size_t>(std::lround(x)) % z.directions.size()].governing_criterion;
    };
    z.near_governing = nearest(z.azimuth_deg);
    z.far_governing = nearest(z.azimuth_deg + 180.0);
    result.solves += z.solves;
    for (std::size_t k = 0; k < z.directions.size(); ++k) {
      if (z.directions[k].allowable_offset_m < result.platform.allowable_offset_m[k]) {
        result.platform.allowable_offset_m[k] = z.directions[k].allowable_offset_m;
        result.platform.governing_riser[k] = z.name;
        result.platform.governing_criterion[k] = z.directions[k].governing_criterion;
      }
    }
  }
  if (risers.empty()) result.notes.push_back("the project has no risers: no SOZ");
  result.zone_wall_s = start.seconds();
  return result;
}

}  // namespace spiral::design

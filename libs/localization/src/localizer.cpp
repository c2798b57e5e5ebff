// Localizer: the pipeline of paper §2.3-2.4 over one set of fused percepts.
//
//   Eq. 7 noise -> proximity filtering (Eqs. 8-9) -> for each seed triple of percepts:
//   orientation filtering (Eq. 10) -> interpretation search and restriction spheres (Eqs. 11-15)
//   with Eq. 16 poses -> validation against all percepts -> decision -> Ceres refinement and the
//   precision requirement.
//
// Seeds (seeds.hpp). Every hypothesis consistent with all percepts is consistent with any three
// true ones, and orientation filtering enumerates every model triple that three percepts can be;
// so one seed of true percepts yields all the hypotheses there are (up to the tolerances). A seed
// holding a false positive yields wrong hypotheses only, which validation scores low. Seeds are
// therefore tried in turn, each sharing as few percepts as possible with the previous ones (and
// avoiding those of seeds that gave nothing), until the best hypothesis explains every percept of
// `confirming_seeds` of them (then at least one of them is almost surely free of false
// positives; one seed when the best explains nearly every percept) or `max_seeds` are spent.
//
// Cost control, without losing a hypothesis the data support:
//  - an interpretation is abandoned once it cannot explain as many percepts as needed to be
//    reported (min_explained_fraction) or to come near the best found so far (a quarter fewer,
//    with slack): the bar rises as hypotheses are found, so wrong subgraphs stop after a few
//    misses;
//  - a subgraph whose seed pose lands, within 10 cm and 3 degrees, on a hypothesis validated from
//    an earlier seed that already gives the seed's percepts the subgraph's objects is skipped;
//  - an interpretation whose Eq. 16 pose is the same as one already found is not validated again;
//  - validated hypotheses are kept merged (indistinguishable ones are one) in a spatial index.
#include "vsl/localization/localizer.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "vsl/localization/hypotheses.hpp"
#include "vsl/localization/localization_context.hpp"
#include "vsl/localization/node_grid.hpp"
#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/pose_index.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/localization/seeds.hpp"
#include "vsl/localization/validation.hpp"

namespace vsl::localization {
namespace {

using Clock = std::chrono::steady_clock;

// Adds the time since construction (or the last lap) to a stage's milliseconds.
class StageTimer {
 public:
  explicit StageTimer(double& total_ms) : total_ms_(total_ms), start_(Clock::now()) {}
  ~StageTimer() {
    total_ms_ += std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double& total_ms_;
  Clock::time_point start_;
};

// Cell of the spatial index (m): a validation gate (3 sigma, 0.1-0.5 m) spans one or two cells
// per axis.
constexpr double kGridCellM = 1.0;

// Hypotheses reported beside the best one when localized or failed (for inspection).
constexpr std::size_t kReportedRunnersUp = 9;

Association to_association(const world::WorldModel& world, const world::WorldGraph& graph,
                           const NodeAssociation& a) {
  const std::size_t object = graph.object_index(a.node);
  return {a.percept, object, world.objects[object].id};
}

Hypothesis to_hypothesis(const world::WorldModel& world, const world::WorldGraph& graph,
                         const ValidatedHypothesis& v) {
  Hypothesis h;
  h.world_T_ego = v.world_T_ego;
  h.score = v.score;
  for (const NodeAssociation& a : v.explanation.associations) {
    h.associations.push_back(to_association(world, graph, a));
  }
  return h;
}

// Validated hypotheses, kept free of indistinguishable pairs (of two such the better ranked
// stays), found by position.
class HypothesisSet {
 public:
  explicit HypothesisSet(const HypothesisOptions& options) : options_(options) {}

  void add(ValidatedHypothesis candidate) {
    // indistinguishable() reaches at most 2 sqrt(sigma_a^2 + sigma_b^2) <= 2 (0.1 + 0.1) m.
    const double radius = std::max(options_.same_position_m, 0.4);
    std::optional<std::size_t> same;
    index_.for_each_near(candidate.world_T_ego.translation(), radius, [&](std::size_t id) {
      if (!same && indistinguishable(hypotheses_[id], candidate, options_)) same = id;
    });
    if (same) {
      // The better one stays; it is within the radius of the indexed position.
      if (ranks_before(candidate, hypotheses_[*same])) {
        index_.add(candidate.world_T_ego.translation(), *same);  // it may have moved a little
        hypotheses_[*same] = std::move(candidate);
      }
      return;
    }
    index_.add(candidate.world_T_ego.translation(), hypotheses_.size());
    hypotheses_.push_back(std::move(candidate));
  }

  // Whether a hypothesis within tolerance_m and tolerance_rad of `pose` already gives the three
  // seed percepts the subgraph's three objects.
  bool covers(const Eigen::Isometry3d& pose, double tolerance_m, double tolerance_rad,
              const PerceptTriple& seed, const ModelTriple& subgraph) const {
    bool covered = false;
    index_.for_each_near(pose.translation(), tolerance_m, [&](std::size_t id) {
      const ValidatedHypothesis& h = hypotheses_[id];
      if (covered || (h.world_T_ego.translation() - pose.translation()).norm() >= tolerance_m ||
          rotation_angle_rad(h.world_T_ego, pose) >= tolerance_rad) {
        return;
      }
      const auto& associations = h.explanation.associations;
      covered = true;
      for (std::size_t k = 0; k < seed.percepts.size() && covered; ++k) {
        covered =
            std::any_of(associations.begin(), associations.end(), [&](const NodeAssociation& a) {
              return a.percept == seed.percepts[k] && a.node == subgraph.nodes[k];
            });
      }
    });
    return covered;
  }

  // Ranked, best first (a copy: the set keeps its own order for the index).
  std::vector<ValidatedHypothesis> ranked() const {
    std::vector<ValidatedHypothesis> out = hypotheses_;
    std::sort(out.begin(), out.end(), ranks_before);
    return out;
  }
  const ValidatedHypothesis* best() const {
    const auto it = std::min_element(hypotheses_.begin(), hypotheses_.end(), ranks_before);
    return it == hypotheses_.end() ? nullptr : &*it;
  }

 private:
  const HypothesisOptions& options_;
  std::vector<ValidatedHypothesis> hypotheses_;
  PoseIndex index_{0.5};
};

// Standard deviations along the worst axes of the pose covariance.
struct Precision {
  double position_m = 0.0;
  double angle_rad = 0.0;
};

Precision precision_of(const RefinedPose& refined) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  Precision out;
  eigen.computeDirect(refined.covariance.topLeftCorner<3, 3>());
  out.position_m = std::sqrt(std::max(0.0, eigen.eigenvalues()[2]));
  eigen.computeDirect(refined.covariance.bottomRightCorner<3, 3>());
  out.angle_rad = std::sqrt(std::max(0.0, eigen.eigenvalues()[2]));
  return out;
}

std::string format_cm(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", metres * 100.0);
  return text;
}

std::string format_deg(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", radians * 180.0 / std::numbers::pi);
  return text;
}

}  // namespace

struct Localizer::State {
  const world::WorldModel* world;
  LocalizerOptions options;
  world::WorldGraph graph;
  TypedAdjacency adjacency;
  NodeGrid grid;
};

Localizer::Localizer(const world::WorldModel& world, LocalizerOptions options) {
  world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  TypedAdjacency adjacency = TypedAdjacency::build(graph);
  NodeGrid grid = NodeGrid::build(graph, kGridCellM);
  state_ = std::make_unique<State>(
      State{&world, std::move(options), std::move(graph), std::move(adjacency), std::move(grid)});
}

Localizer::~Localizer() = default;
Localizer::Localizer(Localizer&&) noexcept = default;
Localizer& Localizer::operator=(Localizer&&) noexcept = default;

const world::WorldModel& Localizer::world() const {
  return *state_->world;
}
const world::WorldGraph& Localizer::graph() const {
  return state_->graph;
}
const LocalizerOptions& Localizer::options() const {
  return state_->options;
}

LocalizationResult Localizer::localize(const std::vector<FusedPercept>& percepts,
                                       const StageObserver& on_stage) const {
  const auto start = Clock::now();
  std::optional<LocalizationStage> reached;
  const auto enter = [&](LocalizationStage stage) {
    if (reached && *reached >= stage) return;
    reached = stage;
    if (on_stage) on_stage(stage);
  };
  const LocalizerOptions& options = state_->options;
  const world::WorldGraph& graph = state_->graph;
  LocalizationResult result;
  StageTimes& times = result.timing;
  const auto finish = [&]() {
    times.total_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return result;
  };

  if (percepts.size() > static_cast<std::size_t>(options.pruning.max_percepts)) {
    result.message = "too many percepts: " + std::to_string(percepts.size()) + " (limit " +
                     std::to_string(options.pruning.max_percepts) + ", pruning.max_percepts)";
    return finish();
  }
  std::vector<PerceptNoise> noise;
  try {
    noise = percept_noise(percepts, options.noise);
  } catch (const std::invalid_argument& e) {
    result.message = e.what();
    return finish();
  }
  if (percepts.size() < 3) {
    result.message = "fewer than three percepts: a pose needs three non-collinear associations";
    return finish();
  }

  CandidateSets candidates;
  enter(LocalizationStage::kPruning);
  {
    StageTimer timer(times.proximity_filter_ms);
    candidates = proximity_filter(graph, state_->adjacency, percepts, noise, options.pruning);
  }
  const std::size_t usable =
      static_cast<std::size_t>(std::count_if(candidates.types.begin(), candidates.types.end(),
                                             [](const auto& type) { return type.has_value(); }));
  const LocalizationContext context{graph, state_->adjacency, state_->grid, percepts,
                                    noise, candidates,        options};

  std::optional<SeedChooser> chooser;
  {
    StageTimer timer(times.orientation_filter_ms);
    chooser.emplace(graph, percepts, noise, candidates, options.pruning);
  }

  // Interpretations worth extending must be able to compete: reach the explained fraction and
  // come within the ambiguity margin of the best so far. The slack covers what validation's
  // re-estimate adds over the seed's pose.
  const double slack = std::max(2.0, 0.15 * static_cast<double>(usable));
  const double floor_count =
      std::max<double>(options.hypotheses.min_associations,
                       options.validation.min_explained_fraction * static_cast<double>(usable));
  HypothesisSet validated_set(options.hypotheses);
  // Where the interpretations of every seed so far put the robot (ids into `interpreted`).
  PoseIndex interpreted_at(0.25);
  std::vector<Interpretation> interpreted;
  std::size_t budget =
      static_cast<std::size_t>(std::max(options.hypotheses.max_interpretations, 1));
  std::vector<PerceptTriple> tried;  // seeds processed
  const auto max_seeds = static_cast<std::size_t>(std::max(options.hypotheses.max_seeds, 1));
  while (tried.size() < max_seeds && budget > 0) {
    OrientationFilterResult subgraphs;
    PerceptTriple seed;
    {
      StageTimer timer(times.orientation_filter_ms);
      const auto next = chooser->next();
      if (!next) break;
      seed = *next;
      tried.push_back(seed);
      subgraphs = orientation_filter(graph, state_->adjacency, percepts, noise, candidates, seed,
                                     options.pruning, budget);
      budget -= std::min(budget, subgraphs.subgraphs.size());
      if (subgraphs.subgraphs.empty()) {
        chooser->report_empty(seed);
        continue;
      }
    }

    std::vector<std::pair<Eigen::Isometry3d, std::vector<NodeAssociation>>> poses;
    enter(LocalizationStage::kGenerating);
    {
      StageTimer timer(times.hypothesis_generation_ms);
      // Relative to the best so far (validated, or found by this seed): an interpretation that
      // explains a quarter fewer percepts cannot come within the margin unless its fits are far
      // tighter, which the slack allows for. Raising the bar as better interpretations appear lets
      // the search abandon the rest after a few misses.
      const auto bar = [&](double best) {
        return static_cast<int>(
            std::ceil(std::max({3.0, floor_count - slack, best - std::max(slack, 0.25 * best)})));
      };
      const ValidatedHypothesis* leader = validated_set.best();
      std::size_t best_count = leader ? leader->explained() : 0;
      struct Candidate {
        Eigen::Isometry3d pose;
        std::size_t interpretation;
      };
      std::vector<Candidate> found;
      for (const ModelTriple& subgraph : subgraphs.subgraphs) {
        const auto start = seed_pose(context, seed, subgraph);
        if (!start) continue;
        // A place an earlier seed already found and validated, with these three percepts given
        // these three objects, would only be found again. The tolerance is tight (at most
        // 10 cm, 3 degrees) so that a hypothesis that converged near, but not onto, this one
        // never hides it.
        const double tolerance_m =
            std::min(3.0 * start->uncertainty.sigma_at_m(Eigen::Vector3d::Zero()), 0.1);
        const double tolerance_rad = std::min(3.0 * start->uncertainty.sigma_rotation_rad, 0.05);
        if (validated_set.covers(start->world_T_ego, tolerance_m, tolerance_rad, seed, subgraph)) {
          continue;
        }
        auto interpretation = extend_interpretation(context, seed, subgraph, *start,
                                                    bar(static_cast<double>(best_count)));
        if (!interpretation) continue;
        // The same place found again (from this seed or an earlier one; Eq. 16 over all its
        // associations is as precise as the data) needs no second validation.
        bool known = false;
        const Eigen::Isometry3d& pose = interpretation->world_T_ego;
        interpreted_at.for_each_near(
            pose.translation(), options.hypotheses.same_position_m, [&](std::size_t id) {
              known =
                  known || same_hypothesis(interpreted[id].world_T_ego, pose, options.hypotheses);
            });
        if (known) continue;
        const std::vector<Eigen::Isometry3d> located = hypothesis_poses(context, *interpretation);
        // Only an interpretation that stands as a hypothesis raises the bar.
        if (!located.empty())
          best_count = std::max(best_count, interpretation->associations.size());
        for (const Eigen::Isometry3d& p : located) found.push_back({p, interpreted.size()});
        interpreted_at.add(interpretation->world_T_ego.translation(), interpreted.size());
        interpreted.push_back(std::move(*interpretation));
      }
      // Hypotheses found before the bar rose may now be below it.
      const int final_bar = bar(static_cast<double>(best_count));
      for (const Candidate& c : found) {
        if (static_cast<int>(interpreted[c.interpretation].associations.size()) < final_bar)
          continue;
        poses.emplace_back(c.pose, interpreted[c.interpretation].associations);
      }
    }

    if (!poses.empty()) enter(LocalizationStage::kValidating);
    {
      StageTimer timer(times.validation_ms);
      for (const auto& [pose, generating] : poses) {
        auto v = validate_hypothesis(context, pose, generating);
        if (v) validated_set.add(std::move(*v));
      }
      if (const ValidatedHypothesis* leader = validated_set.best()) {
        const ValidatedHypothesis& top = *leader;
        const auto confirmed =
            std::count_if(tried.begin(), tried.end(), [&](const PerceptTriple& t) {
              const auto& p = t.percepts;
              return top.explains(p[0]) && top.explains(p[1]) && top.explains(p[2]);
            });
        const bool clear_leader =
            static_cast<double>(top.explained()) >=
            options.hypotheses.single_seed_explained_fraction * static_cast<double>(usable);
        const int needed = clear_leader ? std::min(options.hypotheses.confirming_seeds, 1)
                                        : options.hypotheses.confirming_seeds;
        if (confirmed >= needed) break;
      }
    }
  }

  const std::vector<ValidatedHypothesis> validated = validated_set.ranked();
  Decision decision;
  {
    StageTimer timer(times.validation_ms);
    decision = decide(validated, usable, options.validation, options.hypotheses);
  }
  result.status = decision.status;
  result.message = decision.message;
  const std::size_t reported = decision.status == Status::kAmbiguous
                                   ? decision.contenders
                                   : std::min(validated.size(), 1 + kReportedRunnersUp);
  for (std::size_t h = 0; h < reported; ++h) {
    result.hypotheses.push_back(to_hypothesis(*state_->world, graph, validated[h]));
  }
  if (!validated.empty() && decision.status != Status::kFailed) {
    result.world_T_ego = validated.front().world_T_ego;
    result.associations = result.hypotheses.front().associations;
  }
  if (decision.status == Status::kLocalized) {
    enter(LocalizationStage::kRefining);
    StageTimer timer(times.refinement_ms);
    std::vector<PointCorrespondence> points;
    for (const NodeAssociation& a : validated.front().explanation.associations) {
      points.push_back(context.correspondence(a.percept, a.node));
    }
    RefinedPose refined = refine_pose(validated.front().world_T_ego, points, options.refinement);
    // Reported (and checked against required_position_m below) as the residuals support it.
    scale_covariance_by_residuals(refined, points.size(), options.refinement.planar_prior);
    if (refined.world_T_ego.matrix().allFinite()) {
      result.world_T_ego = refined.world_T_ego;
      result.hypotheses.front().world_T_ego = refined.world_T_ego;
    }
    if (refined.covariance_valid) result.covariance = refined.covariance;
    result.message =
        "explains " + std::to_string(points.size()) + " of " + std::to_string(usable) + " percepts";
    const ValidationOptions& v = options.validation;
    if (v.precision_sigmas > 0.0) {
      const Precision p = precision_of(refined);
      if (!refined.covariance_valid || v.precision_sigmas * p.position_m > v.required_position_m ||
          v.precision_sigmas * p.angle_rad > v.required_angle_rad) {
        result.status = Status::kFailed;
        result.too_uncertain = refined.covariance_valid;
        result.message += refined.covariance_valid
                              ? "; pose too uncertain (sigma " + format_cm(p.position_m) + " cm, " +
                                    format_deg(p.angle_rad) + " deg)"
                              : "; pose covariance unavailable";
      }
    }
  }
  return finish();
}

std::optional<ActiveValidationTarget> Localizer::choose_discriminator(
    const LocalizationResult& result, const LookLimits& limits,
    const std::vector<Eigen::Vector3d>& looked_at_ego_m) const {
  std::vector<Eigen::Isometry3d> poses;
  for (const Hypothesis& h : result.hypotheses) poses.push_back(h.world_T_ego);
  return localization::choose_discriminator(*state_->world, state_->graph, state_->grid, poses,
                                            state_->options, limits, looked_at_ego_m);
}

std::optional<ActiveValidationTarget> Localizer::choose_precision_look(
    const LocalizationResult& result, const LookLimits& limits,
    const std::vector<Eigen::Vector3d>& looked_at_ego_m) const {
  if (!result.too_uncertain || result.hypotheses.empty()) return std::nullopt;
  return localization::choose_precision_look(*state_->world, state_->graph, state_->grid,
                                             result.hypotheses.front().world_T_ego, state_->options,
                                             limits, looked_at_ego_m);
}

}  // namespace vsl::localization

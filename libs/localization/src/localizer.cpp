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

#include "vsl/localization/chi_square.hpp"
#include "vsl/localization/deleted_residuals.hpp"
#include "vsl/localization/floor_model.hpp"
#include "vsl/localization/hypotheses.hpp"
#include "vsl/localization/localization_context.hpp"
#include "vsl/localization/node_grid.hpp"
#include "vsl/localization/orientation_filter.hpp"
#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/pose_index.hpp"
#include "vsl/localization/proximity_filter.hpp"
#include "vsl/localization/seeds.hpp"
#include "vsl/localization/segment_nodes.hpp"
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
  FloorModel floor;
  NodeSegments segments;  // segment_nodes.hpp
};

Localizer::Localizer(const world::WorldModel& world, LocalizerOptions options) {
  world::WorldGraph graph = world::WorldGraph::build(world, options.graph);
  TypedAdjacency adjacency = TypedAdjacency::build(graph);
  NodeGrid grid = NodeGrid::build(graph, kGridCellM);
  FloorModel floor = FloorModel::build(graph, options.pruning);
  NodeSegments segments = node_segments(world, graph, options.validation.segment_types);
  state_ = std::make_unique<State>(State{&world, std::move(options), std::move(graph),
                                         std::move(adjacency), std::move(grid), std::move(floor),
                                         std::move(segments)});
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
const NodeSegments& Localizer::segments() const {
  return state_->segments;
}
const LocalizerOptions& Localizer::options() const {
  return state_->options;
}

namespace {

// Reports each stage once, when first reached, and never one before a later one.
class StageReporter {
 public:
  explicit StageReporter(const StageObserver& observer) : observer_(observer) {}
  void enter(LocalizationStage stage) {
    if (reached_ && *reached_ >= stage) return;
    reached_ = stage;
    if (observer_) observer_(stage);
  }

 private:
  const StageObserver& observer_;
  std::optional<LocalizationStage> reached_;
};

using PoseWithAssociations = std::pair<Eigen::Isometry3d, std::vector<NodeAssociation>>;

// The seed loop (header comment): what every seed so far found, and the next seed's turn of
// orientation filtering (Eq. 10), hypothesis generation (Eqs. 11-16) and validation.
class SeedSearch {
 public:
  SeedSearch(const LocalizationContext& context, const TypedAdjacency& adjacency,
             std::size_t usable, StageTimes& times, StageReporter& stages)
      : context_(context),
        adjacency_(adjacency),
        options_(context.options),
        times_(times),
        stages_(stages),
        validated_(context.options.hypotheses),
        // Interpretations worth extending must be able to compete: reach the explained
        // fraction and come within the ambiguity margin of the best so far. The slack covers
        // what validation's re-estimate adds over the seed's pose.
        slack_(std::max(2.0, 0.15 * static_cast<double>(usable))),
        floor_count_(std::max<double>(
            options_.hypotheses.min_associations,
            options_.validation.min_explained_fraction * static_cast<double>(usable))),
        usable_(usable),
        budget_(static_cast<std::size_t>(std::max(options_.hypotheses.max_interpretations, 1))) {}

  // Seeds in turn until the best hypothesis is confirmed or the seeds or the budget are spent.
  void run(SeedChooser& chooser) {
    const auto max_seeds = static_cast<std::size_t>(std::max(options_.hypotheses.max_seeds, 1));
    while (tried_.size() < max_seeds && budget_ > 0) {
      PerceptTriple seed;
      OrientationFilterResult subgraphs;
      {
        StageTimer timer(times_.orientation_filter_ms);
        const auto next = chooser.next();
        if (!next) break;
        seed = *next;
        tried_.push_back(seed);
        subgraphs =
            orientation_filter(context_.graph, adjacency_, context_.percepts, context_.noise,
                               context_.candidates, seed, options_.pruning, budget_);
        budget_ -= std::min(budget_, subgraphs.subgraphs.size());
        if (subgraphs.subgraphs.empty()) {
          chooser.report_empty(seed);
          continue;
        }
      }
      stages_.enter(LocalizationStage::kGenerating);
      const std::vector<PoseWithAssociations> poses = generate(seed, subgraphs);
      if (!poses.empty()) stages_.enter(LocalizationStage::kValidating);
      if (validate(poses)) break;
    }
  }

  const HypothesisSet& validated() const { return validated_; }

 private:
  // The bar an interpretation must reach, relative to the best count so far (validated, or
  // found by this seed): an interpretation that explains a quarter fewer percepts cannot come
  // within the margin unless its fits are far tighter, which the slack allows for. Raising the
  // bar as better interpretations appear lets the search abandon the rest after a few misses.
  int bar(double best) const {
    return static_cast<int>(
        std::ceil(std::max({3.0, floor_count_ - slack_, best - std::max(slack_, 0.25 * best)})));
  }

  // Hypotheses from the seed's subgraphs (Eqs. 11-16), with the associations that made them.
  std::vector<PoseWithAssociations> generate(const PerceptTriple& seed,
                                             const OrientationFilterResult& subgraphs) {
    StageTimer timer(times_.hypothesis_generation_ms);
    const ValidatedHypothesis* leader = validated_.best();
    std::size_t best_count = leader ? leader->explained() : 0;
    struct Candidate {
      Eigen::Isometry3d pose;
      std::size_t interpretation;
    };
    std::vector<Candidate> found;
    for (const ModelTriple& subgraph : subgraphs.subgraphs) {
      const auto start = seed_pose(context_, seed, subgraph);
      if (!start) continue;
      // A place an earlier seed already found and validated, with these three percepts given
      // these three objects, would only be found again. The tolerance is tight (at most
      // 10 cm, 3 degrees) so that a hypothesis that converged near, but not onto, this one
      // never hides it.
      const double tolerance_m =
          std::min(3.0 * start->uncertainty.sigma_at_m(Eigen::Vector3d::Zero()), 0.1);
      const double tolerance_rad = std::min(3.0 * start->uncertainty.sigma_rotation_rad, 0.05);
      if (validated_.covers(start->world_T_ego, tolerance_m, tolerance_rad, seed, subgraph)) {
        continue;
      }
      auto interpretation = extend_interpretation(context_, seed, subgraph, *start,
                                                  bar(static_cast<double>(best_count)));
      if (!interpretation || known(interpretation->world_T_ego)) continue;
      const std::vector<Eigen::Isometry3d> located = hypothesis_poses(context_, *interpretation);
      // Only an interpretation that stands as a hypothesis raises the bar.
      if (!located.empty()) {
        best_count = std::max(best_count, interpretation->associations.size());
      }
      for (const Eigen::Isometry3d& p : located) found.push_back({p, interpreted_.size()});
      interpreted_at_.add(interpretation->world_T_ego.translation(), interpreted_.size());
      interpreted_.push_back(std::move(*interpretation));
    }
    // Hypotheses found before the bar rose may now be below it.
    const int final_bar = bar(static_cast<double>(best_count));
    std::vector<PoseWithAssociations> poses;
    for (const Candidate& c : found) {
      const auto& associations = interpreted_[c.interpretation].associations;
      if (static_cast<int>(associations.size()) >= final_bar) {
        poses.emplace_back(c.pose, associations);
      }
    }
    return poses;
  }

  // The same place found again (from this seed or an earlier one; Eq. 16 over all its
  // associations is as precise as the data) needs no second validation.
  bool known(const Eigen::Isometry3d& pose) const {
    bool found = false;
    interpreted_at_.for_each_near(
        pose.translation(), options_.hypotheses.same_position_m, [&](std::size_t id) {
          found = found || same_hypothesis(interpreted_[id].world_T_ego, pose, options_.hypotheses);
        });
    return found;
  }

  // Validates the poses against every percept; true when the best hypothesis now explains every
  // percept of enough seeds (confirming_seeds, or one when it explains nearly every percept).
  bool validate(const std::vector<PoseWithAssociations>& poses) {
    StageTimer timer(times_.validation_ms);
    for (const auto& [pose, generating] : poses) {
      auto v = validate_hypothesis(context_, pose, generating);
      if (v) validated_.add(std::move(*v));
    }
    const ValidatedHypothesis* leader = validated_.best();
    if (leader == nullptr) return false;
    const auto confirmed = std::count_if(tried_.begin(), tried_.end(), [&](const PerceptTriple& t) {
      const auto& p = t.percepts;
      return leader->explains(p[0]) && leader->explains(p[1]) && leader->explains(p[2]);
    });
    const bool clear_leader =
        static_cast<double>(leader->explained()) >=
        options_.hypotheses.single_seed_explained_fraction * static_cast<double>(usable_);
    const int needed = clear_leader ? std::min(options_.hypotheses.confirming_seeds, 1)
                                    : options_.hypotheses.confirming_seeds;
    return confirmed >= needed;
  }

  const LocalizationContext& context_;
  const TypedAdjacency& adjacency_;
  const LocalizerOptions& options_;
  StageTimes& times_;
  StageReporter& stages_;
  HypothesisSet validated_;
  const double slack_;
  const double floor_count_;
  const std::size_t usable_;
  std::size_t budget_;
  std::vector<PerceptTriple> tried_;  // seeds processed
  // Where the interpretations of every seed so far put the robot (ids into `interpreted_`).
  PoseIndex interpreted_at_{0.25};
  std::vector<Interpretation> interpreted_;
};

// A LOCALIZED decision's pose refined with Ceres over all its associations (Eq. 16 and the
// refinement's covariance), and the precision requirement: 3 sigma within the required position
// and angle, otherwise FAILED "too uncertain" with the pose and covariance still reported.
void refine_localized(const LocalizationContext& context, const ValidatedHypothesis& best,
                      std::size_t usable, LocalizationResult& result) {
  const LocalizerOptions& options = context.options;
  const ValidationOptions& v = options.validation;
  std::vector<PointCorrespondence> points;
  for (const NodeAssociation& a : best.explanation.associations) {
    points.push_back(context.correspondence(a.percept, a.node));
  }
  RefinedPose refined = refine_pose(best.world_T_ego, points, options.refinement);
  // The w-test (deleted_residuals.hpp): the association the others contradict most, beyond the
  // quantile, is dropped and the pose refined without it, until every one passes.
  std::size_t dropped = 0;
  const double w2_threshold =
      v.outlier_test_alpha > 0.0 ? chi_square_quantile(3, v.outlier_test_alpha) : 0.0;
  while (v.outlier_test_alpha > 0.0 && refined.world_T_ego.matrix().allFinite() &&
         points.size() > 3) {
    const std::vector<double> w2 =
        deleted_residuals_sq(refined.world_T_ego, points, options.refinement);
    std::size_t worst = w2.size();
    for (std::size_t i = 0; i < w2.size(); ++i) {
      if (std::isfinite(w2[i]) && (worst == w2.size() || w2[i] > w2[worst])) worst = i;
    }
    if (worst == w2.size() || w2[worst] <= w2_threshold) break;
    points.erase(points.begin() + static_cast<std::ptrdiff_t>(worst));
    result.associations.erase(result.associations.begin() + static_cast<std::ptrdiff_t>(worst));
    ++dropped;
    refined = refine_pose(refined.world_T_ego, points, options.refinement);
  }
  result.hypotheses.front().associations = result.associations;
  // Reported (and checked against required_position_m below) as the residuals support it.
  scale_covariance_by_residuals(refined, points.size(), options.refinement.planar_prior);
  if (refined.world_T_ego.matrix().allFinite()) {
    result.world_T_ego = refined.world_T_ego;
    result.hypotheses.front().world_T_ego = refined.world_T_ego;
  }
  if (refined.covariance_valid) result.covariance = refined.covariance;
  // Pieces of bars (segment_nodes.hpp) at the refined pose are set aside: the share is of the
  // rest. A percept validation associated and the w-test then dropped is no piece: it contradicts
  // the others, and forgiving it as a piece let a pose 18 cm off through on five such drops.
  const std::size_t pieces =
      bar_pieces(context, result.world_T_ego, PoseUncertainty{}, best.explanation.associations)
          .size();
  const std::size_t judged = usable - std::min(pieces, usable);
  const double needed = std::max(static_cast<double>(options.hypotheses.min_associations),
                                 v.min_explained_fraction * static_cast<double>(judged));
  result.message = "explains " + std::to_string(points.size()) + " of " + std::to_string(judged) +
                   " percepts" + pieces_note(pieces);
  if (dropped > 0) {
    result.message += " (" + std::to_string(dropped) + " inconsistent with the others dropped)";
  }
  if (static_cast<double>(points.size()) < needed) {
    result.status = Status::kFailed;
    result.message += ", fewer than needed";
    return;
  }
  if (v.precision_sigmas <= 0.0) return;
  const Precision p = precision_of(refined);
  if (refined.covariance_valid && !(v.precision_sigmas * p.position_m > v.required_position_m) &&
      !(v.precision_sigmas * p.angle_rad > v.required_angle_rad)) {
    return;
  }
  result.status = Status::kFailed;
  result.too_uncertain = refined.covariance_valid;
  result.message += refined.covariance_valid
                        ? "; pose too uncertain (sigma " + format_cm(p.position_m) + " cm, " +
                              format_deg(p.angle_rad) + " deg)"
                        : "; pose covariance unavailable";
}

}  // namespace

LocalizationResult Localizer::localize(const std::vector<FusedPercept>& percepts,
                                       const StageObserver& on_stage) const {
  const auto start = Clock::now();
  StageReporter stages(on_stage);
  const LocalizerOptions& options = state_->options;
  const world::WorldGraph& graph = state_->graph;
  LocalizationResult result;
  StageTimes& times = result.timing;
  const auto finish = [&]() {
    times.total_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return result;
  };

  // Inputs: within the limits, with Eq. 7 noise, at least three.
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

  // Pruning: proximity filtering (Eqs. 8-9), then the seeds' order.
  stages.enter(LocalizationStage::kPruning);
  // A percept at no height of its type's objects over a floor can be no model object
  // (floor_model.hpp): it is clutter the recognizer reported, known as such. The share of the
  // percepts a hypothesis must explain (min_explained_fraction) bounds the clutter a scan may hold;
  // known clutter beyond that share leaves no basis for a pose, and within it is set aside, the
  // rest to be explained at the same share.
  const auto has_type = [](const auto& type) { return type.has_value(); };
  const std::vector<std::optional<world::TypeId>> types = percept_types(graph, percepts);
  const auto typed = static_cast<std::size_t>(std::count_if(types.begin(), types.end(), has_type));
  CandidateSets candidates;
  {
    StageTimer timer(times.proximity_filter_ms);
    candidates = proximity_filter(graph, state_->adjacency, percepts, noise, options.pruning,
                                  state_->floor.admissible_types(types, percepts, noise));
  }
  const auto usable = static_cast<std::size_t>(
      std::count_if(candidates.types.begin(), candidates.types.end(), has_type));
  const std::size_t off_floor_heights = typed - usable;
  if (static_cast<double>(off_floor_heights) >
      (1.0 - options.validation.min_explained_fraction) * static_cast<double>(typed)) {
    result.message = std::to_string(off_floor_heights) + " of " + std::to_string(typed) +
                     " percepts at no height of their type's objects over a floor: more clutter "
                     "than validation.min_explained_fraction allows";
    return finish();
  }
  const LocalizationContext context{graph, state_->adjacency, state_->grid, percepts,
                                    noise, candidates,        options,      &state_->segments};
  std::optional<SeedChooser> chooser;
  {
    StageTimer timer(times.orientation_filter_ms);
    chooser.emplace(graph, percepts, noise, candidates, options.pruning);
  }

  // Per seed: orientation filtering, hypothesis generation, validation.
  SeedSearch search(context, state_->adjacency, usable, times, stages);
  search.run(*chooser);

  // The decision over every validated hypothesis, and what is reported.
  const std::vector<ValidatedHypothesis> validated = search.validated().ranked();
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
    stages.enter(LocalizationStage::kRefining);
    StageTimer timer(times.refinement_ms);
    refine_localized(context, validated.front(), usable, result);
  }
  if (off_floor_heights > 0) {
    result.message += "; " + std::to_string(off_floor_heights) +
                      " at no height of their type's objects over a floor";
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
  return localization::choose_precision_look(
      *state_->world, state_->graph, state_->grid, result.hypotheses.front().world_T_ego,
      result.covariance, state_->options, limits, looked_at_ego_m);
}

}  // namespace vsl::localization

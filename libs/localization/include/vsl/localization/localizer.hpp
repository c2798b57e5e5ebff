// The localizer core (paper §2.3-2.4): from fused percepts in the ego frame and a world model to
// a 6-DoF pose world_T_ego, or an honest "ambiguous" with every hypothesis the data support.
// No middleware: the localizer daemon and vsl-localize drive it.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/localization/refinement.hpp"
#include "vsl/localization/types.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::localization {

struct NodeSegments;  // localization_context.hpp

// Eq. 7: a percept's positional error grows with the square of its distance to the left camera:
// epsilon_i = ||X_i - C_L||^2 / zeta (metres, one standard deviation per axis).
struct PerceptNoiseOptions {
  double zeta_m = 133.0;  // zeta: 133 m gives 3 cm at 2 m
  Eigen::Vector3d ego_camera_position_m = Eigen::Vector3d(0.0, 0.0, 1.5);  // C_L, ego frame
  double min_sigma_m = 0.005;  // floor for percepts right in front of the camera
  friend bool operator==(const PerceptNoiseOptions&, const PerceptNoiseOptions&) = default;
};

struct PruningOptions {
  // tau of Eq. 8 for a percept pair, in sigmas of their combined Eq. 7 error.
  double tau_sigmas = 3.0;
  double min_tau_m = 0.01;
  // mu_max and kappa_max of §2.3.2 (orientation filtering): the largest length (m) and angle (rad)
  // discrepancy between percept and model displacement vectors.
  double mu_max_m = 0.15;
  double kappa_max_rad = 0.2;
  // Robust Eq. 9 (proximity_filter.hpp): a candidate keeps its place while at most this fraction
  // of the percepts it is paired with give it no support (false positives); 0 is the literal
  // intersection.
  double max_unsupported_fraction = 0.34;
  // Eq. 9 intersects m link sets; each percept is filtered against its `max_partners` most
  // precise partners (smallest tau). More pairs prune little more but cost candidates x partners.
  int max_partners = 8;
  // Only the most precise percepts (smallest Eq. 7 sigma) are filtered, at most this many: a far
  // percept's tau admits nearly every node of its type, so filtering it costs much and prunes
  // nothing, and seeds are drawn from the precise ones anyway. The others stay unconstrained
  // (validation still uses them all).
  int max_filtered_percepts = 16;
  // More fused percepts than this and the localizer answers FAILED ("too many percepts") at
  // once: the percept-pair table is n x n (10,000 percepts took 2.4 GB). A scan of a room gives
  // tens; hundreds are a malformed or hostile list.
  int max_percepts = 500;
  // A percept with a link set (Eq. 8, one per partner) of more links than this is left
  // unconstrained: in a large repetitive building it would keep thousands of candidates (one per
  // identical room) at a cost far above what orientation filtering then saves.
  int max_link_set = 5000;
  // The ego frame's z axis is up (gravity): world_R_ego is a rotation about z up to max_tilt_rad.
  // Orientation filtering then compares displacement vectors in gravity-aligned frames, which
  // tells a triangle from its mirror image and rejects upside-down matches
  // (orientation_filter.hpp).
  bool use_gravity = true;
  double max_tilt_rad = 0.05;
  // With gravity, the world z of each floor the robot may stand on (its ego origin: the point on
  // the floor under it), and how far from such a height that origin may be (m): a percept at no
  // height of its type's objects over a floor is known clutter (floor_model.hpp). Empty: percepts
  // at any height.
  std::vector<double> floor_heights_m{0.0};
  double floor_tolerance_m = 0.05;
  friend bool operator==(const PruningOptions&, const PruningOptions&) = default;
};

struct HypothesisOptions {
  // A hypothesis needs at least this many associations (3 non-collinear fix a rigid pose).
  int min_associations = 3;
  // Hypotheses closer than this (position m, angle rad) are the same hypothesis (and so are two
  // closer than twice their combined pose uncertainty, each sigma capped at 10 cm and 0.05 rad:
  // validation.hpp).
  double same_position_m = 0.05;
  double same_angle_rad = 0.035;
  // Upper bound on interpretations explored, so a pathological input cannot run away.
  int max_interpretations = 20000;
  // Seeds (percept triples, seeds.hpp) tried at most; generation stops earlier once the best
  // hypothesis explains every percept of `confirming_seeds` of the seeds tried: every hypothesis
  // consistent with a seed of true percepts is generated from it, so the truth cannot be missing
  // unless all those seeds held a false positive.
  int max_seeds = 8;
  int confirming_seeds = 2;
  // One confirming seed suffices when the best hypothesis explains at least this share of the
  // percepts: a false percept is explained only by coincidence, so a seed whose three percepts such
  // a hypothesis all explains is almost surely clean. On the 100k building this halves the time
  // with no verdict changed (docs/benchmarks.md); a view of 5 percepts of which the best explains 3
  // still needs the second seed (one such case was localized 3 m off with a single seed).
  double single_seed_explained_fraction = 0.8;
  friend bool operator==(const HypothesisOptions&, const HypothesisOptions&) = default;
};

struct ValidationOptions {
  // A percept confirms a hypothesis when a model object of its type lies within this many sigmas
  // of where the hypothesis puts it.
  double gate_sigmas = 3.0;
  // Two hypotheses are both "consistent with all percepts" when their scores differ by less than
  // this. Score units: nats of log-likelihood ratio (validation.hpp); 4.6 = the best must be 100
  // times as likely as the runner-up to be picked.
  double ambiguity_margin = 4.6;
  // Density of clutter (false-positive percepts) per m^3, the alternative against which each
  // explained percept's likelihood is weighed (validation.hpp).
  double clutter_density_per_m3 = 0.025;
  // Below this fraction of percepts explained, the best hypothesis is not reported as localized.
  double min_explained_fraction = 0.6;
  // LOCALIZED also asserts precision: the refined pose's covariance must put precision_sigmas
  // standard deviations (along its worst axis) within required_position_m and
  // required_angle_rad; otherwise the result is FAILED ("too uncertain"), pose and covariance
  // still reported. With Eq. 7 noise a view of far objects fixes the pose only to several cm even
  // with every association right. 0 disables the check. 3 sigmas, not 2: the refined covariance
  // is slightly optimistic (mean NEES 3.7 for 3 dof on the kitchen scenarios), and at 2 sigmas
  // 1 in 200 "localized" results was 5.6 cm off.
  double precision_sigmas = 3.0;
  double required_position_m = 0.05;
  double required_angle_rad = 0.0349;  // 2 degrees
  // Before the precision check each association of the refined pose is tested against the pose
  // the others give (deleted_residuals.hpp, the w-test): the worst beyond the chi^2(3) quantile of
  // this false-alarm probability is dropped and the pose refined again, until all pass; with
  // fewer associations left than a localized pose needs, FAILED. 0 disables the test.
  double outlier_test_alpha = 0.01;
  // Objects of these types are bars (segment_nodes.hpp): a percept validation associates with
  // nothing that lies along one is a piece of it, set aside (not held against the pose, not used
  // for it), and min_explained_fraction is taken over the other percepts.
  std::vector<std::string> segment_types{"handle"};
  friend bool operator==(const ValidationOptions&, const ValidationOptions&) = default;
};

// Every default equals config/localizer.yaml (a test compares them), so a tool run without a
// config file localizes as the shipped daemon does.
struct LocalizerOptions {
  // Nodes: what a recognizer reports (walls and worktops have none); a door's top and bottom
  // edges are nodes too (a door cut by the image border or a worktop's lip).
  world::WorldGraphOptions graph{.link_threshold_m = 4.0,
                                 .node_types = {"door", "handle", "drawer_front", "window"},
                                 .edge_node_types = {"door"}};
  PerceptNoiseOptions noise;
  PruningOptions pruning;
  HypothesisOptions hypotheses;
  ValidationOptions validation;
  // The robot stands upright on the floor (ARMAR-III on its platform): roll and pitch held at 0.
  RefinementOptions refinement{.huber_sigmas = 3.0, .planar_prior = true};
  friend bool operator==(const LocalizerOptions&, const LocalizerOptions&) = default;
};

// Reads the localizer config (config/localizer.yaml: sections world_graph, percept_noise,
// pruning, hypotheses, validation, refinement), every key validated; throws config::Error.
LocalizerOptions localizer_options_from(const config::Node& root);

// What to look at next to tell the remaining hypotheses apart (paper §2.4.2, active validation).
struct ActiveValidationTarget {
  std::string object_id;             // the discriminating model object
  std::size_t hypothesis_index = 0;  // the hypothesis under which it is predicted there
  Eigen::Vector3d ego_target_m;      // where to point the head, ego frame
  double discrimination_m = 0.0;     // how far apart the hypotheses predict it (larger: better)
  // The discrimination of every candidate in view around the target under the same hypothesis
  // (m, summed): what one look there can settle.
  double view_discrimination_m = 0.0;
  // Precision looks (choose_precision_look): the summed 1 / sigma^2 (Eq. 7) of the objects newly
  // in view around the target (1/m^2); 0 for discriminating looks.
  double view_information_per_m2 = 0.0;
  // Precision looks: the pose's predicted worst-axis standard deviation after the look over the
  // precision requirement (position or angle, whichever is larger; below 1 / precision_sigmas
  // the bound would be met); 0 for discriminating looks.
  double predicted_precision_ratio = 0.0;
};

// Where active validation may point the head (paper §2.4.2 leaves the choice to the robot). The
// defaults are ARMAR-III's head and what recognition does well (docs/recognition.md: handles to
// 1 cm at 1-2 m).
struct LookLimits {
  double min_range_m = 1.0;  // nearer: the stereo head cannot fixate nor triangulate it
  double max_range_m = 4.0;  // farther: Eq. 7 error grows with range^2; recognition is poor
  // Among looks that settle as much, the one whose target is nearest this range from the camera.
  double preferred_range_m = 2.0;
  double max_azimuth_rad = 3.141592653589793;  // |azimuth| from ego +x about ego z
  // |elevation| of the target above or below the camera's horizontal plane: steeper views of
  // fronts and handles (from below a wall cupboard, say) are foreshortened and not recognized.
  double max_elevation_rad = 1.5707963267948966;
  double view_half_angle_rad = 0.35;  // 20 deg: objects this near the gaze ray are seen too
  double cap_m = 1.0;                 // discrimination beyond this counts as this
  // The object types the running recognizer reports: a look is rated by these objects only (a
  // window in view settles nothing when no recognizer reports windows). Empty: every node type.
  std::vector<std::string> types;
};

// The stages of one localize() call (paper §2.3-2.4), in the order they are first reached:
// pruning the world graph (proximity and orientation filters), generating hypotheses by sphere
// intersections, validating them with the unused associations, refining the winner with its
// covariance. The search interleaves the first three per seed; a stage is reported once, when it
// is first reached, and never after a later one. A call that stops early (too few percepts, no
// hypothesis, no LOCALIZED decision) reports only the stages it reached.
enum class LocalizationStage { kPruning, kGenerating, kValidating, kRefining };
using StageObserver = std::function<void(LocalizationStage)>;

class Localizer {
 public:
  Localizer(const world::WorldModel& world, LocalizerOptions options);
  ~Localizer();
  Localizer(Localizer&&) noexcept;
  Localizer& operator=(Localizer&&) noexcept;

  const world::WorldModel& world() const;
  const world::WorldGraph& graph() const;
  const LocalizerOptions& options() const;
  // Every node as a segment (validation.segment_types; segment_nodes.hpp), built with the graph.
  const NodeSegments& segments() const;

  // Localizes from fused percepts (ego frame). Thread-safe (const, no shared mutable state).
  // `on_stage`, when set, is called on this thread as each stage is first reached.
  LocalizationResult localize(const std::vector<FusedPercept>& percepts,
                              const StageObserver& on_stage = {}) const;

  // For an ambiguous result: the model object that best discriminates its hypotheses and the
  // ego-frame point to look at; nullopt when fewer than two hypotheses or nothing discriminates.
  // Only targets within `limits` (the head's reach), and not near an ego point already looked
  // at, are chosen (validation.hpp: choose_discriminator).
  std::optional<ActiveValidationTarget> choose_discriminator(
      const LocalizationResult& result, const LookLimits& limits = {},
      const std::vector<Eigen::Vector3d>& looked_at_ego_m = {}) const;
  // For a result that is too uncertain (LocalizationResult::too_uncertain): where to look to
  // make its one hypothesis precise; `looked_at_ego_m` holds every gaze of the request so far
  // (validation.hpp: choose_precision_look). nullopt for any other result.
  std::optional<ActiveValidationTarget> choose_precision_look(
      const LocalizationResult& result, const LookLimits& limits = {},
      const std::vector<Eigen::Vector3d>& looked_at_ego_m = {}) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vsl::localization

// Validation (paper §2.4.2): how well does a location hypothesis explain ALL fused percepts?
//
// A hypothesis world_T_ego puts percept i at world_T_ego X_i^pf. The percept is explained when a
// model object of its type lies within gate_sigmas there: Mahalanobis distance under the
// percept's covariance (Eq. 7) carried into the world frame, widened by the pose's own
// uncertainty at that point (pose_uncertainty.hpp). Each model object explains at most one
// percept (closest pairs first). This counts the associations that generated the hypothesis and
// every other one, as the paper asks; a false-positive percept simply explains nothing, so it
// lowers every hypothesis alike and cannot eliminate the true one.
//
// Each hypothesis is then re-estimated from everything it explains (Eq. 16 over all its
// associations) and re-scored, until its associations stop changing: hypotheses generated from
// three percepts become as precise as the data allow, and near-duplicates converge to the same
// pose (the caller merges them).
//
// Score. Counting explained percepts would treat a percept 4 m away (Eq. 7: 12 cm, a gate of
// half a metre, explained by almost any pose that is roughly right) like one at 1 m (7 mm). The
// score is therefore the log-likelihood ratio of the percepts under the hypothesis against their
// being clutter (false positives spread with density c per m^3):
//
//   score = sum over explained i of max(0, log N(e_i; 0, Sigma_i') - log c)
//         = sum_i max(0, -d_i^2 / 2 - 1/2 log det(2 pi Sigma_i') - log c),
//
// d_i the Mahalanobis distance, Sigma_i' the widened covariance; an unexplained percept is
// clutter and adds 0. Two hypotheses whose scores differ by less than ambiguity_margin (nats:
// the better is less than e^margin times as likely) are equally supported. Ties are broken by the
// chi^2 of the distances.
//
// Decision. With the best score s1 over n usable percepts (types the world knows):
//  - FAILED when nothing is supported: no hypothesis, or the best explains fewer than
//    min_associations or n * min_explained_fraction percepts;
//  - AMBIGUOUS when another distinct hypothesis scores within ambiguity_margin of s1: the data
//    support several poses equally; all of them are reported and none is picked;
//  - LOCALIZED otherwise.
#pragma once

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

#include "vsl/localization/localization_context.hpp"
#include "vsl/localization/localizer.hpp"
#include "vsl/localization/pose_uncertainty.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::localization {

struct Explanation {
  std::vector<NodeAssociation> associations;  // sorted by percept
  // Percepts the associations leave out that lie along a bar no association holds
  // (segment_nodes.hpp): set aside, neither scored nor used for the pose, and the explained
  // fraction taken over the rest. Sorted by percept.
  std::vector<NodeAssociation> bar_pieces;
  double chi2 = 0.0;                  // sum of squared Mahalanobis distances
  double log_likelihood_ratio = 0.0;  // the score, see above
};

// The percepts explained by `world_T_ego` (see above).
Explanation explain(const LocalizationContext& context, const Eigen::Isometry3d& world_T_ego,
                    const PoseUncertainty& uncertainty);

struct ValidatedHypothesis {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  Explanation explanation;
  double score = 0.0;           // explanation.log_likelihood_ratio
  PoseUncertainty uncertainty;  // of world_T_ego, from the associations it was estimated from

  std::size_t explained() const { return explanation.associations.size(); }
  bool explains(int percept) const;
};

// Scores `world_T_ego`, generated from `generating`, and re-estimates it from what it explains
// (at most `max_rounds` times). nullopt when it explains fewer than three percepts.
std::optional<ValidatedHypothesis> validate_hypothesis(
    const LocalizationContext& context, const Eigen::Isometry3d& world_T_ego,
    const std::vector<NodeAssociation>& generating, int max_rounds = 4);

// Best first: higher score, then lower chi^2.
bool ranks_before(const ValidatedHypothesis& a, const ValidatedHypothesis& b);

// Whether a and b are one hypothesis: within same_position_m and same_angle_rad, or closer than
// two standard deviations of their combined pose uncertainty (the data cannot tell them apart:
// typically the same place with a percept given to one of two neighbouring objects of its type).
bool indistinguishable(const ValidatedHypothesis& a, const ValidatedHypothesis& b,
                       const HypothesisOptions& options);

struct Decision {
  Status status = Status::kFailed;
  std::size_t contenders = 0;  // hypotheses (from the front of the ranking) the status refers to
  std::string message;
};

// " (N more, pieces of bars, set aside)" for N > 0 pieces, "" for none: the messages' note.
std::string pieces_note(std::size_t pieces);

// `ranked` sorted with ranks_before and free of duplicates; `usable_percepts` as above; the best
// hypothesis' pieces of bars are set aside, its explained share taken over the other percepts.
Decision decide(const std::vector<ValidatedHypothesis>& ranked, std::size_t usable_percepts,
                const ValidationOptions& validation, const HypothesisOptions& hypotheses);

// Active validation (§2.4.2): "the criterion to select the discriminator percept is the maximal
// pose difference between pairs of hypotheses". For each hypothesis h and each model object o of a
// recognizable type within `limits.max_range_m` of the camera under h, o is predicted at the ego
// point e = h^-1 X_o. Looking at e settles the question when the other hypotheses expect nothing
// of o's type there: under h' the point e is the world point h' e, and the nearest object of o's
// type to it is d(h') away. The discrimination of (o, h) is min over h' != h of d(h') (capped at
// `limits.cap_m`): large means that whatever is (or is not) seen at e confirms h or refutes it
// against every other hypothesis. Pairs whose discrimination is below the gate of a percept at e
// (it would be explained under h' too) do not discriminate.
//
// A look sees more than its target: every discriminating (o', h) whose ego point lies within
// `limits.view_half_angle_rad` of the gaze ray from the camera to e is in view too. The look is
// rated by the sum of those discriminations (view_discrimination_m, o itself included), so a
// look at a cluster of telling objects beats one at a lone handle; equal ratings go to the target
// nearest `preferred_range_m`.
//
// Only targets the head can look at usefully are candidates (`limits`): between min_range_m
// (under some hypothesis an object may lie at the robot's own head) and max_range_m from the
// camera, within max_azimuth_rad of ego +x (the head's reach) and max_elevation_rad of the
// camera's horizontal (a front seen steeply from below is not recognized). Ego points already
// looked at (`looked_at_ego_m`, within 0.3 m) are not chosen again: validation counts what is
// seen, not what is missing, so a look that found nothing there would only repeat.
// Returns the best, or nullopt.
std::optional<ActiveValidationTarget> choose_discriminator(
    const world::WorldModel& world, const world::WorldGraph& graph, const NodeGrid& grid,
    const std::vector<Eigen::Isometry3d>& hypotheses, const LocalizerOptions& options,
    const LookLimits& limits = {}, const std::vector<Eigen::Vector3d>& looked_at_ego_m = {});

// A precision look: one hypothesis won, but its refined pose fails the precision bound
// (ValidationOptions::precision_sigmas), typically because its percepts lie in the narrow cone of
// one gaze, or far away, so that the turn's lever to the robot leaves its position uncertain.
// Percepts in other directions constrain the pose better. Under the hypothesis `world_T_ego`,
// with the refined pose's `covariance`, each model object o of a recognizable type predicted at
// ego point e = world_T_ego^-1 X_o within `limits` would add the information of a percept with
// the Eq. 7 error sigma(e). A look at e is rated by the pose's predicted precision after it: the
// worst-axis position and angle standard deviations of (covariance^-1 + the information of every
// such object within `limits.view_half_angle_rad` of its gaze ray)^-1, each over its requirement
// (ValidationOptions::required_position_m, required_angle_rad), the larger of the two; the
// smallest rating wins. Objects within the view half angle of an earlier gaze ray
// (`looked_at_ego_m`: every gaze of the request, the scan's included) were seen, or missed,
// then, and rate nothing. Equal ratings go to the target nearest `preferred_range_m`. The
// result's predicted_precision_ratio is the rating, view_information_per_m2 the summed
// 1 / sigma^2 of the objects in its view; discrimination_m is 0. nullopt when no object in reach
// is newly in view, or the covariance has no positive variance.
std::optional<ActiveValidationTarget> choose_precision_look(
    const world::WorldModel& world, const world::WorldGraph& graph, const NodeGrid& grid,
    const Eigen::Isometry3d& world_T_ego, const PoseCovariance& covariance,
    const LocalizerOptions& options, const LookLimits& limits = {},
    const std::vector<Eigen::Vector3d>& looked_at_ego_m = {});

}  // namespace vsl::localization

// The localizer's inputs and outputs (paper §2.3-2.4), free of any middleware.
// Frames: `ego` is the robot body frame (z up, origin at the ego centre X_ego); `world` is the
// world model's frame. Units: metres, radians.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace vsl::localization {

// A fused percept O_i^pf (paper §2.1.1): a recognized object of one type at a point of the ego
// frame, fused over the scanning strategy.
struct FusedPercept {
  std::string type;                                  // "door", "handle", ...
  Eigen::Vector3d ego_position_m;                    // X_i^f
  std::optional<Eigen::Matrix3d> ego_covariance_m2;  // when the recognizer provides one
  int support = 1;                                   // frames it was seen in (C of Eq. 4)
};

// An association <O_i^pf, O_j^m>: percept index -> world-model object (its index in
// WorldModel::objects and its id).
struct Association {
  int percept_index = -1;
  std::size_t object_index = 0;
  std::string object_id;
};

// A location hypothesis (paper Eq. 15) with the associations that generated or confirmed it.
struct Hypothesis {
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();
  // Validation score: how well all percepts are explained (higher is better; see validation.hpp).
  double score = 0.0;
  std::vector<Association> associations;  // sorted by percept index
};

enum class Status { kLocalized, kAmbiguous, kFailed };
const char* to_string(Status status);

// Wall time of each stage, milliseconds.
struct StageTimes {
  double proximity_filter_ms = 0;
  double orientation_filter_ms = 0;
  double hypothesis_generation_ms = 0;
  double validation_ms = 0;
  double refinement_ms = 0;
  double total_ms = 0;
};

// Pose covariances are 6x6, ordered (x, y, z, rx, ry, rz): the translation of world_T_ego in metres
// (world frame) and a small rotation in radians about the world axes, applied on the left of
// world_R_ego (world_R_ego' = exp([r]x) world_R_ego).
using PoseCovariance = Eigen::Matrix<double, 6, 6>;

struct LocalizationResult {
  Status status = Status::kFailed;
  Eigen::Isometry3d world_T_ego = Eigen::Isometry3d::Identity();  // the best hypothesis, refined
  PoseCovariance covariance = PoseCovariance::Zero();
  std::vector<Hypothesis> hypotheses;     // ranked, best first
  std::vector<Association> associations;  // of the reported pose
  StageTimes timing;
  std::string message;  // why, for failed/ambiguous
  // FAILED only because the one winning hypothesis, refined, fails the precision bound
  // (ValidationOptions::precision_sigmas): another look, in another direction, may settle it.
  // world_T_ego and hypotheses then hold that hypothesis; a caller must not report it as a pose.
  bool too_uncertain = false;
};

}  // namespace vsl::localization

// The Open3D peer (peer.hpp). The only file of vsl that includes Open3D: its headers are heavy.
#include <omp.h>

#include <cstdio>
#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "open3d/geometry/PointCloud.h"
#include "open3d/pipelines/registration/CorrespondenceChecker.h"
#include "open3d/pipelines/registration/Registration.h"
#include "open3d/pipelines/registration/TransformationEstimation.h"
#include "open3d/utility/Random.h"
#include "peer.hpp"

namespace vsl::evaluate {

namespace registration = open3d::pipelines::registration;

struct PeerLocalizer::Impl {
  PeerOptions options;
  // Target cloud: the recognizable objects' reference points (world frame), built once, as the
  // localizer builds its world graph once.
  open3d::geometry::PointCloud world_cloud;
  std::vector<std::size_t> object_index;  // per target point: index in WorldModel::objects
  std::vector<std::string> object_id;     // per target point
  std::unordered_map<std::string, std::vector<int>> targets_by_type;
};

PeerLocalizer::PeerLocalizer(const world::WorldModel& world,
                             const std::vector<std::string>& node_types, PeerOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  const std::unordered_set<std::string> types(node_types.begin(), node_types.end());
  for (std::size_t k = 0; k < world.objects.size(); ++k) {
    const world::ObjectModel& object = world.objects[k];
    if (!types.empty() && !types.contains(object.type)) continue;
    impl_->targets_by_type[object.type].push_back(static_cast<int>(impl_->object_index.size()));
    impl_->world_cloud.points_.push_back(object.world_position_m);
    impl_->object_index.push_back(k);
    impl_->object_id.push_back(object.id);
  }
  // Open3D parallelizes RANSAC with OpenMP over all cores; the localizer runs on one thread, so
  // the peer gets one too (this sets the calling thread's OpenMP thread count).
  omp_set_num_threads(1);
}

PeerLocalizer::~PeerLocalizer() = default;

const char* PeerLocalizer::name() {
  return "open3d-ransac";
}

const PeerOptions& PeerLocalizer::options() const {
  return impl_->options;
}

namespace {

// For each percept, its nearest same-type target within `max_distance_m` under world_T_ego:
// the correspondences (percept, target) that agree with the pose, type-aware (Open3D's own
// fitness counts the nearest target of any type).
registration::CorrespondenceSet inliers(
    const open3d::geometry::PointCloud& ego_cloud, const open3d::geometry::PointCloud& world_cloud,
    const std::vector<localization::FusedPercept>& percepts,
    const std::unordered_map<std::string, std::vector<int>>& targets_by_type,
    const Eigen::Matrix4d& world_T_ego, double max_distance_m) {
  registration::CorrespondenceSet out;
  const Eigen::Isometry3d pose(world_T_ego);
  for (std::size_t i = 0; i < percepts.size(); ++i) {
    const auto of_type = targets_by_type.find(percepts[i].type);
    if (of_type == targets_by_type.end()) continue;
    const Eigen::Vector3d world_position_m = pose * ego_cloud.points_[i];
    int best = -1;
    double best_m2 = max_distance_m * max_distance_m;
    for (const int j : of_type->second) {
      const double d2 =
          (world_cloud.points_[static_cast<std::size_t>(j)] - world_position_m).squaredNorm();
      if (d2 <= best_m2) {
        best_m2 = d2;
        best = j;
      }
    }
    if (best >= 0) out.emplace_back(static_cast<int>(i), best);
  }
  return out;
}

}  // namespace

localization::LocalizationResult PeerLocalizer::localize(
    const std::vector<localization::FusedPercept>& percepts, std::uint32_t seed) const {
  const PeerOptions& o = impl_->options;
  localization::LocalizationResult result;
  result.status = localization::Status::kFailed;

  // Source cloud (ego frame) and every same-type pair: with no descriptor to tell two handles
  // apart, this is all a user can give RANSAC.
  open3d::geometry::PointCloud ego_cloud;
  registration::CorrespondenceSet all_pairs;
  for (std::size_t i = 0; i < percepts.size(); ++i) {
    ego_cloud.points_.push_back(percepts[i].ego_position_m);
    const auto of_type = impl_->targets_by_type.find(percepts[i].type);
    if (of_type == impl_->targets_by_type.end()) continue;
    for (const int j : of_type->second) all_pairs.emplace_back(static_cast<int>(i), j);
  }
  constexpr int kRansacN = 3;
  if (all_pairs.size() < static_cast<std::size_t>(kRansacN)) {
    result.message = "fewer than 3 same-type correspondences";
    return result;
  }

  // Open3D draws its samples from one global generator: seed it per call for reproducible runs.
  open3d::utility::random::Seed(static_cast<int>(seed & 0x7fffffffU));
  const registration::CorrespondenceCheckerBasedOnEdgeLength edge_length(o.edge_length_similarity);
  const registration::CorrespondenceCheckerBasedOnDistance distance(
      o.max_correspondence_distance_m);
  const registration::TransformationEstimationPointToPoint point_to_point(false);
  const registration::RegistrationResult ransac =
      registration::RegistrationRANSACBasedOnCorrespondence(
          ego_cloud, impl_->world_cloud, all_pairs, o.max_correspondence_distance_m, point_to_point,
          kRansacN, {std::cref(edge_length), std::cref(distance)},
          registration::RANSACConvergenceCriteria(o.max_iterations, o.confidence));
  if (ransac.fitness_ <= 0.0) {
    result.message = "RANSAC found no sample that passed its checks";
    return result;
  }

  // RANSAC's pose is fitted to its 3 sampled points only; as Open3D's pipelines follow global
  // registration by a local refinement, refit it by least squares on its (type-aware) inliers
  // until the inlier set stops changing.
  Eigen::Matrix4d world_T_ego = ransac.transformation_;
  registration::CorrespondenceSet agreeing =
      inliers(ego_cloud, impl_->world_cloud, percepts, impl_->targets_by_type, world_T_ego,
              o.max_correspondence_distance_m);
  for (int round = 0; round < 5 && agreeing.size() >= static_cast<std::size_t>(kRansacN); ++round) {
    const Eigen::Matrix4d refit =
        point_to_point.ComputeTransformation(ego_cloud, impl_->world_cloud, agreeing);
    registration::CorrespondenceSet refit_agreeing =
        inliers(ego_cloud, impl_->world_cloud, percepts, impl_->targets_by_type, refit,
                o.max_correspondence_distance_m);
    if (refit_agreeing.size() < agreeing.size()) break;
    const bool same = refit_agreeing == agreeing;
    world_T_ego = refit;
    agreeing = std::move(refit_agreeing);
    if (same) break;
  }

  result.world_T_ego = Eigen::Isometry3d(world_T_ego);
  for (const Eigen::Vector2i& pair : agreeing) {
    const auto target = static_cast<std::size_t>(pair[1]);
    result.associations.push_back({pair[0], impl_->object_index[target], impl_->object_id[target]});
  }
  char message[160];
  std::snprintf(message, sizeof message, "explains %zu of %zu percepts; Open3D fitness %.2f",
                agreeing.size(), percepts.size(), ransac.fitness_);
  result.message = message;
  if (agreeing.size() < static_cast<std::size_t>(o.min_inlier_percepts)) return result;
  result.status = localization::Status::kLocalized;
  localization::Hypothesis best;
  best.world_T_ego = result.world_T_ego;
  best.score = static_cast<double>(agreeing.size());
  best.associations = result.associations;
  result.hypotheses.push_back(std::move(best));
  return result;
}

}  // namespace vsl::evaluate

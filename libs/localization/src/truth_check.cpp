// Percepts against a known pose (truth_check.hpp).
#include "vsl/localization/truth_check.hpp"

#include <cmath>
#include <limits>

#include "vsl/localization/percept_noise.hpp"
#include "vsl/localization/segment_nodes.hpp"

namespace vsl::localization {

std::vector<PerceptTruth> check_against_truth(const Localizer& localizer,
                                              const std::vector<FusedPercept>& percepts,
                                              const Eigen::Isometry3d& world_T_ego) {
  const world::WorldGraph& graph = localizer.graph();
  const LocalizerOptions& options = localizer.options();
  const NodeSegments& segments = localizer.segments();
  const std::vector<PerceptNoise> noise = percept_noise(percepts, options.noise);
  const Eigen::Matrix3d ego_R_world = world_T_ego.linear().transpose();

  std::vector<PerceptTruth> out(percepts.size());
  for (std::size_t i = 0; i < percepts.size(); ++i) {
    const std::optional<world::TypeId> type = graph.find_type(percepts[i].type);
    if (!type) continue;
    const Eigen::Vector3d world_position_m = world_T_ego * percepts[i].ego_position_m;
    // Sigmas of the world-frame error `world_error_m` under the percept's ego-frame covariance.
    const auto sigmas_of = [&](const Eigen::Vector3d& world_error_m) {
      return std::sqrt(noise[i].mahalanobis_sq(ego_R_world * world_error_m));
    };
    PerceptTruth& truth = out[i];
    truth.sigmas = truth.bar_sigmas = std::numeric_limits<double>::infinity();
    for (world::NodeIndex n = 0; n < graph.node_count(); ++n) {
      if (graph.type(n) != *type) continue;
      const Eigen::Vector3d& centre = graph.world_position_m(n);
      const double to_point = sigmas_of(world_position_m - centre);
      if (to_point < truth.sigmas) {
        truth.nearest = n;
        truth.sigmas = to_point;
        truth.distance_m = (world_position_m - centre).norm();
      }
      const double to_bar = sigmas_of(
          world_position_m - nearest_on_segment(centre, segments.half_axes_m[n], world_position_m));
      if (to_bar < truth.bar_sigmas) {
        truth.nearest_bar = n;
        truth.bar_sigmas = to_bar;
      }
    }
    if (!truth.nearest) truth.sigmas = truth.bar_sigmas = 0.0;
  }
  return out;
}

}  // namespace vsl::localization

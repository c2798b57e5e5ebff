#include "view_messages.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "vsl/messages/enum_names.hpp"

namespace vsl::view {
namespace {

bool finite(const double* values, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) return false;
  }
  return true;
}

double yaw_deg(const Eigen::Isometry3d& world_T_ego) {
  const Eigen::Vector3d forward = world_T_ego.linear() * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x()) * 180.0 / std::numbers::pi;
}

std::string format(const char* pattern, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

}  // namespace

std::optional<Eigen::Isometry3d> isometry_of(const vsl::pose_t& pose) {
  if (!finite(pose.position_m, 3) || !finite(pose.orientation_wxyz, 4)) return std::nullopt;
  Eigen::Quaterniond q(pose.orientation_wxyz[0], pose.orientation_wxyz[1], pose.orientation_wxyz[2],
                       pose.orientation_wxyz[3]);
  if (!(q.norm() > 1e-6)) return std::nullopt;
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = q.normalized().toRotationMatrix();
  out.translation() = Eigen::Vector3d(pose.position_m[0], pose.position_m[1], pose.position_m[2]);
  return out;
}

std::vector<Hypothesis> hypotheses_of(const vsl::pose_estimate_t& estimate) {
  std::vector<Hypothesis> out;
  for (const vsl::pose_hypothesis_t& h : estimate.hypotheses) {
    if (const auto pose = isometry_of(h.world_T_ego)) out.push_back({*pose, h.score});
  }
  return out;
}

std::optional<Eigen::Matrix<double, 6, 6>> covariance_of(const vsl::pose_estimate_t& estimate) {
  if (!finite(estimate.covariance, 36)) return std::nullopt;
  return Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(estimate.covariance);
}

std::vector<FusedPercept> fused_percepts_of(const vsl::fused_percept_list_t& list) {
  std::vector<FusedPercept> out;
  for (const vsl::fused_percept_t& p : list.percepts) {
    if (!finite(p.ego_position_m, 3)) continue;
    FusedPercept f;
    f.type = p.type;
    f.ego_position_m =
        Eigen::Vector3d(p.ego_position_m[0], p.ego_position_m[1], p.ego_position_m[2]);
    if (finite(p.ego_covariance_m2, 9)) {
      f.ego_covariance_m2 =
          Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p.ego_covariance_m2);
    }
    out.push_back(std::move(f));
  }
  return out;
}

void mark_matches(const vsl::pose_estimate_t& estimate, std::vector<FusedPercept>& percepts) {
  for (FusedPercept& p : percepts) p.match = FusedPercept::Match::kUnmatched;
  for (const vsl::association_t& a : estimate.associations) {
    if (a.percept_index >= 0 && static_cast<std::size_t>(a.percept_index) < percepts.size()) {
      percepts[static_cast<std::size_t>(a.percept_index)].match = FusedPercept::Match::kMatched;
    }
  }
}

std::vector<CameraPercept> camera_percepts_of(const vsl::percept_list_t& list) {
  std::vector<CameraPercept> out;
  for (const vsl::percept_t& p : list.percepts) {
    if (!finite(p.ego_position_m, 3)) continue;
    out.push_back({p.type,
                   Eigen::Vector3d(p.ego_position_m[0], p.ego_position_m[1], p.ego_position_m[2]),
                   static_cast<double>(p.confidence)});
  }
  return out;
}

std::vector<std::string> map_caption(const std::optional<vsl::localizer_status_t>& status,
                                     const std::optional<vsl::pose_estimate_t>& estimate,
                                     const MapOverlay& overlay) {
  // Line 1: the answer (the estimate beside the truth) or, before one, the localizer's progress.
  // Line 2: the localizer's state and the counts.
  std::string progress = "waiting for the localizer (LOCALIZER_STATUS)";
  if (status) {
    progress = format("localizer %s %.0f%%: %s", messages::localizer_state_name(status->state),
                      100.0 * status->progress, status->message.c_str());
  }
  const int hypotheses = estimate ? estimate->num_hypotheses : status ? status->num_hypotheses : 0;
  const std::string counts = format("%d hypothes%s, %zu fused percepts", hypotheses,
                                    hypotheses == 1 ? "is" : "es", overlay.fused_percepts.size());
  std::string pose_text;
  if (overlay.world_T_ego_estimate) {
    const Eigen::Isometry3d& e = *overlay.world_T_ego_estimate;
    pose_text =
        format("(%.3f, %.3f) m %.1f deg", e.translation().x(), e.translation().y(), yaw_deg(e));
    if (overlay.world_T_ego_truth) {
      const Eigen::Isometry3d& t = *overlay.world_T_ego_truth;
      const double position_error_m = (e.translation() - t.translation()).norm();
      const double rotation_error_deg =
          Eigen::AngleAxisd(t.linear().transpose() * e.linear()).angle() * 180.0 / std::numbers::pi;
      pose_text +=
          format("   error %.2f cm %.2f deg", 100.0 * position_error_m, rotation_error_deg);
    }
  } else if (overlay.world_T_ego_truth) {
    const Eigen::Isometry3d& t = *overlay.world_T_ego_truth;
    pose_text = format("truth (%.3f, %.3f) m %.1f deg", t.translation().x(), t.translation().y(),
                       yaw_deg(t));
  }
  if (estimate) {
    int matched = 0;
    for (const FusedPercept& p : overlay.fused_percepts) {
      matched += p.match == FusedPercept::Match::kMatched;
    }
    const std::string answer = messages::pose_status_name(estimate->status);
    const std::string state =
        status ? format("localizer %s | ", messages::localizer_state_name(status->state)) : "";
    return {answer + "  " + (pose_text.empty() ? estimate->message : pose_text),
            state + counts + format(" (%d matched)", matched)};
  }
  return {progress, counts + (pose_text.empty() ? "" : " | " + pose_text)};
}

}  // namespace vsl::view

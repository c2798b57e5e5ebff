#include "view_messages.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

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

const char* localizer_state_name(int state) {
  static constexpr const char* kNames[] = {
      "IDLE",       "SCANNING",          "FUSING",   "PRUNING", "GENERATING",
      "VALIDATING", "ACTIVE_VALIDATION", "REFINING", "DONE",    "FAILED"};
  return state >= 0 && state < 10 ? kNames[state] : "?";
}

const char* pose_status_name(int status) {
  switch (status) {
    case vsl::pose_estimate_t::LOCALIZED:
      return "LOCALIZED";
    case vsl::pose_estimate_t::AMBIGUOUS:
      return "AMBIGUOUS";
    case vsl::pose_estimate_t::FAILED:
      return "FAILED";
    default:
      return "?";
  }
}

std::vector<std::string> map_caption(const std::optional<vsl::localizer_status_t>& status,
                                     const std::optional<vsl::pose_estimate_t>& estimate,
                                     const MapOverlay& overlay) {
  std::vector<std::string> lines;
  if (estimate) {
    lines.push_back(
        format("%s: %s", pose_status_name(estimate->status), estimate->message.c_str()));
  } else if (status) {
    lines.push_back(format("localizer %s %.0f%%: %s", localizer_state_name(status->state),
                           100.0 * status->progress, status->message.c_str()));
  } else {
    lines.push_back("waiting for the localizer (LOCALIZER_STATUS)");
  }
  std::string detail;
  if (status) {
    detail = format("%d hypotheses, %d fused percepts", status->num_hypotheses,
                    status->num_fused_percepts);
  } else {
    detail = format("%zu fused percepts", overlay.fused_percepts.size());
  }
  if (overlay.world_T_ego_estimate) {
    const Eigen::Isometry3d& e = *overlay.world_T_ego_estimate;
    detail += format("   pose (%.3f, %.3f) m %.1f deg", e.translation().x(), e.translation().y(),
                     yaw_deg(e));
    if (overlay.world_T_ego_truth) {
      const Eigen::Isometry3d& t = *overlay.world_T_ego_truth;
      const double position_error_m = (e.translation() - t.translation()).norm();
      const double rotation_error_deg =
          Eigen::AngleAxisd(t.linear().transpose() * e.linear()).angle() * 180.0 / std::numbers::pi;
      detail += format("   error %.1f cm %.2f deg", 100.0 * position_error_m, rotation_error_deg);
    }
  } else if (overlay.world_T_ego_truth) {
    const Eigen::Isometry3d& t = *overlay.world_T_ego_truth;
    detail += format("   truth (%.3f, %.3f) m %.1f deg", t.translation().x(), t.translation().y(),
                     yaw_deg(t));
  }
  lines.push_back(detail);
  return lines;
}

}  // namespace vsl::view

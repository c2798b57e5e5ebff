// What vsl-request prints about one finished request: the estimate beside the ground truth (when
// a simulator published one) and the errors between them. Plain values, no LCM: unit-tested.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace vsl::request {

// A pose as the messages carry it: world_T_ego, position (m) and unit quaternion (w, x, y, z).
struct Pose {
  Eigen::Vector3d world_position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond world_R_ego = Eigen::Quaterniond::Identity();
};

struct PoseError {
  double position_m = 0.0;    // |t_estimate - t_truth|, world frame
  double rotation_rad = 0.0;  // angle of R_truth^-1 R_estimate (all three axes)
  double yaw_rad = 0.0;       // heading difference about world z, wrapped to [-pi, pi]
};

// Heading of ego x about world z (rad, counter-clockwise from world +x).
double yaw_rad(const Pose& pose);

PoseError pose_error(const Pose& estimate, const Pose& truth);

// The result table: one line each for the estimate, the truth (when given) and the errors, with
// the standard deviations of the estimate from its 6x6 covariance (x y z roll pitch yaw, m and
// rad, row-major) when it is non-zero.
std::string format_result(const std::string& status, const Pose& estimate,
                          const double (&covariance)[36], const std::optional<Pose>& truth);

// One machine-readable line for scripts and tests:
// "result: status=LOCALIZED x_m=... y_m=... z_m=... yaw_deg=... [position_error_m=...
//  rotation_error_deg=...]".
std::string result_line(const std::string& status, const Pose& estimate,
                        const std::optional<Pose>& truth);

}  // namespace vsl::request

#include "single_view.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "triangulation.hpp"

namespace vsl::recognition::detail {

std::optional<SingleViewDoor> place_single_view_door(
    const std::array<Eigen::Vector2d, 4>& corners, const SideCorrelator& sweep,
    const head::CameraIntrinsics& own, const Eigen::Vector3d& up, const StereoMatchOptions& options,
    const StereoMatchOptions::ExtentRange* height_range, double max_width_m) {
  if (!(up.norm() > 0.0)) return std::nullopt;
  Eigen::Matrix3d k;
  k << own.fx_px, 0.0, own.cx_px, 0.0, own.fy_px, own.cy_px, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d k_inverse = k.inverse();
  const auto sides = Triangulator::vertical_sides(corners);
  // The whole depth range: every pixel of motion from max_depth_m to min_depth_m.
  const double initial_m = std::sqrt(options.min_depth_m * options.max_depth_m);
  constexpr double kWholeRangePx = 1e4;
  // Per side, its candidate distances D: the peak, and when the second peak is within the
  // margin (a repeated edge), that one too.
  std::array<std::vector<double>, 2> candidates_m;
  std::array<double, 2> correlation{};
  for (int s = 0; s < 2; ++s) {
    const auto [i, j] = sides[static_cast<std::size_t>(s)];
    // A vertical 3D line and the camera centre span a plane that holds `up`: |n . up| / |n| is
    // the sine of the side's tilt from vertical (as Triangulator::side_tilts).
    if (options.max_side_tilt_rad > 0.0) {
      const Eigen::Vector3d n =
          (k_inverse * corners[i].homogeneous()).cross(k_inverse * corners[j].homogeneous());
      if (!(n.norm() > 0.0) ||
          std::abs(n.dot(up)) / (n.norm() * up.norm()) > std::sin(options.max_side_tilt_rad)) {
        return std::nullopt;
      }
    }
    const auto depth = sweep.correlate(corners[i], corners[j], initial_m, kWholeRangePx,
                                       options.min_depth_m, options.max_depth_m);
    if (!depth || depth->correlation < options.min_single_view_correlation) return std::nullopt;
    correlation[static_cast<std::size_t>(s)] = depth->correlation;
    candidates_m[static_cast<std::size_t>(s)].push_back(depth->horizontal_distance_m);
    // (second_correlation is -1 when there is no second peak, whatever the margin.)
    if (depth->second_correlation > -1.0 &&
        depth->correlation - depth->second_correlation < options.single_view_min_peak_margin) {
      candidates_m[static_cast<std::size_t>(s)].push_back(depth->second_distance_m);
    }
  }
  // An ambiguous side has two candidate depths: the door's shape (level edges, its height) must
  // single out exactly one combination of the two sides' candidates.
  const auto ends_at = [&](double d0, double d1) -> std::optional<std::array<Eigen::Vector3d, 4>> {
    std::array<Eigen::Vector3d, 4> ends;
    for (int s = 0; s < 2; ++s) {
      const auto [i, j] = sides[static_cast<std::size_t>(s)];
      const auto top = sweep.point_at(corners[i], s == 0 ? d0 : d1);
      const auto bottom = sweep.point_at(corners[j], s == 0 ? d0 : d1);
      if (!top || !bottom) return std::nullopt;
      ends[static_cast<std::size_t>(2 * s)] = *top;
      ends[static_cast<std::size_t>(2 * s + 1)] = *bottom;
    }
    if (options.max_edge_slope_rad > 0.0) {
      const std::optional<double> slope = Triangulator::informative_edge_slope(ends, up);
      if (!slope || std::atan(*slope) > options.max_edge_slope_rad) return std::nullopt;
    }
    if (max_width_m > 0.0 && Triangulator::rectangle_width(ends) > max_width_m) {
      return std::nullopt;
    }
    if (height_range) {
      const double height_m = 0.5 * ((ends[0] - ends[1]).norm() + (ends[2] - ends[3]).norm());
      if (height_m < height_range->min_m || height_m > height_range->max_m) return std::nullopt;
    }
    return ends;
  };
  std::optional<std::array<Eigen::Vector3d, 4>> found;
  int admissible = 0;
  for (const double d0 : candidates_m[0]) {
    for (const double d1 : candidates_m[1]) {
      if (const auto ends = ends_at(d0, d1)) {
        found = ends;
        ++admissible;
      }
    }
  }
  if (admissible != 1) return std::nullopt;
  const std::array<Eigen::Vector3d, 4>& ends = *found;
  SingleViewDoor out;
  out.worst_side_correlation = std::min(correlation[0], correlation[1]);
  out.centre_m = Triangulator::rectangle_centre(ends);
  return out;
}

std::optional<StereoPercept> one_image_percept(const Detection& detection, int index, int image,
                                               const Eigen::Vector3d& centre_in_own_m, double score,
                                               double up_sigma_m, const IdealPixel& reference_ideal,
                                               const Triangulator& triangulator,
                                               const StereoRig& rig,
                                               const StereoMatchOptions& options,
                                               double reference_offset_m) {
  const Eigen::Isometry3d right_T_left = rig.left_T_right.inverse();
  const Eigen::Vector3d centre = image == 0 ? centre_in_own_m : rig.left_T_right * centre_in_own_m;
  // Disparity range, as depth along the left optical axis (as for pairs).
  if (centre.z() < options.min_depth_m || centre.z() > options.max_depth_m) return std::nullopt;
  const Eigen::Vector3d centre_in_right = right_T_left * centre;
  if (!(centre_in_right.z() > 0.0)) return std::nullopt;
  const auto ideal_in = [](const head::CameraIntrinsics& k, const Eigen::Vector3d& p) {
    return Eigen::Vector2d(k.fx_px * p.x() / p.z() + k.cx_px, k.fy_px * p.y() / p.z() + k.cy_px);
  };
  IdealPixel left_point, right_point;
  (image == 0 ? left_point : right_point) = reference_ideal;
  left_point.ideal_px = ideal_in(rig.left, centre);
  right_point.ideal_px = ideal_in(rig.right, centre_in_right);
  const std::optional<Triangulation> triangulation =
      triangulator.triangulate(left_point, right_point, options.pixel_sigma_px, reference_offset_m);
  if (!triangulation) return std::nullopt;
  StereoPercept percept;
  (image == 0 ? percept.left_detection : percept.right_detection) = index;
  percept.left_camera_position_m = centre + reference_offset_m * centre.normalized();
  percept.left_camera_covariance_m2 = triangulation->left_camera_covariance_m2;
  if (up_sigma_m > 0.0 && rig.up_in_left_camera.norm() > 0.0) {
    const Eigen::Vector3d u = rig.up_in_left_camera.normalized();
    percept.left_camera_covariance_m2 += up_sigma_m * up_sigma_m * u * u.transpose();
  }
  percept.left_px = image == 0 ? detection.reference_px : distort(left_point.ideal_px, rig.left);
  percept.right_px = image == 1 ? detection.reference_px : distort(right_point.ideal_px, rig.right);
  // One image's evidence: the detection's confidence, scaled by its sides' agreement with the
  // other image.
  percept.confidence =
      static_cast<float>(std::clamp(static_cast<double>(detection.confidence), 0.0, 1.0) *
                         std::clamp(score, 0.0, 1.0));
  return percept;
}

std::optional<StereoPercept> single_view_percept(
    const Detection& detection, int index, int image, const std::array<Eigen::Vector2d, 4>& corners,
    const IdealPixel& reference_ideal, const SideCorrelator& sweep,
    const Triangulator& triangulator, const StereoRig& rig, const StereoMatchOptions& options,
    const StereoMatchOptions::ExtentRange* height_range, double max_width_m,
    double reference_offset_m) {
  const Eigen::Isometry3d right_T_left = rig.left_T_right.inverse();
  const std::optional<SingleViewDoor> door = place_single_view_door(
      corners, sweep, image == 0 ? rig.left : rig.right,
      image == 0 ? rig.up_in_left_camera
                 : Eigen::Vector3d(right_T_left.linear() * rig.up_in_left_camera),
      options, height_range, max_width_m);
  if (!door) return std::nullopt;
  return one_image_percept(detection, index, image, door->centre_m, door->worst_side_correlation,
                           0.0, reference_ideal, triangulator, rig, options, reference_offset_m);
}

}  // namespace vsl::recognition::detail

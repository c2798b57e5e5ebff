// The detections of both images as the cross match's stages need them (stereo_match.cpp,
// door_pairing.cpp), and the options' per-class entries. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bars_on_outline.hpp"
#include "door_pair.hpp"
#include "epipolar.hpp"
#include "partly_seen_door.hpp"
#include "side_correlation.hpp"
#include "triangulation.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Undistorted corners of a detection's outline in the fit's order
// (Triangulator::outline_in_fit_order; empty unless it has four).
std::vector<IdealPixel> undistorted_corners(const Detection& d,
                                            const head::CameraIntrinsics& intrinsics);
// Which of those corners' raw pixels lie outside the image (an extrapolation of the outline's
// sides: the door's corner there is hidden, not seen); all false without four corners.
std::array<bool, 4> corners_beyond_image(const Detection& d,
                                         const head::CameraIntrinsics& intrinsics);
// The two ends of a bar detection's segment (raw pixels): its reference point (the middle of the
// bar's ends along the major axis, handle_recognizer.cpp) plus and minus half the major extent.
std::vector<Eigen::Vector2d> bar_ends_raw(const Detection& d);
// An outline's four corners as an array (ideal pixels).
std::array<Eigen::Vector2d, 4> corner_array(const std::vector<IdealPixel>& corners);

// The options' entries for a type: its reference point's depth offset (0 without one), its
// extent and height ranges, its door class (door_classes), its cut-bar class; nullptr where the
// options have none.
double reference_depth_offset(const StereoMatchOptions& options, const std::string& type);
const StereoMatchOptions::ExtentRange* extent_range(const StereoMatchOptions& options,
                                                    const std::string& type);
const StereoMatchOptions::ExtentRange* height_range(const StereoMatchOptions& options,
                                                    const std::string& type);
const StereoMatchOptions::DoorClass* door_class_of(const StereoMatchOptions& options,
                                                   const std::string& type);
const StereoMatchOptions::CutBar* cut_bar_of(const StereoMatchOptions& options,
                                             const std::string& type);

// The detections of both images as the cross match's stages need them: undistorted reference
// points, outline corners and bar ends, the rig's epipolar geometry and triangulation, and the side
// correlators (both ways) when the options and images allow them.
struct StereoViews {
  StereoViews(const std::vector<Detection>& left_in, const std::vector<Detection>& right_in,
              const head::CameraIntrinsics& left_intrinsics_in,
              const head::CameraIntrinsics& right_intrinsics_in,
              const Eigen::Isometry3d& left_T_right_in, const StereoMatchOptions& options_in,
              const Eigen::Vector3d& up_in, const StereoImages& images)
      : left(left_in),
        right(right_in),
        left_intrinsics(left_intrinsics_in),
        right_intrinsics(right_intrinsics_in),
        left_T_right(left_T_right_in),
        options(options_in),
        up(up_in),
        epipolar(left_intrinsics, right_intrinsics, left_T_right),
        triangulator(left_intrinsics, right_intrinsics, left_T_right),
        rig{camera_matrix(left_intrinsics), camera_matrix(right_intrinsics), left_T_right.inverse(),
            up.norm() > 0.0 ? up.normalized() : up},
        log_max_area_ratio(std::log(std::max(options.max_area_ratio, 1.0 + 1e-9))) {
    std::vector<Eigen::Vector2d> left_raw, right_raw;
    for (const Detection& d : left) left_raw.push_back(d.reference_px);
    for (const Detection& d : right) right_raw.push_back(d.reference_px);
    left_ideal = undistort(left_raw, left_intrinsics);
    right_ideal = undistort(right_raw, right_intrinsics);
    if (options.min_side_correlation > 0.0 && images.left_grey && images.right_grey &&
        up.norm() > 0.0) {
      correlator.emplace(*images.left_grey, *images.right_grey, left_intrinsics, right_intrinsics,
                         left_T_right, up);
      reverse_correlator.emplace(*images.right_grey, *images.left_grey, right_intrinsics,
                                 left_intrinsics, left_T_right.inverse(),
                                 left_T_right.linear().transpose() * up);
    }
    for (const Detection& d : left) {
      left_corners.push_back(undistorted_corners(d, left_intrinsics));
      left_beyond_image.push_back(corners_beyond_image(d, left_intrinsics));
    }
    for (const Detection& d : right) {
      right_corners.push_back(undistorted_corners(d, right_intrinsics));
      right_beyond_image.push_back(corners_beyond_image(d, right_intrinsics));
    }
    left_bar_ends = bar_ends(left, left_intrinsics);
    right_bar_ends = bar_ends(right, right_intrinsics);
  }

  // Undistorted ends of the bar-type detections (empty for the others).
  std::vector<std::vector<IdealPixel>> bar_ends(const std::vector<Detection>& detections,
                                                const head::CameraIntrinsics& intrinsics) const {
    std::vector<std::vector<IdealPixel>> out(detections.size());
    for (std::size_t i = 0; i < detections.size(); ++i) {
      const Detection& d = detections[i];
      if (d.corners_px.empty() && d.major_extent_px > 0.0 && is_bar_type(options, d.type)) {
        out[i] = undistort(bar_ends_raw(d), intrinsics);
      }
    }
    return out;
  }

  // The worse of the two outlines' verdicts on the handles they hold (bars_on_outline.hpp).
  BarVerdict judge_bars(const Detection& dl, const Detection& dr) const {
    const BarVerdict on_left = judge_bars_on_outline(left, dl, options);
    return on_left.gate != StereoGate::kNone ? on_left : judge_bars_on_outline(right, dr, options);
  }
  DoorOutlines outlines(int l, int r) const {
    return {corner_array(left_corners[l]), corner_array(right_corners[r])};
  }

  const std::vector<Detection>& left;
  const std::vector<Detection>& right;
  const head::CameraIntrinsics& left_intrinsics;
  const head::CameraIntrinsics& right_intrinsics;
  const Eigen::Isometry3d& left_T_right;
  const StereoMatchOptions& options;
  const Eigen::Vector3d& up;  // in the left camera frame; zero when unknown
  const EpipolarGeometry epipolar;
  const Triangulator triangulator;
  const PinholeRig rig;  // the ideal pinholes and `up` for the door and bar fits
  const double log_max_area_ratio;
  std::vector<IdealPixel> left_ideal, right_ideal;
  std::optional<SideCorrelator> correlator, reverse_correlator;
  std::vector<std::vector<IdealPixel>> left_corners, right_corners;
  std::vector<std::array<bool, 4>> left_beyond_image, right_beyond_image;
  std::vector<std::vector<IdealPixel>> left_bar_ends, right_bar_ends;
};

}  // namespace vsl::recognition::detail

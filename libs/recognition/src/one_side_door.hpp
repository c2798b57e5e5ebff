// A door outline of one image placed from one vertical side and the level planes of its top and
// bottom edges (StereoMatchOptions::BorderCutDoor::from_one_side), when no pair took it and the
// sweep of both sides (single_view.hpp) did not place it. Near the left border of the left image a
// door is cut along its left side by the right image's left border (the right camera sees
// everything further left), near the right border of the right image along its right side by
// the left image's right border: that side has nothing to correlate with. Elsewhere a side's
// sweep over the whole depth range may peak twice (a run of equal doors repeats every edge),
// while the door's shape fixes where that side must be. Internal to vsl_recognition.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>

#include "side_correlation.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/detection.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

// Which vertical side is swept: the inner one, the other placed on the level planes
// (BorderCutDoor::from_one_side), or, for a whole outline, the outer one, the inner one placed
// where the other image shows it or shows no edge at all (BorderCutDoor::merged_side).
enum class SweptSide { kInner, kOuter };

struct OneSideDoor {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // the sweep's own camera frame, metres
  double side_correlation = 0.0;                       // the inner side's score
  // The spread of the centre along `up` that the class's heights add (metres, standard
  // deviation): BorderCutDoor::height_sigma_m / 2 for a door cut by its own image's top or
  // bottom border, 0 for a whole one.
  double height_sigma_m = 0.0;
};

// `corners_ideal_px`: the outline in its own image (`own_image`: 0 left, 1 right; ideal pixels,
// clockwise from the top left; for a door cut by the top or bottom border, `cut`, the two on
// that side where its vertical sides leave the image). `sweep` is built over (own, other) with
// `up_in_own_camera`; `other_T_own` takes own camera points into the other camera.
// `height_range`: the class's height range (whole doors), or nullptr. nullopt unless every test
// of BorderCutDoor::from_one_side passes.
std::optional<OneSideDoor> place_one_side_door(
    const std::array<Eigen::Vector2d, 4>& corners_ideal_px, BorderCut cut, int own_image,
    const SideCorrelator& sweep, const head::CameraIntrinsics& own,
    const head::CameraIntrinsics& other, const Eigen::Isometry3d& other_T_own,
    const Eigen::Vector3d& up_in_own_camera, const StereoMatchOptions& options,
    const StereoMatchOptions::BorderCutDoor& door,
    const StereoMatchOptions::ExtentRange* height_range, SweptSide swept = SweptSide::kInner);

}  // namespace vsl::recognition::detail

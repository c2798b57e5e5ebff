// A door placed from one image alone (StereoMatchOptions::min_single_view_correlation): its
// outline is clean in that image, while the other image's blob is merged with a neighbour or a
// little off the class model, so that no pair was made. The outline's two vertical sides are
// swept into the other image over the whole depth range (side_correlation.hpp), and the four
// ends so placed must describe a door: vertical sides, level top and bottom edges, a door's
// height (the caller tests the depth range, along the left optical axis). Internal to
// vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "side_correlation.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

struct SingleViewDoor {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // the sweep's own camera frame, metres
  double worst_side_correlation = 0.0;                 // the lower of the two sides' scores
};

// `corners_ideal_px`: the outline clockwise from the top left, ideal pixels of the image the
// sweep starts from (`own`, whose up direction is `up_in_own_camera`). `height_range`: the class's
// height range, or nullptr. nullopt unless every test of min_single_view_correlation passes.
std::optional<SingleViewDoor> place_single_view_door(
    const std::array<Eigen::Vector2d, 4>& corners_ideal_px, const SideCorrelator& sweep,
    const head::CameraIntrinsics& own, const Eigen::Vector3d& up_in_own_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::ExtentRange* height_range);

}  // namespace vsl::recognition::detail

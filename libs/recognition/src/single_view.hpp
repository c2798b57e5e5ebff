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

#include <Eigen/Geometry>

#include "epipolar.hpp"
#include "side_correlation.hpp"
#include "triangulation.hpp"
#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/stereo_match.hpp"

namespace vsl::recognition::detail {

struct SingleViewDoor {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // the sweep's own camera frame, metres
  double worst_side_correlation = 0.0;                 // the lower of the two sides' scores
};

// `corners_ideal_px`: the outline clockwise from the top left, ideal pixels of the image the
// sweep starts from (`own`, whose up direction is `up_in_own_camera`). `height_range`: the class's
// height range, or nullptr; `max_width_m`: the class's greatest width (0: not tested; a peak on
// another door's edge places a side a metre off). nullopt unless every test of
// min_single_view_correlation passes.
std::optional<SingleViewDoor> place_single_view_door(
    const std::array<Eigen::Vector2d, 4>& corners_ideal_px, const SideCorrelator& sweep,
    const head::CameraIntrinsics& own, const Eigen::Vector3d& up_in_own_camera,
    const StereoMatchOptions& options, const StereoMatchOptions::ExtentRange* height_range,
    double max_width_m);

// The cameras of one stereo frame (left camera frame; `up` from the head kinematics).
struct StereoRig {
  const head::CameraIntrinsics& left;
  const head::CameraIntrinsics& right;
  Eigen::Isometry3d left_T_right;
  Eigen::Vector3d up_in_left_camera;
};

// The percept of a detection (`index` into its image's detections) of image `image` (0 left, 1
// right) placed from that image alone at `centre_in_own_m` (that image's camera frame, on the
// face): within the depth range (along the left optical axis), `reference_offset_m` behind the
// face along the ray, its covariance the one the pixel noise gives a pair at that point (the
// centre's projections into both images, with the lens Jacobian of `reference_ideal`, the
// detection's own reference point) plus up_sigma_m^2 along the up direction, the other image's
// pixel the centre's projection, and the confidence the detection's times `score` (in [0, 1]).
std::optional<StereoPercept> one_image_percept(const Detection& detection, int index, int image,
                                               const Eigen::Vector3d& centre_in_own_m, double score,
                                               double up_sigma_m, const IdealPixel& reference_ideal,
                                               const Triangulator& triangulator,
                                               const StereoRig& rig,
                                               const StereoMatchOptions& options,
                                               double reference_offset_m);

// The percept of an unpaired door detection (`index` into its image's detections) of image
// `image` (0 left, 1 right), placed from that image alone by `sweep` (built over that image and
// the other one) with place_single_view_door: its centre in the left camera frame within the
// depth range, `reference_offset_m` behind the surface along the ray, the covariance the pixel
// noise gives a pair at that point (the centre's projections into both images, with the lens
// Jacobian of `reference_ideal`, the detection's own reference point), the other image's pixel
// the centre's projection, and the confidence the detection's times its lower side score.
// nullopt when the door is not placed (`height_range`, `max_width_m`: place_single_view_door).
std::optional<StereoPercept> single_view_percept(
    const Detection& detection, int index, int image,
    const std::array<Eigen::Vector2d, 4>& corners_ideal_px, const IdealPixel& reference_ideal,
    const SideCorrelator& sweep, const Triangulator& triangulator, const StereoRig& rig,
    const StereoMatchOptions& options, const StereoMatchOptions::ExtentRange* height_range,
    double max_width_m, double reference_offset_m);

}  // namespace vsl::recognition::detail

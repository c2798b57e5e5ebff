// Left-right cross match of detections (paper §2.1: size, position, orientation, perpendicular
// distance to the epipolar line and the disparity range), triangulation with a 3x3 covariance
// from the pixel noise, in the left camera frame (x right, y down, z forward, metres).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <utility>
#include <vector>

#include "vsl/head/camera_intrinsics.hpp"
#include "vsl/recognition/detection.hpp"

namespace vsl::config {
class Node;
}
namespace cv {
class Mat;
}

namespace vsl::recognition {

struct StereoMatchOptions {
  double max_epipolar_distance_px = 3.0;  // of the right point from the left point's epipolar line
  double min_depth_m = 0.3;               // disparity range, as depths along the left optical axis
  double max_depth_m = 6.0;
  double max_area_ratio = 1.6;                   // larger / smaller blob area
  double max_orientation_difference_rad = 0.35;  // of the major axes (elongated blobs only)
  // A blob is elongated (its orientation is compared) when major / minor extent is at least this.
  double min_elongation_for_orientation = 2.0;
  double pixel_sigma_px = 0.7;  // noise of a reference point, each image coordinate
  // Per class: how far the reference point (the world model's object position) lies behind the
  // visible surface along the viewing ray, metres (a handle's is its bar's axis). Others: 0.
  std::vector<std::pair<std::string, double>> reference_depth_offset_m;
  // Optional, per class: the range of the object's physical length along the blob's major axis
  // (major_extent_px * z / f at the triangulated depth), metres. Without it, repeated objects on
  // one epipolar line admit pairings at wrong depths. Classes not listed are not checked.
  struct ExtentRange {
    std::string type;
    double min_m = 0.0;
    double max_m = 0.0;
  };
  std::vector<ExtentRange> major_extent_range_m;
  // Optional, per class: the range of the object's height (its vertical edges at the triangulated
  // depth), metres: a door is taller than a drawer front of its colour and any width.
  std::vector<ExtentRange> height_range_m;
  // A door outline's sides nearer the image vertical must be vertical in 3D within this angle: a
  // side that is not is no door edge (an occluder's contour, a neighbour's strip), and its corners
  // are merged in the door's fit (partly_seen_door.hpp); with more than one such side the pair is
  // refused. Needs the up direction; 0 turns it off.
  double max_side_tilt_rad = 0.0;
  // Types whose detections are bars (handles): a pair of elongated views across the epipolar
  // lines, or cut by the border, is placed by the fit of a 3D segment to both views
  // (partly_seen_bar.hpp), since segmentation often keeps only a fragment of a thin bar in one
  // image. The size gate then compares mean widths, and the class length is the fitted bar's.
  std::vector<std::string> bar_types;
  // Door outlines measured in the images themselves: each vertical side is placed where the
  // image around it is found again in the other image (side_correlation.hpp, a plane sweep along
  // the epipolar lines scored by a normalized cross-correlation), not where the other outline's
  // side is, since one image's outline often lacks a stile. A side scoring below this keeps the
  // outlines' depth. Needs the images and the up direction; 0 turns it off.
  double min_side_correlation = 0.0;
  // A side's correlation peak is taken only when it beats the second-best distinct peak by this
  // (a run of equal doors repeats every edge); a door from one image tries both peaks instead,
  // and exactly one combination must fit.
  double min_peak_margin = 0.1;
  // Door outlines that no pair took, placed from their own image by the door's fit with their
  // vertical sides swept into the other image over the whole depth range (one_image_door.hpp):
  // each swept side must score at least this. Needs min_side_correlation > 0; 0 turns it off.
  double min_single_view_correlation = 0.0;
  // ... and no percept of the type may lie within this distance (a second outline of a door
  // already placed), metres.
  double single_view_min_separation_m = 0.2;
  // Any door outline is refused when the handles on it lie at heights differing by more than this
  // fraction of its height: one above another they are a stack of drawer fronts merged into one
  // door-shaped blob. Needs bar_types; 0 turns it off.
  double max_bar_height_spread = 0.0;
  // Per door class: its sizes, the prior of the door's fit (partly_seen_door.hpp) for what
  // neither image shows. A door outline pair of a listed class, whole, cut by the image border,
  // or refused in a way an occluder in front of the door explains (one corner hidden in both
  // images, or the lower part), and a door outline that no pair took (from one image), is placed
  // by that one fit. Border-cut detections of other classes are not paired. Needs the up
  // direction.
  struct DoorClass {
    std::string type;
    // The class's common heights, ascending, metres: a door whose top or bottom neither image
    // shows is as tall as the least of them its visible height does not exceed by more than 5 %,
    // with the spread height_sigma_m; at least half of the least must be in view.
    std::vector<double> typical_heights_m;
    double height_sigma_m = 0.0;
    // A fitted door narrower than min_width_m is a strip that segmentation split off (not tested
    // for a door from one image swept on both sides, whose one outline may measure it short); one
    // wider than max_width_m is two doors, or a correlation peak on another door's edge (metres).
    double min_width_m = 0.0;
    double max_width_m = 0.0;
    // A door whose left or right side neither image shows is as wide as this or its visible
    // width, the greater, with the spread width_sigma_m; at least half of it must be in view.
    // Metres; 0 pairs no such detections.
    double typical_width_m = 0.0;
    double width_sigma_m = 0.0;
  };
  std::vector<DoorClass> door_classes;
  // Per bar class: bars cut at one end by the image border (HandleRecognizerParameters::
  // detect_border_cut) are placed by the bar's fit; where neither image shows an end, the bar is
  // as long as typical_length_m with the spread length_sigma_m, and its visible part must be 0.4
  // .. 1.1 of that. Views cut by different borders are not paired. Metres; a type without an
  // entry pairs no cut bars.
  struct CutBar {
    std::string type;
    double typical_length_m = 0.0;
    double length_sigma_m = 0.0;
  };
  std::vector<CutBar> cut_bars;
  // Per class: the part of a percept's error that every frame of one scan shares, which fusion
  // must keep out of its average (percept_t.shared_sigma_m, shared_ray_sigma_m): floor_m in every
  // direction (where on the object the reference point falls from this robot pose) and a
  // disparity bias of shared_disparity_px along the viewing ray. Both are added to the
  // covariance. Measured with vsl-scan-noise on recorded scans; a class not listed claims none.
  struct SharedNoise {
    std::string type;
    double floor_m = 0.0;
    double shared_disparity_px = 0.0;
  };
  std::vector<SharedNoise> shared_noise;
};

// The frame's grey images (CV_8UC1, raw pixels, the intrinsics' size), for the gates that look
// at the images themselves (StereoMatchOptions::min_side_correlation,
// min_single_view_correlation); without them those are off.
struct StereoImages {
  const cv::Mat* left_grey = nullptr;
  const cv::Mat* right_grey = nullptr;
};

// Reads the `stereo:` section (every key optional, defaults above; reference_depth_offset_m maps
// a type to metres, major_extent_range_m a type to [min_m, max_m], bar_types is a list of types,
// shared_noise a type to {floor_m, shared_disparity_px}).
// Unknown keys, non-finite or out-of-range values are errors: vsl::config::Error "file:line: key:
// what".
StereoMatchOptions stereo_match_options_from(const config::Node& section);

// A matched, triangulated pair, or a door placed from one image
// (StereoMatchOptions::min_single_view_correlation).
struct StereoPercept {
  // Indices into the left and right detections; -1 for the image a single-view percept
  // (StereoMatchOptions::min_single_view_correlation) has no detection in.
  int left_detection = -1;
  int right_detection = -1;
  // The reference point in each raw image, pixels: the detections' (their outlines' centres
  // for rectangles), or for a single-view percept the projection of its point into the image
  // without a detection.
  Eigen::Vector2d left_px = Eigen::Vector2d::Zero();
  Eigen::Vector2d right_px = Eigen::Vector2d::Zero();
  Eigen::Vector3d left_camera_position_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d left_camera_covariance_m2 = Eigen::Matrix3d::Zero();
  float confidence = 0.0f;
};

// The gates of match_and_triangulate (kTriangulation: the pair's point cannot be triangulated,
// e.g. it is not in front of both cameras). A pair meets them in this order: with its
// position kStackedBars, kEpipolar and kSideTilt; kAreaRatio, kOrientation; for door outlines
// kHeight before the sides' correlation (too short at any depth it can reach); kTriangulation and
// kRectangleFit (a door's fit); kDepth, kExtent, kHeight.
enum class StereoGate {
  kNone,
  kEpipolar,
  kSideTilt,
  kAreaRatio,
  kOrientation,
  kTriangulation,
  kDepth,
  kExtent,
  kHeight,
  // bar detections on an outline one above another (max_bar_height_spread)
  kStackedBars,
  // a corner of a door's outline farther from the fitted rectangle than the outlines' tolerance
  // (docs/recognition.md, "Doors: one model")
  kRectangleFit
};
const char* stereo_gate_name(StereoGate gate);  // "epipolar", "side_tilt", ...

// How one left-right pair fared in match_and_triangulate.
struct StereoPairTrace {
  int left_detection = -1;
  int right_detection = -1;
  StereoGate refused_by = StereoGate::kNone;  // kNone: a candidate of the assignment
  double value = 0.0;  // the refusing gate's quantity (px, rad, ratio or m) and its limit
  double limit = 0.0;
  double cost = 0.0;      // a candidate's normalized cost
  bool assigned = false;  // a candidate the assignment kept (a percept)
  // A candidate placed with one corner hidden by an occluder in both images after the side gate
  // or the door's fit refused it (docs/recognition.md).
  bool occluded_corner = false;
};

// Matches detections of the same type one to one (each left detection to at most one right
// detection and vice versa) and triangulates each pair. A pair is admissible when it passes every
// gate (same type, epipolar distance, depth range, area ratio, orientation of elongated blobs,
// the class's length range); its normalized cost is the sum of the squared epipolar distance, log
// area ratio and orientation difference, each over its limit. Two door outlines of a class with
// sizes (StereoMatchOptions::door_classes) are instead judged by the door's fit, whose cost is its
// worst corner residual over its tolerance, squared (docs/recognition.md). Among the admissible
// pairs the assignment makes as many matches as possible and, among those, the ones of least total
// cost (Hungarian method): with repeated identical objects (the two handles of a double door are 7
// cm apart, a disparity of 20 px at 2 m), taking the cheapest pair first can pair one object's left
// image with its neighbour's right image and leave both true partners unmatched. Two assigned
// pairs of one type side by side (overlapping rows) that cross, the left-to-right order of their
// detections differing between the images, are then uncrossed when the uncrossed pairs are
// admissible (the ordering constraint of stereo: crossed, one would be far in front of the
// other). `left_T_right` is
// the right camera's pose in the left camera frame at capture time (from the head kinematics, so
// verging eyes are handled). Raw pixels are undistorted with each camera's intrinsics first.
// The pairs come sorted by left detection, the single-view doors after them. The confidence of a
// pair is the geometric mean of its two detections' confidences, sqrt(c_l c_r): symmetric, in
// [0, 1], and on the scale of a single detection's (two views of confidence c give c; the product
// would give c^2, penalizing every stereo percept for having been seen twice). A single-view
// door's is its detection's confidence times its lower side score.
//
// `pair_trace`, when given, receives one entry per pair of detections of the same type that is
// judged: the first gate that refused it, or none and whether the assignment kept it (a debug
// aid: where the evaluation's ground-truth pairs were lost). Two door views cut by the image
// border are judged as a pair only when they can show one door (cut alike, or the image that sees
// less beyond a left or right border cut there alone), not cut doors of a class without
// StereoMatchOptions::door_classes or without the up direction. `images`: the frame's
// grey images, for the door sides' correlation (StereoMatchOptions::min_side_correlation) and the
// single-view doors; without them both are off.
std::vector<StereoPercept> match_and_triangulate(
    const std::vector<Detection>& left, const std::vector<Detection>& right,
    const head::CameraIntrinsics& left_intrinsics, const head::CameraIntrinsics& right_intrinsics,
    const Eigen::Isometry3d& left_T_right, const StereoMatchOptions& options,
    const Eigen::Vector3d& up_in_left_camera = Eigen::Vector3d::Zero(),
    std::vector<StereoPairTrace>* pair_trace = nullptr, const StereoImages& images = {});

}  // namespace vsl::recognition

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
  // Each class's reference point (the world model's object position) lies this far behind the
  // visible surface along the viewing ray, metres: a handle's is the bar's axis, 6 mm behind the
  // 12 mm bar's surface; a door's (config/worlds/kitchen.yaml) is on its frame's front face, 0.
  // Classes not listed: 0.
  std::vector<std::pair<std::string, double>> reference_depth_offset_m;
  // Optional, per class: the range of the object's physical length along the blob's major axis,
  // metres. A pair is admissible only when the blobs' mean major extent at the triangulated
  // depth, major_extent_px * z / f, lies in it. Without it, repeated objects on one epipolar
  // line admit wrong pairings at other depths (a handle 10 px long in the image, paired with
  // another handle 135 px away, would be 7 mm long at 0.37 m). Classes not listed, and
  // detections without extents, are not checked.
  struct ExtentRange {
    std::string type;
    double min_m = 0.0;
    double max_m = 0.0;
  };
  std::vector<ExtentRange> major_extent_range_m;
  // Optional, per class: the range of the object's height (the physical length of its vertical
  // edges, Detection::height_px at the triangulated depth), metres. A door is taller than a
  // drawer front of the same colour and of any width, and a camera turning about the vertical
  // does not foreshorten it. Classes not listed, and detections without a height, are not checked.
  std::vector<ExtentRange> height_range_m;
  // Rectangle outlines (detections with corners: doors) whose sides nearer the image vertical
  // are not vertical in 3D within this angle, in either image, are no door's front face (an
  // occluder's contour or a neighbour's strip gave the outline a side). When only one side in
  // one image is so tilted, its corners there are merged in the door's fit (partly_seen_door.hpp:
  // the other image's and the other side's corners place the door; classes without a
  // border_cut entry have no fit, and such a pair is refused); otherwise the pair is refused
  // (but see BorderCutDoor::occluded_corner for a side that is no door edge in both images).
  // Needs the up direction (match_and_triangulate's up_in_left_camera); 0 turns it off.
  double max_side_tilt_rad = 0.0;
  // Types whose detections are bars (handles): a pair of such elongated detections (both at
  // least min_elongation_for_orientation, their axis at least 45 degrees from the epipolar line)
  // is placed by the fit of a 3D segment to both views (partly_seen_bar.hpp) rather than by its
  // reference points. Segmentation often loses a part of a thin bar in one image: that image's
  // segment is then a fragment, its midpoint moves along the bar by half the part lost, and the
  // reference-point gates (epipolar distance, area ratio) refuse the pair. As bars, the
  // epipolar gate tests that the shorter view, placed along the longer by the epipolar lines,
  // lies within it (to max_epipolar_distance_px), and the fit that every end lies within that
  // distance of the fitted bar; the area ratio compares the mean widths (area over length); the
  // bar's ends are the union's, and the class length (major_extent_range_m) the fitted bar's.
  std::vector<std::string> bar_types;
  // Rectangle outlines (doors) measured in the images themselves: the depth of each vertical
  // side of the left outline is where the image around it is found again in the right image
  // (side_correlation.hpp: a plane sweep of the vertical side along the epipolar lines, scored by
  // 2 cov / (var_l + var_r), a normalized cross-correlation that also wants equal contrast),
  // searched within 6 px plus a quarter of the outline's width of the outlines' depth; not where
  // the right outline's side is. One image's outline often lacks a stile or a rail that the
  // other keeps, and that side's disparity from the outlines is then off by the stile's width.
  // A side whose best score is below this, or not BorderCutDoor::min_peak_margin above its
  // second-best, keeps the outlines' depth (a side without texture to correlate: the middle of a
  // double door, a reveal of sub-pixel width; a run of equal doors); so do both sides when the
  // sides so placed make the door wider than BorderCutDoor::max_width_m (a peak on another door's
  // edge). Needs the images (match_and_triangulate's `images`) and the up direction; 0 turns it
  // off.
  double min_side_correlation = 0.0;
  // Rectangle outlines (doors) that no pair took, placed from their own image alone: a door
  // whose outline is clean in one image is often merged with a neighbour, or a little off the
  // class model, in the other, and then has no partner. Both vertical sides of the outline are
  // swept into the other image over the whole depth range (side_correlation.hpp), and the door's
  // fit (partly_seen_door.hpp) places it from the outline and the sides where the sweeps put
  // them (one_image_door.hpp). The outline makes a percept when both sides score at least this,
  // its sides are vertical in 3D (max_side_tilt_rad), exactly one combination of the sides' peaks
  // (the best, and the second-best where it is within single_view_min_peak_margin: a run of equal
  // doors repeats every edge) fits a door of its class (border_cut: a type without a door class
  // makes no single views), at most single_view_max_bars_inside detections of a bar type
  // (handles) lie inside the outline (a door carries one handle; a stack of drawer fronts, or two
  // doors, merged into one door-shaped blob carry several), and no percept of its type lies
  // within single_view_min_separation_m of it. Its covariance is the fit's. Needs
  // min_side_correlation > 0 (its correlator and images; stereo_match_options_from refuses the
  // option without it) and the up direction; 0 turns it off.
  double min_single_view_correlation = 0.0;
  double single_view_min_peak_margin = 0.1;
  double single_view_min_separation_m = 0.2;
  int single_view_max_bars_inside = 1;
  // An outline that holds one handle more than single_view_max_bars_inside allows (two where
  // one is) is kept when both lie within this fraction of its width (along its top and bottom
  // edges) from the same vertical side: its own handle by its closing edge and its double-door
  // neighbour's a few centimetres beyond the reveal, inside the outline's slack. Two doors merged
  // into one blob hold their handles in the middle, a drawer stack one above another
  // (max_bar_height_spread). Applies wherever single_view_max_bars_inside does (single views and
  // occluded-corner pairs); 0 turns it off.
  double neighbour_handle_side_band = 0.0;
  // A pair of whole door outlines (detections with corners) is refused when more than this many
  // detections of a bar type (handles) lie inside either outline: a door carries one handle, and
  // a neighbour's may stand within its outline's slack (a double door's two handles are a few
  // centimetres apart), but three or more are a stack of drawer fronts, or several doors, merged
  // into one door-shaped blob in both images. Needs bar_types; 0 turns it off.
  int pair_max_bars_inside = 0;
  // Any door outline (of a pair, either image's; of a single view; of a border-cut or
  // occluded-corner pair) is refused when the detections of a bar type (handles) on it lie at
  // heights that differ by more than this fraction of the outline's height (along its vertical
  // sides; a handle counts when its reference point lies inside the outline or up to 3 px
  // outside). A door carries one handle, and a double door's neighbour's stands at the same
  // height; handles one above another are a stack of drawer fronts, or a door and the drawer
  // above it, merged into one door-shaped blob. Seen at a grazing angle a drawer's handle stands
  // on the outline's near edge, so the count of bars inside misses it. Needs bar_types; 0 turns
  // it off.
  double max_bar_height_spread = 0.0;
  // Before the match, a whole door outline (of either image, cut by no border) that holds
  // exactly two bar detections (handles) at one height, at most this fraction of its width apart
  // (along its top and bottom edges), their middle within the outline's middle 40%, is replaced
  // by its two halves either side of the line between them: the two doors of a double door that
  // segmentation merged where the reveal between them is unseen (at a grazing angle it is under
  // a pixel wide and shows the doors' own colour). A door carries one handle, and a double
  // door's two stand 3-6 cm either side of the reveal (twin_handle_split.hpp).
  // Needs bar_types; 0 turns it off.
  double max_twin_handle_gap = 0.0;
  // Optional, per class: the class's sizes, the prior of the door's fit (partly_seen_door.hpp,
  // docs/recognition.md). A pair of door outlines, whole, cut by the image border
  // (Detection::border_cut) or refused in a way an occluder explains (occluded_corner,
  // occluder_cut), is placed by one fit of a vertical rectangle to the corners each image shows,
  // a size neither image gives taken from these. Each vertical side is placed where the images
  // around it correlate (min_side_correlation), when that peak is clear (min_peak_margin).
  // Detections cut along a border, of classes not listed here, are not paired; whole pairs of
  // such classes are placed by their reference points. Needs the up direction.
  struct BorderCutDoor {
    std::string type;
    // The class's common door heights, ascending, metres. A door whose top or bottom neither
    // image shows is as tall as the least of them that its visible height does not exceed by more
    // than 5%, with the spread height_sigma_m; at least half of the least must be in view.
    std::vector<double> typical_heights_m;
    double height_sigma_m = 0.0;  // the spread of the class's heights about them, metres
    // A door's width, metres: a fitted door narrower than min_width_m is a strip of a door that
    // segmentation split off (not tested for a door from one image swept on both sides: at the
    // grazing angles where the other image's blob is off the class model, one outline measures a
    // door short), one wider than max_width_m two doors (also the single views' bound: a side's
    // correlation peak on another door's edge can move it a metre).
    double min_width_m = 0.0;
    double max_width_m = 0.0;
    // With from_one_side: the greatest tilt from vertical (radians) of a cut outline's sides, as
    // StereoMatchOptions::max_side_tilt_rad is of whole ones (a cut outline's sides are shorter and
    // end at the border, so they are fitted less well). 0 turns the test off.
    double max_side_tilt_rad = 0.0;
    // With min_side_correlation: a side is placed by correlation only when its best score beats
    // its second-best distinct peak by this (SideCorrelator::SideDepth::second_correlation; a run
    // of equal doors repeats every edge), else it keeps the outlines'. 0: any best peak.
    double min_peak_margin = 0.0;
    // With min_single_view_correlation: a door outline that neither a pair nor a single view
    // placed (whole, or cut by its own image's top or bottom border) is placed by the door's fit
    // with one vertical side swept (one_image_door.hpp): the side the other image shows even near
    // its border (the right side of a left-image outline), as for single views
    // (min_single_view_correlation; a second peak within single_view_min_peak_margin is tried
    // too, and exactly one must pass); the other side is placed by the outline's level edges. Kept
    // when the own image measures the width, the placed side projects beyond the other image's
    // left or right border or the other image shows it there, and the fit's gates pass (a cut
    // one's height the class's, as for pairs above); at most single_view_max_bars_inside handles
    // inside, no percept of its type within single_view_min_separation_m. The covariance is the
    // fit's.
    bool from_one_side = false;
    // With from_one_side: a whole door outline that it did not place is tried once more
    // with the roles swapped: its outer side swept, its inner side placed by the level edges,
    // and kept when the other image shows the inner side there or shows no edge at all there
    // (its window's contrast under 0.3 of the own image's: the reveal between the door and a
    // neighbour of its colour, unseen in the other image, where segmentation merged the two).
    // The other tests are from_one_side's.
    bool merged_side = false;
    // A pair of whole door outlines that the position gate, the side gate or the door's fit
    // refused, placed with one corner hidden in both images (an occluder in front of the door: a
    // chair's back, a table top): when exactly one corner so hidden lets the fit meet
    // max_epipolar_distance_px and that corner's outline point lies inside the fitted door in both
    // images, at least that far from the door's own corner in one.
    bool occluded_corner = false;
    // A pair of whole door outlines that the height gate finds too short (height_range_m) or the
    // door's fit refuses, placed with its lower corners on the door's sides (an occluder in front
    // of the door, a chair's seat or the table's top, hides its lower part in both images), its
    // height the class's (typical_heights_m), when the fit meets max_epipolar_distance_px.
    bool occluder_cut = false;
    // With occluder_cut: a pair whose lower edge is level on the door's face (within 0.05 rad, as
    // a table's edge along the cupboards is) shows at least this much of the door, metres: a
    // drawer front of the door's colour, both edges level, is at most this tall.
    double occluder_cut_min_level_visible_m = 0.0;
    // A door whose left or right side neither image shows (the left or right image border cuts
    // it) is as wide as this or as its visible width, the greater, with the spread
    // width_sigma_m; at least half of it must be in view. Metres; 0 pairs no such detections.
    double typical_width_m = 0.0;
    double width_sigma_m = 0.0;  // the spread of the class's widths about it, metres
  };
  std::vector<BorderCutDoor> border_cut;
  // Bars of a bar type (bar_types) cut at one end by the image border
  // (HandleRecognizerParameters::detect_border_cut), placed by the same fit: the view's end at
  // the border is only a point of the bar. Where neither image shows an end (both cut by the same
  // border, or the other view ends short of it), the bar's length is the class's typical one,
  // with its spread as the prior's sigma, and the visible part must be 0.4 .. 1.1 of the typical
  // length. A cut pair along the epipolar lines (a level handle) goes through the same fit, its
  // depth from the ends both images see. Views cut by different borders are not paired. Metres;
  // a type without an entry pairs no cut bars.
  struct CutBar {
    std::string type;
    double typical_length_m = 0.0;
    double length_sigma_m = 0.0;  // the spread of the class's lengths about it
  };
  std::vector<CutBar> cut_bars;
};

// The epipolar gate of two rectangle outlines (doors): their vertical sides nest along the
// epipolar direction to this fraction of their image height (pixels), when that is more than
// StereoMatchOptions::max_epipolar_distance_px.
inline constexpr double kRectangleEpipolarFraction = 0.05;

// The frame's grey images (CV_8UC1, raw pixels, the intrinsics' size), for the gates that look
// at the images themselves (StereoMatchOptions::min_side_correlation,
// min_single_view_correlation); without them those are off.
struct StereoImages {
  const cv::Mat* left_grey = nullptr;
  const cv::Mat* right_grey = nullptr;
};

// Reads the `stereo:` section (every key optional, defaults above; reference_depth_offset_m maps
// a type to metres, major_extent_range_m a type to [min_m, max_m], bar_types is a list of types).
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
// e.g. it is not in front of both cameras). A pair meets them in this order: kWeakPair; with its
// position kBarsInside, kStackedBars, kEpipolar and kSideTilt; kAreaRatio, kOrientation;
// kTriangulation and kRectangleFit (a door's fit); kDepth, kExtent, kHeight.
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
  kWeakPair,  // both detections weak (Detection::needs_partner)
  // more bar detections inside an outline than allowed (door pairs, whole or cut by the border:
  // pair_max_bars_inside; single views: single_view_max_bars_inside)
  kBarsInside,
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
  // A candidate placed with one corner hidden by an occluder in both images after the position
  // gate, the side gate or the door's fit refused it (BorderCutDoor::occluded_corner,
  // docs/recognition.md).
  bool occluded_corner = false;
};

// Matches detections of the same type one to one (each left detection to at most one right
// detection and vice versa) and triangulates each pair. A pair is admissible when it passes every
// gate (same type, epipolar distance, depth range, area ratio, orientation of elongated blobs,
// the class's length range; for two rectangle outlines the epipolar gate is that their vertical
// sides nest along the epipolar direction, one image's outline possibly a strip longer at the top
// or the bottom, up to 15% of the side); its normalized cost is the sum of the squared epipolar
// distance, log area ratio and orientation difference, each over its limit. Among the admissible
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
// StereoMatchOptions::border_cut or without the up direction. `images`: the frame's
// grey images, for the door sides' correlation (StereoMatchOptions::min_side_correlation) and the
// single-view doors; without them both are off.
std::vector<StereoPercept> match_and_triangulate(
    const std::vector<Detection>& left, const std::vector<Detection>& right,
    const head::CameraIntrinsics& left_intrinsics, const head::CameraIntrinsics& right_intrinsics,
    const Eigen::Isometry3d& left_T_right, const StereoMatchOptions& options,
    const Eigen::Vector3d& up_in_left_camera = Eigen::Vector3d::Zero(),
    std::vector<StereoPairTrace>* pair_trace = nullptr, const StereoImages& images = {});

}  // namespace vsl::recognition

// What a class-specific recognizer reports for one blob of one raw camera image.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace vsl::recognition {

// Which image border cuts a detection's outline along a whole side; the last four: two borders,
// meeting at that image corner, cut it along two adjoining sides.
enum class BorderCut {
  kNone,
  kTop,
  kBottom,
  kLeft,
  kRight,
  kTopLeft,
  kTopRight,
  kBottomLeft,
  kBottomRight
};

struct Detection {
  std::string type;     // object type as in the world model: "door", "handle", ...
  int blob_index = -1;  // index into the blobs of the image it was found in
  // The object's reference point in the raw image, pixels (u, v): the blob centroid X_c (doors);
  // for handles the middle of the bar's two ends along the major axis (handle_recognizer.cpp).
  Eigen::Vector2d reference_px = Eigen::Vector2d::Zero();
  // Blob geometry the stereo cross match compares (size, orientation), pixels and radians.
  double area_px = 0.0;
  double major_axis_angle_rad = 0.0;  // angle of the major axis from the +u axis, in [0, pi)
  double major_extent_px = 0.0;       // length of the blob along its major axis
  double minor_extent_px = 0.0;       // and along its minor axis
  // Image length of the object's vertical edges (doors: the outline's sides nearest the image
  // vertical, quadrilateral.hpp), pixels; 0 when the recognizer does not measure it. With the
  // depth, the stereo match turns it into metres (StereoMatchOptions::height_range_m).
  double height_px = 0.0;
  // The corners of the object's outline when it is a rectangle seen as a quadrilateral (doors,
  // quadrilateral.hpp: clockwise from the top left), raw pixels; empty otherwise. The stereo
  // match triangulates the centre of a rectangle from its two vertical sides in both images
  // (StereoMatchOptions), not from the reference point alone.
  std::vector<Eigen::Vector2d> corners_px;
  // Squared Mahalanobis distance of the blob's descriptor to the class model (unitless), and
  // the confidence derived from it: the chi-square survival probability, 0 .. 1.
  double mahalanobis2 = 0.0;
  float confidence = 0.0f;
  // A door whose outline the top or bottom image border cuts along a whole side
  // (DoorRecognizerParameters::detect_border_cut): its corners_px are the outline's with the two
  // on the cut side where the vertical sides leave the image, its height_px is the visible length
  // of the vertical sides, and its reference_px is the middle of the edge it shows whole (the
  // bottom edge for kTop). The stereo match pairs it only with a detection cut along the same
  // border and places its centre from that edge and the class's typical height
  // (StereoMatchOptions::door_classes); its mahalanobis2 is its colour's alone.
  // kLeft and kRight: the left or right border cuts it along a whole side; its
  // corners_px on the cut side are where the top and bottom edges leave the image, its height_px
  // is the length of the vertical side it shows whole and its reference_px that side's middle.
  // The stereo match places it from that side, the edges' level planes and the class's typical
  // width (StereoMatchOptions::DoorClass::typical_width_m).
  // kTopLeft .. kBottomRight: two borders cut it, and the outline's corner at
  // that image corner is the image's; the two corners on the cut sides are where the door's
  // edge and side leave the image, the opposite corner (the one real corner) is its
  // reference_px, and its height_px is the visible length of the side through it. The stereo
  // match pairs it with a detection cut by the top or bottom border alone in the other image
  // (which sees more beyond the left or right border).
  // Handles (HandleRecognizerParameters::detect_border_cut): kTop .. kRight, the
  // border cuts the bar at one end; reference_px and major_extent_px are the visible segment's.
  BorderCut border_cut = BorderCut::kNone;
};

}  // namespace vsl::recognition

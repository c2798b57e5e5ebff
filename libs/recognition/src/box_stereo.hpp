// The learned recognizer's stereo steps (learned_stereo_recognizer.hpp): pairing boxes across the
// images, and finding a region of the left image again in the right one. Internal to
// vsl_recognition.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <vector>

#include "epipolar.hpp"
#include "triangulation.hpp"
#include "vsl/recognition/learned_detector.hpp"
#include "vsl/recognition/learned_stereo_recognizer.hpp"

namespace cv {
class Mat;
}

namespace vsl::recognition::detail {

struct BoxPair {
  int left = -1;
  int right = -1;
};

// Pairs boxes of one class across the images, one to one: a right box is admissible for a left
// box when its centre lies within max_epipolar_distance_px + epipolar_box_fraction * height of
// the left centre's epipolar line, the centres triangulate to a depth in the disparity range, and
// the widths and heights differ by at most max_size_ratio or by at most size_tolerance_px
// pixels. Admissible pairs are taken greedily, the lowest cost first: epipolar distance over box
// height plus the two log size ratios. Boxes within border_margin_px of the border take no part.
// `appearance(l, r)`, when given, is the normalized cross-correlation (-1 .. 1) of the two boxes'
// surroundings at the pair's shift, and adds (1 - it) to the cost: a row of identical handles at
// one height lies along the epipolar line, and only what is around each (a door's edge, the next
// handle) tells them apart.
std::vector<BoxPair> pair_boxes(const std::vector<BoxDetection>& left,
                                const std::vector<BoxDetection>& right,
                                const head::CameraIntrinsics& left_intrinsics,
                                const head::CameraIntrinsics& right_intrinsics,
                                const EpipolarGeometry& epipolar, const Triangulator& triangulator,
                                const BoxStereoOptions& options,
                                const std::function<double(int, int)>& appearance = {});

// Whether a box is at least `margin_px` from every border of a width x height image.
bool inside_image(const BoxDetection& box, int width, int height, double margin_px);

// Which horizontal border of an image `height` pixels high cuts the box (nearer than margin_px):
// 2 the top, 3 the bottom (the sides of DoorFitOptions::free_side), -1 neither, 4 both.
int cut_horizontal_side(const BoxDetection& box, int height, double margin_px);

// Whether a box may be paired: inside the image by border_margin_px, or, for a class placed by
// one horizontal edge (BoxStereoOptions::edge_types), inside it across and cut by one of the top
// and bottom borders.
bool pairable(const BoxDetection& box, int width, int height, const BoxStereoOptions& options);

// Where the left image's region (continuous pixel coordinates, min and max corners) is found in
// the right image: the shift (right minus left, pixels) maximizing the normalized
// cross-correlation, searched within +-search_half_px of predicted_shift_px, to a tenth of a pixel
// by a parabola through the peak and its neighbours. Regions larger than max_template_px pixels
// are correlated at a reduced scale (a whole factor). nullopt when the region or the search window
// leaves an image or the region has no texture.
struct RegionMatch {
  Eigen::Vector2d shift_px = Eigen::Vector2d::Zero();
  double correlation = 0.0;
};
std::optional<RegionMatch> find_in_right_image(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                               const Eigen::Vector2d& min_px,
                                               const Eigen::Vector2d& max_px,
                                               const Eigen::Vector2d& predicted_shift_px,
                                               const Eigen::Vector2d& search_half_px,
                                               double max_template_px);

// The centre, in raw pixel-centre coordinates, of the whole pixels that the region [min_px, max_px]
// (continuous pixels) covers: the point whose epipolar line find_on_epipolar_line takes.
Eigen::Vector2d region_centre_raw(const Eigen::Vector2d& min_px, const Eigen::Vector2d& max_px);

// The epipolar line of a left raw pixel (pixel-centre coordinates) in the right image's raw
// pixels, (a, b, c) with a^2 + b^2 = 1: the ideal image's line (epipolar.hpp) through two of its
// points 40 px apart around the foot of `right_guess_raw`, distorted back into the raw image. A
// lens's distortion bends the line; over a box's search the chord stays within a small fraction
// of a pixel of it. Without distortion, the ideal line itself.
Eigen::Vector3d right_epipolar_line_raw(const EpipolarGeometry& epipolar,
                                        const head::CameraIntrinsics& left_intrinsics,
                                        const head::CameraIntrinsics& right_intrinsics,
                                        const Eigen::Vector2d& left_raw,
                                        const Eigen::Vector2d& right_guess_raw);

// The same match with the epipolar constraint (paper §2.1: a point's match lies on its epipolar
// line): the region's centre (region_centre_raw) is moved onto `right_line_raw`,
// (a, b, c) with a^2 + b^2 = 1, the line a u + b v + c = 0 in the right image's raw pixels, and
// only the shift along it is searched, within +-search_half_u_px of predicted_shift_px's u.
// Why: a bar seen aslant looks the same moved along itself; searched in two dimensions its
// match slides along it, and the part of the slide along the rows is a disparity error (a rail
// across a drawer seen from aside, 1.3 m away: 3-5 px, 20-28 cm along the ray). Only the
// crossing of the bar with the line says where it is. The score along the line is the score
// map sampled bilinearly between its rows, and the peak taken to a tenth of a pixel by a
// parabola; the correlation reported is the better of the two grid placements beside the peak.
// nullopt as find_in_right_image, or when the line is steeper than 45 deg (the cameras are side by
// side).
std::optional<RegionMatch> find_on_epipolar_line(
    const cv::Mat& left_grey, const cv::Mat& right_grey, const Eigen::Vector2d& min_px,
    const Eigen::Vector2d& max_px, const Eigen::Vector2d& predicted_shift_px,
    double search_half_u_px, const Eigen::Vector3d& right_line_raw, double max_template_px);

// The box's sides moved onto the image's outline of the object: each side to the strongest edge
// across it (mean absolute Sobel gradient along the side's middle 60 %) within
// +-max(min_band_px, band_fraction * the box's size across the side), to a tenth of a pixel by a
// parabola; a side stays where it is when that edge is not distinct (below 1.3 times the band's
// median). A detector's boxes are good to a few pixels, the outline to a fraction of one.
// `grey`: the image the box was found in (CV_8UC1).
BoxDetection snap_to_outline(const cv::Mat& grey, const BoxDetection& box, double band_fraction,
                             double min_band_px);

}  // namespace vsl::recognition::detail

// The learned recognizer's stereo frame (StereoRecognizer): the convolutional detector
// (learned_detector.hpp) finds boxes of doors and handles in both raw images; boxes of one class
// are paired across the images by the epipolar constraint, the disparity range and their sizes;
// each pair's disparity is then measured on the pixels, not on the boxes (a box's side is only
// good to a few pixels, a disparity must be good to a fraction of one): the left box's contents
// are found again in the right image by normalized cross-correlation along the epipolar line. A
// door's reference point, the centre of its front face, comes from its outline: each vertical
// side of the box is correlated on its own and the four corners are triangulated at their sides'
// disparities (a door seen at an angle is nearer on one side, and the box's centre is not its
// face's); from there a vertical rectangle is fitted in 3D to the edges both images see along
// its outline, and the door is kept only when all four sides are seen (door_rectangle_fit.hpp).
// A handle's reference point is its bar's middle: a bar is followed from its box to its ends in
// both images (a box may hold only a piece of a long rail), and placed at the middle of its ends,
// each end's disparity from the pixels around it; a knob by its box's. Then, as for the paper's
// recognizer, a 3x3 covariance from the pixel noise and registration into the ego frame through
// the head kinematics at capture time (paper §2.1.1).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vsl/recognition/learned_detector.hpp"
#include "vsl/recognition/stereo_recognizer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

struct BoxStereoOptions {
  // A right box's centre may lie this far from the left box centre's epipolar line, pixels,
  // plus this fraction of the box's height (a box's centre is only as good as its sides).
  double max_epipolar_distance_px = 8.0;
  double epipolar_box_fraction = 0.1;
  double min_depth_m = 0.3;  // disparity range, as depths along the left optical axis
  double max_depth_m = 6.0;
  // Larger over smaller of the two boxes' widths, and of their heights; or, whatever the
  // ratio, a difference of at most size_tolerance_px: the detector's box sides jitter by
  // several pixels from image to image at any size, so on a handle 8 px high a ratio alone
  // refuses the usual jitter (one pair in three on the selection worlds).
  double max_size_ratio = 1.6;
  double size_tolerance_px = 15.0;
  // Boxes nearer than this to the image border are cut by it: their centre is not the object's,
  // and they are not used.
  double border_margin_px = 8.0;
  // Each box side moves onto the strongest image edge within +-max(snap_min_band_px,
  // snap_band_fraction * the box's size) of it, when that edge is distinct (box_stereo.hpp);
  // 0 and 0: boxes as detected.
  double snap_band_fraction = 0.08;
  double snap_min_band_px = 2.0;
  // The correlation (normalized, -1 .. 1) the left box's pixels must reach in the right image.
  double min_correlation = 0.5;
  // Templates larger than this many pixels are correlated at a reduced scale.
  double max_template_px = 3000.0;
  // Per class, the noise model of a percept's position: where the left image places its
  // reference point (sigma of each coordinate, pixels), the disparity the right image gives it
  // (pixels; triangulation.hpp, reference_disparity_covariance), and a floor in every direction
  // that does not shrink with the range (metres: where on the object the reference point is
  // taken). Fitted to simulation's ground truth by vsl-eval-recognition ("noise model of the
  // true positives"). Beside them, the part of the disparity's error that every frame of a scan
  // shares (pixels): the same object seen from one robot pose gives the match the same bias in
  // every frame, so fusion must not average it down (percept_t.shared_ray_sigma_m); it is added
  // to the covariance along the ray. Classes not listed: 1 px, 1 px, no floor, none shared.
  // Of the floor, the part every frame of a scan shares (metres; percept_t.shared_sigma_m): where
  // on the object the reference point falls from one robot pose (a worktop's lip hides a door's
  // top in every frame). The rest is the frame's own (box jitter) and fusion averages it down.
  // Measured by vsl-scan-noise on whole-pipeline scans (docs/fusion.md); unset: all of the floor.
  struct Noise {
    std::string type;
    double reference_px = 1.0;
    double disparity_px = 1.0;
    double floor_m = 0.0;
    double shared_disparity_px = 0.0;
    std::optional<double> shared_floor_m;
    double shared_floor() const { return shared_floor_m.value_or(floor_m); }
  };
  std::vector<Noise> noise{{"door", 0.0, 0.18, 0.022, 0.2, std::nullopt},
                           {"handle", 1.8, 0.10, 0.012, 0.2, std::nullopt}};
  // Classes whose box is a rectangle in 3D with vertical sides (doors): centre from the corners.
  std::vector<std::string> rectangle_types{"door"};
  // Candidate pairs are also scored by how well the boxes' surroundings correlate at the pair's
  // shift (a row of identical handles lies along the epipolar line; box_stereo.hpp).
  bool pair_by_surroundings = true;
  // Rectangles are fitted in 3D to the edges of their outline in both images (a vertical
  // rectangle, door_rectangle_fit.hpp) and kept only when every side is seen; false: the centre
  // is the mean of the corners triangulated at their sides' disparities.
  bool fit_rectangle = true;
  // Rectangle classes a pair may place by one horizontal edge when the images show the sides and
  // that edge but not the other one (the box cut by the image's top or bottom border, or the
  // fit finding no edge there: a worktop's lip, a chair): the fit measures the seen part
  // (DoorFitOptions::free_side) and the percept is the seen edge's middle, of type
  // "<type>_bottom_edge" or "<type>_top_edge" (the world graph's edge nodes,
  // WorldGraphOptions::edge_node_types). The seen part must reach height_range_m's minimum (a
  // drawer front is lower). Needs fit_rectangle; empty: such pairs are not placed.
  std::vector<std::string> edge_types;
  // Each class's reference point lies this far behind where the box's correlation places it,
  // along the viewing ray, metres. A handle's is its bar's axis, 6 mm behind the bar's surface;
  // but the box holds the door behind the bar too, and the correlation lands 8 mm behind the bar
  // (measured against simulation's truth: vsl-eval-recognition's median signed error), hence
  // -2 mm. Classes not listed: 0.
  std::vector<std::pair<std::string, double>> reference_depth_offset_m{{"handle", -0.002}};
  // Optional per class: the physical range of a rectangle's height and width (doors: a drawer
  // front is lower than any door), or of a box's longer side (handles), metres.
  struct Range {
    std::string type;
    double min_m = 0.0;
    double max_m = 0.0;
  };
  std::vector<Range> height_range_m{{"door", 0.5, 2.5}};
  // A rectangle whose height lies in [min_m, max_m] is reported as another type: the detector's
  // one door class holds drawer fronts, which the world model types on their own and which are
  // lower than any door (a room's door 2 m, a wall cupboard's 0.5 m, a drawer front 0.1-0.45 m).
  struct Retype {
    std::string from;
    std::string to;
    double min_m = 0.0;
    double max_m = 0.0;
  };
  std::vector<Retype> retype_by_height_m;  // none by default
  std::vector<Range> width_range_m{{"door", 0.2, 1.4}};
  std::vector<Range> length_range_m{{"handle", 0.02, 0.6}};
  // And of its shorter side: a handle is a bar or a knob, a few centimetres across; a drawer
  // front with its handle, which the detector can box as a handle, is 15 cm or more.
  std::vector<Range> thickness_range_m{{"handle", 0.0, 0.1}};
  // Classes whose box may hold only a piece of a bar: a rail seen at an angle is boxed in pieces,
  // each box's middle 10-50 cm from the bar's. Such a box is followed along its bar to the bar's
  // ends in both images (bar_trace.hpp; the bar's colour standing out from its background by at
  // least bar_min_contrast, L1 over the channels, 0 .. 765), and the pair is placed at the middle
  // of the ends, each end's disparity from the correlation of a patch bar_end_patch_px either side
  // of it, each end triangulated with bar_end_noise (pixels: where the trace puts the end, and the
  // patch's disparity). A box that shows no bar, or whose ends the right image does not show
  // again, is placed by its pixels; a bar cut by the image border or not of length_range_m is not
  // placed. Bars placed within same_bar_m of each other in one frame are one (several boxes
  // along one rail). Empty: every box placed by its pixels.
  std::vector<std::string> bar_types{"handle"};
  double bar_min_contrast = 120.0;
  double bar_end_patch_px = 6.0;
  struct BarEndNoise {
    double reference_px = 2.0;
    double disparity_px = 0.3;
  };
  BarEndNoise bar_end_noise;
  double same_bar_m = 0.05;
};

// Reads a `box_stereo:` section; every key optional and validated (config::Error).
BoxStereoOptions box_stereo_options_from(const config::Node& section);

class LearnedStereoRecognizer final : public StereoRecognizer {
 public:
  LearnedStereoRecognizer(std::shared_ptr<const LearnedDetector> detector, BoxStereoOptions options,
                          head::HeadKinematics head);

  FrameResult recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                        const head::JointState& joints_at_capture) const override;
  const head::HeadKinematics& head() const override { return head_; }
  const BoxStereoOptions& options() const { return options_; }

 private:
  std::shared_ptr<const LearnedDetector> detector_;
  BoxStereoOptions options_;
  head::HeadKinematics head_;
};

}  // namespace vsl::recognition

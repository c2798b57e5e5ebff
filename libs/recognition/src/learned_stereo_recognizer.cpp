#include "vsl/recognition/learned_stereo_recognizer.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "bar_trace.hpp"
#include "box_stereo.hpp"
#include "door_rectangle_fit.hpp"
#include "epipolar.hpp"
#include "frame_capture.hpp"

namespace vsl::recognition {
namespace {

using detail::Clock;
using detail::elapsed_ms;

// Why a bar's ends did not place it when the right image does not show one of them again.
constexpr const char* kEndNotFound = "bar: end not found in the right image";

// A box as the pipeline's Detection (raw pixel-centre coordinates: pixel (u, v)'s centre at
// (u, v), so a box's continuous corners move by half a pixel).
Detection as_detection(const BoxDetection& box) {
  const Eigen::Vector2d half(0.5, 0.5);
  const Eigen::Vector2d lo = box.min_px - half;
  const Eigen::Vector2d hi = box.max_px - half;
  Detection d;
  d.type = box.type;
  d.reference_px = box.centre_px() - half;
  d.area_px = box.width_px() * box.height_px();
  const bool tall = box.height_px() >= box.width_px();
  d.major_axis_angle_rad = tall ? 0.5 * std::numbers::pi : 0.0;
  d.major_extent_px = std::max(box.width_px(), box.height_px());
  d.minor_extent_px = std::min(box.width_px(), box.height_px());
  d.height_px = box.height_px();
  d.corners_px = {lo, Eigen::Vector2d(hi.x(), lo.y()), hi, Eigen::Vector2d(lo.x(), hi.y())};
  d.confidence = box.confidence;
  return d;
}

template <class List>
const BoxStereoOptions::Range* range_of(const List& ranges, const std::string& type) {
  for (const auto& range : ranges) {
    if (range.type == type) return &range;
  }
  return nullptr;
}

bool in_range(const std::vector<BoxStereoOptions::Range>& ranges, const std::string& type,
              double value) {
  const BoxStereoOptions::Range* range = range_of(ranges, type);
  return range == nullptr || (value >= range->min_m && value <= range->max_m);
}

double depth_offset_of(const BoxStereoOptions& options, const std::string& type) {
  for (const auto& [name, offset] : options.reference_depth_offset_m) {
    if (name == type) return offset;
  }
  return 0.0;
}

// The class's noise model (BoxStereoOptions::noise).
BoxStereoOptions::Noise noise_of(const BoxStereoOptions& options, const std::string& type) {
  BoxStereoOptions::Noise noise;
  for (const BoxStereoOptions::Noise& n : options.noise) {
    if (n.type == type) noise = n;
  }
  return noise;
}

// One matched pair of boxes placed in the left camera frame.
struct Placed {
  std::string type;  // the detection's, or what its size retypes it to
  detail::Triangulation triangulation;
  Eigen::Vector2d left_px = Eigen::Vector2d::Zero();
  Eigen::Vector2d right_px = Eigen::Vector2d::Zero();
  bool from_bar = false;  // placed by its bar's ends (BoxStereoOptions::bar_types)
};

class PairPlacer {
 public:
  // `ideal_greys`: both images undistorted (the rectangle fit's pinhole images); `up_in_left`:
  // the world's vertical in the left camera frame.
  PairPlacer(const head::StereoCalibration& calibration, const Eigen::Isometry3d& left_T_right,
             const std::array<cv::Mat, 2>& bgrs, const cv::Mat& left_grey,
             const cv::Mat& right_grey, const std::array<cv::Mat, 2>& ideal_greys,
             const Eigen::Vector3d& up_in_left, const BoxStereoOptions& options)
      : calibration_(calibration),
        triangulator_(calibration.left, calibration.right, left_T_right),
        epipolar_(calibration.left, calibration.right, left_T_right),
        bgrs_(bgrs),
        left_grey_(left_grey),
        right_grey_(right_grey),
        up_in_left_(up_in_left),
        options_(options) {
    fit_cameras_[0] = {&ideal_greys[0], detail::camera_matrix(calibration.left),
                       Eigen::Isometry3d::Identity()};
    fit_cameras_[1] = {&ideal_greys[1], detail::camera_matrix(calibration.right),
                       left_T_right.inverse()};
  }

  const detail::Triangulator& triangulator() const { return triangulator_; }

  // `left_boxes`: every box of the left image (a door's side strips leave out its handle's).
  // `refusal`: why the pair was not placed, when it was not.
  std::optional<Placed> place(const BoxDetection& left, const BoxDetection& right,
                              const std::vector<BoxDetection>& left_boxes,
                              std::string& refusal) const {
    // The box and 2 px around it, within the image (a box cut by the border reaches it).
    const Eigen::Vector2d margin(2.0, 2.0);
    const Eigen::Vector2d image_size(left_grey_.cols, left_grey_.rows);
    const Eigen::Vector2d predicted = right.centre_px() - left.centre_px();
    const double width = std::max(left.width_px(), right.width_px());
    const double search_half_u = 0.2 * width + 4.0;
    const Eigen::Vector2d lo = (left.min_px - margin).cwiseMax(Eigen::Vector2d::Zero());
    const Eigen::Vector2d hi = (left.max_px + margin).cwiseMin(image_size);
    const auto whole = match_on_epipolar_line(lo, hi, predicted, search_half_u);
    if (!whole || whole->correlation < options_.min_correlation) {
      refusal = "correlation";
      return std::nullopt;
    }
    const bool rectangle =
        std::find(options_.rectangle_types.begin(), options_.rectangle_types.end(), left.type) !=
        options_.rectangle_types.end();
    if (rectangle) return place_rectangle(left, whole->shift_px, left_boxes, refusal);
    const bool bar = std::find(options_.bar_types.begin(), options_.bar_types.end(), left.type) !=
                     options_.bar_types.end();
    if (bar) {
      // The box may hold a piece of a bar: placed by the bar's ends, traced in both images. A box
      // that shows no bar (a knob, a bar too faint) is placed by its pixels, and so is a bar whose
      // ends the right image does not show again; a bar cut by the border or longer than any of
      // the class is not placed (the box is a piece of it, and its middle is not the object's).
      const double max_length_px = std::max(left_grey_.cols, left_grey_.rows);
      const auto left_bar =
          detail::trace_bar(bgrs_[0], left, max_length_px, options_.bar_min_contrast);
      const auto right_bar =
          left_bar ? detail::trace_bar(bgrs_[1], right, max_length_px, options_.bar_min_contrast)
                   : std::nullopt;
      if (left_bar && right_bar) {
        if (auto placed = place_bar(left.type, *left_bar, *right_bar, refusal)) return placed;
        if (refusal != kEndNotFound) return std::nullopt;
        refusal.clear();
      }
    }
    return place_point(left, whole->shift_px, refusal);
  }

 private:
  // Raw pixel-centre coordinates of a continuous image point.
  static Eigen::Vector2d raw(const Eigen::Vector2d& continuous_px) {
    return continuous_px - Eigen::Vector2d(0.5, 0.5);
  }

  // The left region [lo, hi] (continuous pixels) found in the right image on the epipolar line of
  // its centre (box_stereo.hpp), within +-search_half_u_px of the predicted shift along it.
  std::optional<detail::RegionMatch> match_on_epipolar_line(const Eigen::Vector2d& lo,
                                                            const Eigen::Vector2d& hi,
                                                            const Eigen::Vector2d& predicted_shift,
                                                            double search_half_u_px) const {
    const Eigen::Vector2d centre = detail::region_centre_raw(lo, hi);
    return detail::find_on_epipolar_line(
        left_grey_, right_grey_, lo, hi, predicted_shift, search_half_u_px,
        detail::right_epipolar_line_raw(epipolar_, calibration_.left, calibration_.right, centre,
                                        centre + predicted_shift),
        options_.max_template_px);
  }

  // A triangulation's covariance from the class's noise model: the pixel pair's through the
  // triangulation, plus the floor in every direction, plus the shared disparity's part along the
  // ray r: its variance there, r^T C_s r with C_s the shared disparity's covariance through the
  // triangulation (nearly all of C_s lies along the ray), added as sigma^2 r r^T.
  std::optional<detail::Triangulation> triangulate_with_noise(const std::string& type,
                                                              const detail::IdealPixel& left,
                                                              const detail::IdealPixel& right,
                                                              double offset_m) const {
    const BoxStereoOptions::Noise noise = noise_of(options_, type);
    auto t = triangulator_.triangulate(
        left, right, detail::reference_disparity_covariance(noise.reference_px, noise.disparity_px),
        offset_m);
    if (t) add_floor_and_shared(type, *t);
    return t;
  }

  // The class's floor in every direction and its shared disparity's part along the ray
  // (ray_sigma_of_disparity: nearly all of a disparity's covariance lies along the ray), added
  // to a placed point's covariance.
  void add_floor_and_shared(const std::string& type, detail::Triangulation& t) const {
    const BoxStereoOptions::Noise noise = noise_of(options_, type);
    t.left_camera_covariance_m2 += noise.floor_m * noise.floor_m * Eigen::Matrix3d::Identity();
    if (noise.shared_disparity_px > 0.0) {
      const Eigen::Vector3d& x = t.left_camera_position_m;
      t.shared_ray_sigma_m = triangulator_.ray_sigma_of_disparity(x, noise.shared_disparity_px);
      const Eigen::Vector3d r = x.normalized();
      t.left_camera_covariance_m2 +=
          t.shared_ray_sigma_m * t.shared_ray_sigma_m * r * r.transpose();
    }
  }

  // A left camera point's ideal pixel in camera k (0 left, 1 right).
  Eigen::Vector2d ideal_projection(int k, const Eigen::Vector3d& left_point_m) const {
    const detail::FitCamera& camera = fit_cameras_[static_cast<std::size_t>(k)];
    return (camera.K * (camera.camera_T_left * left_point_m)).hnormalized();
  }

  std::optional<detail::Triangulation> triangulate(const std::string& type,
                                                   const Eigen::Vector2d& left_raw,
                                                   const Eigen::Vector2d& right_raw,
                                                   double offset_m) const {
    return triangulate_with_noise(type, detail::undistort({left_raw}, calibration_.left).front(),
                                  detail::undistort({right_raw}, calibration_.right).front(),
                                  offset_m);
  }

  std::optional<Placed> place_point(const BoxDetection& box, const Eigen::Vector2d& shift,
                                    std::string& refusal) const {
    Placed placed;
    placed.type = box.type;
    placed.left_px = raw(box.centre_px());
    placed.right_px = placed.left_px + shift;
    const auto t =
        triangulate(box.type, placed.left_px, placed.right_px, depth_offset_of(options_, box.type));
    const double depth = t ? t->left_camera_position_m.z() : 0.0;
    if (!t || depth < options_.min_depth_m || depth > options_.max_depth_m) {
      refusal = "depth";
      return std::nullopt;
    }
    const double length_m =
        std::max(box.width_px(), box.height_px()) * depth / calibration_.left.fx_px;
    if (!in_range(options_.length_range_m, box.type, length_m)) {
      refusal = "length";
      return std::nullopt;
    }
    const double thickness_m =
        std::min(box.width_px(), box.height_px()) * depth / calibration_.left.fx_px;
    if (!in_range(options_.thickness_range_m, box.type, thickness_m)) {
      refusal = "thickness";
      return std::nullopt;
    }
    placed.triangulation = *t;
    return placed;
  }

  // A bar placed at the middle of its ends. Each end's disparity is measured by correlating the
  // patch around it (the end and the background beyond it: a point both images agree on, unlike
  // any point along the bar) within a few pixels of where the right image's trace puts it; each
  // end triangulated with the covariance of BoxStereoOptions::bar_end_noise, and the middle's is
  // the mean's, (C_0 + C_1) / 4, plus the class's floor and shared part. Refused when the border
  // cuts an end in either image, an end's patch is not found again (kEndNotFound), or the bar is
  // not of the class's length.
  std::optional<Placed> place_bar(const std::string& type, const detail::TracedBar& left_bar,
                                  detail::TracedBar right_bar, std::string& refusal) const {
    if (left_bar.cut[0] || left_bar.cut[1] || right_bar.cut[0] || right_bar.cut[1]) {
      refusal = "bar: cut";
      return std::nullopt;
    }
    if ((right_bar.ends_px[1] - right_bar.ends_px[0])
            .dot(left_bar.ends_px[1] - left_bar.ends_px[0]) < 0.0) {
      std::swap(right_bar.ends_px[0], right_bar.ends_px[1]);
    }
    const double half = options_.bar_end_patch_px;  // half the patch's side
    std::array<detail::Triangulation, 2> ends;
    const Eigen::Matrix4d end_covariance = detail::reference_disparity_covariance(
        options_.bar_end_noise.reference_px, options_.bar_end_noise.disparity_px);
    for (std::size_t e = 0; e < 2; ++e) {
      const Eigen::Vector2d& at = left_bar.ends_px[e];
      const auto match =
          match_on_epipolar_line(at - Eigen::Vector2d(half, half), at + Eigen::Vector2d(half, half),
                                 right_bar.ends_px[e] - at, 3.0);
      if (!match || match->correlation < options_.min_correlation) {
        refusal = kEndNotFound;
        return std::nullopt;
      }
      const auto l = detail::undistort({raw(at)}, calibration_.left);
      const auto r = detail::undistort({raw(at + match->shift_px)}, calibration_.right);
      const auto end = triangulator_.triangulate(l.front(), r.front(), end_covariance, 0.0);
      if (!end) {
        refusal = "depth";
        return std::nullopt;
      }
      ends[e] = *end;
    }
    // The middle of the ends, with the covariance of the mean of two independent points.
    detail::Triangulation t;
    t.left_camera_position_m =
        0.5 * (ends[0].left_camera_position_m + ends[1].left_camera_position_m);
    t.left_camera_covariance_m2 =
        0.25 * (ends[0].left_camera_covariance_m2 + ends[1].left_camera_covariance_m2);
    add_floor_and_shared(type, t);
    const Eigen::Vector3d& centre = t.left_camera_position_m;
    if (centre.z() < options_.min_depth_m || centre.z() > options_.max_depth_m) {
      refusal = "depth";
      return std::nullopt;
    }
    if (!in_range(options_.length_range_m, type,
                  (ends[1].left_camera_position_m - ends[0].left_camera_position_m).norm())) {
      refusal = "bar: length";
      return std::nullopt;
    }
    Placed placed;
    placed.type = type;
    placed.from_bar = true;
    placed.triangulation = t;
    placed.left_px = raw(0.5 * (left_bar.ends_px[0] + left_bar.ends_px[1]));
    placed.right_px = raw(0.5 * (right_bar.ends_px[0] + right_bar.ends_px[1]));
    return placed;
  }

  // The shift of the strip [from_u, to_u] of a rectangle's box: its rows between a tenth of the
  // box's height from the top and from the bottom, less those that other classes' boxes cross
  // (3 px around them), of which the longest run is correlated near the whole box's shift; the
  // whole box's shift when that run is under 30 % of the rows or does not correlate.
  Eigen::Vector2d side_shift(const BoxDetection& box, const Eigen::Vector2d& whole_shift,
                             const std::vector<BoxDetection>& left_boxes, double from_u,
                             double to_u) const {
    const double top = box.min_px.y() + 0.1 * box.height_px();
    const double bottom = box.max_px.y() - 0.1 * box.height_px();
    std::vector<std::pair<double, double>> clear{{top, bottom}};
    for (const BoxDetection& other : left_boxes) {
      if (other.type == box.type || other.max_px.x() < from_u || other.min_px.x() > to_u) continue;
      std::vector<std::pair<double, double>> next;
      for (const auto& [a, b] : clear) {
        const double cut_from = other.min_px.y() - 3.0;
        const double cut_to = other.max_px.y() + 3.0;
        if (cut_to <= a || cut_from >= b) {
          next.emplace_back(a, b);
          continue;
        }
        if (cut_from > a) next.emplace_back(a, cut_from);
        if (cut_to < b) next.emplace_back(cut_to, b);
      }
      clear = std::move(next);
    }
    const auto longest = std::max_element(
        clear.begin(), clear.end(),
        [](const auto& x, const auto& y) { return x.second - x.first < y.second - y.first; });
    if (longest == clear.end() || longest->second - longest->first < 0.3 * (bottom - top)) {
      return whole_shift;
    }
    const Eigen::Vector2d search(2.0 + 0.03 * box.width_px(), 1.5);
    const auto m = detail::find_in_right_image(
        left_grey_, right_grey_, Eigen::Vector2d(from_u, longest->first),
        Eigen::Vector2d(to_u, longest->second), whole_shift, search, options_.max_template_px);
    return m && m->correlation >= options_.min_correlation ? m->shift_px : whole_shift;
  }

  // A door's front face: each vertical side's strip of the box correlated on its own (near the
  // whole box's shift), the four corners triangulated at their side's shift, the centre the
  // corners' mean (for a rectangle, exactly its centre), height and width the sides' mean length
  // and the distance between the sides' middles.
  // A handle stands off the door by a few centimetres: inside a side's strip its texture, at
  // its own disparity, would pull the side's. The strip keeps the longest run of rows clear of
  // the other classes' boxes across it (at least 30 % of the strip, else the whole box's shift).
  std::optional<Placed> place_rectangle(const BoxDetection& box, const Eigen::Vector2d& whole_shift,
                                        const std::vector<BoxDetection>& left_boxes,
                                        std::string& refusal) const {
    const double strip = std::max(8.0, 0.15 * box.width_px());
    const std::array<Eigen::Vector2d, 2> shifts{
        side_shift(box, whole_shift, left_boxes, box.min_px.x() - 4.0, box.min_px.x() + strip),
        side_shift(box, whole_shift, left_boxes, box.max_px.x() - strip, box.max_px.x() + 4.0)};
    // Corners: top left, bottom left (left side), top right, bottom right (right side).
    const std::array<Eigen::Vector2d, 4> corners{
        raw(box.min_px), raw(Eigen::Vector2d(box.min_px.x(), box.max_px.y())),
        raw(Eigen::Vector2d(box.max_px.x(), box.min_px.y())), raw(box.max_px)};
    std::array<Eigen::Vector3d, 4> ends;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d& shift = shifts[static_cast<std::size_t>(k / 2)];
      const auto left_ideal =
          detail::undistort({corners[static_cast<std::size_t>(k)]}, calibration_.left);
      const auto right_ideal =
          detail::undistort({corners[static_cast<std::size_t>(k)] + shift}, calibration_.right);
      const auto point =
          triangulator_.point(left_ideal.front().ideal_px, right_ideal.front().ideal_px);
      if (!point) {
        refusal = "depth";
        return std::nullopt;
      }
      ends[static_cast<std::size_t>(k)] = *point;
    }
    Eigen::Vector3d centre = 0.25 * (ends[0] + ends[1] + ends[2] + ends[3]);
    double height = 0.5 * ((ends[0] - ends[1]).norm() + (ends[2] - ends[3]).norm());
    double width = (0.5 * (ends[0] + ends[1]) - 0.5 * (ends[2] + ends[3])).norm();
    int free_side = -1;
    if (options_.fit_rectangle) {
      const auto fit = fit_rectangle(box, detail::rectangle_from_ends(ends, up_in_left_), refusal);
      if (!fit) return std::nullopt;
      free_side = fit->free_side;
      // With a free side, the point the fit determines is the seen edge's middle.
      const double to_edge = free_side == 2 ? -0.5 : free_side == 3 ? 0.5 : 0.0;
      centre = fit->rectangle.centre_m + to_edge * fit->rectangle.height_m * up_in_left_;
      height = fit->rectangle.height_m;
      width = fit->rectangle.width_m;
    }
    std::string type = box.type;
    if (free_side == 2) type += "_bottom_edge";  // world::edge_node_type's names
    if (free_side == 3) type += "_top_edge";
    for (const BoxStereoOptions::Retype& rule : options_.retype_by_height_m) {
      if (free_side < 0 && rule.from == box.type && height >= rule.min_m && height <= rule.max_m)
        type = rule.to;
    }
    if (centre.z() < options_.min_depth_m || centre.z() > options_.max_depth_m) {
      refusal = "depth";
      return std::nullopt;
    }
    // Of a rectangle seen by one edge, only the part the images show: at least the class's least.
    const BoxStereoOptions::Range* heights = range_of(options_.height_range_m, box.type);
    const bool height_ok = free_side >= 0 ? heights == nullptr || height >= heights->min_m
                                          : in_range(options_.height_range_m, box.type, height);
    if ((type == box.type || free_side >= 0) && !height_ok) {
      refusal = free_side >= 0 ? "edge: height" : "height";
      return std::nullopt;
    }
    if (!in_range(options_.width_range_m, box.type, width)) {
      refusal = "width";
      return std::nullopt;
    }
    Placed placed;
    placed.type = type;
    placed.left_px = raw(box.centre_px());
    placed.right_px = placed.left_px + 0.5 * (shifts[0] + shifts[1]);
    // The position: the fit's centre, or the corners'. The covariance: the class's noise model
    // at the centre's projections into both images.
    const auto t = triangulate_with_noise(box.type, detail::IdealPixel{ideal_projection(0, centre)},
                                          detail::IdealPixel{ideal_projection(1, centre)}, 0.0);
    if (!t) {
      refusal = "depth";
      return std::nullopt;
    }
    placed.triangulation = *t;
    const double offset = depth_offset_of(options_, box.type);
    placed.triangulation.left_camera_position_m = centre + offset * centre.normalized();
    return placed;
  }

  // The rectangle fitted to the outline's edges in both images (door_rectangle_fit.hpp), from
  // the box's corners. For a class placed by one edge (BoxStereoOptions::edge_types), a box cut
  // by the top or bottom border, or a fit that finds no edge along its top or bottom, is fitted
  // again with that side free: the seen part, measured by its sides and its other edge.
  struct RectangleFit {
    detail::DoorRectangle rectangle;
    int free_side = -1;  // DoorFitOptions::free_side
  };
  std::optional<RectangleFit> fit_rectangle(const BoxDetection& box,
                                            const detail::DoorRectangle& initial,
                                            std::string& refusal) const {
    const bool by_edge = std::find(options_.edge_types.begin(), options_.edge_types.end(),
                                   box.type) != options_.edge_types.end();
    detail::DoorFitOptions fit_options;
    if (by_edge) {
      const int cut = detail::cut_horizontal_side(box, left_grey_.rows, options_.border_margin_px);
      fit_options.free_side = cut == 2 || cut == 3 ? cut : -1;
    }
    auto fit = detail::fit_door_rectangle(initial, up_in_left_, fit_cameras_, fit_options);
    if (by_edge && fit_options.free_side < 0 && fit && !fit->accepted) {
      if (fit->refused_side == 2 || fit->refused_side == 3) {
        fit_options.free_side = fit->refused_side;
        fit = detail::fit_door_rectangle(initial, up_in_left_, fit_cameras_, fit_options);
      }
    }
    if (!fit || !fit->accepted) {
      refusal = std::string(fit_options.free_side >= 0 ? "edge fit: " : "fit: ") +
                (fit ? fit->refusal : std::string("degenerate"));
      return std::nullopt;
    }
    return RectangleFit{fit->rectangle, fit_options.free_side};
  }

  const head::StereoCalibration& calibration_;
  detail::Triangulator triangulator_;
  detail::EpipolarGeometry epipolar_;
  const std::array<cv::Mat, 2>& bgrs_;
  const cv::Mat& left_grey_;
  const cv::Mat& right_grey_;
  Eigen::Vector3d up_in_left_;
  std::array<detail::FitCamera, 2> fit_cameras_;
  const BoxStereoOptions& options_;
};

bool distorted(const head::CameraIntrinsics& intrinsics) {
  return std::any_of(intrinsics.distortion.begin(), intrinsics.distortion.end(),
                     [](double d) { return d != 0.0; });
}

// The image undistorted into the ideal pinhole image of the same K (the image itself when the
// camera has no distortion).
cv::Mat ideal_image(const cv::Mat& grey, const head::CameraIntrinsics& intrinsics) {
  if (!distorted(intrinsics)) return grey;
  const cv::Matx33d K(intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, intrinsics.fy_px,
                      intrinsics.cy_px, 0.0, 0.0, 1.0);
  cv::Mat ideal;
  cv::undistort(grey, ideal, K,
                std::vector<double>(intrinsics.distortion.begin(), intrinsics.distortion.end()));
  return ideal;
}

// The correlation of a left box's surroundings (the box grown by its larger side, at least 16
// px, each way) with the right image's at the pair's shift (within 3 x 2 px), -1 when they leave
// the images or have no texture.
double surroundings_correlation(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                const BoxDetection& a, const BoxDetection& b,
                                double max_template_px) {
  const double grow = std::max({a.width_px(), a.height_px(), 16.0});
  const Eigen::Vector2d margin(grow, grow);
  const Eigen::Vector2d image(left_grey.cols, left_grey.rows);
  const Eigen::Vector2d lo = (a.min_px - margin).cwiseMax(Eigen::Vector2d::Zero());
  const Eigen::Vector2d hi = (a.max_px + margin).cwiseMin(image);
  const auto match =
      detail::find_in_right_image(left_grey, right_grey, lo, hi, b.centre_px() - a.centre_px(),
                                  Eigen::Vector2d(3.0, 2.0), max_template_px);
  return match ? match->correlation : -1.0;
}

}  // namespace

LearnedStereoRecognizer::LearnedStereoRecognizer(std::shared_ptr<const LearnedDetector> detector,
                                                 BoxStereoOptions options,
                                                 head::HeadKinematics head)
    : detector_(std::move(detector)), options_(std::move(options)), head_(std::move(head)) {
  if (!detector_) throw std::invalid_argument("LearnedStereoRecognizer: no detector");
}

FrameResult LearnedStereoRecognizer::recognize(const cv::Mat& left_bgr, const cv::Mat& right_bgr,
                                               const head::JointState& joints_at_capture) const {
  const head::StereoCalibration& calibration = head_.calibration();
  const detail::CaptureGeometry capture = detail::check_and_place_cameras(
      "LearnedStereoRecognizer::recognize", left_bgr, right_bgr, head_, joints_at_capture);
  FrameResult result;
  result.ego_T_left_camera = capture.ego_T_left_camera;
  const Eigen::Isometry3d& left_T_right = capture.left_T_right;

  const Clock::time_point start = Clock::now();
  std::vector<BoxDetection> left_boxes = detector_->detect(left_bgr);
  std::vector<BoxDetection> right_boxes = detector_->detect(right_bgr);
  const Clock::time_point detected = Clock::now();

  cv::Mat left_grey, right_grey;
  cv::cvtColor(left_bgr, left_grey, cv::COLOR_BGR2GRAY);
  cv::cvtColor(right_bgr, right_grey, cv::COLOR_BGR2GRAY);
  if (options_.snap_band_fraction > 0.0 || options_.snap_min_band_px > 0.0) {
    for (BoxDetection& box : left_boxes) {
      box = detail::snap_to_outline(left_grey, box, options_.snap_band_fraction,
                                    options_.snap_min_band_px);
    }
    for (BoxDetection& box : right_boxes) {
      box = detail::snap_to_outline(right_grey, box, options_.snap_band_fraction,
                                    options_.snap_min_band_px);
    }
  }
  for (const BoxDetection& box : left_boxes) result.left_detections.push_back(as_detection(box));
  for (const BoxDetection& box : right_boxes) result.right_detections.push_back(as_detection(box));
  // Undistorted only for the rectangle fit, which projects through a pinhole.
  std::array<cv::Mat, 2> ideal_greys{left_grey, right_grey};
  if (options_.fit_rectangle) {
    ideal_greys = {ideal_image(left_grey, calibration.left),
                   ideal_image(right_grey, calibration.right)};
  }
  // The ego frame's z axis is the world's vertical (the robot stands on a level floor).
  const Eigen::Vector3d up_in_left =
      result.ego_T_left_camera.linear().transpose() * Eigen::Vector3d::UnitZ();
  const std::array<cv::Mat, 2> bgrs{left_bgr, right_bgr};
  const PairPlacer placer(calibration, left_T_right, bgrs, left_grey, right_grey, ideal_greys,
                          up_in_left, options_);
  const detail::EpipolarGeometry epipolar(calibration.left, calibration.right, left_T_right);
  const auto surroundings = [&](int l, int r) {
    return surroundings_correlation(left_grey, right_grey, left_boxes[static_cast<std::size_t>(l)],
                                    right_boxes[static_cast<std::size_t>(r)],
                                    options_.max_template_px);
  };
  const std::vector<detail::BoxPair> pairs = detail::pair_boxes(
      left_boxes, right_boxes, calibration.left, calibration.right, epipolar, placer.triangulator(),
      options_,
      options_.pair_by_surroundings ? std::function<double(int, int)>(surroundings)
                                    : std::function<double(int, int)>());
  // Registration into ego: p_ego = ego_T_left p_left, Sigma_ego = R Sigma_left R^T.
  const Eigen::Matrix3d ego_R_left = result.ego_T_left_camera.linear();
  // Boxes around pieces of one bar place it once each: the bar is kept once.
  std::vector<Eigen::Vector3d> bars_placed;
  for (const detail::BoxPair& pair : pairs) {
    const BoxDetection& left = left_boxes[static_cast<std::size_t>(pair.left)];
    const BoxDetection& right = right_boxes[static_cast<std::size_t>(pair.right)];
    std::string refusal;
    const std::optional<Placed> placed = placer.place(left, right, left_boxes, refusal);
    if (!placed) {
      result.stereo_refusals.push_back({pair.left, pair.right, std::move(refusal)});
      continue;
    }
    if (placed->from_bar) {
      const Eigen::Vector3d& at = placed->triangulation.left_camera_position_m;
      if (std::any_of(bars_placed.begin(), bars_placed.end(), [&](const Eigen::Vector3d& other) {
            return (other - at).norm() < options_.same_bar_m;
          })) {
        result.stereo_refusals.push_back({pair.left, pair.right, "bar: placed already"});
        continue;
      }
      bars_placed.push_back(at);
    }
    FramePercept p;
    p.type = placed->type;
    p.ego_position_m = result.ego_T_left_camera * placed->triangulation.left_camera_position_m;
    p.ego_covariance_m2 =
        ego_R_left * placed->triangulation.left_camera_covariance_m2 * ego_R_left.transpose();
    // The floor's shared part is where on the object the reference point falls from this robot
    // pose: the same in every frame of a scan (percept_t.shared_sigma_m).
    p.shared_sigma_m = noise_of(options_, left.type).shared_floor();
    p.shared_ray_sigma_m = placed->triangulation.shared_ray_sigma_m;
    p.left_px = placed->left_px;
    p.right_px = placed->right_px;
    p.confidence = std::sqrt(left.confidence * right.confidence);
    p.left_detection = pair.left;
    p.right_detection = pair.right;
    result.percepts.push_back(std::move(p));
  }
  result.classification_ms = elapsed_ms(start, detected);
  result.stereo_ms = elapsed_ms(detected, Clock::now());
  return result;
}

}  // namespace vsl::recognition

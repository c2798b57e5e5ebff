// Left-right cross match and triangulation (paper §2.1): the gates of each pair, in order. The
// door outlines' own gates and centre: door_pair.hpp; doors cut by the image border:
// border_cut.hpp; doors from one image: single_view.hpp. Geometry: epipolar.hpp (gate) and
// triangulation.hpp (point and covariance); the one-to-one assignment: stereo_assignment.hpp.
#include "vsl/recognition/stereo_match.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "bars_on_outline.hpp"
#include "border_cut.hpp"
#include "convex_polygon.hpp"
#include "corner_cut_door.hpp"
#include "cut_bar.hpp"
#include "door_pair.hpp"
#include "epipolar.hpp"
#include "occluded_corner_door.hpp"
#include "occluder_cut_door.hpp"
#include "one_side_door.hpp"
#include "pair_refusal.hpp"
#include "side_correlation.hpp"
#include "side_cut_door.hpp"
#include "single_view.hpp"
#include "stereo_assignment.hpp"
#include "triangulation.hpp"

namespace vsl::recognition {
namespace {

// Added to each bar's mean width (pixels) before their ratio is compared: the quantization of a
// thin bar's two edges.
constexpr double kBarWidthQuantizationPx = 1.0;

// Undistorted corners of a detection's outline (empty unless it has four).
std::vector<detail::IdealPixel> undistorted_corners(const Detection& d,
                                                    const head::CameraIntrinsics& intrinsics) {
  if (d.corners_px.size() != 4) return {};
  return detail::undistort(d.corners_px, intrinsics);
}

// The two ends of a bar detection's segment (raw pixels): its reference point (the middle of the
// bar's ends along the major axis, handle_recognizer.cpp) plus and minus half the major extent.
std::vector<Eigen::Vector2d> bar_ends_raw(const Detection& d) {
  const Eigen::Vector2d half =
      0.5 * d.major_extent_px *
      Eigen::Vector2d(std::cos(d.major_axis_angle_rad), std::sin(d.major_axis_angle_rad));
  return {d.reference_px - half, d.reference_px + half};
}

// Orientation difference of two undirected axes (angles in [0, pi)), in [0, pi / 2].
double axis_difference_rad(double a, double b) {
  const double d = std::fmod(std::abs(a - b), M_PI);
  return std::min(d, M_PI - d);
}

// Major over minor extent; 1 (not elongated) when the recognizer gave no extents.
double elongation(const Detection& d) {
  if (!(d.major_extent_px > 0.0)) return 1.0;
  return d.minor_extent_px > 0.0 ? d.major_extent_px / d.minor_extent_px
                                 : std::numeric_limits<double>::infinity();
}

double reference_depth_offset(const StereoMatchOptions& options, const std::string& type) {
  for (const auto& [name, offset] : options.reference_depth_offset_m) {
    if (name == type) return offset;
  }
  return 0.0;
}

const StereoMatchOptions::ExtentRange* extent_range(const StereoMatchOptions& options,
                                                    const std::string& type) {
  for (const StereoMatchOptions::ExtentRange& range : options.major_extent_range_m) {
    if (range.type == type) return &range;
  }
  return nullptr;
}

const StereoMatchOptions::BorderCutDoor* border_cut_door(const StereoMatchOptions& options,
                                                         const std::string& type) {
  for (const StereoMatchOptions::BorderCutDoor& height : options.border_cut) {
    if (height.type == type) return &height;
  }
  return nullptr;
}

// The class's greatest width, metres (its border_cut entry's max_width_m); 0 when not configured.
double class_max_width_m(const StereoMatchOptions& options, const std::string& type) {
  const StereoMatchOptions::BorderCutDoor* door = border_cut_door(options, type);
  return door ? door->max_width_m : 0.0;
}

const StereoMatchOptions::CutBar* cut_bar_of(const StereoMatchOptions& options,
                                             const std::string& type) {
  for (const StereoMatchOptions::CutBar& bar : options.cut_bars) {
    if (bar.type == type) return &bar;
  }
  return nullptr;
}

const StereoMatchOptions::ExtentRange* height_range(const StereoMatchOptions& options,
                                                    const std::string& type) {
  for (const StereoMatchOptions::ExtentRange& range : options.height_range_m) {
    if (range.type == type) return &range;
  }
  return nullptr;
}

}  // namespace

std::vector<StereoPercept> match_and_triangulate(
    const std::vector<Detection>& left, const std::vector<Detection>& right,
    const head::CameraIntrinsics& left_intrinsics, const head::CameraIntrinsics& right_intrinsics,
    const Eigen::Isometry3d& left_T_right, const StereoMatchOptions& options,
    const Eigen::Vector3d& up_in_left_camera, std::vector<StereoPairTrace>* pair_trace,
    const StereoImages& images) {
  if (pair_trace) pair_trace->clear();
  const bool single_view = options.min_single_view_correlation > 0.0;
  if ((left.empty() || right.empty()) && !single_view) return {};
  if (left.empty() && right.empty()) return {};
  std::vector<Eigen::Vector2d> left_raw, right_raw;
  left_raw.reserve(left.size());
  right_raw.reserve(right.size());
  for (const Detection& d : left) left_raw.push_back(d.reference_px);
  for (const Detection& d : right) right_raw.push_back(d.reference_px);
  const std::vector<detail::IdealPixel> left_ideal = detail::undistort(left_raw, left_intrinsics);
  const std::vector<detail::IdealPixel> right_ideal =
      detail::undistort(right_raw, right_intrinsics);
  const detail::EpipolarGeometry epipolar(left_intrinsics, right_intrinsics, left_T_right);
  const detail::Triangulator triangulator(left_intrinsics, right_intrinsics, left_T_right);
  std::optional<detail::SideCorrelator> correlator, reverse_correlator;
  if (options.min_side_correlation > 0.0 && images.left_grey && images.right_grey &&
      up_in_left_camera.norm() > 0.0) {
    correlator.emplace(*images.left_grey, *images.right_grey, left_intrinsics, right_intrinsics,
                       left_T_right, up_in_left_camera);
    reverse_correlator.emplace(*images.right_grey, *images.left_grey, right_intrinsics,
                               left_intrinsics, left_T_right.inverse(),
                               left_T_right.linear().transpose() * up_in_left_camera);
  }
  std::vector<std::vector<detail::IdealPixel>> left_corners, right_corners;
  for (const Detection& d : left) left_corners.push_back(undistorted_corners(d, left_intrinsics));
  for (const Detection& d : right) {
    right_corners.push_back(undistorted_corners(d, right_intrinsics));
  }
  // Undistorted ends of the bar-type detections (empty for the others).
  const auto bar_ends = [&](const std::vector<Detection>& detections,
                            const head::CameraIntrinsics& intrinsics) {
    std::vector<std::vector<detail::IdealPixel>> out(detections.size());
    for (std::size_t i = 0; i < detections.size(); ++i) {
      const Detection& d = detections[i];
      if (d.corners_px.empty() && d.major_extent_px > 0.0 && detail::is_bar_type(options, d.type)) {
        out[i] = detail::undistort(bar_ends_raw(d), intrinsics);
      }
    }
    return out;
  };
  const std::vector<std::vector<detail::IdealPixel>> left_bar_ends =
      bar_ends(left, left_intrinsics);
  const std::vector<std::vector<detail::IdealPixel>> right_bar_ends =
      bar_ends(right, right_intrinsics);
  const auto corner_array = [](const std::vector<detail::IdealPixel>& corners) {
    std::array<Eigen::Vector2d, 4> out;
    for (int k = 0; k < 4; ++k) out[k] = corners[k].ideal_px;
    return out;
  };

  // The worse of the two outlines' verdicts on the handles they hold (bars_on_outline.hpp).
  const auto judge_bars = [&](const Detection& dl, const Detection& dr, int max_bars_inside) {
    const detail::BarVerdict on_left =
        detail::judge_bars_on_outline(left, dl, max_bars_inside, options);
    return on_left.gate != StereoGate::kNone
               ? on_left
               : detail::judge_bars_on_outline(right, dr, max_bars_inside, options);
  };
  const double log_max_area_ratio = std::log(std::max(options.max_area_ratio, 1.0 + 1e-9));
  // Two views of a bar that the image border cuts at one end in one or both (cut_bar.hpp): the
  // class's typical length, and the border when it cuts both.
  struct CutBarViews {
    const StereoMatchOptions::CutBar* bar = nullptr;
    BorderCut both = BorderCut::kNone;
  };
  // Judges one pair against every gate, in order; a pair that passes all of them is a candidate
  // with its triangulation. Triangulating here rather than after the assignment means that a
  // pair which cannot be triangulated is never assigned, and its detections stay free for other
  // pairs.
  const auto judge = [&](int l, int r, StereoPairTrace& trace,
                         const CutBarViews* cut_bar = nullptr) -> std::optional<detail::Candidate> {
    const Detection& dl = left[l];
    const Detection& dr = right[r];
    // Hysteresis: a blob the class model rates just beyond its threshold in one image counts
    // when the other image shows it clearly; two weak views are not evidence enough.
    if (dl.needs_partner && dr.needs_partner)
      return detail::refuse(trace, StereoGate::kWeakPair, 0.0, 0.0);
    // Position: the right reference point on (near) the left one's epipolar line. For two
    // rectangle outlines, their vertical sides nest along the epipolar direction
    // (rectangle_containment_excess_px), to kRectangleEpipolarFraction of the height.
    const bool rectangles = !left_corners[l].empty() && !right_corners[r].empty();
    // A stack of drawer fronts merged into one door-shaped blob carries a handle per front, one
    // above another; judged on each image's outline, also when the other image's blob has none.
    if (const detail::BarVerdict bars = judge_bars(
            dl, dr, options.pair_max_bars_inside > 0 ? options.pair_max_bars_inside : -1);
        bars.gate != StereoGate::kNone) {
      return detail::refuse(trace, bars.gate, bars.value, bars.limit);
    }
    // Two views of a bar across the epipolar lines (StereoMatchOptions::bar_types): its span in
    // 3D, and the position gate as the containment of the shorter segment in the longer.
    std::optional<detail::Triangulator::BarSpan> bar;
    if (!left_bar_ends[l].empty() && !right_bar_ends[r].empty() &&
        elongation(dl) >= options.min_elongation_for_orientation &&
        elongation(dr) >= options.min_elongation_for_orientation) {
      const Eigen::Vector2d a = right_bar_ends[r][0].ideal_px, b = right_bar_ends[r][1].ideal_px;
      const Eigen::Vector3d line = epipolar.right_line(left_ideal[l].ideal_px);  // a^2+b^2 = 1
      const double length = (b - a).norm();
      // |cos| of the angle between the bar and the line's normal: sin of the angle to the line.
      if (length > 0.0 && std::abs((b - a).dot(line.head<2>())) >= std::sqrt(0.5) * length) {
        bar = triangulator.bar_span({left_bar_ends[l][0].ideal_px, left_bar_ends[l][1].ideal_px},
                                    {a, b}, up_in_left_camera);
        if (!bar) return detail::refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
      }
    }
    // A cut view's reference point is the middle of what it shows, another point of the bar in
    // each image: a cut bar is placed only from its span, across the epipolar lines.
    if (cut_bar && !bar) return detail::refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
    const double mean_f_px = 0.5 * (left_intrinsics.fx_px + right_intrinsics.fx_px);
    double epipolar_px =
        bar ? bar->containment_excess_px
            : epipolar.distance_px(left_ideal[l].ideal_px, right_ideal[r].ideal_px);
    if (rectangles) {
      epipolar_px =
          detail::rectangle_containment_excess_px(left_corners[l], right_corners[r], epipolar);
    }
    const double max_epipolar_px =
        rectangles ? std::max(options.max_epipolar_distance_px,
                              kRectangleEpipolarFraction * 0.5 * (dl.height_px + dr.height_px))
                   : options.max_epipolar_distance_px;
    // Two door outlines that the position or the side gate refuses may show a door with one
    // corner hidden by an occluder in both images (occluded_corner_door.hpp).
    std::optional<detail::OccludedCornerDoor> occluded;
    const auto place_occluded_corner = [&]() {
      const StereoMatchOptions::BorderCutDoor* door = border_cut_door(options, dl.type);
      if (!rectangles || !door || !door->occluded_corner || !(up_in_left_camera.norm() > 0.0) ||
          judge_bars(dl, dr, options.single_view_max_bars_inside).gate != StereoGate::kNone) {
        return false;
      }
      occluded = detail::place_occluded_corner_door(
          {corner_array(left_corners[l]), corner_array(right_corners[r])}, triangulator,
          up_in_left_camera.normalized(), options.max_side_tilt_rad,
          options.max_epipolar_distance_px, *door, height_range(options, dl.type));
      if (!occluded) return false;
      trace.refused_by = StereoGate::kNone;
      trace.value = trace.limit = 0.0;
      trace.occluded_corner = true;
      epipolar_px = occluded->residual_px;
      return true;
    };
    if (!(epipolar_px <= max_epipolar_px)) {
      detail::refuse(trace, StereoGate::kEpipolar, epipolar_px, max_epipolar_px);
      if (!place_occluded_corner()) return std::nullopt;
    }
    // The side gate of two door outlines (door_pair.hpp).
    std::optional<detail::DoorSides> sides;
    if (rectangles && !occluded) {
      sides = detail::judge_door_sides(
          {corner_array(left_corners[l]), corner_array(right_corners[r])}, triangulator,
          up_in_left_camera, correlator.has_value(), options, trace);
      if (!sides && !place_occluded_corner()) return std::nullopt;
    }
    // Size: both cameras are about equally far from the object, so the areas agree.
    // Two views of a bar: their mean widths (one may be a fragment of the other), each with a
    // pixel of quantization added: a bar 2-3 px wide that loses one column of pixels in one image
    // would otherwise differ by a ratio of 1.5.
    double area_term = 0.0;
    if (dl.area_px > 0.0 && dr.area_px > 0.0) {
      const double log_ratio =
          bar ? std::abs(std::log((dl.area_px / dl.major_extent_px + kBarWidthQuantizationPx) /
                                  (dr.area_px / dr.major_extent_px + kBarWidthQuantizationPx)))
              : std::abs(std::log(dl.area_px / dr.area_px));
      if (log_ratio > log_max_area_ratio) {
        return detail::refuse(trace, StereoGate::kAreaRatio, std::exp(log_ratio),
                              options.max_area_ratio);
      }
      area_term = log_ratio / log_max_area_ratio;
    }
    // Orientation: only defined for elongated blobs (a near-round blob's axis is noise).
    double orientation_term = 0.0;
    if (elongation(dl) >= options.min_elongation_for_orientation &&
        elongation(dr) >= options.min_elongation_for_orientation) {
      const double difference =
          axis_difference_rad(dl.major_axis_angle_rad, dr.major_axis_angle_rad);
      if (difference > options.max_orientation_difference_rad) {
        return detail::refuse(trace, StereoGate::kOrientation, difference,
                              options.max_orientation_difference_rad);
      }
      orientation_term = difference / options.max_orientation_difference_rad;
    }
    // The 3D point: for two rectangle outlines the centre from their vertical sides
    // (Triangulator::rectangle_centre), with the covariance the pixel noise gives the centre
    // triangulated from the reference points; otherwise from the reference points.
    const double offset = reference_depth_offset(options, dl.type);
    std::optional<detail::Triangulation> triangulation =
        triangulator.triangulate(left_ideal[l], right_ideal[r], options.pixel_sigma_px, offset);
    if (!triangulation) return detail::refuse(trace, StereoGate::kTriangulation, 0.0, 0.0);
    // The gates below measure the visible surface, before the reference point's offset.
    Eigen::Vector3d point = triangulation->left_camera_position_m -
                            offset * triangulation->left_camera_position_m.normalized();
    if (bar) {
      point = bar->centre_m;
      triangulation->left_camera_position_m = point + offset * point.normalized();
    }
    // Cut by one border in both images: the centre from the bar's own end (cut_bar.hpp).
    if (cut_bar && cut_bar->both != BorderCut::kNone) {
      const std::optional<detail::CutBarCentre> placed =
          detail::place_cut_bar(*bar, cut_bar->both, triangulator, *cut_bar->bar, trace);
      if (!placed) return std::nullopt;
      point = placed->centre_m;
      triangulation->left_camera_position_m = point + offset * point.normalized();
      triangulation->left_camera_covariance_m2 += placed->length_covariance_m2;
    }
    // Two door outlines: the centre from their vertical sides (door_pair.hpp).
    bool rectangle = false;
    if (occluded) {
      point = occluded->centre_m;
      triangulation->left_camera_position_m = point + offset * point.normalized();
      rectangle = true;
    } else if (rectangles) {
      const detail::DoorCentre door = detail::door_centre(
          {corner_array(left_corners[l]), corner_array(right_corners[r])}, *sides, triangulator,
          correlator ? &*correlator : nullptr, reverse_correlator ? &*reverse_correlator : nullptr,
          left_T_right, up_in_left_camera, options, class_max_width_m(options, dl.type), trace);
      if (door.refused) return std::nullopt;
      if (door.centre) {
        point = *door.centre;
        triangulation->left_camera_position_m = point + offset * point.normalized();
        rectangle = true;
      }
    }
    // Disparity range, as the depth of the triangulated point along the left optical axis
    // (verging eyes make disparity alone depend on where the point is in the image).
    if (point.z() < options.min_depth_m) {
      return detail::refuse(trace, StereoGate::kDepth, point.z(), options.min_depth_m);
    }
    if (point.z() > options.max_depth_m) {
      return detail::refuse(trace, StereoGate::kDepth, point.z(), options.max_depth_m);
    }
    // Size at that depth: a fronto-parallel length L spans f L / z pixels.
    // (A cut bar's visible length was judged against its class's typical one.)
    const auto* range =
        cut_bar && cut_bar->both != BorderCut::kNone ? nullptr : extent_range(options, dl.type);
    if (range && (dl.major_extent_px > 0.0 || dr.major_extent_px > 0.0)) {
      const double length_m =
          bar ? bar->length_m
              : 0.5 * (dl.major_extent_px + dr.major_extent_px) * point.z() / mean_f_px;
      if (length_m < range->min_m)
        return detail::refuse(trace, StereoGate::kExtent, length_m, range->min_m);
      if (length_m > range->max_m)
        return detail::refuse(trace, StereoGate::kExtent, length_m, range->max_m);
    }
    // Height at that depth: the image length of the vertical edges in metres.
    const auto* height = height_range(options, dl.type);
    if (height && dl.height_px > 0.0 && dr.height_px > 0.0) {
      const double height_m = 0.5 * (dl.height_px + dr.height_px) * point.z() /
                              (0.5 * (left_intrinsics.fy_px + right_intrinsics.fy_px));
      if (height_m < height->min_m)
        return detail::refuse(trace, StereoGate::kHeight, height_m, height->min_m);
      if (height_m > height->max_m)
        return detail::refuse(trace, StereoGate::kHeight, height_m, height->max_m);
    }
    const double epipolar_term = max_epipolar_px > 0.0 ? epipolar_px / max_epipolar_px : 0.0;
    detail::Candidate c;
    c.left = l;
    c.right = r;
    c.cost =
        epipolar_term * epipolar_term + area_term * area_term + orientation_term * orientation_term;
    c.rectangle = rectangle;
    c.triangulation = *triangulation;
    trace.cost = c.cost;
    return c;
  };

  std::vector<detail::Candidate> candidates;
  std::vector<StereoPairTrace> traces;
  for (int l = 0; l < static_cast<int>(left.size()); ++l) {
    for (int r = 0; r < static_cast<int>(right.size()); ++r) {
      if (left[l].type != right[r].type) continue;
      // A door cut by the image border pairs only with one cut along the same border, judged
      // by border_cut.hpp's gates when its class has a typical height.
      const bool cut =
          left[l].border_cut != BorderCut::kNone || right[r].border_cut != BorderCut::kNone;
      // A bar cut at one end by the image border (cut_bar.hpp): with a whole view in the other
      // image, judged as any two views of a bar (their union is the whole bar); cut by the same
      // border in both, placed from its own end; by different borders, not paired.
      if (cut && detail::is_bar_type(options, left[l].type)) {
        const bool both =
            left[l].border_cut != BorderCut::kNone && right[r].border_cut != BorderCut::kNone;
        const CutBarViews cut_bar{cut_bar_of(options, left[l].type),
                                  both ? left[l].border_cut : BorderCut::kNone};
        if (!cut_bar.bar || (both && left[l].border_cut != right[r].border_cut)) continue;
        StereoPairTrace trace;
        trace.left_detection = l;
        trace.right_detection = r;
        std::optional<detail::Candidate> c = judge(l, r, trace, &cut_bar);
        if (c) candidates.push_back(std::move(*c));
        if (pair_trace) traces.push_back(trace);
        continue;
      }
      const StereoMatchOptions::BorderCutDoor* cut_height =
          cut ? border_cut_door(options, left[l].type) : nullptr;
      // A door cut by the left border in the right image only (the right camera sees less
      // beyond its left border), or by the right border in the left image only, pairs with a
      // whole outline in the other image (side_cut_door.hpp).
      const bool side_cut_by_one =
          (left[l].border_cut == BorderCut::kNone && right[r].border_cut == BorderCut::kLeft) ||
          (left[l].border_cut == BorderCut::kRight && right[r].border_cut == BorderCut::kNone);
      const bool side_cut = side_cut_by_one || left[l].border_cut == BorderCut::kLeft ||
                            left[l].border_cut == BorderCut::kRight;
      // A door cut at an image corner in the image that sees less beyond that side pairs with
      // one cut by the top or bottom border alone in the other (corner_cut_door.hpp).
      const bool corner_cut = detail::is_corner_cut_pair(left[l].border_cut, right[r].border_cut);
      // Cut along the same border in both images (at the same image corner: no judge takes it),
      // or one of the two mixed cases above.
      const BorderCut same =
          left[l].border_cut == right[r].border_cut ? left[l].border_cut : BorderCut::kNone;
      const bool judged = same == BorderCut::kTop || same == BorderCut::kBottom ||
                          same == BorderCut::kLeft || same == BorderCut::kRight ||
                          side_cut_by_one || corner_cut;
      if (cut && (!judged || !cut_height || left_corners[l].size() != 4 ||
                  right_corners[r].size() != 4 || !(up_in_left_camera.norm() > 0.0))) {
        continue;
      }
      StereoPairTrace trace;
      trace.left_detection = l;
      trace.right_detection = r;
      std::optional<detail::Candidate> c;
      if (!cut) {
        c = judge(l, r, trace);
        // Too short for a door, an edge sloping or one side shorter than the other: perhaps an
        // occluder hides the door's lower part in both images (occluder_cut_door.hpp). The first
        // refusal stays in the trace unless the pair is so placed.
        const StereoMatchOptions::BorderCutDoor* door = border_cut_door(options, left[l].type);
        if (!c && door && door->occluder_cut && detail::may_be_occluder_cut(trace) &&
            left_corners[l].size() == 4 && right_corners[r].size() == 4 &&
            up_in_left_camera.norm() > 0.0) {
          StereoPairTrace retry;
          retry.left_detection = l;
          retry.right_detection = r;
          c = detail::judge_occluder_cut_pair(
              l, r, {left[l], corner_array(left_corners[l]), left_ideal[l]},
              {right[r], corner_array(right_corners[r]), right_ideal[r]}, epipolar, triangulator,
              correlator ? &*correlator : nullptr, up_in_left_camera.normalized(), options, *door,
              reference_depth_offset(options, left[l].type), retry);
          if (c) trace = retry;
        }
      } else if (const detail::BarVerdict bars = judge_bars(
                     left[l], right[r],
                     options.pair_max_bars_inside > 0 ? options.pair_max_bars_inside : -1);
                 bars.gate != StereoGate::kNone) {
        // Several handles inside, or one above another: drawer fronts or doors merged into one
        // blob. A cut pair is two views, as a whole pair is: a double door's second handle, a
        // few centimetres past the reveal, may lie inside the outline, and the bound is the
        // pairs' (the single views' 1 lost 16 true door percepts of the tuning set's cut doors
        // and kept no false one out).
        trace.refused_by = bars.gate;
        trace.value = bars.value;
        trace.limit = bars.limit;
      } else if (corner_cut) {
        c = detail::judge_corner_cut_pair(
            l, r, {left[l], corner_array(left_corners[l]), left_ideal[l]},
            {right[r], corner_array(right_corners[r]), right_ideal[r]}, epipolar, triangulator,
            up_in_left_camera.normalized(), options, *cut_height,
            reference_depth_offset(options, left[l].type), trace);
      } else if (side_cut) {
        c = detail::judge_side_cut_pair(
            l, r, {left[l], corner_array(left_corners[l]), left_ideal[l]},
            {right[r], corner_array(right_corners[r]), right_ideal[r]}, epipolar, triangulator,
            correlator ? &*correlator : nullptr, up_in_left_camera.normalized(), options,
            *cut_height, height_range(options, left[l].type),
            reference_depth_offset(options, left[l].type), trace);
      } else {
        c = detail::judge_border_cut_pair(
            l, r, {left[l], corner_array(left_corners[l]), left_ideal[l]},
            {right[r], corner_array(right_corners[r]), right_ideal[r]}, epipolar, triangulator,
            correlator ? &*correlator : nullptr, up_in_left_camera.normalized(), options,
            *cut_height, reference_depth_offset(options, left[l].type), trace);
      }
      if (c) candidates.push_back(std::move(*c));
      if (pair_trace) traces.push_back(trace);
    }
  }

  // Pairs of two clear detections first; a weak detection (Detection::needs_partner) then takes
  // only a partner left over, so that it never draws a clear detection into a worse pair (the
  // assignment maximizes the number of pairs before their cost).
  const auto is_weak_pair = [&](const detail::Candidate& c) {
    return left[c.left].needs_partner || right[c.right].needs_partner;
  };
  std::vector<detail::Candidate> clear, weak;
  for (const detail::Candidate& c : candidates) (is_weak_pair(c) ? weak : clear).push_back(c);
  const int left_count = static_cast<int>(left.size());
  const int right_count = static_cast<int>(right.size());
  std::vector<detail::Candidate> assigned = detail::assign(clear, left_count, right_count);
  if (!weak.empty()) {
    std::vector<char> left_taken(left.size(), 0), right_taken(right.size(), 0);
    for (const detail::Candidate& c : assigned) {
      left_taken[static_cast<std::size_t>(c.left)] = 1;
      right_taken[static_cast<std::size_t>(c.right)] = 1;
    }
    std::erase_if(weak, [&](const detail::Candidate& c) {
      return left_taken[static_cast<std::size_t>(c.left)] ||
             right_taken[static_cast<std::size_t>(c.right)];
    });
    for (detail::Candidate& c : detail::assign(weak, left_count, right_count)) {
      assigned.push_back(std::move(c));
    }
    std::sort(
        assigned.begin(), assigned.end(),
        [](const detail::Candidate& a, const detail::Candidate& b) { return a.left < b.left; });
  }
  detail::uncross(assigned, candidates, left, left_ideal, right_ideal);
  std::vector<StereoPercept> out;
  for (const detail::Candidate& c : assigned) {
    StereoPercept percept;
    percept.left_detection = c.left;
    percept.right_detection = c.right;
    percept.left_camera_position_m = c.triangulation.left_camera_position_m;
    percept.left_camera_covariance_m2 = c.triangulation.left_camera_covariance_m2;
    percept.left_px = left[c.left].reference_px;
    percept.right_px = right[c.right].reference_px;
    percept.confidence = static_cast<float>(
        std::sqrt(std::clamp(static_cast<double>(left[c.left].confidence), 0.0, 1.0) *
                  std::clamp(static_cast<double>(right[c.right].confidence), 0.0, 1.0)));
    out.push_back(percept);
    if (pair_trace) {
      for (StereoPairTrace& t : traces) {
        if (t.left_detection == c.left && t.right_detection == c.right) t.assigned = true;
      }
    }
  }
  if (pair_trace) *pair_trace = std::move(traces);
  if (single_view && correlator) {
    std::vector<char> left_paired(left.size(), 0), right_paired(right.size(), 0);
    for (const detail::Candidate& c : assigned) {
      left_paired[static_cast<std::size_t>(c.left)] = 1;
      right_paired[static_cast<std::size_t>(c.right)] = 1;
    }
    const detail::StereoRig rig{left_intrinsics, right_intrinsics, left_T_right, up_in_left_camera};
    // Pass 0 places whole outlines from both sides (single_view.hpp) in both images; pass 1 then
    // places what is left from one side (one_side_door.hpp), so that a one-side percept, less
    // exact, never displaces the other image's two-sided one of the same door
    // (single_view_min_separation_m).
    std::array<std::vector<char>, 2> placed{std::vector<char>(left.size(), 0),
                                            std::vector<char>(right.size(), 0)};
    for (int pass = 0; pass < 2; ++pass) {
      for (int image = 0; image < 2; ++image) {
        const std::vector<Detection>& detections = image == 0 ? left : right;
        const auto& corners = image == 0 ? left_corners : right_corners;
        const std::vector<char>& paired = image == 0 ? left_paired : right_paired;
        for (std::size_t d = 0; d < detections.size(); ++d) {
          const Detection& detection = detections[d];
          const StereoMatchOptions::BorderCutDoor* cut_door =
              border_cut_door(options, detection.type);
          const bool from_one_side = cut_door && cut_door->from_one_side;
          const bool cut = detection.border_cut != BorderCut::kNone;
          if (paired[d] || detection.needs_partner || corners[d].size() != 4) continue;
          if (pass == 0 ? cut : !from_one_side || placed[static_cast<std::size_t>(image)][d]) {
            continue;
          }
          if (detail::judge_bars_on_outline(detections, detection,
                                            options.single_view_max_bars_inside, options)
                  .gate != StereoGate::kNone) {
            continue;
          }
          const detail::SideCorrelator& sweep = image == 0 ? *correlator : *reverse_correlator;
          const detail::IdealPixel& reference = (image == 0 ? left_ideal : right_ideal)[d];
          const double offset_m = reference_depth_offset(options, detection.type);
          std::optional<StereoPercept> percept;
          if (pass == 0) {
            percept = detail::single_view_percept(
                detection, static_cast<int>(d), image, corner_array(corners[d]), reference, sweep,
                triangulator, rig, options, height_range(options, detection.type),
                class_max_width_m(options, detection.type), offset_m);
            if (percept) placed[static_cast<std::size_t>(image)][d] = 1;
          } else {
            // Not placed from both sides: from one side and the level planes of its edges (the
            // other side beyond the other image's border, or one of two peaks of a repeated edge).
            const Eigen::Isometry3d other_T_own =
                image == 0 ? left_T_right.inverse() : left_T_right;
            const Eigen::Vector3d up_in_own =
                image == 0 ? up_in_left_camera
                           : Eigen::Vector3d(left_T_right.linear().transpose() * up_in_left_camera);
            const auto place = [&](detail::SweptSide swept) {
              return detail::place_one_side_door(
                  corner_array(corners[d]), detection.border_cut, image, sweep,
                  image == 0 ? left_intrinsics : right_intrinsics,
                  image == 0 ? right_intrinsics : left_intrinsics, other_T_own, up_in_own, options,
                  *cut_door, height_range(options, detection.type), swept);
            };
            std::optional<detail::OneSideDoor> door = place(detail::SweptSide::kInner);
            if (!door && cut_door->merged_side) door = place(detail::SweptSide::kOuter);
            if (door) {
              percept = detail::one_image_percept(
                  detection, static_cast<int>(d), image, door->centre_m, door->side_correlation,
                  door->height_sigma_m, reference, triangulator, rig, options, offset_m);
            }
          }
          if (!percept) continue;
          // A second outline of a door that a percept already places.
          const bool near_another =
              std::any_of(out.begin(), out.end(), [&](const StereoPercept& p) {
                const Detection& other =
                    p.left_detection >= 0 ? left[p.left_detection] : right[p.right_detection];
                return other.type == detection.type &&
                       (p.left_camera_position_m - percept->left_camera_position_m).norm() <
                           options.single_view_min_separation_m;
              });
          if (near_another) continue;
          out.push_back(*percept);
        }
      }
    }
  }
  return out;
}

const char* stereo_gate_name(StereoGate gate) {
  switch (gate) {
    case StereoGate::kNone:
      return "none";
    case StereoGate::kEpipolar:
      return "epipolar";
    case StereoGate::kSideTilt:
      return "side_tilt";
    case StereoGate::kAreaRatio:
      return "area_ratio";
    case StereoGate::kOrientation:
      return "orientation";
    case StereoGate::kTriangulation:
      return "triangulation";
    case StereoGate::kDepth:
      return "depth";
    case StereoGate::kExtent:
      return "extent";
    case StereoGate::kHeight:
      return "height";
    case StereoGate::kEdgeSlope:
      return "edge_slope";
    case StereoGate::kWeakPair:
      return "weak_pair";
    case StereoGate::kBarsInside:
      return "bars_inside";
    case StereoGate::kStackedBars:
      return "stacked_bars";
    case StereoGate::kSideHeights:
      return "side_heights";
  }
  return "?";
}

}  // namespace vsl::recognition

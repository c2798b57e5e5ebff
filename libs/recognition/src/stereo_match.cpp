// Left-right cross match and triangulation (paper §2.1), as its stages: both images' detections
// (stereo_views.hpp); every pair judged, its gates in order (PairJudge; the door outlines' own
// gates: door_pair.hpp; the door's fit, whole, cut by the image border or by an occluder:
// door_pairing.hpp, partly_seen_door.hpp); the one-to-one assignment (stereo_assignment.hpp); the
// whole door pairs an occluder explains (door_pairing.hpp); doors from one image
// (one_image_door.hpp). Geometry: epipolar.hpp (gate) and triangulation.hpp (point and
// covariance).
#include "vsl/recognition/stereo_match.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "bars_on_outline.hpp"
#include "door_pair.hpp"
#include "door_pairing.hpp"
#include "epipolar.hpp"
#include "one_image_door.hpp"
#include "pair_refusal.hpp"
#include "partly_seen_bar.hpp"
#include "partly_seen_door.hpp"
#include "side_correlation.hpp"
#include "stereo_assignment.hpp"
#include "stereo_views.hpp"
#include "triangulation.hpp"

namespace vsl::recognition {
namespace {

// Added to each bar's mean width (pixels) before their ratio is compared: the quantization of a
// thin bar's two edges.
constexpr double kBarWidthQuantizationPx = 1.0;

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

using detail::cut_bar_of;
using detail::door_class_of;
using detail::extent_range;
using detail::height_range;
using detail::judge_door;
using detail::reference_depth_offset;
using detail::StereoViews;

// Judges one pair of views that are not a door's outlines against every gate, in order (paper
// §2.1: position on the epipolar line, size, orientation, then the triangulated point's depth and
// extent); a pair that passes all of them is a candidate with its triangulation. Triangulating
// here rather than after the assignment means that a pair which cannot be triangulated is never
// assigned, and its detections stay free for other pairs.
class PairJudge {
 public:
  PairJudge(const StereoViews& views, int l, int r, StereoPairTrace& trace, bool cut_bar)
      : v_(views),
        o_(views.options),
        l_(l),
        r_(r),
        dl_(views.left[l]),
        dr_(views.right[r]),
        trace_(trace),
        cut_bar_(cut_bar) {}

  std::optional<detail::Candidate> judge() {
    if (!gate_position() || !gate_appearance() || !place_point() || !gate_size()) {
      return std::nullopt;
    }
    const double epipolar_term =
        o_.max_epipolar_distance_px > 0.0 ? epipolar_px_ / o_.max_epipolar_distance_px : 0.0;
    detail::Candidate c;
    c.left = l_;
    c.right = r_;
    c.cost = epipolar_term * epipolar_term + area_term_ * area_term_ +
             orientation_term_ * orientation_term_;
    c.triangulation = *triangulation_;
    trace_.cost = c.cost;
    return c;
  }

 private:
  // Position: the right reference point on (near) the left one's epipolar line; for two views of
  // a bar across the epipolar lines, the containment of the shorter segment in the longer, and for
  // a cut bar along them, its ends both images see on each other's epipolar lines.
  bool gate_position() {
    // A stack of drawer fronts merged into one door-shaped blob carries a handle per front, one
    // above another; judged on each image's outline, also when the other image's blob has none.
    if (const detail::BarVerdict bars = v_.judge_bars(dl_, dr_); bars.gate != StereoGate::kNone) {
      detail::refuse(trace_, bars.gate, bars.value, bars.limit);
      return false;
    }
    if (!span_bar()) return false;
    // A cut view's reference point is the middle of what it shows, another point of the bar in
    // each image: a cut bar is placed only by the bar's fit.
    if (cut_bar_ && !bar_) {
      detail::refuse(trace_, StereoGate::kTriangulation, 0.0, 0.0);
      return false;
    }
    epipolar_px_ =
        bar_ ? bar_->containment_excess_px
             : v_.epipolar.distance_px(v_.left_ideal[l_].ideal_px, v_.right_ideal[r_].ideal_px);
    if (!(epipolar_px_ <= o_.max_epipolar_distance_px)) {
      detail::refuse(trace_, StereoGate::kEpipolar, epipolar_px_, o_.max_epipolar_distance_px);
      return false;
    }
    return true;
  }

  // Two views of a bar (StereoMatchOptions::bar_types) across the epipolar lines, or along them
  // and cut by the border: which of their ends are the bar's (partly_seen_bar.hpp).
  bool span_bar() {
    if (v_.left_bar_ends[l_].empty() || v_.right_bar_ends[r_].empty() ||
        elongation(dl_) < o_.min_elongation_for_orientation ||
        elongation(dr_) < o_.min_elongation_for_orientation) {
      return true;
    }
    const Eigen::Vector2d a = v_.right_bar_ends[r_][0].ideal_px;
    const Eigen::Vector2d b = v_.right_bar_ends[r_][1].ideal_px;
    const Eigen::Vector3d line = v_.epipolar.right_line(v_.left_ideal[l_].ideal_px);  // a^2+b^2=1
    const double length = (b - a).norm();
    const std::array<detail::BarView, 2> views{
        {{{v_.left_bar_ends[l_][0].ideal_px, v_.left_bar_ends[l_][1].ideal_px}, dl_.border_cut},
         {{a, b}, dr_.border_cut}}};
    // |cos| of the angle between the bar and the line's normal: sin of the angle to the line.
    if (!(length > 0.0 && std::abs((b - a).dot(line.head<2>())) >= std::sqrt(0.5) * length)) {
      // Along the epipolar lines a whole pair keeps its reference points; a cut view's is
      // another point of the bar, so a cut pair is placed by the fit.
      if (!cut_bar_) return true;
      bar_ = detail::bar_views_along_epipolar(views, v_.epipolar.fundamental());
    } else {
      bar_ = detail::bar_views_along(views, v_.epipolar.fundamental(), o_.max_epipolar_distance_px);
    }
    if (!bar_) {
      detail::refuse(trace_, StereoGate::kTriangulation, 0.0, 0.0);
      return false;
    }
    return true;
  }

  // Size: both cameras are about equally far from the object, so the areas agree. Two views of
  // a bar: their mean widths (one may be a fragment of the other), each with a pixel of
  // quantization added: a bar 2-3 px wide that loses one column of pixels in one image would
  // otherwise differ by a ratio of 1.5. Orientation: only defined for elongated blobs (a
  // near-round blob's axis is noise).
  bool gate_appearance() {
    if (dl_.area_px > 0.0 && dr_.area_px > 0.0) {
      const double log_ratio =
          bar_ ? std::abs(std::log((dl_.area_px / dl_.major_extent_px + kBarWidthQuantizationPx) /
                                   (dr_.area_px / dr_.major_extent_px + kBarWidthQuantizationPx)))
               : std::abs(std::log(dl_.area_px / dr_.area_px));
      if (log_ratio > v_.log_max_area_ratio) {
        detail::refuse(trace_, StereoGate::kAreaRatio, std::exp(log_ratio), o_.max_area_ratio);
        return false;
      }
      area_term_ = log_ratio / v_.log_max_area_ratio;
    }
    if (elongation(dl_) >= o_.min_elongation_for_orientation &&
        elongation(dr_) >= o_.min_elongation_for_orientation) {
      const double difference =
          axis_difference_rad(dl_.major_axis_angle_rad, dr_.major_axis_angle_rad);
      if (difference > o_.max_orientation_difference_rad) {
        detail::refuse(trace_, StereoGate::kOrientation, difference,
                       o_.max_orientation_difference_rad);
        return false;
      }
      orientation_term_ = difference / o_.max_orientation_difference_rad;
    }
    return true;
  }

  // The 3D point: triangulated from the reference points, with the covariance the pixel noise
  // gives it; two views of a bar by the bar's fit (partly_seen_bar.hpp), with the fit's.
  bool place_point() {
    offset_m_ = reference_depth_offset(o_, dl_.type);
    // A bar's views need not show the same part of it, so their reference points are not one
    // point: the bar's fit alone places it.
    if (bar_) return place_bar();
    triangulation_ = v_.triangulator.triangulate(v_.left_ideal[l_], v_.right_ideal[r_],
                                                 o_.pixel_sigma_px, offset_m_);
    if (!triangulation_) {
      detail::refuse(trace_, StereoGate::kTriangulation, 0.0, 0.0);
      return false;
    }
    // The gates below measure the visible surface, before the reference point's offset.
    point_ = triangulation_->left_camera_position_m -
             offset_m_ * triangulation_->left_camera_position_m.normalized();
    return true;
  }
  bool place_bar() {
    const std::optional<detail::BarFit> fit =
        detail::judge_partly_seen_bar(*bar_, v_.rig, v_.triangulator, cut_bar_of(o_, dl_.type),
                                      o_.pixel_sigma_px, o_.max_epipolar_distance_px, trace_);
    if (!fit) return false;
    triangulation_.emplace();
    set_point(fit->centre_m);
    triangulation_->left_camera_covariance_m2 = fit->centre_covariance_m2;
    if (!fit->length_from_prior) bar_length_m_ = fit->length_m;
    return true;
  }
  void set_point(const Eigen::Vector3d& visible_m) {
    point_ = visible_m;
    triangulation_->left_camera_position_m = point_ + offset_m_ * point_.normalized();
  }

  // Disparity range, as the depth of the triangulated point along the left optical axis (verging
  // eyes make disparity alone depend on where the point is in the image); the class's extent
  // and height at that depth (a fronto-parallel length L spans f L / z pixels).
  bool gate_size() {
    const auto refuse = [&](StereoGate gate, double value, double limit) {
      detail::refuse(trace_, gate, value, limit);
      return false;
    };
    if (point_.z() < o_.min_depth_m) return refuse(StereoGate::kDepth, point_.z(), o_.min_depth_m);
    if (point_.z() > o_.max_depth_m) return refuse(StereoGate::kDepth, point_.z(), o_.max_depth_m);
    // (A bar whose length is the class's had its visible length judged against it.)
    const auto* range = bar_ && !bar_length_m_ ? nullptr : extent_range(o_, dl_.type);
    if (range && (dl_.major_extent_px > 0.0 || dr_.major_extent_px > 0.0)) {
      const double mean_f_px = 0.5 * (v_.left_intrinsics.fx_px + v_.right_intrinsics.fx_px);
      const double length_m =
          bar_ ? *bar_length_m_
               : 0.5 * (dl_.major_extent_px + dr_.major_extent_px) * point_.z() / mean_f_px;
      if (length_m < range->min_m) return refuse(StereoGate::kExtent, length_m, range->min_m);
      if (length_m > range->max_m) return refuse(StereoGate::kExtent, length_m, range->max_m);
    }
    const auto* height = height_range(o_, dl_.type);
    if (height && dl_.height_px > 0.0 && dr_.height_px > 0.0) {
      const double height_m = 0.5 * (dl_.height_px + dr_.height_px) * point_.z() /
                              (0.5 * (v_.left_intrinsics.fy_px + v_.right_intrinsics.fy_px));
      if (height_m < height->min_m) return refuse(StereoGate::kHeight, height_m, height->min_m);
      if (height_m > height->max_m) return refuse(StereoGate::kHeight, height_m, height->max_m);
    }
    return true;
  }

  const StereoViews& v_;
  const StereoMatchOptions& o_;
  const int l_, r_;
  const Detection& dl_;
  const Detection& dr_;
  StereoPairTrace& trace_;
  const bool cut_bar_;
  std::optional<detail::BarViewsAlong> bar_;
  std::optional<double> bar_length_m_;  // the fitted bar's, none when the class's
  std::optional<detail::Triangulation> triangulation_;
  Eigen::Vector3d point_ = Eigen::Vector3d::Zero();  // the visible surface, left camera frame
  double offset_m_ = 0.0;
  double epipolar_px_ = 0.0;
  double area_term_ = 0.0, orientation_term_ = 0.0;
};

// A pair of door outlines of a class with sizes (is_door_pair): one door seen whole or in part,
// placed by the door's fit (door_pairing.hpp), the corners' states from the border's cuts. Before
// it, what the outlines hold: no handles one above another (a stack of drawer fronts merged into
// one door-shaped blob carries a handle per front), and for whole outlines the side gate
// (door_pair.hpp: a side that is no door edge in one outline is merged there). A whole pair so
// refused that an occluder may explain is added to `occluded` (explain_unpaired_by_occluder).
std::optional<detail::Candidate> judge_door_pair(const StereoViews& v, int l, int r,
                                                 StereoPairTrace& trace,
                                                 std::vector<StereoPairTrace>& occluded) {
  using detail::CornerState;
  const Detection& dl = v.left[l];
  const Detection& dr = v.right[r];
  if (const detail::BarVerdict bars = v.judge_bars(dl, dr); bars.gate != StereoGate::kNone) {
    return detail::refuse(trace, bars.gate, bars.value, bars.limit);
  }
  if (dl.border_cut != BorderCut::kNone || dr.border_cut != BorderCut::kNone) {
    return judge_door(v, l, r, detail::corner_states_of(dl.border_cut),
                      detail::corner_states_of(dr.border_cut), trace);
  }
  std::optional<detail::Candidate> c;
  if (const auto sides =
          detail::judge_door_sides(v.outlines(l, r), v.triangulator, v.up, v.options, trace)) {
    std::array<std::array<CornerState, 4>, 2> states;
    for (std::array<CornerState, 4>& image : states) image.fill(CornerState::kSeen);
    if (sides->tilted_side >= 0) {  // side 0 is corners 0-3, side 1 corners 1-2
      std::array<CornerState, 4>& merged = states[sides->tilted_in_left ? 0 : 1];
      const std::size_t top = sides->tilted_side == 0 ? 0 : 1;
      merged[top] = merged[3 - top] = CornerState::kMerged;
    }
    c = judge_door(v, l, r, states[0], states[1], trace);
  }
  if (!c) occluded.push_back(trace);
  return c;
}

// The cross match (paper §2.1): every pair of same-type detections judged; the candidates, and
// every judged pair's trace when `traces`; the refused whole door pairs in `occluded`.
std::vector<detail::Candidate> judge_all_pairs(const StereoViews& v,
                                               std::vector<StereoPairTrace>* traces,
                                               std::vector<StereoPairTrace>& occluded) {
  std::vector<detail::Candidate> candidates;
  for (int l = 0; l < static_cast<int>(v.left.size()); ++l) {
    for (int r = 0; r < static_cast<int>(v.right.size()); ++r) {
      const Detection& dl = v.left[l];
      const Detection& dr = v.right[r];
      if (dl.type != dr.type) continue;
      const bool cut = dl.border_cut != BorderCut::kNone || dr.border_cut != BorderCut::kNone;
      StereoPairTrace trace;
      trace.left_detection = l;
      trace.right_detection = r;
      std::optional<detail::Candidate> c;
      if (cut && detail::is_bar_type(v.options, dl.type)) {
        // A bar cut at one end by the image border: placed by the bar's fit (partly_seen_bar.hpp),
        // which needs the class's typical length where neither image shows an end; cut by
        // different borders in the two images, not paired.
        const bool both = dl.border_cut != BorderCut::kNone && dr.border_cut != BorderCut::kNone;
        if (!cut_bar_of(v.options, dl.type) || (both && dl.border_cut != dr.border_cut)) continue;
        c = PairJudge(v, l, r, trace, true).judge();
      } else if (detail::is_door_pair(v, l, r)) {
        c = judge_door_pair(v, l, r, trace, occluded);
      } else if (!cut) {
        c = PairJudge(v, l, r, trace, false).judge();
      } else {
        continue;
      }
      if (c) candidates.push_back(std::move(*c));
      if (traces) traces->push_back(trace);
    }
  }
  return candidates;
}

// The one-to-one assignment (stereo_assignment.hpp), then crossed pairs swapped
// (detail::uncross).
std::vector<detail::Candidate> assign_pairs(const StereoViews& v,
                                            const std::vector<detail::Candidate>& candidates) {
  std::vector<detail::Candidate> assigned =
      detail::assign(candidates, static_cast<int>(v.left.size()), static_cast<int>(v.right.size()));
  detail::uncross(assigned, candidates, v.left, v.left_ideal, v.right_ideal);
  return assigned;
}

StereoPercept to_percept(const StereoViews& v, const detail::Candidate& c) {
  StereoPercept percept;
  percept.left_detection = c.left;
  percept.right_detection = c.right;
  percept.left_camera_position_m = c.triangulation.left_camera_position_m;
  percept.left_camera_covariance_m2 = c.triangulation.left_camera_covariance_m2;
  percept.left_px = v.left[c.left].reference_px;
  percept.right_px = v.right[c.right].reference_px;
  percept.confidence = static_cast<float>(
      std::sqrt(std::clamp(static_cast<double>(v.left[c.left].confidence), 0.0, 1.0) *
                std::clamp(static_cast<double>(v.right[c.right].confidence), 0.0, 1.0)));
  return percept;
}

// One detection of one image that no pair took, placed from that image alone by the door's fit
// (one_image_door.hpp): whole outlines from both sides (pass 0); what is left from one side
// (pass 1: the other side beyond the other image's border, or one of two peaks of a repeated
// edge), and whole outlines also with the sides' roles swapped (the outer side swept, the inner
// one placed and found in the other image).
std::optional<StereoPercept> place_from_one_image(const StereoViews& v, int image, std::size_t d,
                                                  int pass) {
  const int index = static_cast<int>(d);
  if (pass == 0) return detail::place_one_image_door(v, image, index, detail::SweptSides::kBoth);
  std::optional<StereoPercept> percept =
      detail::place_one_image_door(v, image, index, detail::SweptSides::kInner);
  if (!percept) percept = detail::place_one_image_door(v, image, index, detail::SweptSides::kOuter);
  return percept;
}

// The detections no pair took, placed from one image (place_from_one_image) unless a percept of
// the same type already lies within single_view_min_separation_m (a second outline of a door
// already placed). Pass 0 runs on both images before pass 1, so that a one-side percept, less
// exact, never displaces the other image's two-sided one of the same door.
void place_single_views(const StereoViews& v, const std::vector<detail::Candidate>& assigned,
                        std::vector<StereoPercept>& out) {
  const StereoMatchOptions& options = v.options;
  std::array<std::vector<char>, 2> paired{std::vector<char>(v.left.size(), 0),
                                          std::vector<char>(v.right.size(), 0)};
  for (const detail::Candidate& c : assigned) {
    paired[0][static_cast<std::size_t>(c.left)] = 1;
    paired[1][static_cast<std::size_t>(c.right)] = 1;
  }
  std::array<std::vector<char>, 2> placed{std::vector<char>(v.left.size(), 0),
                                          std::vector<char>(v.right.size(), 0)};
  for (int pass = 0; pass < 2; ++pass) {
    for (int image = 0; image < 2; ++image) {
      const std::vector<Detection>& detections = image == 0 ? v.left : v.right;
      const auto& corners = image == 0 ? v.left_corners : v.right_corners;
      for (std::size_t d = 0; d < detections.size(); ++d) {
        const Detection& detection = detections[d];
        const bool door_class = door_class_of(options, detection.type) != nullptr;
        const bool cut = detection.border_cut != BorderCut::kNone;
        if (paired[static_cast<std::size_t>(image)][d] || corners[d].size() != 4) {
          continue;
        }
        if (pass == 0 ? cut : !door_class || placed[static_cast<std::size_t>(image)][d]) {
          continue;
        }
        if (detail::judge_bars_on_outline(detections, detection, options).gate !=
            StereoGate::kNone) {
          continue;
        }
        const std::optional<StereoPercept> percept = place_from_one_image(v, image, d, pass);
        if (!percept) continue;
        if (pass == 0) placed[static_cast<std::size_t>(image)][d] = 1;
        const bool near_another = std::any_of(out.begin(), out.end(), [&](const StereoPercept& p) {
          const Detection& other =
              p.left_detection >= 0 ? v.left[p.left_detection] : v.right[p.right_detection];
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
  const StereoViews views(left, right, left_intrinsics, right_intrinsics, left_T_right, options,
                          up_in_left_camera, images);
  std::vector<StereoPairTrace> traces, occluded;
  const std::vector<detail::Candidate> candidates =
      judge_all_pairs(views, pair_trace ? &traces : nullptr, occluded);
  std::vector<detail::Candidate> assigned = assign_pairs(views, candidates);
  detail::explain_unpaired_by_occluder(views, std::move(occluded), assigned,
                                       pair_trace ? &traces : nullptr);
  std::vector<StereoPercept> out;
  for (const detail::Candidate& c : assigned) {
    out.push_back(to_percept(views, c));
    for (StereoPairTrace& t : traces) {
      if (t.left_detection == c.left && t.right_detection == c.right) t.assigned = true;
    }
  }
  if (pair_trace) *pair_trace = std::move(traces);
  if (single_view && views.correlator) place_single_views(views, assigned, out);
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
    case StereoGate::kStackedBars:
      return "stacked_bars";
    case StereoGate::kRectangleFit:
      return "rectangle_fit";
  }
  return "?";
}

}  // namespace vsl::recognition

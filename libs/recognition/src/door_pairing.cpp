// The door pairs placed by the door's fit (door_pairing.hpp).
#include "door_pairing.hpp"

#include <algorithm>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// The cut an image shows of a door that the other image shows cut by `cut`, less its left
// (`left_border`) or right border: the right camera sees less beyond its left border, the left
// camera less beyond its right one.
BorderCut without_border(BorderCut cut, bool left_border) {
  using enum BorderCut;
  if (cut == (left_border ? kLeft : kRight)) return kNone;
  if (cut == (left_border ? kTopLeft : kTopRight)) return kTop;
  if (cut == (left_border ? kBottomLeft : kBottomRight)) return kBottom;
  return cut;
}

// Whether two cut views can be one door: cut alike, or the right image cut by its left border
// where the left image is not, or the left image by its right border where the right is not.
bool cuts_of_one_door(BorderCut left, BorderCut right) {
  const bool at_image_corner = left == BorderCut::kTopLeft || left == BorderCut::kTopRight ||
                               left == BorderCut::kBottomLeft || left == BorderCut::kBottomRight;
  return (left == right && !at_image_corner) ||
         (right != without_border(right, true) && without_border(right, true) == left) ||
         (left != without_border(left, false) && without_border(left, false) == right);
}

// Whole outlines refused in a way an occluder hiding the door's lower part explains: too short,
// or corners off the door's fit (a sloping lower edge, one side shorter than the other).
bool may_be_occluder_cut(const StereoPairTrace& refusal) {
  return (refusal.refused_by == StereoGate::kHeight && refusal.value < refusal.limit) ||
         refusal.refused_by == StereoGate::kRectangleFit;
}

// A corner on its vertical side in an image: the door's corner, or where the side leaves the
// outline.
bool on_side(CornerState s) {
  return s == CornerState::kSeen || s == CornerState::kOnSide;
}

// The sides' correlation searches this far (pixels of image motion) around the outlines' depth:
// a margin and a fraction of the left outline's width (side_correlation.hpp).
double side_search_px(const DoorOutlineView& left) {
  const std::array<Eigen::Vector2d, 4>& c = left.corners_ideal_px;
  return kSideSearchPx +
         kSideSearchWidthFraction * 0.5 * ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
}

// Each vertical side of the left outline placed where the images around it correlate, searched
// around the outlines' depth (side_correlation.hpp): one image's outline often lacks a stile that
// the other keeps. The right view's corners on that side become where the right camera sees the
// side so placed. A side that does not correlate, or not unambiguously (a run of equal doors
// repeats every edge: StereoMatchOptions::min_peak_margin), keeps the right outline's.
void correlate_sides(const StereoViews& v, const StereoMatchOptions::DoorClass& door,
                     std::array<DoorOutlineView, 2>& views) {
  const std::array<Eigen::Vector2d, 4>& left = views[0].corners_ideal_px;
  std::array<Eigen::Vector2d, 4>& right = views[1].corners_ideal_px;
  const double search_px = side_search_px(views[0]);
  const DoorOutlineView outline = views[1];
  // Each side's middle (left camera frame, metres), where it was placed.
  std::array<std::optional<Eigen::Vector3d>, 2> middle_m;
  for (const auto& [top, bottom] : {std::array<std::size_t, 2>{0, 3}, {1, 2}}) {
    if (!on_side(views[0].states[top]) || !on_side(views[0].states[bottom]) ||
        !on_side(views[1].states[top]) || !on_side(views[1].states[bottom])) {
      continue;
    }
    const auto top_point = v.triangulator.point(left[top], right[top]);
    const auto bottom_point = v.triangulator.point(left[bottom], right[bottom]);
    if (!top_point || !bottom_point) continue;
    middle_m[top == 0 ? 0 : 1] = 0.5 * (*top_point + *bottom_point);
    const double initial_m = 0.5 * (v.correlator->horizontal_distance(*top_point) +
                                    v.correlator->horizontal_distance(*bottom_point));
    const auto depth = v.correlator->correlate(left[top], left[bottom], initial_m, search_px,
                                               v.options.min_depth_m, v.options.max_depth_m);
    if (!depth || depth->correlation < v.options.min_side_correlation ||
        depth->second_correlation > depth->correlation - v.options.min_peak_margin) {
      continue;
    }
    const auto top_at = v.correlator->point_at(left[top], depth->horizontal_distance_m);
    const auto bottom_at = v.correlator->point_at(left[bottom], depth->horizontal_distance_m);
    if (!top_at || !bottom_at) continue;
    const auto top_px = v.triangulator.project_right(*top_at);
    const auto bottom_px = v.triangulator.project_right(*bottom_at);
    if (!top_px || !bottom_px) continue;
    right[top] = *top_px;
    right[bottom] = *bottom_px;
    views[1].sigma_px[top] = views[1].sigma_px[bottom] = 0.0;
    middle_m[top == 0 ? 0 : 1] = 0.5 * (*top_at + *bottom_at);
  }
  // A peak on another edge within the search (a repeated door's, the neighbour's) can move a side
  // a metre: sides so placed that the door is wider than its class allows are not what the
  // outlines show, and the right outline's are kept.
  if (middle_m[0] && middle_m[1] && door.max_width_m > 0.0 &&
      (*middle_m[0] - *middle_m[1]).norm() > door.max_width_m) {
    views[1] = outline;
  }
}

// The least visible height the door's fit accepts (metres): half the class's least typical height
// (a size from the prior) and the least of its height range (a measured one); 0 when either bound
// is missing.
double least_visible_height_m(const StereoViews& v, const StereoMatchOptions::DoorClass& door) {
  const StereoMatchOptions::ExtentRange* range = height_range(v.options, door.type);
  if (door.typical_heights_m.empty() || !range) return 0.0;
  return std::min(kMinVisibleOfTypicalHeight * door.typical_heights_m.front(), range->min_m);
}

// Before the sides' correlation, whether the outlines are too short for the door at any depth the
// correlation and the fit can give them. A side's depth is taken as the fit takes it from the right
// image: where the right outline's side line crosses the epipolar line of the left side's middle.
// The correlation moves it by its search and the fit by the position gate, together `reach_px` of
// image motion; the farthest depth so reached, D_far, makes the side longest: |X(top, D_far) -
// X(bottom, D_far)| on the left rays (SideCorrelator::point_at), times the right outline's side
// length over the left's where that is longer. Refused when twice the longest side stays under
// least_visible_height_m: two outlines of different doors paired at a depth of decimetres, which
// the fit refuses after the correlation. The factor of two is the margin for what the bound
// leaves out: ideal against raw pixels of a distorted image, the right camera's own focal length
// and distance, the left corners' own error. False (no bound) unless both sides are on the
// outline in both images.
bool too_short_at_any_depth(const StereoViews& v, const std::array<DoorOutlineView, 2>& views,
                            double reach_px, double least_height_m, StereoPairTrace& trace) {
  if (!(least_height_m > 0.0)) return false;
  const std::array<Eigen::Vector2d, 4>& left = views[0].corners_ideal_px;
  const std::array<Eigen::Vector2d, 4>& right = views[1].corners_ideal_px;
  double longest_m = 0.0;
  for (const auto& [top, bottom] : {std::array<std::size_t, 2>{0, 3}, {1, 2}}) {
    for (const DoorOutlineView& view : views) {
      if (!on_side(view.states[top]) || !on_side(view.states[bottom])) return false;
    }
    // The side's depth from the right side line (not from where its ends are).
    const Eigen::Vector2d left_middle = 0.5 * (left[top] + left[bottom]);
    const Eigen::Vector3d crossing =
        v.epipolar.right_line(left_middle)
            .cross(right[top].homogeneous().cross(right[bottom].homogeneous()));
    if (!(std::abs(crossing.z()) > 1e-12)) return false;
    const auto middle_point =
        v.triangulator.point(left_middle, Eigen::Vector2d(crossing.head<2>() / crossing.z()));
    if (!middle_point) return false;
    // lambda = 1 / D, and the side's image motion per unit of lambda at its depth.
    const Eigen::Vector3d middle = *middle_point;
    const double lambda = 1.0 / v.correlator->horizontal_distance(middle);
    const auto at = v.triangulator.project_right(middle);
    const auto nearer = v.triangulator.project_right(middle / 1.001);
    if (!(lambda > 0.0) || !at || !nearer) return false;
    const double px_per_lambda = (*nearer - *at).norm() / (0.001 * lambda);
    const double far_lambda = lambda - reach_px / px_per_lambda;
    const double far_m = far_lambda > 0.0 ? std::min(1.0 / far_lambda, v.options.max_depth_m)
                                          : v.options.max_depth_m;
    const auto top_far = v.correlator->point_at(left[top], far_m);
    const auto bottom_far = v.correlator->point_at(left[bottom], far_m);
    if (!top_far || !bottom_far) return false;
    const double left_px = (left[bottom] - left[top]).norm();
    const double right_px = (right[bottom] - right[top]).norm();
    longest_m = std::max(longest_m, (*top_far - *bottom_far).norm() *
                                        std::max(1.0, right_px / std::max(left_px, 1e-9)));
  }
  if (2.0 * longest_m >= least_height_m) return false;
  refuse(trace, StereoGate::kHeight, 2.0 * longest_m, least_height_m);
  return true;
}

// Before the sides' correlation (the costliest step), what the two outlines alone refuse: where
// both show the door's width (no corner on an edge or hidden), unlike widths: two views of one
// door at about one depth are about as wide (max_area_ratio; an outline's width is the mean of its
// top and bottom edges' lengths, pixels). Their corners are the fit's to judge.
bool widths_refused(const StereoViews& v, const std::array<DoorOutlineView, 2>& views,
                    StereoPairTrace& trace) {
  const auto shows_width = [](const DoorOutlineView& o) {
    return std::all_of(o.states.begin(), o.states.end(), [](CornerState state) {
      return state == CornerState::kSeen || state == CornerState::kOnSide;
    });
  };
  if (!shows_width(views[0]) || !shows_width(views[1])) return false;
  const auto width_px = [](const DoorOutlineView& o) {
    const std::array<Eigen::Vector2d, 4>& c = o.corners_ideal_px;
    return 0.5 * ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
  };
  const double a = width_px(views[0]), b = width_px(views[1]);
  const double ratio = std::max(a, b) / std::max(std::min(a, b), 1e-9);
  const double max_ratio = std::max(v.options.max_area_ratio, 1.0);
  if (ratio <= max_ratio) return false;
  refuse(trace, StereoGate::kAreaRatio, ratio, max_ratio);
  return true;
}

}  // namespace

std::optional<Candidate> judge_door(const StereoViews& v, int l, int r,
                                    const std::array<CornerState, 4>& left,
                                    const std::array<CornerState, 4>& right, StereoPairTrace& trace,
                                    Explanation explanation) {
  const StereoMatchOptions& options = v.options;
  const StereoMatchOptions::DoorClass& door = *door_class_of(options, v.left[l].type);
  std::array<DoorOutlineView, 2> views{DoorOutlineView{corner_array(v.left_corners[l]), left},
                                       DoorOutlineView{corner_array(v.right_corners[r]), right}};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::array<bool, 4>& beyond =
        (k == 0 ? v.left_beyond_image
                : v.right_beyond_image)[static_cast<std::size_t>(k == 0 ? l : r)];
    for (std::size_t j = 0; j < 4; ++j) {
      if (beyond[j] && views[k].states[j] == CornerState::kSeen) {
        views[k].states[j] = CornerState::kHidden;
      }
    }
  }
  // Corners within the position gate of two door outlines: a strip that segmentation adds along a
  // side in one image moves its corners by a few per cent of the height. An occluder's
  // explanation of a refused pair is held to the pixel gate alone: its outlines already disagree
  // with a whole door, and the explanation must fit where they do not.
  PartlySeenLimits limits;
  limits.tolerance_px = options.max_epipolar_distance_px;
  if (explanation == Explanation::kOutlines) {
    limits.tolerance_px =
        std::max(limits.tolerance_px,
                 kRectangleEpipolarFraction * 0.5 * (v.left[l].height_px + v.right[r].height_px));
  }
  limits.hidden_by_occluder = explanation == Explanation::kCornerHidden;
  if (widths_refused(v, views, trace)) return std::nullopt;
  // Uncorrelated, a right outline's side is where segmentation put it: within the position
  // gate's tolerance of the left one's, not within the pixel noise (a side that correlates is
  // measured to that noise: correlate_sides).
  views[1].sigma_px.fill(options.max_epipolar_distance_px);
  if (v.correlator) {
    const double reach_px = side_search_px(views[0]) + limits.tolerance_px;
    if (too_short_at_any_depth(v, views, reach_px, least_visible_height_m(v, door), trace)) {
      return std::nullopt;
    }
    correlate_sides(v, door, views);
  }
  return judge_partly_seen_door(l, r, views, v.rig, v.triangulator, options, door,
                                reference_depth_offset(options, v.left[l].type), limits, trace);
}

namespace {

// Two whole door outlines that the cross match refused, explained by an occluder in front of the
// door (a chair, the table's top): the lower corners on the sides (the occluder hides the door's
// lower part: the pair was too short, or its lower corners off the fit), or one corner hidden in
// both images (its contour is where the side gate or the fit found no door edge). Exactly one
// hidden corner must explain the pair: with two, the outlines do not say which one the occluder
// hides, and the doors they give differ. `trace` keeps the cross match's refusal unless the pair is
// so placed.
std::optional<Candidate> explain_by_occluder(const StereoViews& v, int l, int r,
                                             StereoPairTrace& trace) {
  StereoPairTrace retry = trace;
  retry.refused_by = StereoGate::kNone;
  retry.value = retry.limit = 0.0;
  if (may_be_occluder_cut(trace)) {
    constexpr std::array<CornerState, 4> kLowerOnSides{CornerState::kSeen, CornerState::kSeen,
                                                       CornerState::kOnSide, CornerState::kOnSide};
    StereoPairTrace t = retry;
    if (auto c =
            judge_door(v, l, r, kLowerOnSides, kLowerOnSides, t, Explanation::kLowerPartHidden)) {
      trace = t;
      return c;
    }
  }
  const bool position_or_side = trace.refused_by == StereoGate::kEpipolar ||
                                trace.refused_by == StereoGate::kSideTilt ||
                                trace.refused_by == StereoGate::kRectangleFit;
  if (!position_or_side) return std::nullopt;
  // Two views of one door are about as large (the appearance gate), and the three corners an
  // occluder leaves lie on each other's epipolar lines: pairs of two doors are not fitted.
  const Detection& dl = v.left[l];
  const Detection& dr = v.right[r];
  if (dl.area_px > 0.0 && dr.area_px > 0.0 &&
      std::abs(std::log(dl.area_px / dr.area_px)) > v.log_max_area_ratio) {
    return std::nullopt;
  }
  const double tolerance_px =
      std::max(v.options.max_epipolar_distance_px,
               kRectangleEpipolarFraction * 0.5 * (dl.height_px + dr.height_px));
  std::array<bool, 4> on_epipolar{};
  for (std::size_t j = 0; j < 4; ++j) {
    on_epipolar[j] = v.epipolar.distance_px(v.left_corners[l][j].ideal_px,
                                            v.right_corners[r][j].ideal_px) <= tolerance_px;
  }
  std::optional<Candidate> found;
  StereoPairTrace found_trace;
  int explaining = 0;
  for (std::size_t hidden = 0; hidden < 4; ++hidden) {
    bool others_on_epipolar = true;
    for (std::size_t j = 0; j < 4; ++j) others_on_epipolar &= j == hidden || on_epipolar[j];
    if (!others_on_epipolar) continue;
    std::array<CornerState, 4> states{CornerState::kSeen, CornerState::kSeen, CornerState::kSeen,
                                      CornerState::kSeen};
    states[hidden] = CornerState::kHidden;
    StereoPairTrace t = retry;
    auto placed = judge_door(v, l, r, states, states, t, Explanation::kCornerHidden);
    if (!placed) continue;
    if (++explaining > 1) return std::nullopt;
    found = std::move(placed);
    found_trace = t;
    found_trace.occluded_corner = true;
  }
  if (explaining != 1) return std::nullopt;
  trace = found_trace;
  return found;
}

}  // namespace

bool is_door_pair(const StereoViews& v, int l, int r) {
  return cuts_of_one_door(v.left[l].border_cut, v.right[r].border_cut) &&
         door_class_of(v.options, v.left[l].type) != nullptr && v.left_corners[l].size() == 4 &&
         v.right_corners[r].size() == 4 && v.up.norm() > 0.0;
}

void explain_unpaired_by_occluder(const StereoViews& v, std::vector<StereoPairTrace> occluded,
                                  std::vector<Candidate>& assigned,
                                  std::vector<StereoPairTrace>* traces) {
  std::vector<char> left_taken(v.left.size(), 0), right_taken(v.right.size(), 0);
  for (const Candidate& c : assigned) {
    left_taken[static_cast<std::size_t>(c.left)] = 1;
    right_taken[static_cast<std::size_t>(c.right)] = 1;
  }
  std::vector<Candidate> explained;
  std::vector<StereoPairTrace> explained_traces;
  for (StereoPairTrace& t : occluded) {
    if (left_taken[static_cast<std::size_t>(t.left_detection)] ||
        right_taken[static_cast<std::size_t>(t.right_detection)]) {
      continue;
    }
    if (auto c = explain_by_occluder(v, t.left_detection, t.right_detection, t)) {
      explained.push_back(std::move(*c));
      explained_traces.push_back(t);
    }
  }
  for (Candidate& c :
       assign(explained, static_cast<int>(v.left.size()), static_cast<int>(v.right.size()))) {
    if (traces) {
      for (StereoPairTrace& t : *traces) {
        if (t.left_detection != c.left || t.right_detection != c.right) continue;
        for (const StereoPairTrace& e : explained_traces) {
          if (e.left_detection == c.left && e.right_detection == c.right) t = e;
        }
      }
    }
    assigned.push_back(std::move(c));
  }
  std::sort(assigned.begin(), assigned.end(),
            [](const Candidate& a, const Candidate& b) { return a.left < b.left; });
}

}  // namespace vsl::recognition::detail

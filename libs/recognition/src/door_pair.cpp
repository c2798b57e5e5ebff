// The door gates of a pair of outlines and the door's centre (door_pair.hpp). Moved here from
// match_and_triangulate, whose gate order they keep: the position gate, then the side gate, then
// (after the size gates and the reference points' triangulation) the centre.
#include "door_pair.hpp"

#include <algorithm>
#include <cmath>

#include "pair_refusal.hpp"

namespace vsl::recognition::detail {
namespace {

// rectangle_containment_excess_px: a strip that segmentation adds in one image only is at most
// this fraction of the longer side (top edge face, shadow: a few pixels). Without the bound the
// galley gained 3 true and 5 false door percepts (drawer stacks merged in one image); the kitchen
// was the same for any bound from 0.15 to 1 and lost recall at 0.1.
constexpr double kMaxRectangleSideMismatch = 0.15;

}  // namespace

// How far two views of a rectangle's vertical sides fail to nest along the epipolar direction
// (pixels): for each side (corners 0-3 and 1-2, clockwise from the top left), the signed
// distances of the right image's top and bottom ends from the epipolar lines of the left image's
// (positive down the side). One image's side may lie within the other's: segmentation adds a
// strip along the top or the bottom of a door in one image only (its top edge face seen from
// above, the shadow under the worktop), which moves the outline's centre but not its sides. A
// side shifted as a whole is a wrong pairing, and one more than kMaxRectangleSideMismatch longer
// than the other is two objects merged in one image (a drawer stack against one drawer front);
// both count as excess.
double rectangle_containment_excess_px(const std::vector<IdealPixel>& left,
                                       const std::vector<IdealPixel>& right,
                                       const EpipolarGeometry& epipolar) {
  double excess = 0.0;
  for (const auto& [top, bottom] : {std::pair{0, 3}, std::pair{1, 2}}) {
    const Eigen::Vector2d down = right[bottom].ideal_px - right[top].ideal_px;
    const auto signed_px = [&](int k) {
      const Eigen::Vector3d line = epipolar.right_line(left[k].ideal_px);
      const double d = line.head<2>().dot(right[k].ideal_px) + line.z();
      return line.head<2>().dot(down) >= 0.0 ? d : -d;
    };
    const double d_top = signed_px(top), d_bottom = signed_px(bottom);
    const double right_within_left = std::max({0.0, -d_top, d_bottom});
    const double left_within_right = std::max({0.0, d_top, -d_bottom});
    excess = std::max(excess, std::min(right_within_left, left_within_right));
    const double left_px = (left[bottom].ideal_px - left[top].ideal_px).norm();
    const double right_px = down.norm();
    excess = std::max(excess, std::abs(left_px - right_px) -
                                  kMaxRectangleSideMismatch * std::max(left_px, right_px));
  }
  return excess;
}

std::optional<DoorSides> judge_door_sides(const DoorOutlines& outlines,
                                          const Triangulator& triangulator,
                                          const Eigen::Vector3d& up_in_left_camera,
                                          bool have_correlator, const StereoMatchOptions& options,
                                          StereoPairTrace& trace) {
  // A pair of outlines with one side that is no door edge in one image (tilted: an
  // occluder's contour, a neighbour's strip) still has its centre from the three good sides
  // (Triangulator::rectangle_centre_from_one_side); more than one such side is refused.
  DoorSides out;
  if (options.max_side_tilt_rad > 0.0 && up_in_left_camera.norm() > 0.0) {
    const std::array<std::array<double, 2>, 2> tilts =
        triangulator.side_tilts(outlines.left, outlines.right, up_in_left_camera);
    const double max_sin = std::sin(options.max_side_tilt_rad);
    int bad = 0, bad_side = -1, bad_image = -1;
    double tilt = 0.0;
    for (int side = 0; side < 2; ++side) {
      for (int image = 0; image < 2; ++image) {
        tilt = std::max(tilt, tilts[side][image]);
        if (tilts[side][image] > max_sin) {
          ++bad;
          bad_side = side;
          bad_image = image;
        }
      }
    }
    if (bad == 1) {
      out.one_side_centre = triangulator.rectangle_centre_from_one_side(
          outlines.left, outlines.right, up_in_left_camera, 1 - bad_side, 1 - bad_image);
      // Otherwise the side tilted in one outline is still a door edge in the other image: its
      // depth can come from the images (side_correlation.hpp), swept from that image, instead
      // of from the horizontal planes, which fail where the door's top or bottom edge is near
      // the cameras' height (or the outline's corner there is off). The pair is kept only if
      // that side correlates, and then passes the level-edge gate like any other.
      if (!out.one_side_centre && have_correlator) {
        out.side_needing_correlation = bad_side;
        out.side_needing_left_image = bad_image == 0;
      }
    }
    out.worst_tilt = tilt;
    if (bad > 0 && !out.one_side_centre && out.side_needing_correlation < 0) {
      return refuse(trace, StereoGate::kSideTilt, std::asin(std::min(tilt, 1.0)),
                    options.max_side_tilt_rad);
    }
  }
  return out;
}

DoorCentre door_centre(const DoorOutlines& outlines, const DoorSides& sides,
                       const Triangulator& triangulator, const SideCorrelator* forward,
                       const SideCorrelator* reverse, const Eigen::Isometry3d& left_T_right,
                       const Eigen::Vector3d& up_in_left_camera, const StereoMatchOptions& options,
                       double max_width_m, StereoPairTrace& trace) {
  const auto refused = [&](StereoGate gate, double value, double limit) {
    trace.refused_by = gate;
    trace.value = value;
    trace.limit = limit;
    DoorCentre out;
    out.refused = true;
    return out;
  };
  DoorCentre out;
  out.centre = sides.one_side_centre;
  if (!sides.one_side_centre) {
    std::optional<std::array<Eigen::Vector3d, 4>> ends =
        triangulator.rectangle_ends(outlines.left, outlines.right, sides.side_needing_correlation);
    // Each side's depth from the images around it (side_correlation.hpp), searched around
    // the outlines' depth by a margin that covers a stile lost in one image.
    if (!ends && sides.side_needing_correlation >= 0) {
      return refused(StereoGate::kSideTilt, std::asin(std::min(sides.worst_tilt, 1.0)),
                     options.max_side_tilt_rad);
    }
    const std::optional<std::array<Eigen::Vector3d, 4>> outline_ends = ends;
    if (ends && forward) {
      const std::array<Eigen::Vector2d, 4> corners = outlines.left;
      const auto vertical = Triangulator::vertical_sides(corners);
      const double width_px = 0.5 * (corners[vertical[0][0]] + corners[vertical[0][1]] -
                                     corners[vertical[1][0]] - corners[vertical[1][1]])
                                        .norm();
      const double search_px = kSideSearchPx + kSideSearchWidthFraction * width_px;
      for (int s = 0; s < 2; ++s) {
        const auto [i, j] = vertical[static_cast<std::size_t>(s)];
        // A side tilted in the left outline is searched from the right image's side into
        // the left image: the same sweep with the cameras' roles swapped.
        const bool from_right =
            s == sides.side_needing_correlation && sides.side_needing_left_image;
        const SideCorrelator& sweep = from_right ? *reverse : *forward;
        const std::array<Eigen::Vector2d, 4> seen = from_right ? outlines.right : corners;
        const Eigen::Isometry3d to_sweep =
            from_right ? left_T_right.inverse() : Eigen::Isometry3d::Identity();
        // Around the outlines' depth of the side; for the tilted one, of the good side: the
        // tilted outline's ends are off, and the two sides of a door differ by a few pixels
        // of disparity at most (0.5 m turned 40 deg at 2.5 m: 2.5 px).
        const int from = s == sides.side_needing_correlation ? 1 - s : s;
        const double initial_m =
            0.5 * (sweep.horizontal_distance(to_sweep * (*ends)[2 * from]) +
                   sweep.horizontal_distance(to_sweep * (*ends)[2 * from + 1]));
        const auto depth = sweep.correlate(seen[i], seen[j], initial_m, search_px,
                                           options.min_depth_m, options.max_depth_m);
        const double correlation = depth ? depth->correlation : -1.0;
        auto top = depth ? sweep.point_at(seen[i], depth->horizontal_distance_m) : std::nullopt;
        auto bottom = depth ? sweep.point_at(seen[j], depth->horizontal_distance_m) : std::nullopt;
        if (from_right && top && bottom) {
          top = left_T_right * *top;
          bottom = left_T_right * *bottom;
        }
        if (correlation < options.min_side_correlation || !top || !bottom) {
          if (s == sides.side_needing_correlation) {
            return refused(StereoGate::kSideTilt, std::asin(std::min(sides.worst_tilt, 1.0)),
                           options.max_side_tilt_rad);
          }
          continue;
        }
        (*ends)[2 * s] = *top;
        (*ends)[2 * s + 1] = *bottom;
      }
    }
    // A side's correlation peak on another edge (a repeated door's, the neighbour's) within
    // the search range can move it a metre: a door wider than its class allows is not what the
    // outlines show, and their own depths are kept.
    if (ends && max_width_m > 0.0 && Triangulator::rectangle_width(*ends) > max_width_m) {
      ends = outline_ends;
    }
    if (ends) {
      // Both sides' heights, h_s = (T_s - B_s) . u (T, B: the side's top and bottom ends, u up),
      // agree within max_side_height_mismatch of the taller: a door's sides are equal, and an
      // occluder that hides a corner in both images shortens one of them.
      if (options.max_side_height_mismatch > 0.0) {
        const Eigen::Vector3d& u = up_in_left_camera;
        const double a = std::abs(((*ends)[0] - (*ends)[1]).dot(u));
        const double b = std::abs(((*ends)[2] - (*ends)[3]).dot(u));
        const double mismatch = std::abs(a - b) / std::max({a, b, 1e-9});
        if (mismatch > options.max_side_height_mismatch) {
          return refused(StereoGate::kSideHeights, mismatch, options.max_side_height_mismatch);
        }
      }
      out.centre = Triangulator::rectangle_centre(*ends);
      // Both sides measured: the edges between their ends must be level.
      if (options.max_edge_slope_rad > 0.0) {
        const std::optional<double> slope = Triangulator::edge_slope(*ends, up_in_left_camera);
        if (slope && std::atan(*slope) > options.max_edge_slope_rad) {
          return refused(StereoGate::kEdgeSlope, std::atan(*slope), options.max_edge_slope_rad);
        }
      }
    }
  }
  return out;
}

}  // namespace vsl::recognition::detail

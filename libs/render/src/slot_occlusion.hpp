// Light lost in narrow slots: the 4 mm gap between two cupboard doors, the carcass edge behind a
// door. A Lambert facet lit by a distant light and an ambient term is as bright deep inside a
// slot as in the open, so two flush doors render as one blue plane; a real camera sees the gap as
// a dark line because little light reaches into it. No shadow maps: a facet that faces another
// facet across a slot of width w (its centroid, moved along its normal by w <= max_width, lands
// inside the other facet, whose normal is opposite) keeps the fraction w / (w + depth) of its
// light, where depth is the facet's shorter side (how deep the slot is): the view factor of a slot
// opening of width w seen from its walls, to first order.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace vsl::render {

// Per triangle, the factor (0, 1] its shade is multiplied by; 1 for triangles in no slot.
// triangles index world_vertices_m; world_planes hold each triangle's unit normal n and offset d
// (n . x = d, world frame, m). max_width_m <= 0: all ones. Triangles marked in `two_sided` (an
// imported mesh's, drawn in both windings) take no part, factor 1: each faces its own reverse
// across no gap, and a flat mesh's thousands of coplanar triangles would make the search
// quadratic. Empty `two_sided`: none is.
std::vector<float> slot_light_factors(const std::vector<Eigen::Vector3d>& world_vertices_m,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                      const std::vector<Eigen::Vector4d>& world_planes,
                                      double max_width_m, const std::vector<bool>& two_sided = {});

}  // namespace vsl::render

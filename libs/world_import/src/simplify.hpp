// Fewer triangles for huge meshes: vertex clustering (Rossignac and Borrel) on a grid whose cell
// grows until the mesh fits the budget. It keeps the outline within a cell of the original and
// needs no topology, which CAD meshes often lack.
#pragma once

#include <cstddef>

#include "scene.hpp"

namespace vsl::world_import {

struct SimplifyResult {
  TriangleSoup soup;
  double cell_m = 0.0;  // the cell used; 0 when the mesh was within budget and left alone
};

// Unused vertices and degenerate triangles are dropped in any case.
SimplifyResult simplify(const TriangleSoup& soup, std::size_t max_triangles);

}  // namespace vsl::world_import

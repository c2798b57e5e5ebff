#include "simplify.hpp"

#include <cmath>
#include <unordered_map>

namespace vsl::world_import {
namespace {

// One pass: vertices in a cell merge to their mean; triangles that collapse go.
TriangleSoup cluster(const TriangleSoup& soup, double cell_m) {
  std::unordered_map<std::uint64_t, std::uint32_t> cell_index;
  std::vector<Eigen::Vector3d> sums;
  std::vector<int> counts;
  std::vector<std::uint32_t> remap(soup.vertices_m.size());
  for (std::size_t v = 0; v < soup.vertices_m.size(); ++v) {
    std::uint64_t key = v;  // cell 0: every vertex its own
    if (cell_m > 0) {
      const Eigen::Vector3f& p = soup.vertices_m[v];
      auto cell = [&](float x) {
        return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cell_m)) +
                                          (1 << 20)) &
               0x1fffff;
      };
      key = cell(p.x()) | (cell(p.y()) << 21) | (cell(p.z()) << 42);
    }
    const auto [it, inserted] =
        cell_index.try_emplace(key, static_cast<std::uint32_t>(sums.size()));
    if (inserted) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      counts.push_back(0);
    }
    sums[it->second] += soup.vertices_m[v].cast<double>();
    ++counts[it->second];
    remap[v] = it->second;
  }
  TriangleSoup out;
  std::vector<std::int64_t> used(sums.size(), -1);
  for (const auto& t : soup.triangles) {
    const std::array<std::uint32_t, 3> m{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2]) continue;
    std::array<std::uint32_t, 3> kept{};
    for (int k = 0; k < 3; ++k) {
      if (used[m[k]] < 0) {
        used[m[k]] = static_cast<std::int64_t>(out.vertices_m.size());
        out.vertices_m.push_back((sums[m[k]] / counts[m[k]]).cast<float>());
      }
      kept[k] = static_cast<std::uint32_t>(used[m[k]]);
    }
    out.triangles.push_back(kept);
  }
  return out;
}

}  // namespace

SimplifyResult simplify(const TriangleSoup& soup, std::size_t max_triangles) {
  SimplifyResult result{cluster(soup, 0.0), 0.0};
  // Start at 2 mm, below what the simulated head resolves at a metre, and double.
  for (double cell = 0.002; result.soup.triangles.size() > max_triangles && cell < 10.0;
       cell *= 2.0) {
    result = {cluster(soup, cell), cell};
  }
  return result;
}

}  // namespace vsl::world_import

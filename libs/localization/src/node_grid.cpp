#include "vsl/localization/node_grid.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <tuple>

namespace vsl::localization {

std::uint64_t NodeGrid::hash(const Key& key) {
  // Large odd multipliers spread neighbouring cells over the table (a multiplicative hash; the
  // top bits are used).
  std::uint64_t h = static_cast<std::uint32_t>(key.x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint32_t>(key.y) * 0xC2B2AE3D27D4EB4Full;
  h ^= static_cast<std::uint32_t>(key.z) * 0x165667B19E3779F9ull;
  h ^= static_cast<std::uint64_t>(key.type) * 0xD6E8FEB86659FD93ull;
  return h ^ (h >> 29);
}

NodeGrid NodeGrid::build(const world::WorldGraph& graph, double cell_m) {
  if (!(cell_m > 0.0) || !std::isfinite(cell_m)) {
    throw std::invalid_argument("node grid cell must be a positive number of metres");
  }
  NodeGrid grid;
  grid.inverse_cell_ = 1.0 / cell_m;
  const std::size_t n = graph.node_count();
  std::vector<std::pair<Key, world::NodeIndex>> keyed(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto node = static_cast<world::NodeIndex>(i);
    const Eigen::Vector3d& p = graph.world_position_m(node);
    keyed[i] = {{grid.cell_of(p.x()), grid.cell_of(p.y()), grid.cell_of(p.z()), graph.type(node)},
                node};
  }
  const auto order = [](const Key& k) { return std::tie(k.type, k.x, k.y, k.z); };
  std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
    return std::make_pair(order(a.first), a.second) < std::make_pair(order(b.first), b.second);
  });
  std::size_t cells = 0;
  for (std::size_t i = 0; i < n; ++i) cells += (i == 0 || !(keyed[i].first == keyed[i - 1].first));
  grid.table_.resize(std::bit_ceil(std::max<std::size_t>(2 * cells, 16)));
  grid.nodes_.reserve(n);
  grid.positions_.reserve(n);
  const std::size_t mask = grid.table_.size() - 1;
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && keyed[end].first == keyed[begin].first) {
      grid.nodes_.push_back(keyed[end].second);
      grid.positions_.push_back(graph.world_position_m(keyed[end].second));
      ++end;
    }
    std::size_t slot = hash(keyed[begin].first) & mask;
    while (grid.table_[slot].key.type != 0xffffffffu) slot = (slot + 1) & mask;
    grid.table_[slot] = {keyed[begin].first, static_cast<std::uint32_t>(begin),
                         static_cast<std::uint32_t>(end)};
    begin = end;
  }
  return grid;
}

const NodeGrid::Slot* NodeGrid::find(const Key& key) const {
  if (table_.empty()) return nullptr;
  const std::size_t mask = table_.size() - 1;
  for (std::size_t slot = hash(key) & mask;; slot = (slot + 1) & mask) {
    const Slot& s = table_[slot];
    if (s.key == key) return &s;
    if (s.key.type == 0xffffffffu) return nullptr;
  }
}

std::optional<NodeGrid::Nearest> NodeGrid::nearest(world::TypeId type,
                                                   const Eigen::Vector3d& world_point_m,
                                                   double radius_m) const {
  std::optional<Nearest> best;
  for_each_within(type, world_point_m, radius_m, [&](world::NodeIndex node, double distance_m) {
    if (!best || distance_m < best->distance_m) best = Nearest{node, distance_m};
  });
  return best;
}

}  // namespace vsl::localization

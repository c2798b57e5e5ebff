#include "vsl/fusion/isolation_filter.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

namespace vsl::fusion {
namespace {

using Cell = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

struct Entry {
  std::size_t frame;
  std::size_t index;
};

Cell cell_of(const Eigen::Vector3d& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x() / size)),
          static_cast<std::int64_t>(std::floor(p.y() / size)),
          static_cast<std::int64_t>(std::floor(p.z() / size))};
}

}  // namespace

std::vector<std::vector<bool>> non_isolated(const std::vector<Frame>& frames,
                                            double isolation_distance_m) {
  std::vector<std::vector<bool>> keep(frames.size());
  // Grid of cell size varpi per type: a neighbour closer than varpi is in one of the 27 cells
  // around a percept's own.
  std::map<std::string, std::map<Cell, std::vector<Entry>>> grid;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    keep[f].assign(frames[f].percepts.size(), false);
    for (std::size_t i = 0; i < frames[f].percepts.size(); ++i) {
      const Percept& p = frames[f].percepts[i];
      grid[p.type][cell_of(p.ego_position_m, isolation_distance_m)].push_back({f, i});
    }
  }
  const double limit2 = isolation_distance_m * isolation_distance_m;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (std::size_t i = 0; i < frames[f].percepts.size(); ++i) {
      const Percept& p = frames[f].percepts[i];
      const auto& cells = grid[p.type];
      const auto [cx, cy, cz] = cell_of(p.ego_position_m, isolation_distance_m);
      bool found = false;
      for (std::int64_t dx = -1; dx <= 1 && !found; ++dx) {
        for (std::int64_t dy = -1; dy <= 1 && !found; ++dy) {
          for (std::int64_t dz = -1; dz <= 1 && !found; ++dz) {
            const auto cell = cells.find({cx + dx, cy + dy, cz + dz});
            if (cell == cells.end()) continue;
            for (const Entry& other : cell->second) {
              // Another frame: a percept repeated within its own frame is not confirmation.
              if (other.frame == f) continue;
              const Percept& q = frames[other.frame].percepts[other.index];
              if ((q.ego_position_m - p.ego_position_m).squaredNorm() < limit2) {
                found = true;
                break;
              }
            }
          }
        }
      }
      keep[f][i] = found;
    }
  }
  return keep;
}

}  // namespace vsl::fusion

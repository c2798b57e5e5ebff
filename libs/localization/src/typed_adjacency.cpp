#include "vsl/localization/typed_adjacency.hpp"

#include <algorithm>

namespace vsl::localization {

TypedAdjacency TypedAdjacency::build(const world::WorldGraph& graph) {
  TypedAdjacency out;
  out.types_ = graph.type_count();
  const std::size_t n = graph.node_count();
  const std::size_t stride = out.types_ + 1;
  out.start_.assign(n * stride, 0);
  std::size_t total = 0;
  for (std::size_t i = 0; i < n; ++i)
    total += graph.neighbours(static_cast<world::NodeIndex>(i)).size();
  out.neighbours_.reserve(total);
  std::vector<std::size_t> count(out.types_);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = graph.neighbours(static_cast<world::NodeIndex>(i));
    std::fill(count.begin(), count.end(), 0);
    for (const world::Neighbour& nb : row) ++count[graph.type(nb.node)];
    const std::size_t base = out.neighbours_.size();
    std::size_t offset = base;
    for (std::size_t t = 0; t < out.types_; ++t) {
      out.start_[i * stride + t] = offset;
      offset += count[t];
    }
    out.start_[i * stride + out.types_] = offset;
    out.neighbours_.resize(offset);
    std::vector<std::size_t> fill(
        out.start_.begin() + static_cast<std::ptrdiff_t>(i * stride),
        out.start_.begin() + static_cast<std::ptrdiff_t>(i * stride + out.types_));
    for (const world::Neighbour& nb : row) out.neighbours_[fill[graph.type(nb.node)]++] = nb;
    for (std::size_t t = 0; t < out.types_; ++t) {
      std::sort(
          out.neighbours_.begin() + static_cast<std::ptrdiff_t>(out.start_[i * stride + t]),
          out.neighbours_.begin() + static_cast<std::ptrdiff_t>(out.start_[i * stride + t + 1]),
          [](const world::Neighbour& a, const world::Neighbour& b) {
            return a.distance_m < b.distance_m || (a.distance_m == b.distance_m && a.node < b.node);
          });
    }
  }
  return out;
}

std::span<const world::Neighbour> TypedAdjacency::within(world::NodeIndex node, world::TypeId type,
                                                         double min_length_m,
                                                         double max_length_m) const {
  const std::size_t at = static_cast<std::size_t>(node) * (types_ + 1) + type;
  const auto first = neighbours_.begin() + static_cast<std::ptrdiff_t>(start_[at]);
  const auto last = neighbours_.begin() + static_cast<std::ptrdiff_t>(start_[at + 1]);
  const auto lo =
      std::lower_bound(first, last, min_length_m,
                       [](const world::Neighbour& x, double v) { return x.distance_m < v; });
  const auto hi = std::upper_bound(
      lo, last, max_length_m, [](double v, const world::Neighbour& x) { return v < x.distance_m; });
  return {neighbours_.data() + (lo - neighbours_.begin()), static_cast<std::size_t>(hi - lo)};
}

}  // namespace vsl::localization

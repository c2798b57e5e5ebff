#include "vsl/world/world_graph.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace vsl::world {
namespace {

// Integer cell of a point in a grid of edge `cell_m`; packed into one key for hashing. 21 bits a
// coordinate covers +-1M cells: +-4000 km at 4 m cells.
std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t kOffset = 1 << 20;
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(x + kOffset) & kMask) << 42 |
         (static_cast<std::uint64_t>(y + kOffset) & kMask) << 21 |
         (static_cast<std::uint64_t>(z + kOffset) & kMask);
}

struct Cell {
  std::int64_t x, y, z;
};

// Sorts links by length, stably. Lengths are non-negative floats, whose IEEE-754 bit patterns
// order like the numbers, so an LSD radix sort over three 11-bit digits does it in linear time:
// the typed lists of a 100k-object building hold millions of links, where std::stable_sort took
// a third of the graph build.
void sort_by_length(std::vector<TypedLink>& links) {
  if (links.size() < 512) {
    std::stable_sort(links.begin(), links.end(), [](const TypedLink& x, const TypedLink& y) {
      return x.length_m < y.length_m;
    });
    return;
  }
  std::vector<TypedLink> buffer(links.size());
  std::vector<TypedLink>* from = &links;
  std::vector<TypedLink>* to = &buffer;
  constexpr int kDigitBits = 11;
  constexpr std::uint32_t kBuckets = 1u << kDigitBits;
  for (int shift = 0; shift < 32; shift += kDigitBits) {
    std::array<std::size_t, kBuckets + 1> start{};
    auto digit = [shift](const TypedLink& link) {
      return (std::bit_cast<std::uint32_t>(link.length_m) >> shift) & (kBuckets - 1);
    };
    for (const TypedLink& link : *from) ++start[digit(link) + 1];
    for (std::uint32_t b = 0; b < kBuckets; ++b) start[b + 1] += start[b];
    for (const TypedLink& link : *from) (*to)[start[digit(link)]++] = link;
    std::swap(from, to);
  }
  if (from != &links) links.swap(*from);
}

// A link of Eq. 6 between nodes a < b, d metres apart.
struct Pair {
  NodeIndex a, b;
  float d;
};

// The node set: objects of the selected types, types interned in order of first appearance.
struct Nodes {
  std::vector<std::size_t> object_index;
  std::vector<Eigen::Vector3d> positions;
  std::vector<TypeId> types;
  std::vector<std::string> type_names;
  std::vector<std::size_t> type_counts;
};

Nodes select_nodes(const WorldModel& world, const WorldGraphOptions& options) {
  Nodes out;
  std::unordered_map<std::string, TypeId> type_ids;
  const auto add = [&](std::size_t object, const std::string& type, const Eigen::Vector3d& at) {
    auto [it, inserted] = type_ids.emplace(type, static_cast<TypeId>(type_ids.size()));
    if (inserted) {
      out.type_names.push_back(type);
      out.type_counts.push_back(0);
    }
    ++out.type_counts[it->second];
    out.object_index.push_back(object);
    out.positions.push_back(at);
    out.types.push_back(it->second);
  };
  const auto listed = [](const std::vector<std::string>& types, const std::string& type) {
    return std::find(types.begin(), types.end(), type) != types.end();
  };
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectModel& object = world.objects[i];
    if (options.node_types.empty() || listed(options.node_types, object.type)) {
      add(i, object.type, object.world_position_m);
    }
    if (!listed(options.edge_node_types, object.type)) continue;
    for (const FaceEdge edge : {FaceEdge::kTop, FaceEdge::kBottom}) {
      if (const auto middle = face_edge_middle_m(object, edge)) {
        add(i, edge_node_type(object.type, edge), *middle);
      }
    }
  }
  return out;
}

// Links (Eq. 6): nodes bucketed by grid cell of edge `cell_m`; each node compared with nodes of
// higher index in the 27 surrounding cells, so every unordered pair is measured once. Pairs come
// out ordered by (a, b): nodes in index order, each node's new partners sorted, which later makes
// every adjacency row sorted by construction. Node ranges are searched on separate threads and
// concatenated in range order: the result does not depend on the number of threads.
std::vector<Pair> find_links(const std::vector<Eigen::Vector3d>& positions, double cell_m,
                             std::size_t threads) {
  const std::size_t n = positions.size();
  // Nodes sorted by cell, and each cell's range in that order.
  std::vector<Cell> cells(n);
  std::vector<std::pair<std::uint64_t, NodeIndex>> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = positions[i];
    cells[i] = {static_cast<std::int64_t>(std::floor(p.x() / cell_m)),
                static_cast<std::int64_t>(std::floor(p.y() / cell_m)),
                static_cast<std::int64_t>(std::floor(p.z() / cell_m))};
    order[i] = {cell_key(cells[i].x, cells[i].y, cells[i].z), static_cast<NodeIndex>(i)};
  }
  std::sort(order.begin(), order.end());
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> cell_range;
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && order[end].first == order[begin].first) ++end;
    cell_range.emplace(order[begin].first, std::make_pair(begin, end));
    begin = end;
  }

  const double threshold_sq = cell_m * cell_m;
  auto find_pairs = [&](std::size_t first, std::size_t last, std::vector<Pair>& pairs) {
    std::vector<Neighbour> found;  // partners of the current node
    for (std::size_t i = first; i < last; ++i) {
      const Cell c = cells[i];
      // Keys of the 27 cells around; deduplicated because far-out coordinates wrap in cell_key.
      std::array<std::uint64_t, 27> keys{};
      std::size_t key_count = 0;
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          for (std::int64_t dz = -1; dz <= 1; ++dz) {
            const std::uint64_t key = cell_key(c.x + dx, c.y + dy, c.z + dz);
            if (std::find(keys.begin(), keys.begin() + key_count, key) ==
                keys.begin() + key_count) {
              keys[key_count++] = key;
            }
          }
        }
      }
      found.clear();
      for (std::size_t k_cell = 0; k_cell < key_count; ++k_cell) {
        const auto range = cell_range.find(keys[k_cell]);
        if (range == cell_range.end()) continue;
        for (std::size_t k = range->second.first; k < range->second.second; ++k) {
          const NodeIndex j = order[k].second;
          if (j <= i) continue;
          const double d_sq = (positions[i] - positions[j]).squaredNorm();
          if (d_sq < threshold_sq) found.push_back({j, static_cast<float>(std::sqrt(d_sq))});
        }
      }
      std::sort(found.begin(), found.end(),
                [](const Neighbour& x, const Neighbour& y) { return x.node < y.node; });
      for (const Neighbour& partner : found) {
        pairs.push_back({static_cast<NodeIndex>(i), partner.node, partner.distance_m});
      }
    }
  };
  std::vector<std::vector<Pair>> chunk_pairs(threads);
  {
    std::vector<std::jthread> workers;
    for (std::size_t w = 1; w < threads; ++w) {
      workers.emplace_back(find_pairs, n * w / threads, n * (w + 1) / threads,
                           std::ref(chunk_pairs[w]));
    }
    find_pairs(0, n / threads, chunk_pairs[0]);
  }
  std::vector<Pair> pairs = std::move(chunk_pairs[0]);
  for (std::size_t w = 1; w < threads; ++w) {
    pairs.insert(pairs.end(), chunk_pairs[w].begin(), chunk_pairs[w].end());
    std::vector<Pair>().swap(chunk_pairs[w]);
  }
  return pairs;
}

// Compressed adjacency rows. Row r receives first its partners a < r (in increasing a, as pairs
// are ordered by a), then its partners b > r (increasing, from r's own sorted batch): sorted.
void fill_rows(const std::vector<Pair>& pairs, std::size_t n, std::vector<std::size_t>& row_start,
               std::vector<Neighbour>& neighbours) {
  std::vector<std::uint32_t> degree(n, 0);
  for (const Pair& p : pairs) {
    ++degree[p.a];
    ++degree[p.b];
  }
  row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) row_start[i + 1] = row_start[i] + degree[i];
  neighbours.resize(row_start[n]);
  std::vector<std::size_t> fill(row_start.begin(), row_start.end() - 1);
  for (const Pair& p : pairs) {
    neighbours[fill[p.a]++] = {p.b, p.d};
    neighbours[fill[p.b]++] = {p.a, p.d};
  }
}

// Typed link lists sorted by length for the range queries of Eq. 8, indexed from_type * t +
// to_type. Sorting is by length alone (ties keep pair order: stable), once per unordered type
// pair; the list of (b, a) is the list of (a, b) with ends swapped, so it is copied, not sorted
// again. Each unordered pair's list is sorted (and mirrored) independently: the lists are spread
// over the threads, the largest first.
std::vector<std::vector<TypedLink>> typed_link_lists(const std::vector<Pair>& pairs,
                                                     const std::vector<TypeId>& types,
                                                     std::size_t t, std::size_t threads) {
  std::vector<std::vector<TypedLink>> typed(t * t);
  std::vector<std::size_t> typed_count(t * t, 0);
  for (const Pair& p : pairs) {
    const std::size_t lo = std::min(types[p.a], types[p.b]);
    const std::size_t hi = std::max(types[p.a], types[p.b]);
    typed_count[lo * t + hi] += lo == hi ? 2 : 1;
  }
  for (std::size_t k = 0; k < t * t; ++k) typed[k].reserve(typed_count[k]);
  for (const Pair& p : pairs) {
    const TypeId ta = types[p.a], tb = types[p.b];
    if (ta <= tb) typed[ta * t + tb].push_back({p.d, p.a, p.b});
    if (tb <= ta) typed[tb * t + ta].push_back({p.d, p.b, p.a});
  }
  std::vector<std::pair<std::size_t, std::size_t>> lists;  // (lo, hi)
  for (std::size_t lo = 0; lo < t; ++lo) {
    for (std::size_t hi = lo; hi < t; ++hi) lists.emplace_back(lo, hi);
  }
  std::sort(lists.begin(), lists.end(), [&](const auto& x, const auto& y) {
    return typed[x.first * t + x.second].size() > typed[y.first * t + y.second].size();
  });
  auto sort_lists = [&](std::size_t worker) {
    for (std::size_t k = worker; k < lists.size(); k += threads) {
      const auto [lo, hi] = lists[k];
      auto& list = typed[lo * t + hi];
      sort_by_length(list);
      if (lo == hi) continue;
      auto& reverse = typed[hi * t + lo];
      reverse.reserve(list.size());
      for (const TypedLink& link : list) reverse.push_back({link.length_m, link.to, link.from});
    }
  };
  {
    std::vector<std::jthread> workers;
    for (std::size_t w = 1; w < threads; ++w) workers.emplace_back(sort_lists, w);
    sort_lists(0);
  }
  return typed;
}

}  // namespace

std::string edge_node_type(const std::string& type, FaceEdge edge) {
  return type + (edge == FaceEdge::kTop ? "_top_edge" : "_bottom_edge");
}

std::optional<Eigen::Vector3d> face_edge_middle_m(const ObjectModel& object, FaceEdge edge) {
  if (!object.size_m) return std::nullopt;
  const Eigen::Vector3d object_z = object.world_orientation.normalized() * Eigen::Vector3d::UnitZ();
  if (object_z.z() < std::cos(8.0 * std::numbers::pi / 180.0)) return std::nullopt;
  const double half_height_m = 0.5 * object.size_m->z();
  return object.world_position_m +
         (edge == FaceEdge::kTop ? half_height_m : -half_height_m) * object_z;
}

WorldGraph WorldGraph::build(const WorldModel& world, const WorldGraphOptions& options) {
  if (!(options.link_threshold_m > 0.0) || !std::isfinite(options.link_threshold_m)) {
    throw std::invalid_argument("link threshold must be a positive number of metres");
  }
  WorldGraph graph;
  graph.link_threshold_m_ = options.link_threshold_m;
  Nodes nodes = select_nodes(world, options);
  graph.object_index_ = std::move(nodes.object_index);
  graph.positions_ = std::move(nodes.positions);
  graph.types_ = std::move(nodes.types);
  graph.type_names_ = std::move(nodes.type_names);
  graph.type_counts_ = std::move(nodes.type_counts);
  const std::size_t n = graph.positions_.size();

  const std::size_t threads = std::max<std::size_t>(
      1,
      std::min<std::size_t>(options.threads ? options.threads : std::thread::hardware_concurrency(),
                            n / 1024 + 1));
  const std::vector<Pair> pairs = find_links(graph.positions_, options.link_threshold_m, threads);
  fill_rows(pairs, n, graph.row_start_, graph.neighbours_);
  graph.typed_links_ = typed_link_lists(pairs, graph.types_, graph.type_names_.size(), threads);
  return graph;
}

std::optional<TypeId> WorldGraph::find_type(const std::string& name) const {
  const auto found = std::find(type_names_.begin(), type_names_.end(), name);
  if (found == type_names_.end()) return std::nullopt;
  return static_cast<TypeId>(found - type_names_.begin());
}

std::size_t WorldGraph::count_of_type(TypeId type) const {
  return type_counts_.at(type);
}

std::span<const Neighbour> WorldGraph::neighbours(NodeIndex node) const {
  return {neighbours_.data() + row_start_[node], row_start_[node + 1] - row_start_[node]};
}

std::optional<float> WorldGraph::distance(NodeIndex a, NodeIndex b) const {
  const std::span<const Neighbour> row = neighbours(a);
  const auto found = std::lower_bound(row.begin(), row.end(), b,
                                      [](const Neighbour& x, NodeIndex v) { return x.node < v; });
  if (found == row.end() || found->node != b) return std::nullopt;
  return found->distance_m;
}

std::span<const TypedLink> WorldGraph::links(TypeId from_type, TypeId to_type, double min_length_m,
                                             double max_length_m) const {
  const std::size_t t = type_names_.size();
  if (from_type >= t || to_type >= t || min_length_m > max_length_m) return {};
  const std::vector<TypedLink>& list = typed_links_[from_type * t + to_type];
  const auto begin =
      std::lower_bound(list.begin(), list.end(), min_length_m,
                       [](const TypedLink& link, double value) { return link.length_m < value; });
  const auto end =
      std::upper_bound(begin, list.end(), max_length_m,
                       [](double value, const TypedLink& link) { return value < link.length_m; });
  return {list.data() + (begin - list.begin()), static_cast<std::size_t>(end - begin)};
}

std::size_t WorldGraph::memory_bytes() const {
  std::size_t bytes =
      object_index_.capacity() * sizeof(std::size_t) +
      positions_.capacity() * sizeof(Eigen::Vector3d) + types_.capacity() * sizeof(TypeId) +
      row_start_.capacity() * sizeof(std::size_t) + neighbours_.capacity() * sizeof(Neighbour);
  for (const auto& list : typed_links_) bytes += list.capacity() * sizeof(TypedLink);
  return bytes;
}

}  // namespace vsl::world

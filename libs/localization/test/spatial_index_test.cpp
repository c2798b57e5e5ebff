// The two lookups the localizer builds over the world graph, against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "vsl/localization/node_grid.hpp"
#include "vsl/localization/typed_adjacency.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/worldgen/building.hpp"

namespace vsl::localization {
namespace {

const world::WorldGraph& building_graph() {
  static const world::WorldGraph graph = [] {
    worldgen::BuildingOptions options;
    options.objects = 3000;
    world::WorldGraphOptions graph_options;
    graph_options.node_types = {"door", "handle", "drawer_front", "window"};
    return world::WorldGraph::build(worldgen::generate_building(options), graph_options);
  }();
  return graph;
}

TEST(NodeGrid, FindsExactlyTheNodesWithinTheRadius) {
  const world::WorldGraph& graph = building_graph();
  const NodeGrid grid = NodeGrid::build(graph, 0.5);
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::size_t> pick(0, graph.node_count() - 1);
  std::uniform_real_distribution<double> offset(-0.8, 0.8);
  for (int q = 0; q < 200; ++q) {
    const auto anchor = static_cast<world::NodeIndex>(pick(rng));
    const Eigen::Vector3d point =
        graph.world_position_m(anchor) + Eigen::Vector3d(offset(rng), offset(rng), offset(rng));
    const double radius = 0.1 + 0.01 * (q % 80);
    const world::TypeId type = graph.type(anchor);
    std::vector<world::NodeIndex> found;
    grid.for_each_within(type, point, radius, [&](world::NodeIndex n, double d) {
      EXPECT_NEAR(d, (graph.world_position_m(n) - point).norm(), 1e-12);
      found.push_back(n);
    });
    std::vector<world::NodeIndex> expected;
    for (std::size_t n = 0; n < graph.node_count(); ++n) {
      const auto node = static_cast<world::NodeIndex>(n);
      if (graph.type(node) == type && (graph.world_position_m(node) - point).norm() <= radius) {
        expected.push_back(node);
      }
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
    const auto nearest = grid.nearest(type, point, radius);
    EXPECT_EQ(nearest.has_value(), !expected.empty());
  }
}

TEST(TypedAdjacency, MatchesTheGraphsNeighboursByTypeAndLength) {
  const world::WorldGraph& graph = building_graph();
  const TypedAdjacency adjacency = TypedAdjacency::build(graph);
  for (std::size_t n = 0; n < graph.node_count(); n += 7) {
    const auto node = static_cast<world::NodeIndex>(n);
    for (std::size_t t = 0; t < graph.type_count(); ++t) {
      const auto type = static_cast<world::TypeId>(t);
      const double lo = 0.5 + 0.1 * static_cast<double>(n % 10);
      const double hi = lo + 1.0;
      std::vector<world::NodeIndex> expected;
      for (const world::Neighbour& nb : graph.neighbours(node)) {
        if (graph.type(nb.node) == type && nb.distance_m >= lo && nb.distance_m <= hi) {
          expected.push_back(nb.node);
        }
      }
      std::vector<world::NodeIndex> found;
      float previous = 0.0f;
      for (const world::Neighbour& nb : adjacency.within(node, type, lo, hi)) {
        EXPECT_GE(nb.distance_m, previous);  // sorted by length
        previous = nb.distance_m;
        found.push_back(nb.node);
      }
      std::sort(found.begin(), found.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(found, expected);
    }
  }
}

}  // namespace
}  // namespace vsl::localization

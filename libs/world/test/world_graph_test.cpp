#include "vsl/world/world_graph.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace vsl::world {
namespace {

WorldModel random_world(std::uint32_t seed, std::size_t count, double extent_m) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coordinate(-extent_m, extent_m);
  std::uniform_real_distribution<double> height(0.0, 2.5);
  const char* types[] = {"door", "handle", "window", "drawer_front"};
  WorldModel world;
  for (std::size_t i = 0; i < count; ++i) {
    ObjectModel object;
    object.id = "o" + std::to_string(i);
    object.type = types[rng() % 4];
    object.world_position_m = {coordinate(rng), coordinate(rng), height(rng)};
    world.objects.push_back(object);
  }
  world.index_ids();
  return world;
}

TEST(WorldGraph, LinksMatchBruteForce) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const WorldModel world = random_world(seed, 600, 12.0);
    const double threshold = 3.0;
    const WorldGraph graph = WorldGraph::build(world, {threshold, {}});
    ASSERT_EQ(graph.node_count(), world.objects.size());
    std::size_t expected_links = 0;
    for (std::size_t i = 0; i < world.objects.size(); ++i) {
      for (std::size_t j = i + 1; j < world.objects.size(); ++j) {
        const double d =
            (world.objects[i].world_position_m - world.objects[j].world_position_m).norm();
        const auto lookup = graph.distance(static_cast<NodeIndex>(i), static_cast<NodeIndex>(j));
        if (d < threshold) {
          ++expected_links;
          ASSERT_TRUE(lookup.has_value()) << i << "-" << j;
          EXPECT_NEAR(*lookup, d, 1e-5);
          EXPECT_EQ(graph.distance(static_cast<NodeIndex>(j), static_cast<NodeIndex>(i)), lookup);
        } else {
          EXPECT_FALSE(lookup.has_value()) << i << "-" << j;
        }
      }
    }
    EXPECT_EQ(graph.link_count(), expected_links);
    EXPECT_GT(expected_links, 1000u);  // the test exercises a dense enough graph
  }
}

TEST(WorldGraph, EdgeNodesSitAtTheFrontFaceEdgesMiddles) {
  WorldModel world;
  ObjectModel door;
  door.id = "door";
  door.type = "door";
  door.world_position_m = {1.0, 2.0, 0.45};
  door.world_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  door.size_m = Eigen::Vector3d(0.4, 0.02, 0.7);
  ObjectModel unsized = door;
  unsized.id = "unsized";
  unsized.size_m.reset();
  ObjectModel lying = door;  // a hatch in the floor: no top or bottom edge
  lying.id = "lying";
  lying.world_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitX()));
  ObjectModel handle;
  handle.id = "handle";
  handle.type = "handle";
  handle.size_m = Eigen::Vector3d(0.16, 0.03, 0.02);
  world.objects = {door, unsized, lying, handle};
  world.index_ids();
  WorldGraphOptions options;
  options.node_types = {"door", "handle"};
  options.edge_node_types = {"door"};
  const WorldGraph graph = WorldGraph::build(world, options);
  EXPECT_EQ(graph.node_count(), 6u);  // 4 objects, the sized upright door's 2 edges
  const auto top = graph.find_type(edge_node_type("door", FaceEdge::kTop));
  const auto bottom = graph.find_type(edge_node_type("door", FaceEdge::kBottom));
  ASSERT_TRUE(top && bottom);
  EXPECT_EQ(graph.type_name(*top), "door_top_edge");
  EXPECT_EQ(graph.count_of_type(*top), 1u);
  EXPECT_EQ(graph.count_of_type(*bottom), 1u);
  for (NodeIndex n = 0; n < graph.node_count(); ++n) {
    if (graph.type(n) != *top && graph.type(n) != *bottom) continue;
    EXPECT_EQ(world.objects[graph.object_index(n)].id, "door");
    const double z = graph.type(n) == *top ? 0.8 : 0.1;
    EXPECT_LT((graph.world_position_m(n) - Eigen::Vector3d(1.0, 2.0, z)).norm(), 1e-12);
  }
  EXPECT_FALSE(face_edge_middle_m(world.objects[1], FaceEdge::kTop));
  EXPECT_FALSE(face_edge_middle_m(world.objects[2], FaceEdge::kBottom));
}

TEST(WorldGraph, TypedQueriesMatchBruteForce) {
  const WorldModel world = random_world(7, 500, 10.0);
  const WorldGraph graph = WorldGraph::build(world, {3.5, {}});
  // Every ordered pair within the threshold, measured once by brute force.
  struct OrderedPair {
    NodeIndex i, j;
    double d;
  };
  std::vector<OrderedPair> close_pairs;
  for (NodeIndex i = 0; i < graph.node_count(); ++i) {
    for (NodeIndex j = 0; j < graph.node_count(); ++j) {
      const double d = (graph.world_position_m(i) - graph.world_position_m(j)).norm();
      if (i != j && d < 3.5) close_pairs.push_back({i, j, d});
    }
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> phi(0.0, 3.5);
  for (int query = 0; query < 200; ++query) {
    const TypeId a = static_cast<TypeId>(rng() % graph.type_count());
    const TypeId b = static_cast<TypeId>(rng() % graph.type_count());
    const double center = phi(rng);
    const double tau = 0.05 + 0.3 * (rng() % 4);
    std::set<std::pair<NodeIndex, NodeIndex>> expected;
    for (const OrderedPair& p : close_pairs) {
      // Compare in float, as stored: the query's bounds are inclusive.
      const float df = static_cast<float>(p.d);
      if (graph.type(p.i) == a && graph.type(p.j) == b && df >= center - tau &&
          df <= center + tau) {
        expected.insert({p.i, p.j});
      }
    }
    std::set<std::pair<NodeIndex, NodeIndex>> got;
    float previous = 0.0f;
    for (const TypedLink& link : graph.links(a, b, center - tau, center + tau)) {
      EXPECT_EQ(graph.type(link.from), a);
      EXPECT_EQ(graph.type(link.to), b);
      EXPECT_GE(link.length_m, previous);  // sorted by length
      previous = link.length_m;
      got.insert({link.from, link.to});
    }
    EXPECT_EQ(got, expected) << "query " << query;
  }
}

TEST(WorldGraph, SameGraphWithAnyNumberOfThreads) {
  const WorldModel world = random_world(9, 5000, 30.0);
  WorldGraphOptions one{3.0, {}, 1};
  WorldGraphOptions three{3.0, {}, 3};
  const WorldGraph a = WorldGraph::build(world, one);
  const WorldGraph b = WorldGraph::build(world, three);
  ASSERT_EQ(a.link_count(), b.link_count());
  for (NodeIndex i = 0; i < a.node_count(); ++i) {
    const auto ra = a.neighbours(i), rb = b.neighbours(i);
    ASSERT_EQ(ra.size(), rb.size());
    for (std::size_t k = 0; k < ra.size(); ++k) {
      ASSERT_EQ(ra[k].node, rb[k].node);
      ASSERT_EQ(ra[k].distance_m, rb[k].distance_m);
    }
  }
  for (TypeId x = 0; x < a.type_count(); ++x) {
    for (TypeId y = 0; y < a.type_count(); ++y) {
      const auto la = a.links(x, y, 0.0, 3.0), lb = b.links(x, y, 0.0, 3.0);
      ASSERT_EQ(la.size(), lb.size());
      for (std::size_t k = 0; k < la.size(); ++k) {
        ASSERT_EQ(la[k].from, lb[k].from);
        ASSERT_EQ(la[k].to, lb[k].to);
      }
    }
  }
}

TEST(WorldGraph, NodeTypesSelectTheNodeSet) {
  const WorldModel world = random_world(5, 200, 5.0);
  const WorldGraph graph = WorldGraph::build(world, {2.0, {"door", "handle"}});
  std::size_t expected = 0;
  for (const ObjectModel& o : world.objects) expected += (o.type == "door" || o.type == "handle");
  EXPECT_EQ(graph.node_count(), expected);
  EXPECT_EQ(graph.type_count(), 2u);
  EXPECT_FALSE(graph.find_type("window").has_value());
  for (NodeIndex i = 0; i < graph.node_count(); ++i) {
    EXPECT_EQ(world.objects[graph.object_index(i)].type, graph.type_name(graph.type(i)));
  }
  EXPECT_EQ(graph.count_of_type(*graph.find_type("door")) +
                graph.count_of_type(*graph.find_type("handle")),
            expected);
}

TEST(WorldGraph, LinkThresholdIsStrict) {
  WorldModel world;
  for (int i = 0; i < 3; ++i) {
    ObjectModel o;
    o.id = std::to_string(i);
    o.type = "door";
    o.world_position_m = {2.0 * i, 0, 0};
    world.objects.push_back(o);
  }
  // Eq. 6: |X_i - X_j| < varpi. Points exactly varpi apart are not linked.
  EXPECT_EQ(WorldGraph::build(world, {2.0, {}}).link_count(), 0u);
  EXPECT_EQ(WorldGraph::build(world, {2.0001, {}}).link_count(), 2u);
  EXPECT_EQ(WorldGraph::build(world, {4.0001, {}}).link_count(), 3u);
  EXPECT_THROW(WorldGraph::build(world, {0.0, {}}), std::invalid_argument);
}

TEST(WorldGraph, FarAwayCoordinatesStillLinkCorrectly) {
  WorldModel world;
  for (int i = 0; i < 2; ++i) {
    ObjectModel o;
    o.id = std::to_string(i);
    o.type = "door";
    o.world_position_m = {-5.0e6 + i, 3.0e6, 0};
    world.objects.push_back(o);
  }
  const WorldGraph graph = WorldGraph::build(world, {2.0, {}});
  EXPECT_EQ(graph.link_count(), 1u);
  EXPECT_EQ(graph.neighbours(0).size(), 1u);
}

}  // namespace
}  // namespace vsl::world

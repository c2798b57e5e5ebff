// The world graph of paper §2.2: node set Xi (Eq. 5) and link set Lambda (Eq. 6), with the two
// lookups the pruning stages of §2.3 need: the distance of a linked pair, and every link between
// two object types whose length lies in [phi - tau, phi + tau] (Eq. 8).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::world {

using NodeIndex = std::uint32_t;  // index into the node set, 0 .. node_count() - 1
using TypeId = std::uint16_t;     // interned object type

struct WorldGraphOptions {
  // varpi of Eq. 6 (m): objects closer than this are linked. The paper takes the size of the 3D
  // field of view: two objects farther apart are never seen in one scan.
  double link_threshold_m = 4.0;
  // Object types that become nodes; empty means every object. Walls and floors have no
  // recognizer, so leaving them out keeps the graph to what percepts can match.
  std::vector<std::string> node_types;
  // Threads for building; 0 means one per hardware thread. The graph is the same for any value.
  unsigned threads = 0;
  // Object types whose front face's top and bottom edges become nodes of their own, of types
  // edge_node_type(type, kTop) and (type, kBottom), at the edges' middles: the reference point
  // (the face's centre) moved half the object's height along its z. A recognizer that sees a
  // door's bottom edge and sides but not its top (cut by the image border, hidden by a worktop's
  // lip) reports the bottom edge's middle, a point of the door as well defined as its centre.
  // Objects without a size, or whose z is not within 8 degrees of the world's vertical, have none.
  std::vector<std::string> edge_node_types{};
  friend bool operator==(const WorldGraphOptions&, const WorldGraphOptions&) = default;
};

enum class FaceEdge { kTop, kBottom };

// "door_top_edge", "door_bottom_edge": the type of a front face's edge node (and of the percept a
// recognizer reports for it).
std::string edge_node_type(const std::string& type, FaceEdge edge);

// The middle of the object's front face's top or bottom edge in the world frame (m), when the
// object has a size and stands upright (its z within 8 degrees of world z).
std::optional<Eigen::Vector3d> face_edge_middle_m(const ObjectModel& object, FaceEdge edge);

// One end of a link as seen from the other node.
struct Neighbour {
  NodeIndex node;
  float distance_m;
};

// A link seen from a node of the first type of a query towards a node of the second type.
struct TypedLink {
  float length_m;
  NodeIndex from;  // of the query's first type
  NodeIndex to;    // of the query's second type
};

class WorldGraph {
 public:
  // Builds nodes and links with a uniform grid of cell size varpi: only pairs in neighbouring
  // cells are measured, so building is linear in the number of links, not quadratic in nodes.
  static WorldGraph build(const WorldModel& world, const WorldGraphOptions& options = {});

  double link_threshold_m() const { return link_threshold_m_; }

  // Node set (Eq. 5).
  std::size_t node_count() const { return positions_.size(); }
  std::size_t object_index(NodeIndex node) const { return object_index_[node]; }
  const Eigen::Vector3d& world_position_m(NodeIndex node) const { return positions_[node]; }
  TypeId type(NodeIndex node) const { return types_[node]; }
  std::size_t type_count() const { return type_names_.size(); }
  const std::string& type_name(TypeId type) const { return type_names_[type]; }
  std::optional<TypeId> find_type(const std::string& name) const;
  std::size_t count_of_type(TypeId type) const;

  // Link set (Eq. 6): each unordered pair {i, j} with |X_i - X_j| < varpi counts once.
  std::size_t link_count() const { return neighbours_.size() / 2; }
  // Linked nodes of `node`, sorted by node index.
  std::span<const Neighbour> neighbours(NodeIndex node) const;
  // |X_a - X_b| when a and b are linked; nullopt otherwise. O(log degree).
  std::optional<float> distance(NodeIndex a, NodeIndex b) const;

  // Every link from a node of type `from_type` to a node of type `to_type` whose length lies in
  // [min_length_m, max_length_m], sorted by length. When the two types are equal each link comes
  // in both directions. O(log links + result).
  std::span<const TypedLink> links(TypeId from_type, TypeId to_type, double min_length_m,
                                   double max_length_m) const;

  // Approximate heap memory held by the graph (bytes), for the scaling benchmark.
  std::size_t memory_bytes() const;

 private:
  double link_threshold_m_ = 0.0;
  std::vector<std::size_t> object_index_;
  std::vector<Eigen::Vector3d> positions_;
  std::vector<TypeId> types_;
  std::vector<std::string> type_names_;
  std::vector<std::size_t> type_counts_;
  // Adjacency in compressed rows: neighbours_[row_start_[i] .. row_start_[i + 1]).
  std::vector<std::size_t> row_start_;
  std::vector<Neighbour> neighbours_;
  // typed_links_[from_type * type_count + to_type], each sorted by length.
  std::vector<std::vector<TypedLink>> typed_links_;
};

}  // namespace vsl::world

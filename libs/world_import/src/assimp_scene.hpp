// Reading a mesh file with assimp into world-frame triangles grouped by the node that owns them
// and by material: shared by load_mesh_pieces (a URDF or SDF link's mesh) and read_mesh_file (a
// whole building as one COLLADA/OBJ/glTF/STL/PLY file).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "scene.hpp"

namespace vsl::world_import {

// Which way is up in a mesh file.
enum class MeshUpAxis {
  kAsRos,           // as ROS tools read meshes: z up, a COLLADA file's <up_axis> ignored
  kFileConvention,  // the file's own: COLLADA's <up_axis>, glTF's y; z for OBJ, STL, PLY
};

struct AssimpPiece {
  std::string node;      // the node's unique name (the file stem for an unnamed one)
  std::string parent;    // the parent node's name, "" at the top
  std::string material;  // material name, "" when the file names none
  std::optional<world::Colour> colour;
  TriangleSoup soup;  // file frame, metres after the scale, z up
};

// A node of the file's hierarchy, with or without triangles of its own.
struct AssimpNode {
  std::string name;    // unique within the file: a repeated name gets "#2", "#3", ...
  std::string parent;  // "" at the top
};

// Throws config::Error, one line naming the file, when assimp cannot read it. `scale` multiplies
// the file's coordinates (after COLLADA's own <unit>). `nodes`, when given, receives every node
// in depth-first order.
std::vector<AssimpPiece> read_assimp_pieces(const std::string& path, const Eigen::Vector3d& scale,
                                            MeshUpAxis up,
                                            std::vector<AssimpNode>* nodes = nullptr);

}  // namespace vsl::world_import

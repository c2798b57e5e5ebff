// A whole building or piece of furniture as one mesh file (COLLADA, OBJ, glTF, STL, PLY): every
// node of the file is a part, named as the file names it; its meshes keep their materials.
#include <map>

#include "assimp_scene.hpp"
#include "scene.hpp"

namespace vsl::world_import {

Scene read_mesh_file(const std::string& path, const ReadOptions& /*options*/) {
  Scene scene;
  scene.source = path;
  std::vector<AssimpNode> nodes;
  std::vector<AssimpPiece> pieces =
      read_assimp_pieces(path, Eigen::Vector3d::Ones(), MeshUpAxis::kFileConvention, &nodes);
  std::map<std::string, std::size_t> part_of;
  for (const AssimpNode& node : nodes) {
    part_of[node.name] = scene.parts.size();
    ScenePart part;
    part.name = node.name;
    part.parent = node.parent;
    scene.parts.push_back(std::move(part));
  }
  for (AssimpPiece& piece : pieces) {
    PartGeometry geometry;  // vertices already in the world frame
    geometry.material = piece.material;
    geometry.colour = piece.colour;
    geometry.shape = std::move(piece.soup);
    scene.parts[part_of.at(piece.node)].geometry.push_back(std::move(geometry));
  }
  return scene;
}

}  // namespace vsl::world_import

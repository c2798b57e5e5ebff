#include "assimp_scene.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

struct MaterialLook {
  std::string name;
  std::optional<world::Colour> colour;
};

MaterialLook material_look(const aiMaterial* material) {
  MaterialLook look;
  aiString name;
  if (material->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) look.name = name.C_Str();
  // assimp names a file's missing material this; it is not a name a rule should see.
  if (look.name == AI_DEFAULT_MATERIAL_NAME) look.name.clear();
  aiColor4D diffuse;
  if (material->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
    look.colour = world::Colour{to_byte(diffuse.r), to_byte(diffuse.g), to_byte(diffuse.b)};
  }
  return look;
}

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return out;
}

struct Walker {
  const aiScene* scene;
  std::string file_stem;
  std::vector<MaterialLook> looks;
  // (node, material index) -> piece index, so that a node's meshes of one material merge.
  std::map<std::pair<const aiNode*, unsigned>, std::size_t> piece_of;
  std::vector<AssimpPiece> pieces;
  std::vector<AssimpNode> nodes;
  std::map<const aiNode*, std::string> unique_name;
  std::map<std::string, int> times_seen;

  std::string name_of(const aiNode* node) const {
    const auto it = unique_name.find(node);
    return it == unique_name.end() ? "" : it->second;
  }

  void walk(const aiNode* node, const Eigen::Matrix4d& file_T_parent) {
    const Eigen::Matrix4d file_T_node = file_T_parent * to_eigen(node->mTransformation);
    std::string name = node->mName.length > 0 ? std::string(node->mName.C_Str()) : file_stem;
    const int seen = ++times_seen[name];
    if (seen > 1) name += "#" + std::to_string(seen);
    unique_name[node] = name;
    nodes.push_back({name, node->mParent != nullptr ? name_of(node->mParent) : ""});
    for (unsigned m = 0; m < node->mNumMeshes; ++m) {
      const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
      const auto key = std::make_pair(node, mesh->mMaterialIndex);
      auto [it, inserted] = piece_of.try_emplace(key, pieces.size());
      if (inserted) {
        AssimpPiece piece;
        piece.node = name_of(node);
        piece.parent = node->mParent != nullptr ? name_of(node->mParent) : "";
        if (mesh->mMaterialIndex < looks.size()) {
          piece.material = looks[mesh->mMaterialIndex].name;
          piece.colour = looks[mesh->mMaterialIndex].colour;
        }
        pieces.push_back(std::move(piece));
      }
      TriangleSoup& soup = pieces[it->second].soup;
      const auto base = static_cast<std::uint32_t>(soup.vertices_m.size());
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const aiVector3D& p = mesh->mVertices[v];
        const Eigen::Vector4d world = file_T_node * Eigen::Vector4d(p.x, p.y, p.z, 1.0);
        soup.vertices_m.push_back(world.head<3>().cast<float>());
      }
      for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines (triangulation did the rest)
        soup.triangles.push_back(
            {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], file_T_node);
  }
};

}  // namespace

std::vector<AssimpPiece> read_assimp_pieces(const std::string& path, const Eigen::Vector3d& scale,
                                            MeshUpAxis up, std::vector<AssimpNode>* nodes) {
  Assimp::Importer importer;
  // ROS reads COLLADA without its up-axis rotation (rviz drops it); a file of its own keeps it.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, up == MeshUpAxis::kAsRos);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    const std::string reason = one_line(importer.GetErrorString());
    throw config::Error(path + ": cannot read mesh: " + (reason.empty() ? "no scene" : reason));
  }
  Walker walker{scene, std::filesystem::path(path).stem().string(), {}, {}, {}, {}, {}, {}};
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    walker.looks.push_back(material_look(scene->mMaterials[i]));
  }
  Eigen::Matrix4d world_T_file = Eigen::Matrix4d::Identity();
  world_T_file.topLeftCorner<3, 3>() = scale.asDiagonal();
  // assimp gives COLLADA (unless told to ignore its axis) and glTF y up; vsl's worlds are z up:
  // a quarter turn about x takes y to z.
  const std::string ext = lower_extension(path);
  const bool y_up =
      up == MeshUpAxis::kFileConvention && (ext == ".dae" || ext == ".gltf" || ext == ".glb");
  if (y_up) {
    Eigen::Matrix4d y_to_z = Eigen::Matrix4d::Identity();
    y_to_z.topLeftCorner<3, 3>() =
        Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitX())
            .toRotationMatrix();
    world_T_file = world_T_file * y_to_z;
  }
  walker.walk(scene->mRootNode, world_T_file);
  std::erase_if(walker.pieces, [](const AssimpPiece& p) { return p.soup.triangles.empty(); });
  if (nodes != nullptr) *nodes = std::move(walker.nodes);
  return walker.pieces;
}

std::vector<MeshPiece> load_mesh_pieces(const std::string& path, const Eigen::Vector3d& scale) {
  // A link's mesh: one piece per material, whatever nodes the file splits it into.
  std::vector<MeshPiece> out;
  std::map<std::string, std::size_t> by_material;
  for (AssimpPiece& piece : read_assimp_pieces(path, scale, MeshUpAxis::kAsRos)) {
    const auto [it, inserted] = by_material.try_emplace(piece.material, out.size());
    if (inserted) out.push_back({{}, piece.material, piece.colour});
    TriangleSoup& soup = out[it->second].soup;
    const auto base = static_cast<std::uint32_t>(soup.vertices_m.size());
    soup.vertices_m.insert(soup.vertices_m.end(), piece.soup.vertices_m.begin(),
                           piece.soup.vertices_m.end());
    for (const auto& t : piece.soup.triangles) {
      soup.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    }
  }
  return out;
}

}  // namespace vsl::world_import

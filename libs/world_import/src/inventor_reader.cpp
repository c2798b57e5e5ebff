// VRML 2.0 (and 1.0) and Open Inventor files -> Scene, through Coin3D. Coin tessellates every
// shape; the triangles, in the world frame, go to the nearest enclosing DEF-named node (a part),
// split by the material in effect. Coin keeps global state (its type system, the read error
// handler), so all Coin use lives in this file behind one mutex.
#include <Inventor/SbMatrix.h>
#include <Inventor/SbRotation.h>
#include <Inventor/SbVec3f.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/VRMLnodes/SoVRMLAppearance.h>
#include <Inventor/VRMLnodes/SoVRMLMaterial.h>
#include <Inventor/VRMLnodes/SoVRMLTransform.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <unordered_map>

#include "scene.hpp"
#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

namespace fs = std::filesystem;

// Path keys are "/i/j/.../" (child indices); this one holds triangles under no DEF-named node.
const std::string kFallbackKey = "#file";

std::mutex& coin_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Coin posts read errors to a global handler (stderr by default); while we read, it collects.
// "Coin read error: WHAT\n\tOccurred at line N in FILE" becomes "WHAT (line N)": our message
// names the file already.
void collect_read_error(const SoError* error, void* data) {
  auto* messages = static_cast<std::vector<std::string>*>(data);
  std::string message = one_line(error->getDebugString().getString());
  const std::string prefix = "Coin read error: ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  const std::string where = " Occurred at line ";
  if (const auto at = message.find(where); at != std::string::npos) {
    const std::string rest = message.substr(at + where.size());
    message = message.substr(0, at) + " (line " + rest.substr(0, rest.find(' ')) + ")";
  }
  messages->push_back(message);
}

// The rigid part of a Coin matrix (row vectors: world = point * matrix); scale stays in the
// vertices, which are stored in this frame.
Eigen::Isometry3d rigid_part(const SbMatrix& world_matrix) {
  SbVec3f translation, scale;
  SbRotation rotation, scale_orientation;
  world_matrix.getTransform(translation, rotation, scale, scale_orientation);
  float x = 0, y = 0, z = 0, w = 1;
  rotation.getValue(x, y, z, w);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  t.translation() = Eigen::Vector3d(translation[0], translation[1], translation[2]);
  return t;
}

std::string node_name(const SoNode* node) {
  return node->getName().getString();
}

// A DEF-named node at one place in the graph: a node USEd twice is two parts.
struct PartBuild {
  std::string name;
  std::string parent_key;  // the next DEF-named node above, or "" (none)
  Eigen::Isometry3d world_T_part = Eigen::Isometry3d::Identity();
  // (material, r, g, b) -> triangles, vertices in the world frame until the part is finished.
  std::map<std::tuple<std::string, std::uint8_t, std::uint8_t, std::uint8_t>, TriangleSoup> soups;
};

class InventorSceneReader {
 public:
  explicit InventorSceneReader(const std::string& path) : path_(path) {
    fallback_name_ = fs::path(path).stem().string();
  }

  Scene read(SoNode& root) {
    SoCallbackAction action{SbViewportRegion(640, 480)};
    action.addPreCallback(SoNode::getClassTypeId(), &InventorSceneReader::pre_node, this);
    action.addPostCallback(SoNode::getClassTypeId(), &InventorSceneReader::post_node, this);
    action.addTriangleCallback(SoShape::getClassTypeId(), &InventorSceneReader::triangle, this);
    action.apply(&root);
    return finish();
  }

 private:
  // Path key of the node at `depth` in `path`: the child indices from the root down to it.
  static std::string path_key(const SoPath& path, int depth) {
    std::string key = "/";
    for (int i = 1; i <= depth; ++i) key += std::to_string(path.getIndex(i)) + "/";
    return key;
  }

  // Every node: remember the frame of DEF-named ones, track the material name in effect.
  // Coin's current path ends at the node only for group children: a VRML Shape's appearance,
  // material and geometry (its fields) are traversed with the path ending at the Shape.
  static SoCallbackAction::Response pre_node(void* self_ptr, SoCallbackAction* action,
                                             const SoNode* node) {
    auto& self = *static_cast<InventorSceneReader*>(self_ptr);
    const int depth = action->getState()->getDepth();
    const SoPath& path = *action->getCurPath();
    const std::string name = node_name(node);
    if (node->isOfType(SoMaterial::getClassTypeId()) ||
        node->isOfType(SoVRMLAppearance::getClassTypeId())) {
      self.set_material_name(depth, name);
    } else if (node->isOfType(SoVRMLMaterial::getClassTypeId())) {
      // An unnamed VRML Material goes by its Appearance's name, traversed just before it.
      const bool keeps_appearance_name = name.empty() && !self.material_names_.empty() &&
                                         self.material_names_.back().first == depth;
      if (!keeps_appearance_name) self.set_material_name(depth, name);
    }
    if (!name.empty() && path.getTail() == node) {
      SbMatrix world_matrix = action->getModelMatrix();
      // A VRML Transform's part frame is the frame of its children.
      if (node->isOfType(SoVRMLTransform::getClassTypeId())) {
        const auto* transform = static_cast<const SoVRMLTransform*>(node);
        SbMatrix local;
        local.setTransform(transform->translation.getValue(), transform->rotation.getValue(),
                           transform->scale.getValue(), transform->scaleOrientation.getValue(),
                           transform->center.getValue());
        world_matrix = local.multRight(world_matrix);
      }
      self.frames_[path_key(path, path.getLength() - 1)] = rigid_part(world_matrix);
    }
    if (node->isOfType(SoShape::getClassTypeId())) {
      self.begin_shape(path, *node, action->getModelMatrix());
    }
    return SoCallbackAction::CONTINUE;
  }

  // A material replaces the one set at its own state depth and those of scopes below it.
  void set_material_name(int depth, const std::string& name) {
    std::erase_if(material_names_, [depth](const auto& entry) { return entry.first >= depth; });
    material_names_.emplace_back(depth, name);
  }

  // After a node, the state is back to its depth: materials of scopes it closed are gone.
  static SoCallbackAction::Response post_node(void* self_ptr, SoCallbackAction* action,
                                              const SoNode*) {
    auto& self = *static_cast<InventorSceneReader*>(self_ptr);
    const int depth = action->getState()->getDepth();
    std::erase_if(self.material_names_, [depth](const auto& entry) { return entry.first > depth; });
    return SoCallbackAction::CONTINUE;
  }

  // Before a shape's triangles: which part they belong to and the material name in effect.
  void begin_shape(const SoPath& path, const SoNode& shape, const SbMatrix& world_matrix) {
    // The DEF-named nodes enclosing the shape, nearest first.
    std::vector<int> named_depths;
    for (int i = path.getLength() - 1; i >= 0; --i) {
      if (!node_name(path.getNode(i)).empty()) named_depths.push_back(i);
    }
    // Registered from the top down so that parents take their names before their children.
    std::string nearest_key = kFallbackKey;
    std::string parent_key;
    for (auto it = named_depths.rbegin(); it != named_depths.rend(); ++it) {
      nearest_key = path_key(path, *it);
      part(nearest_key, node_name(path.getNode(*it)), parent_key);
      parent_key = nearest_key;
    }
    // A DEF-named VRML geometry node (off the path, below its Shape) is a part of its own.
    if (path.getTail() != &shape && !node_name(&shape).empty()) {
      nearest_key = path_key(path, path.getLength() - 1) + "geometry/";
      frames_[nearest_key] = rigid_part(world_matrix);
      part(nearest_key, node_name(&shape), parent_key);
    }
    shape_part_ = &part(nearest_key, fallback_name_, "");
    shape_material_ = material_names_.empty() ? "" : material_names_.back().second;
  }

  static void triangle(void* self_ptr, SoCallbackAction* action, const SoPrimitiveVertex* v1,
                       const SoPrimitiveVertex* v2, const SoPrimitiveVertex* v3) {
    auto& self = *static_cast<InventorSceneReader*>(self_ptr);
    if (self.shape_part_ == nullptr) return;
    SbColor ambient, diffuse, specular, emission;
    float shininess = 0, transparency = 0;
    action->getMaterial(ambient, diffuse, specular, emission, shininess, transparency,
                        v1->getMaterialIndex());
    TriangleSoup& soup = self.shape_part_->soups[{self.shape_material_, to_byte(diffuse[0]),
                                                  to_byte(diffuse[1]), to_byte(diffuse[2])}];
    const SbMatrix& world_matrix = action->getModelMatrix();
    std::array<std::uint32_t, 3> triangle{};
    const SoPrimitiveVertex* corners[] = {v1, v2, v3};
    for (int i = 0; i < 3; ++i) {
      SbVec3f world;
      world_matrix.multVecMatrix(corners[i]->getPoint(), world);
      triangle[i] = static_cast<std::uint32_t>(soup.vertices_m.size());
      soup.vertices_m.emplace_back(world[0], world[1], world[2]);
    }
    soup.triangles.push_back(triangle);
  }

  // The part of this key, made on first sight with a name unique in the scene.
  PartBuild& part(const std::string& key, const std::string& name, const std::string& parent_key) {
    auto it = parts_.find(key);
    if (it != parts_.end()) return it->second;
    std::string unique = name;
    for (int n = 2; !used_names_.insert(unique).second; ++n) {
      unique = name + "_" + std::to_string(n);
    }
    PartBuild build;
    build.name = unique;
    build.parent_key = parent_key;
    if (const auto frame = frames_.find(key); frame != frames_.end()) {
      build.world_T_part = frame->second;
    }
    order_.push_back(key);
    return parts_.emplace(key, std::move(build)).first->second;
  }

  Scene finish() {
    // A part is kept when it has triangles or encloses a part that has (it groups them).
    std::set<std::string> kept;
    for (const auto& key : order_) {
      if (parts_.at(key).soups.empty()) continue;
      std::string k = key;
      while (!k.empty() && kept.insert(k).second) k = parts_.at(k).parent_key;
    }
    Scene scene;
    scene.source = path_;
    for (const auto& key : order_) {
      if (kept.count(key) == 0) continue;
      PartBuild& build = parts_.at(key);
      ScenePart part;
      part.name = build.name;
      part.parent = build.parent_key.empty() ? "" : parts_.at(build.parent_key).name;
      part.world_T_part = build.world_T_part;
      const Eigen::Isometry3f part_T_world = build.world_T_part.inverse().cast<float>();
      for (auto& [look, soup] : build.soups) {
        for (auto& vertex : soup.vertices_m) vertex = part_T_world * vertex;
        const auto& [material, r, g, b] = look;
        part.geometry.push_back(
            {build.world_T_part, std::move(soup), material, world::Colour{r, g, b}});
      }
      scene.parts.push_back(std::move(part));
    }
    return scene;
  }

  std::string path_;
  std::string fallback_name_;  // the file's stem: triangles under no DEF-named node
  std::unordered_map<std::string, PartBuild> parts_;  // path key -> part
  std::vector<std::string> order_;                    // path keys in order of first sight
  std::set<std::string> used_names_;
  std::unordered_map<std::string, Eigen::Isometry3d> frames_;  // path key -> DEF node's frame
  std::vector<std::pair<int, std::string>> material_names_;    // (state depth, name) in effect
  PartBuild* shape_part_ = nullptr;
  std::string shape_material_;
};

}  // namespace

Scene read_inventor(const std::string& path, const ReadOptions& /*options*/) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw config::Error(path + ": no such file");
  const std::lock_guard<std::mutex> lock(coin_mutex());
  if (!SoDB::isInitialized()) {
    SoDB::init();
    // Coin's database lives until the process ends; SoDB::finish() hands its memory back then,
    // so that a leak checker sees only our own allocations.
    std::atexit([] { SoDB::finish(); });
  }

  std::vector<std::string> messages;
  SoErrorCB* const previous_handler = SoReadError::getHandlerCallback();
  void* const previous_data = SoReadError::getHandlerData();
  SoReadError::setHandlerCallback(&collect_read_error, &messages);
  SoSeparator* root = nullptr;
  {
    SoInput input;
    if (input.openFile(path.c_str(), TRUE) && input.isValidFile()) root = SoDB::readAll(&input);
  }
  SoReadError::setHandlerCallback(previous_handler, previous_data);
  if (root == nullptr) {
    throw config::Error(path + ": not a VRML or Open Inventor file" +
                        (messages.empty() ? std::string(" (no VRML or Inventor header)")
                                          : ": " + messages.front()));
  }
  root->ref();
  Scene scene;
  try {
    scene = InventorSceneReader(path).read(*root);
  } catch (...) {
    root->unref();
    throw;
  }
  root->unref();
  return scene;
}

}  // namespace vsl::world_import

#include "vsl/world_import/import.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <set>

#include "object_frames.hpp"
#include "scene.hpp"
#include "simplify.hpp"
#include "vsl/config/node.hpp"

namespace vsl::world_import {
namespace {

Scene read_scene(const std::string& path, ModelFormat format, const ReadOptions& options) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw config::Error(path + ": no such file");
  }
  switch (format) {
    case ModelFormat::kUrdf:
      return read_urdf(path, options);
    case ModelFormat::kSdf:
      return read_sdf(path, options);
    case ModelFormat::kMesh:
      return read_mesh_file(path, options);
    case ModelFormat::kInventor:
      return read_inventor(path, options);
  }
  return {};
}

// Moves a file's scene into the world: a quarter turn about x for a y-up file, then `at`.
// Scales a file's scene into metres (a file in millimetres: 0.001): positions and shapes alike,
// so that frames stay rigid.
void scale_scene(Scene& scene, double scale) {
  for (ScenePart& part : scene.parts) {
    part.world_T_part.translation() *= scale;
    part.world_joint_point_m *= scale;
    if (part.joint == JointKind::prismatic) {
      part.joint_lower *= scale;
      part.joint_upper *= scale;
    }
    for (PartGeometry& geometry : part.geometry) {
      geometry.world_T_geometry.translation() *= scale;
      if (auto* box = std::get_if<world::Box>(&geometry.shape)) {
        box->size_m *= scale;
      } else if (auto* cylinder = std::get_if<world::Cylinder>(&geometry.shape)) {
        cylinder->radius_m *= scale;
        cylinder->height_m *= scale;
      } else {
        for (Eigen::Vector3f& v : std::get<TriangleSoup>(geometry.shape).vertices_m) {
          v *= static_cast<float>(scale);
        }
      }
    }
  }
}

void place(Scene& scene, const Placement& at, bool y_up) {
  Eigen::Isometry3d world_T_file = Eigen::Isometry3d::Identity();
  world_T_file.translation() = at.position_m;
  world_T_file.linear() =
      Eigen::AngleAxisd(at.yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  if (y_up) {
    world_T_file.rotate(Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitX()));
  }
  for (ScenePart& part : scene.parts) {
    part.world_T_part = world_T_file * part.world_T_part;
    part.world_joint_axis = world_T_file.linear() * part.world_joint_axis;
    part.world_joint_point_m = world_T_file * part.world_joint_point_m;
    for (PartGeometry& geometry : part.geometry) {
      geometry.world_T_geometry = world_T_file * geometry.world_T_geometry;
    }
  }
}

// Materials by name; a file's unnamed colour becomes a material named after the colour.
class MaterialTable {
 public:
  std::string name_for(const PartGeometry& geometry) {
    std::string name = geometry.material;
    if (name.empty()) {
      const world::Colour c = geometry.colour.value_or(world::Colour{});
      char text[16];
      std::snprintf(text, sizeof text, "colour_%02x%02x%02x", c.r, c.g, c.b);
      name = text;
    }
    if (index_.try_emplace(name, materials_.size()).second) {
      world::Material material;
      material.name = name;
      material.colour = geometry.colour.value_or(world::Colour{});
      materials_.push_back(material);
    }
    return name;
  }
  const world::Colour& colour_of(const std::string& name) const {
    return materials_[index_.at(name)].colour;
  }
  std::vector<world::Material> take() { return std::move(materials_); }

 private:
  std::map<std::string, std::size_t> index_;
  std::vector<world::Material> materials_;
};

world::Primitive to_primitive(const PartGeometry& geometry, const Eigen::Isometry3d& object_T_world,
                              MaterialTable& materials, std::size_t max_triangles,
                              ImportReport& report, bool& simplified) {
  world::Primitive primitive;
  const Eigen::Isometry3d object_T_geometry = object_T_world * geometry.world_T_geometry;
  primitive.object_position_m = object_T_geometry.translation();
  primitive.object_orientation = Eigen::Quaterniond(object_T_geometry.linear()).normalized();
  primitive.material = materials.name_for(geometry);
  primitive.colour = geometry.colour.value_or(materials.colour_of(primitive.material));
  if (const auto* box = std::get_if<world::Box>(&geometry.shape)) {
    primitive.shape = *box;
  } else if (const auto* cylinder = std::get_if<world::Cylinder>(&geometry.shape)) {
    primitive.shape = *cylinder;
  } else {
    const TriangleSoup& soup = std::get<TriangleSoup>(geometry.shape);
    SimplifyResult small = simplify(soup, max_triangles);
    simplified = simplified || small.cell_m > 0;
    report.triangles_read += soup.triangles.size();
    report.triangles_kept += small.soup.triangles.size();
    world::TriangleMesh mesh;
    mesh.vertices_m = std::move(small.soup.vertices_m);
    mesh.triangles = std::move(small.soup.triangles);
    primitive.shape = std::move(mesh);
  }
  return primitive;
}

struct Part {
  const ScenePart* part;
  std::string id;
  int parent = -1;  // index into the parts list
};

// All parts of all scenes with world-unique ids and parents resolved to indices.
std::vector<Part> collect_parts(const std::vector<Scene>& scenes) {
  std::vector<Part> parts;
  std::set<std::string> taken;
  for (const Scene& scene : scenes) {
    const std::string stem = std::filesystem::path(scene.source).stem().string();
    std::map<std::string, int> index_of;
    const std::size_t first = parts.size();
    for (const ScenePart& part : scene.parts) {
      std::string id = part.name;
      // A name an earlier file took gets the file's stem in front.
      if (taken.contains(id)) id = stem + "/" + part.name;
      for (int n = 2; taken.contains(id); ++n)
        id = stem + "/" + part.name + "#" + std::to_string(n);
      taken.insert(id);
      index_of[part.name] = static_cast<int>(parts.size());
      parts.push_back({&part, id, -1});
    }
    for (std::size_t i = first; i < parts.size(); ++i) {
      const auto it = index_of.find(parts[i].part->parent);
      if (it != index_of.end() && it->second != static_cast<int>(i)) parts[i].parent = it->second;
    }
  }
  return parts;
}

std::vector<std::string> materials_of(const ScenePart& part) {
  std::vector<std::string> out;
  for (const PartGeometry& g : part.geometry) {
    if (!g.material.empty()) out.push_back(g.material);
  }
  return out;
}

// Reads, scales and places each file; a file spanning more than 500 m gets a warning (a
// building is not half a kilometre long: such a file is most likely in millimetres).
std::vector<Scene> read_scenes(const std::vector<ImportInput>& inputs, const ImportOptions& options,
                               ImportReport& report) {
  const ReadOptions read_options{options.package_paths, options.joint_positions};
  std::vector<Scene> scenes;
  for (const ImportInput& input : inputs) {
    const ModelFormat format = model_format_of(input.path);
    Scene scene = read_scene(input.path, format, read_options);
    if (input.scale != 1.0) scale_scene(scene, input.scale);
    if (input.at || input.y_up) place(scene, input.at.value_or(Placement{}), input.y_up);
    report.files.push_back({input.path, format, scene.parts.size()});
    report.warnings.insert(report.warnings.end(), scene.warnings.begin(), scene.warnings.end());
    Eigen::AlignedBox3d bounds;
    std::vector<Eigen::Vector3d> points;
    for (const ScenePart& part : scene.parts) {
      for (const PartGeometry& g : part.geometry) {
        points.clear();
        append_world_points(g, points);
        for (const Eigen::Vector3d& p : points) bounds.extend(p);
      }
    }
    if (!bounds.isEmpty() && bounds.sizes().maxCoeff() > 500.0) {
      report.warnings.push_back(scene.source + ": spans " +
                                std::to_string(static_cast<long>(bounds.sizes().maxCoeff())) +
                                " m; if it is in millimetres, import it with --scale 0.001");
    }
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

// The parts that become objects (those with geometry that no rule left out), typed, each with
// its nearest ancestor among them.
struct Chosen {
  std::vector<Candidate> candidates;
  std::vector<std::size_t> part_of_candidate;  // index into the parts
};

Chosen choose_candidates(const std::vector<Part>& parts, const TypeRules& rules,
                         ImportReport& report) {
  Chosen chosen;
  std::vector<int> candidate_of(parts.size(), -1);
  std::vector<std::size_t> fired(rules.rules().size(), 0);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const ScenePart& part = *parts[i].part;
    const TypeDecision decision =
        rules.classify({part.name, materials_of(part), joint_kind_name(part.joint)});
    if (decision.rule >= 0) ++fired[static_cast<std::size_t>(decision.rule)];
    if (decision.skip) {
      report.skipped.push_back(parts[i].id);
      continue;
    }
    if (part.geometry.empty()) {
      // A frame that only groups others; a typed one is worth a line (a door whose mesh is
      // missing and has no collision geometry).
      if (!decision.type.empty() && default_reference(decision.type) != Reference::kCentre) {
        report.dropped.push_back(parts[i].id + ": " + decision.type + " without geometry");
      }
      continue;
    }
    Candidate candidate;
    candidate.part = &part;
    candidate.type = decision.type.empty() ? kUnmatchedType : decision.type;
    candidate.reference = decision.rule >= 0 ? decision.reference : Reference::kCentre;
    if (decision.type.empty()) report.unmatched.push_back(parts[i].id);
    for (const PartGeometry& g : part.geometry) append_world_points(g, candidate.world_points_m);
    candidate_of[i] = static_cast<int>(chosen.candidates.size());
    chosen.candidates.push_back(std::move(candidate));
    chosen.part_of_candidate.push_back(i);
  }
  for (std::size_t c = 0; c < chosen.candidates.size(); ++c) {
    for (int p = parts[chosen.part_of_candidate[c]].parent; p >= 0;
         p = parts[static_cast<std::size_t>(p)].parent) {
      if (candidate_of[static_cast<std::size_t>(p)] >= 0) {
        chosen.candidates[c].parent = candidate_of[static_cast<std::size_t>(p)];
        break;
      }
    }
  }
  for (std::size_t r = 0; r < fired.size(); ++r) {
    if (fired[r] > 0) report.rules_fired.emplace_back(rules.rules()[r].describe(), fired[r]);
  }
  return chosen;
}

// Candidate `c` as a world object: its frame, its parent's id, its geometry as primitives.
world::ObjectModel object_of(const Chosen& chosen, std::size_t c, const ObjectFrame& frame,
                             const std::vector<Part>& parts, const ImportOptions& options,
                             MaterialTable& materials, ImportReport& report) {
  const Candidate& candidate = chosen.candidates[c];
  world::ObjectModel object;
  object.id = parts[chosen.part_of_candidate[c]].id;
  object.type = candidate.type;
  object.world_position_m = frame.world_position_m;
  object.world_orientation = Eigen::Quaterniond(frame.world_R_object).normalized();
  // The format wants positive extents; a flat part (a floor plane) is 1 mm thick.
  object.size_m = frame.size_m.cwiseMax(1e-3);
  if (candidate.parent >= 0) {
    object.parent_id =
        parts[chosen.part_of_candidate[static_cast<std::size_t>(candidate.parent)]].id;
  }
  const Eigen::Isometry3d object_T_world = object.world_T_object().inverse();
  const std::size_t triangles_per_piece =
      options.max_triangles_per_object / std::max<std::size_t>(1, candidate.part->geometry.size());
  bool simplified = false;
  for (const PartGeometry& g : candidate.part->geometry) {
    object.primitives.push_back(
        to_primitive(g, object_T_world, materials, triangles_per_piece, report, simplified));
  }
  report.simplified_objects += simplified ? 1 : 0;
  if (!frame.front_from.empty()) report.front_decided_by[object.id] = frame.front_from;
  ++report.objects_by_type[object.type];
  return object;
}

}  // namespace

const char* model_format_name(ModelFormat format) {
  switch (format) {
    case ModelFormat::kUrdf:
      return "URDF";
    case ModelFormat::kSdf:
      return "SDF";
    case ModelFormat::kMesh:
      return "mesh";
    case ModelFormat::kInventor:
      return "VRML/Open Inventor";
  }
  return "?";
}

ModelFormat model_format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".urdf") return ModelFormat::kUrdf;
  if (ext == ".sdf" || ext == ".world") return ModelFormat::kSdf;
  if (ext == ".wrl" || ext == ".vrml" || ext == ".iv") return ModelFormat::kInventor;
  for (const char* mesh :
       {".dae", ".obj", ".gltf", ".glb", ".stl", ".ply", ".fbx", ".3ds", ".off", ".x3d"}) {
    if (ext == mesh) return ModelFormat::kMesh;
  }
  if (ext == ".xacro") {
    throw config::Error(path + ": a xacro file; expand it first (xacro " + path + " > model.urdf)");
  }
  throw config::Error(path + ": unknown model format '" + ext +
                      "' (expected .urdf, .sdf, .world, .wrl, .iv, .dae, .obj, .gltf, .glb, "
                      ".stl, .ply)");
}

ImportResult import_world(const std::vector<ImportInput>& inputs, const ImportOptions& options,
                          const TypeRules& rules) {
  ImportResult result;
  ImportReport& report = result.report;
  const std::vector<Scene> scenes = read_scenes(inputs, options, report);
  const std::vector<Part> parts = collect_parts(scenes);
  Chosen chosen = choose_candidates(parts, rules, report);
  const std::vector<ObjectFrame> frames = object_frames(chosen.candidates);

  MaterialTable materials;
  world::WorldModel& world = result.world;
  world.name = !options.world_name.empty() ? options.world_name
               : inputs.empty()            ? "imported"
                                           : std::filesystem::path(inputs[0].path).stem().string();
  for (std::size_t c = 0; c < chosen.candidates.size(); ++c) {
    world.objects.push_back(object_of(chosen, c, frames[c], parts, options, materials, report));
  }
  world.materials = materials.take();
  world.index_ids();
  return result;
}

}  // namespace vsl::world_import

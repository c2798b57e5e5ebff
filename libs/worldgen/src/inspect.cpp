#include "vsl/worldgen/inspect.hpp"

#include <cmath>
#include <unordered_map>

#include "vsl/worldgen/geometry.hpp"

namespace vsl::worldgen {

WorldCounts count_world(const world::WorldModel& world) {
  WorldCounts counts;
  counts.objects = world.objects.size();
  for (const world::ObjectModel& object : world.objects) {
    ++counts.by_type[object.type];
    for (const world::Primitive& p : object.primitives) {
      if (std::holds_alternative<world::Box>(p.shape)) {
        ++counts.boxes;
      } else if (std::holds_alternative<world::Cylinder>(p.shape)) {
        ++counts.cylinders;
      } else if (const auto* mesh = std::get_if<world::TriangleMesh>(&p.shape)) {
        ++counts.meshes;
        counts.mesh_triangles += mesh->triangles.size();
      } else {
        const auto& poly = std::get<world::Polyhedron>(p.shape);
        ++counts.polyhedra;
        counts.polyhedron_faces += poly.faces.size();
        counts.polyhedron_vertices += poly.vertices_m.size();
      }
    }
  }
  return counts;
}

std::string describe(const WorldCounts& counts) {
  std::string types;
  for (const auto& [type, n] : counts.by_type) {
    types += (types.empty() ? "" : ", ") + type + " " + std::to_string(n);
  }
  std::string out = std::to_string(counts.objects) + " objects (" + types + "), " +
                    std::to_string(counts.boxes) + " boxes, " + std::to_string(counts.cylinders) +
                    " cylinders, " + std::to_string(counts.polyhedra) + " polyhedra";
  if (counts.meshes > 0) {
    out += ", " + std::to_string(counts.meshes) + " meshes (" +
           std::to_string(counts.mesh_triangles) + " triangles)";
  }
  return out;
}

namespace {

// What is wrong with an imported mesh, or "" (open and inconsistently wound meshes are fine).
std::string check_mesh(const world::TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return "has no triangles";
  for (const Eigen::Vector3f& v : mesh.vertices_m) {
    if (!v.allFinite()) return "vertex not finite";
  }
  for (const auto& triangle : mesh.triangles) {
    for (const std::uint32_t index : triangle) {
      if (index >= mesh.vertices_m.size()) return "vertex index out of range";
    }
  }
  return "";
}

}  // namespace

std::vector<std::string> check_generated_world(const world::WorldModel& world) {
  std::vector<std::string> problems;
  std::unordered_map<std::string, std::size_t> index;
  index.reserve(world.objects.size());
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    if (!index.emplace(world.objects[i].id, i).second) {
      problems.push_back("duplicate id " + world.objects[i].id);
    }
  }
  for (const world::ObjectModel& object : world.objects) {
    const std::string& id = object.id;
    if (!object.world_position_m.allFinite() || !object.world_orientation.coeffs().allFinite()) {
      problems.push_back(id + ": pose not finite");
    }
    if (object.size_m && !((object.size_m->array() > 0.0).all()))
      problems.push_back(id + ": size not positive");
    for (const world::Primitive& p : object.primitives) {
      if (!p.object_position_m.allFinite())
        problems.push_back(id + ": primitive position not finite");
      if (const auto* poly = std::get_if<world::Polyhedron>(&p.shape)) {
        const std::string what = check_polyhedron(*poly);
        if (!what.empty()) problems.push_back(id + ": polyhedron " + what);
      } else if (const auto* mesh = std::get_if<world::TriangleMesh>(&p.shape)) {
        const std::string what = check_mesh(*mesh);
        if (!what.empty()) problems.push_back(id + ": mesh " + what);
      } else if (const auto* b = std::get_if<world::Box>(&p.shape)) {
        if (!((b->size_m.array() > 0.0).all())) problems.push_back(id + ": box size not positive");
      } else {
        const auto& c = std::get<world::Cylinder>(p.shape);
        if (!(c.radius_m > 0.0 && c.height_m > 0.0))
          problems.push_back(id + ": cylinder size not positive");
      }
    }
    if (object.parent_id.empty()) continue;
    const auto parent = index.find(object.parent_id);
    if (parent == index.end()) {
      problems.push_back(id + ": parent " + object.parent_id + " does not exist");
      continue;
    }
    if (object.type != "handle") continue;
    const world::ObjectModel& front = world.objects[parent->second];
    if (!front.size_m) {
      problems.push_back(id + ": parent " + front.id + " has no size");
      continue;
    }
    // The grip's two ends along its long axis, in the parent's frame.
    const Eigen::Isometry3d parent_T_handle =
        front.world_T_object().inverse() * object.world_T_object();
    const Eigen::Vector3d half = 0.5 * object.size_m.value_or(Eigen::Vector3d::Zero());
    const Eigen::Vector3d axis =
        half.x() >= half.z() ? Eigen::Vector3d(half.x(), 0, 0) : Eigen::Vector3d(0, 0, half.z());
    for (const Eigen::Vector3d& end :
         {Eigen::Vector3d(parent_T_handle * axis), Eigen::Vector3d(parent_T_handle * -axis)}) {
      // A recessed grip's opening lies on the front face; everything else stands in front of it.
      if (!(end.y() <= 1e-9)) problems.push_back(id + ": behind the front face of " + front.id);
      if (std::abs(end.x()) > 0.5 * front.size_m->x() + 1e-9 ||
          std::abs(end.z()) > 0.5 * front.size_m->z() + 1e-9) {
        problems.push_back(id + ": beyond the extent of " + front.id);
      }
    }
  }
  return problems;
}

}  // namespace vsl::worldgen

// World-model file loader: YAML (docs/world-model.md) -> validated WorldModel.
#include <cmath>
#include <cstdint>
#include <map>
#include <thread>
#include <unordered_map>

#include "vsl/config/eigen.hpp"
#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::world {
namespace {

using config::Node;

// A world spans at most 100 km. Bigger numbers are typos or hostile input, and the renderer's
// rasterizer and the grids over the world overflow long before 1e308 m.
constexpr double kMaxCoordinateM = 1e5;

Eigen::Vector3d bounded_vector3(const Node& node) {
  const Eigen::Vector3d v = config::as_vector3(node);
  if (!(v.array().abs() <= kMaxCoordinateM).all()) node.fail("beyond 100 km (limit 1e5 m)");
  return v;
}

double length_m(const Node& node) {
  const double value = node.as_positive_double();
  if (value > kMaxCoordinateM) node.fail("beyond 100 km (limit 1e5 m)");
  return value;
}

Eigen::Vector3d positive_vector3(const Node& node) {
  const Eigen::Vector3d v = bounded_vector3(node);
  if (!(v.array() > 0.0).all()) node.fail("every extent must be positive");
  return v;
}

// Orientation from exactly one of `orientation: [w, x, y, z]`, `rpy: [roll, pitch, yaw]` (rad,
// extrinsic x-y-z, i.e. R = Rz(yaw) Ry(pitch) Rx(roll)) or `yaw: rad`; identity when none is given.
Eigen::Quaterniond orientation(const Node& parent) {
  const auto quaternion = parent.find("orientation");
  const auto rpy = parent.find("rpy");
  const auto yaw = parent.find("yaw");
  if (int(quaternion.has_value()) + int(rpy.has_value()) + int(yaw.has_value()) > 1) {
    (quaternion ? *quaternion : *rpy).fail("give only one of orientation, rpy and yaw");
  }
  if (quaternion) return config::as_unit_quaternion(*quaternion);
  if (rpy) {
    const auto a = rpy->as_array<3>();
    return Eigen::Quaterniond(Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitX()));
  }
  if (yaw) return Eigen::Quaterniond(Eigen::AngleAxisd(yaw->as_double(), Eigen::Vector3d::UnitZ()));
  return Eigen::Quaterniond::Identity();
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

Colour colour(const Node& node) {
  const std::string text = node.as_string();
  bool ok = text.size() == 7 && text[0] == '#';
  for (std::size_t i = 1; ok && i < 7; ++i) ok = hex_digit(text[i]) >= 0;
  if (!ok) node.fail("expected a colour \"#rrggbb\", got '" + text + "'");
  auto byte = [&](std::size_t at) {
    return static_cast<std::uint8_t>(hex_digit(text[at]) * 16 + hex_digit(text[at + 1]));
  };
  return Colour{byte(1), byte(3), byte(5)};
}

// `{colour, finish, pattern_colour, pattern_scale, contrast, specular, roughness, light}`; only
// the colour is required, so files written before finishes existed load as matte colours.
Material material_from(const Node& node, const std::string& name) {
  node.expect_keys({"colour", "finish", "pattern_colour", "pattern_scale", "contrast", "specular",
                    "roughness", "light"});
  Material out{name, colour(node.at("colour"))};
  if (const auto finish = node.find("finish")) {
    const std::optional<Finish> found = finish_from_name(finish->as_string());
    if (!found) {
      std::string allowed;
      for (const Finish f : kAllFinishes)
        allowed += std::string(allowed.empty() ? "" : ", ") + finish_name(f);
      finish->fail("unknown finish '" + finish->as_string() + "' (allowed: " + allowed + ")");
    }
    out.finish = *found;
  }
  if (const auto v = node.find("pattern_colour")) out.pattern_colour = colour(*v);
  if (const auto v = node.find("pattern_scale")) out.pattern_scale_m = v->as_double_in(0.001, 10.0);
  if (const auto v = node.find("contrast")) out.contrast = v->as_double_in(0.0, 1.0);
  if (const auto v = node.find("specular")) out.specular = v->as_double_in(0.0, 1.0);
  if (const auto v = node.find("roughness")) out.roughness = v->as_double_in(0.0, 1.0);
  if (const auto light = node.find("light")) {
    light->expect_keys({"flux_lm", "colour_temperature_k", "beam_half_angle"});
    MaterialLight emitted;
    if (const auto v = light->find("flux_lm")) emitted.luminous_flux_lm = v->as_double_in(0.0, 1e6);
    if (const auto v = light->find("colour_temperature_k")) {
      emitted.colour_temperature_k = v->as_double_in(1500.0, 12000.0);
    }
    if (const auto v = light->find("beam_half_angle")) {
      emitted.beam_half_angle_rad = v->as_double_in(0.1, 1.45);
    }
    out.light = emitted;
  }
  return out;
}

Polyhedron polyhedron(const Node& node) {
  node.expect_keys({"vertices", "faces"});
  Polyhedron out;
  const Node vertices = node.at("vertices");
  for (std::size_t i = 0; i < vertices.size(); ++i)
    out.vertices_m.push_back(bounded_vector3(vertices[i]));
  if (out.vertices_m.size() < 4) vertices.fail("a polyhedron needs at least 4 vertices");
  const Node faces = node.at("faces");
  if (faces.size() < 4) faces.fail("a polyhedron needs at least 4 faces");
  // A closed, consistently oriented surface uses every directed edge exactly once and its reverse
  // exactly once; the renderer relies on that for outward normals.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edges;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Node face = faces[f];
    if (face.size() < 3) face.fail("a face needs at least 3 vertex indices");
    std::vector<std::uint32_t> loop;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::int64_t index = face[k].as_int();
      if (index < 0 || index >= static_cast<std::int64_t>(out.vertices_m.size())) {
        face[k].fail("vertex index " + std::to_string(index) + " out of range [0, " +
                     std::to_string(out.vertices_m.size() - 1) + "]");
      }
      loop.push_back(static_cast<std::uint32_t>(index));
    }
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto edge = std::make_pair(loop[k], loop[(k + 1) % loop.size()]);
      if (++directed_edges[edge] > 1) {
        face.fail("edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                  " is used twice in the same direction: faces must all be counter-clockwise "
                  "seen from outside");
      }
    }
    out.faces.push_back(std::move(loop));
  }
  for (const auto& [edge, count] : directed_edges) {
    if (!directed_edges.count({edge.second, edge.first})) {
      faces.fail("the surface is not closed: edge " + std::to_string(edge.first) + "-" +
                 std::to_string(edge.second) + " has no neighbouring face");
    }
  }
  // Signed volume (divergence theorem over fan triangles) must be positive for outward faces.
  double volume = 0.0;
  for (const auto& loop : out.faces) {
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      volume +=
          out.vertices_m[loop[0]].dot(out.vertices_m[loop[k]].cross(out.vertices_m[loop[k + 1]]));
    }
  }
  if (!(volume > 0.0)) faces.fail("faces are clockwise seen from outside (or the volume is zero)");
  return out;
}

// An imported triangle soup: only the indices are checked (open, inconsistently wound and
// degenerate triangles are all legal). Linear in the mesh's size: meshes of 100k triangles are
// normal, so no per-edge bookkeeping as for polyhedra.
TriangleMesh triangle_mesh(const Node& node) {
  node.expect_keys({"vertices", "triangles"});
  TriangleMesh out;
  const Node vertices = node.at("vertices");
  const std::size_t vertex_count = vertices.size();
  if (vertex_count < 3) vertices.fail("a mesh needs at least 3 vertices");
  out.vertices_m.reserve(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    // Within 100 km, so well inside float's range.
    const Eigen::Vector3d v = bounded_vector3(vertices[i]);
    out.vertices_m.push_back(v.cast<float>());
  }
  const Node triangles = node.at("triangles");
  const std::size_t triangle_count = triangles.size();
  if (triangle_count == 0) triangles.fail("a mesh needs at least one triangle");
  out.triangles.reserve(triangle_count);
  const auto last = static_cast<std::int64_t>(vertex_count) - 1;
  for (std::size_t t = 0; t < triangle_count; ++t) {
    const Node triangle = triangles[t];
    if (triangle.size() != 3) {
      triangle.fail("a triangle needs 3 vertex indices, got " + std::to_string(triangle.size()));
    }
    std::array<std::uint32_t, 3> corners{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t index = triangle[k].as_int();
      if (index < 0 || index > last) {
        triangle[k].fail("vertex index " + std::to_string(index) + " out of range [0, " +
                         std::to_string(last) + "]");
      }
      corners[k] = static_cast<std::uint32_t>(index);
    }
    out.triangles.push_back(corners);
  }
  return out;
}

Primitive primitive(const Node& node, const WorldModel& world) {
  node.expect_keys({"box", "cylinder", "polyhedron", "mesh", "position", "orientation", "rpy",
                    "yaw", "material", "colour"});
  Primitive out;
  const auto box = node.find("box");
  const auto cylinder = node.find("cylinder");
  const auto poly = node.find("polyhedron");
  const auto mesh = node.find("mesh");
  const int shapes = int(box.has_value()) + int(cylinder.has_value()) + int(poly.has_value()) +
                     int(mesh.has_value());
  if (shapes != 1) node.fail("a primitive needs exactly one of box, cylinder, polyhedron, mesh");
  if (mesh) {
    out.shape = triangle_mesh(*mesh);
  } else if (box) {
    out.shape = Box{positive_vector3(*box)};
  } else if (cylinder) {
    cylinder->expect_keys({"radius", "height"});
    out.shape = Cylinder{length_m(cylinder->at("radius")), length_m(cylinder->at("height"))};
  } else {
    out.shape = polyhedron(*poly);
  }
  if (const auto position = node.find("position"))
    out.object_position_m = bounded_vector3(*position);
  out.object_orientation = orientation(node);
  if (const auto material = node.find("material")) {
    out.material = material->as_string();
    const Material* found = world.find_material(out.material);
    if (found == nullptr) material->fail("unknown material '" + out.material + "'");
    out.colour = found->colour;
  }
  if (const auto override_colour = node.find("colour")) out.colour = colour(*override_colour);
  return out;
}

struct ParentReference {
  std::size_t object;
  Node node;  // the `parent:` value, for the error's line
};

// An id or a type of nothing but blanks names nothing: `id: ""` is a typo, not an object.
std::string non_blank_text(const Node& node) {
  std::string text = node.as_string();
  if (text.find_first_not_of(" \t") == std::string::npos) node.fail("must not be empty");
  return text;
}

ObjectModel object(const Node& node, const WorldModel& world) {
  node.expect_keys(
      {"id", "type", "position", "orientation", "rpy", "yaw", "size", "parent", "primitives"});
  ObjectModel out;
  out.id = non_blank_text(node.at("id"));
  out.type = non_blank_text(node.at("type"));
  out.world_position_m = bounded_vector3(node.at("position"));
  out.world_orientation = orientation(node);
  if (const auto size = node.find("size")) out.size_m = positive_vector3(*size);
  if (const auto parent = node.find("parent")) out.parent_id = parent->as_string();
  if (const auto primitives = node.find("primitives")) {
    const std::size_t count = primitives->size();
    out.primitives.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
      out.primitives.push_back(primitive((*primitives)[i], world));
  }
  return out;
}

void check_parents(const WorldModel& world, const std::vector<ParentReference>& references) {
  for (const ParentReference& reference : references) {
    const ObjectModel& child = world.objects[reference.object];
    if (!world.find(child.parent_id)) {
      reference.node.fail("unknown parent '" + child.parent_id + "'");
    }
  }
  // Parent chains must end: walk each chain at most objects.size() steps, memoising finished ones.
  std::vector<std::uint8_t> state(world.objects.size(), 0);  // 0 new, 1 on the current walk, 2 ok
  for (const ParentReference& reference : references) {
    std::vector<std::size_t> walk;
    std::size_t at = reference.object;
    while (state[at] == 0) {
      state[at] = 1;
      walk.push_back(at);
      const std::string& parent = world.objects[at].parent_id;
      if (parent.empty()) break;
      at = *world.find(parent);
    }
    if (state[at] == 1 && !world.objects[at].parent_id.empty()) {
      reference.node.fail("parent chain of '" + world.objects[reference.object].id +
                          "' forms a cycle through '" + world.objects[at].id + "'");
    }
    for (std::size_t i : walk) state[i] = 2;
  }
}

// The objects of one document, converted on its own thread.
struct DocumentObjects {
  Node list;
  std::vector<ObjectModel> objects;
};

// Documents after the first hold more objects: a bare list, or a map with only `objects`.
Node objects_of(const Node& document, bool first, WorldModel& world) {
  if (document.is_sequence()) return document;
  if (!first) {
    document.expect_keys({"objects"});
    return document.at("objects");
  }
  document.expect_keys({"name", "materials", "objects"});
  world.name = document.get("name", "");
  if (const auto materials = document.find("materials")) {
    for (const std::string& name : materials->keys()) {
      world.materials.push_back(material_from(materials->at(name), name));
    }
  }
  return document.at("objects");
}

WorldModel world_from(const std::vector<Node>& documents) {
  WorldModel world;
  std::vector<DocumentObjects> parts;
  for (std::size_t d = 0; d < documents.size(); ++d) {
    parts.push_back({objects_of(documents[d], d == 0, world), {}});
    parts.back().list.size();  // a list, or the error names where
  }

  // Convert each document's objects on its own thread (materials are complete and read-only).
  std::vector<std::exception_ptr> errors(parts.size());
  const std::size_t workers = std::max<std::size_t>(
      1, std::min<std::size_t>(std::thread::hardware_concurrency(), parts.size()));
  auto convert_every_nth = [&](std::size_t worker) {
    for (std::size_t k = worker; k < parts.size(); k += workers) {
      try {
        const std::size_t count = parts[k].list.size();
        parts[k].objects.reserve(count);
        for (std::size_t i = 0; i < count; ++i) {
          parts[k].objects.push_back(object(parts[k].list[i], world));
        }
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(convert_every_nth, w);
    convert_every_nth(0);
  }
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }

  std::size_t total = 0;
  for (const DocumentObjects& part : parts) total += part.objects.size();
  world.objects.reserve(total);
  // Where each id was first defined (document, position), for the rare duplicate's message.
  std::unordered_map<std::string, std::pair<std::size_t, std::size_t>> first_definition;
  first_definition.reserve(total);
  std::vector<ParentReference> parents;
  for (std::size_t d = 0; d < parts.size(); ++d) {
    DocumentObjects& part = parts[d];
    for (std::size_t i = 0; i < part.objects.size(); ++i) {
      world.objects.push_back(std::move(part.objects[i]));
      const ObjectModel& added = world.objects.back();
      const auto [it, inserted] = first_definition.emplace(added.id, std::make_pair(d, i));
      if (!inserted) {
        const int first_line = parts[it->second.first].list[it->second.second].line();
        part.list[i].at("id").fail("duplicate id '" + it->first + "' (first defined on line " +
                                   std::to_string(first_line) + ")");
      }
      if (!added.parent_id.empty()) {
        parents.push_back({world.objects.size() - 1, part.list[i].at("parent")});
      }
    }
  }
  world.index_ids();
  check_parents(world, parents);
  return world;
}

}  // namespace

WorldModel load_world(const std::string& path) {
  return world_from(Node::load_file_documents(path));
}

WorldModel load_world_from_string(const std::string& text, const std::string& source_name) {
  return world_from(Node::load_string_documents(text, source_name));
}

}  // namespace vsl::world

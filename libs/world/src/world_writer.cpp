// World-model file writer: the inverse of world_loader.cpp, in the same format.
#include <charconv>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <ostream>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::world {
namespace {

// Fixed-point text with trailing zeros dropped: positions to a micrometre, angles and quaternion
// components to a nanoradian. Keeps generated files short and diff-able.
std::string number(double value, int decimals) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  std::string out(buffer, result.ptr);
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out;
}

constexpr int kMetre = 6;      // decimals: 1 um
constexpr int kMeshMetre = 4;  // decimals: 0.1 mm; mesh vertices are floats and many
constexpr int kUnitless = 9;   // decimals: 1 nrad

// "[a, b, ...]", appended piecewise: GCC 12 warns falsely (-Wrestrict, GCC bug 105651) on
// `"[" + std::string` once inlined at -O2.
std::string flow_list(std::initializer_list<std::string> items) {
  std::string out = "[";
  for (const std::string& item : items) {
    if (out.size() > 1) out += ", ";
    out += item;
  }
  out += ']';
  return out;
}

std::string vector3(const Eigen::Vector3d& v) {
  return flow_list({number(v.x(), kMetre), number(v.y(), kMetre), number(v.z(), kMetre)});
}

bool plain_safe(const std::string& text) {
  if (text.empty()) return false;
  for (char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.' || c == '/';
    if (!ok) return false;
  }
  // Text that YAML would read as something else (a number, a boolean, null) gets quotes.
  const char first = text.front();
  if ((first >= '0' && first <= '9') || first == '-' || first == '.') return false;
  for (const char* word : {"true", "false", "yes", "no", "on", "off", "null", "True", "False",
                           "Null", "NULL", "TRUE", "FALSE", "Yes", "No", "On", "Off"}) {
    if (text == word) return false;
  }
  return true;
}

std::string text(const std::string& value) {
  if (plain_safe(value)) return value;
  std::string out = "\"";
  for (char c : value) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string colour(const Colour& c) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"#";
  for (std::uint8_t channel : {c.r, c.g, c.b}) {
    out += kHex[channel >> 4];
    out += kHex[channel & 15];
  }
  return out + "\"";
}

// "yaw: a" for a rotation about z only (the common case in buildings), the quaternion otherwise,
// nothing for the identity. Written as a flow-map fragment with a leading ", " or as a block line.
std::string orientation_value(const Eigen::Quaterniond& q_in, std::string* key) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0) q.coeffs() *= -1.0;
  if (std::abs(q.x()) < 1e-12 && std::abs(q.y()) < 1e-12) {
    double yaw = 2.0 * std::atan2(q.z(), q.w());
    if (std::abs(yaw) < 1e-12) return "";
    // Half a turn either way is the same rotation; always write +pi so that text round-trips.
    if (yaw < -M_PI + 1e-9) yaw = M_PI;
    *key = "yaw";
    return number(yaw, kUnitless);
  }
  *key = "orientation";
  return flow_list({number(q.w(), kUnitless), number(q.x(), kUnitless), number(q.y(), kUnitless),
                    number(q.z(), kUnitless)});
}

// One flow-style line however big the mesh: appended in place, no temporary per number, so that
// writing 100k triangles stays linear and quick.
std::string triangle_mesh(const TriangleMesh& mesh) {
  std::string out = "mesh: {vertices: [";
  out.reserve(out.size() + mesh.vertices_m.size() * 32 + mesh.triangles.size() * 24 + 16);
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i) {
    out += i ? ", [" : "[";
    for (int k = 0; k < 3; ++k) {
      if (k) out += ", ";
      out += number(static_cast<double>(mesh.vertices_m[i][k]), kMeshMetre);
    }
    out += ']';
  }
  out += "], triangles: [";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    out += t ? ", [" : "[";
    for (int k = 0; k < 3; ++k) {
      if (k) out += ", ";
      out += std::to_string(mesh.triangles[t][k]);
    }
    out += ']';
  }
  return out + "]}";
}

std::string shape(const Shape& s) {
  if (const auto* box = std::get_if<Box>(&s)) return "box: " + vector3(box->size_m);
  if (const auto* cylinder = std::get_if<Cylinder>(&s)) {
    return "cylinder: {radius: " + number(cylinder->radius_m, kMetre) +
           ", height: " + number(cylinder->height_m, kMetre) + "}";
  }
  if (const auto* mesh = std::get_if<TriangleMesh>(&s)) return triangle_mesh(*mesh);
  const auto& poly = std::get<Polyhedron>(s);
  std::string out = "polyhedron: {vertices: [";
  for (std::size_t i = 0; i < poly.vertices_m.size(); ++i) {
    out += (i ? ", " : "") + vector3(poly.vertices_m[i]);
  }
  out += "], faces: [";
  for (std::size_t f = 0; f < poly.faces.size(); ++f) {
    out += f ? ", [" : "[";
    for (std::size_t k = 0; k < poly.faces[f].size(); ++k) {
      out += (k ? ", " : "") + std::to_string(poly.faces[f][k]);
    }
    out += "]";
  }
  return out + "]}";
}

void write_primitive(const Primitive& p, const WorldModel& world, std::ostream& out) {
  out << "      - {" << shape(p.shape);
  if (!p.object_position_m.isZero(0.0)) out << ", position: " << vector3(p.object_position_m);
  std::string key;
  const std::string value = orientation_value(p.object_orientation, &key);
  if (!value.empty()) out << ", " << key << ": " << value;
  const Material* material = p.material.empty() ? nullptr : world.find_material(p.material);
  if (material != nullptr) out << ", material: " << text(p.material);
  if (material == nullptr || !(material->colour == p.colour))
    out << ", colour: " << colour(p.colour);
  out << "}\n";
}

// The optional fields of a material, each as ", key: value" (none for a plain colour).
void write_appearance(const Material& m, std::ostream& out) {
  if (m.finish != Finish::matte) out << ", finish: " << finish_name(m.finish);
  if (m.pattern_colour) out << ", pattern_colour: " << colour(*m.pattern_colour);
  if (m.pattern_scale_m) out << ", pattern_scale: " << number(*m.pattern_scale_m, kUnitless);
  if (m.contrast) out << ", contrast: " << number(*m.contrast, kUnitless);
  if (m.specular) out << ", specular: " << number(*m.specular, kUnitless);
  if (m.roughness) out << ", roughness: " << number(*m.roughness, kUnitless);
  if (m.light) {
    out << ", light: {flux_lm: " << number(m.light->luminous_flux_lm, kUnitless)
        << ", colour_temperature_k: " << number(m.light->colour_temperature_k, kUnitless)
        << ", beam_half_angle: " << number(m.light->beam_half_angle_rad, kUnitless) << "}";
  }
}

}  // namespace

void write_world(const WorldModel& world, std::ostream& out) {
  if (world.objects.empty()) {
    if (!world.name.empty()) out << "name: " << text(world.name) << "\n";
    out << "objects: []\n";
    return;
  }
  if (!world.name.empty()) out << "name: " << text(world.name) << "\n";
  if (!world.materials.empty()) {
    out << "materials:\n";
    for (const Material& m : world.materials) {
      out << "  " << text(m.name) << ": {colour: " << colour(m.colour);
      write_appearance(m, out);
      out << "}\n";
    }
  }
  out << "objects:\n";
  for (std::size_t index = 0; index < world.objects.size(); ++index) {
    // Big worlds become a stream of documents that load_world parses in parallel.
    if (index > 0 && index % kObjectsPerDocument == 0) out << "---\nobjects:\n";
    const ObjectModel& o = world.objects[index];
    out << "  - id: " << text(o.id) << "\n";
    out << "    type: " << text(o.type) << "\n";
    out << "    position: " << vector3(o.world_position_m) << "\n";
    std::string key;
    const std::string value = orientation_value(o.world_orientation, &key);
    if (!value.empty()) out << "    " << key << ": " << value << "\n";
    if (o.size_m) out << "    size: " << vector3(*o.size_m) << "\n";
    if (!o.parent_id.empty()) out << "    parent: " << text(o.parent_id) << "\n";
    if (!o.primitives.empty()) {
      out << "    primitives:\n";
      for (const Primitive& p : o.primitives) write_primitive(p, world, out);
    }
  }
}

void write_world_file(const WorldModel& world, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw config::Error(path + ": cannot open for writing");
  write_world(world, out);
  out.flush();
  if (!out) throw config::Error(path + ": write failed");
}

}  // namespace vsl::world

// The world model, paper §2.2: two levels of abstraction.
//  1. Geometric primitives (boxes, cylinders, general polyhedra, imported triangle meshes), each
//     with a transform and a colour/material. The simulator renders them; localization never
//     needs them.
//  2. Typed object-model instances O_i^m (id, type, pose, size, optional parent, the primitives
//     that make them up). Their collection is the node set Xi of Eq. 5.
// Frames: every object pose is world_T_object (metres, unit quaternion); every primitive pose is
// object_T_primitive, in the frame of the object that owns it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace vsl::world {

// sRGB colour, 0-255 per channel.
struct Colour {
  std::uint8_t r = 200, g = 200, b = 200;
  friend bool operator==(const Colour&, const Colour&) = default;
};

// How a surface looks beyond its colour when the renderer's realism is on (docs/rendering.md).
// `matte` is the flat colour every material had before finishes existed.
enum class Finish {
  matte,           // flat colour, no pattern
  painted,         // fine noise of a painted surface, slight sheen
  laminate,        // fine noise, clear specular highlights
  wood,            // grain: distorted growth rings along the surface's long axis
  brushed_metal,   // fine streaks along the long axis, broad highlights
  polished_metal,  // mirror-like: sharp highlights, reflected room
  stone,           // speckled granite or marble
  tiles,           // square tiles with grout lines
  glass,           // transparent-looking pane: reflection of the room, sharp highlights
};
inline constexpr Finish kAllFinishes[] = {
    Finish::matte,          Finish::painted, Finish::laminate, Finish::wood, Finish::brushed_metal,
    Finish::polished_metal, Finish::stone,   Finish::tiles,    Finish::glass};
const char* finish_name(Finish finish);
// The finish of this name, or nullopt.
std::optional<Finish> finish_from_name(const std::string& name);

// Light a lamp material emits (a downlight, an under-cupboard strip). Each primitive of the
// material is one lamp, at the primitive's centre, shining along the primitive's -z axis.
struct MaterialLight {
  double luminous_flux_lm = 500.0;       // total light out, lumens (a kitchen downlight: 400-800)
  double colour_temperature_k = 3000.0;  // correlated colour temperature, kelvin (1500-12000)
  double beam_half_angle_rad = 1.05;     // half angle of the cone it lights, rad (0.1-1.45)
  friend bool operator==(const MaterialLight&, const MaterialLight&) = default;
};

// A named surface appearance that primitives refer to, so that a kitchen's door panels share one.
// Every field but the colour is optional: unset, the renderer takes the finish's default.
struct Material {
  std::string name;
  Colour colour;
  Finish finish = Finish::matte;
  std::optional<Colour> pattern_colour =
      std::nullopt;  // grain, grout or speckle colour; default: from colour
  std::optional<double> pattern_scale_m =
      std::nullopt;  // size of the pattern's features (ring spacing, tile), m
  std::optional<double> contrast = std::nullopt;   // strength of the pattern, 0 (none) to 1
  std::optional<double> specular = std::nullopt;   // strength of highlights, 0 to 1
  std::optional<double> roughness = std::nullopt;  // 0 (mirror) to 1 (chalk): width of highlights
  std::optional<MaterialLight> light = std::nullopt;  // set: the material emits light (a lamp)
};

// Axis-aligned box in its own frame, centred on the origin; full extents along x, y, z (m).
struct Box {
  Eigen::Vector3d size_m = Eigen::Vector3d::Ones();
};

// Cylinder along its own z axis, centred on the origin (m).
struct Cylinder {
  double radius_m = 0.5;
  double height_m = 1.0;
};

// Closed polyhedron: vertices in its own frame (m); each face a loop of >= 3 vertex indices,
// counter-clockwise seen from outside (so that the right-hand normal points out).
struct Polyhedron {
  std::vector<Eigen::Vector3d> vertices_m;
  std::vector<std::vector<std::uint32_t>> faces;
};

// Triangle soup from an imported mesh (CAD, URDF, SDF, VRML): need not be closed or consistently
// oriented, so it is rendered two-sided and has no inside. Vertices in the primitive's frame (m).
// Degenerate triangles (repeated or collinear corners) are allowed and ignored by the renderer.
struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices_m;  // float: meshes are large; 0.1 mm precision is plenty
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into vertices_m
};

using Shape = std::variant<Box, Cylinder, Polyhedron, TriangleMesh>;

struct Primitive {
  Shape shape;
  Eigen::Vector3d object_position_m = Eigen::Vector3d::Zero();  // primitive origin, object frame
  Eigen::Quaterniond object_orientation = Eigen::Quaterniond::Identity();  // object_R_primitive
  std::string material;  // name in WorldModel::materials, or empty
  Colour colour;         // resolved: the material's colour unless the file overrides it

  Eigen::Isometry3d object_T_primitive() const;
};

// An object-model instance O_i^m.
struct ObjectModel {
  std::string id;    // unique within the world
  std::string type;  // class as recognized: "door", "handle", "drawer_front", "window", ...
  Eigen::Vector3d world_position_m = Eigen::Vector3d::Zero();  // X_i: the point a percept sees
  Eigen::Quaterniond world_orientation = Eigen::Quaterniond::Identity();  // world_R_object
  std::optional<Eigen::Vector3d> size_m;  // extents along the object's x, y, z, when known
  std::string parent_id;                  // id of the enclosing object (a door's cupboard), or ""
  std::vector<Primitive> primitives;      // geometry, object frame; may be empty

  Eigen::Isometry3d world_T_object() const;
};

class WorldModel {
 public:
  std::string name;
  std::vector<Material> materials;
  std::vector<ObjectModel> objects;

  // Index of the object with this id, or nullopt. Valid after index_ids() (the loader calls it).
  std::optional<std::size_t> find(const std::string& id) const;
  const Material* find_material(const std::string& name) const;
  // Rebuilds the id lookup; call after editing `objects`.
  void index_ids();

 private:
  std::unordered_map<std::string, std::size_t> index_by_id_;
};

}  // namespace vsl::world

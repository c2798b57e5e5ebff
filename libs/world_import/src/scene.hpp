// What every model-file reader produces: the file's named parts (URDF/SDF links, a mesh file's
// nodes, VRML DEF nodes), placed in the world frame, with their geometry, appearance and the
// joint that attaches each to its parent. The readers know formats; they know nothing of door
// types or reference points (type_rules.hpp and object_builder.hpp decide those).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "vsl/world/world_model.hpp"

namespace vsl::world_import {

// How a part attaches to its parent (URDF/SDF joint types; `none` for formats without joints).
enum class JointKind { none, fixed, revolute, continuous, prismatic, floating, planar, other };
const char* joint_kind_name(JointKind kind);

// Triangles in their geometry frame (m); need not be closed or consistently oriented.
struct TriangleSoup {
  std::vector<Eigen::Vector3f> vertices_m;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// A sphere (URDF, SDF) arrives tessellated as a TriangleSoup; everything else is one of these.
using PartShape = std::variant<world::Box, world::Cylinder, TriangleSoup>;

// One piece of a part's geometry with its appearance.
struct PartGeometry {
  Eigen::Isometry3d world_T_geometry = Eigen::Isometry3d::Identity();  // geometry frame, world
  PartShape shape;
  std::string material;                 // the file's material name, or ""
  std::optional<world::Colour> colour;  // diffuse colour (sRGB) when the file gives one
};

// One named part of a model file.
struct ScenePart {
  std::string name;                   // unique within its scene
  std::string parent;                 // name of the enclosing part in the same scene, or ""
  JointKind joint = JointKind::none;  // how it attaches to `parent`
  // For revolute, continuous and prismatic joints: the axis (unit, world frame), a point on it
  // (world, m) and the limits (rad or m; both 0 when the file gives none).
  Eigen::Vector3d world_joint_axis = Eigen::Vector3d::Zero();
  Eigen::Vector3d world_joint_point_m = Eigen::Vector3d::Zero();
  double joint_lower = 0.0;
  double joint_upper = 0.0;
  Eigen::Isometry3d world_T_part = Eigen::Isometry3d::Identity();  // the part's own frame
  std::vector<PartGeometry> geometry;  // may be empty (a frame that only groups others)
};

struct Scene {
  std::string source;  // the file read
  std::vector<ScenePart> parts;
  std::vector<std::string> warnings;  // one line each, naming the file (a missing mesh, ...)
};

struct ReadOptions {
  // Roots searched for `package://NAME/...` (as ROS_PACKAGE_PATH: NAME is a folder under a root,
  // or the root itself is NAME) and `model://NAME/...` URIs.
  std::vector<std::string> package_paths;
  // Joint name -> position (rad or m) for forward kinematics; joints not named are at 0.
  std::map<std::string, double> joint_positions;
};

// Each reader throws config::Error, one line naming the file, for a file it cannot read; a
// referenced mesh that is missing or unreadable is a warning in Scene::warnings, not an error.
Scene read_urdf(const std::string& path, const ReadOptions& options);
Scene read_sdf(const std::string& path, const ReadOptions& options);        // SDF, Gazebo .world
Scene read_mesh_file(const std::string& path, const ReadOptions& options);  // assimp formats
Scene read_inventor(const std::string& path, const ReadOptions& options);   // VRML 2, Inventor

// A mesh file's triangles in the file's frame (metres after `scale`), one piece per material.
struct MeshPiece {
  TriangleSoup soup;
  std::string material;
  std::optional<world::Colour> colour;
};
// Throws config::Error naming the file when assimp cannot read it.
std::vector<MeshPiece> load_mesh_pieces(const std::string& path, const Eigen::Vector3d& scale);

// The file a model refers to: `package://NAME/rest`, `model://NAME/rest`, `file://abs` or a path
// relative to `referring_file`'s folder. Empty when no candidate exists.
std::string resolve_uri(const std::string& uri, const std::string& referring_file,
                        const std::vector<std::string>& package_paths);

// A colour channel of 0..1 (as the libraries give them) as an sRGB byte, clamped.
std::uint8_t to_byte(float unit);

// A file's extension in lower case, with its dot (".dae"): how formats are told apart.
std::string lower_extension(const std::string& path);

// `text` with every run of white space (newlines too) as one space, trimmed: the libraries'
// messages can span lines, vsl's errors and warnings are one line each.
std::string one_line(const std::string& text);

// A UV sphere of about 1 cm edge length at the equator (8-32 segments), centred on the origin.
TriangleSoup tessellate_sphere(double radius_m);

}  // namespace vsl::world_import

// Importing building models into a vsl world: URDF (urdfdom), SDF and Gazebo worlds (sdformat),
// COLLADA/OBJ/glTF/STL/PLY meshes (assimp) and VRML 2 / Open Inventor (Coin3D), several files
// into one world. Each named part of a file (a link, a node, a DEF) becomes an object whose type
// comes from TypeRules, whose reference point, orientation and size come from its geometry
// (docs/world-model.md, "Import"), and whose geometry is kept for the simulator.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vsl/world/world_model.hpp"
#include "vsl/world_import/type_rules.hpp"

namespace vsl::world_import {

enum class ModelFormat { kUrdf, kSdf, kMesh, kInventor };
const char* model_format_name(ModelFormat format);
// From the file's extension; throws config::Error naming the file for one no reader takes.
ModelFormat model_format_of(const std::string& path);

// Where a file's own world frame goes in the imported world: x, y, z (m) and a yaw (rad).
struct Placement {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double yaw_rad = 0.0;
};

struct ImportInput {
  std::string path;
  std::optional<Placement> at;  // unset: the file is in world coordinates
  // The file's y axis is up (VRML's convention, many CAD exports): a quarter turn about x takes
  // it to vsl's z up before `at` places it.
  bool y_up = false;
  // Multiplies the file's coordinates first: 0.001 for a file in millimetres (Simox, many CAD
  // exports), 0.0254 for inches.
  double scale = 1.0;
};

struct ImportOptions {
  std::vector<std::string> package_paths;         // for package:// and model:// URIs
  std::map<std::string, double> joint_positions;  // joint -> rad or m; others at 0
  std::size_t max_triangles_per_object = 20000;   // more are simplified (vertex clustering)
  std::string world_name;                         // "" = the first file's stem
};

struct ImportReport {
  struct File {
    std::string path;
    ModelFormat format;
    std::size_t parts = 0;
  };
  std::vector<File> files;
  std::map<std::string, std::size_t> objects_by_type;
  std::vector<std::pair<std::string, std::size_t>> rules_fired;  // rule described, times; in order
  std::vector<std::string> unmatched;  // parts no rule typed (kept as kUnmatchedType)
  std::vector<std::string> skipped;    // parts a rule left out
  std::vector<std::string> dropped;    // "name: why" (a door without geometry, ...)
  std::vector<std::string> warnings;   // missing meshes and the like, one line each
  std::map<std::string, std::string> front_decided_by;  // panel or handle id -> "its handle", ...
  std::size_t triangles_read = 0, triangles_kept = 0;
  std::size_t simplified_objects = 0;
};

struct ImportResult {
  world::WorldModel world;
  ImportReport report;
};

// Throws config::Error (one line naming the file) for a file that cannot be read at all.
ImportResult import_world(const std::vector<ImportInput>& inputs, const ImportOptions& options,
                          const TypeRules& rules);

// The report as text for `vsl-world import --dry-run`: counts by type, the rules that fired,
// unmatched names, what was left out and why, warnings.
std::string format_report(const ImportReport& report, bool list_objects,
                          const world::WorldModel& world);

}  // namespace vsl::world_import

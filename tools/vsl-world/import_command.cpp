#include "import_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/world_import/import.hpp"

namespace vsl::world_tool {
namespace {

constexpr const char* kUsage =
    R"(usage: vsl-world import FILE [--at X,Y,Z,YAW] [FILE [--at ...]]... -o WORLD.yaml [options]
       vsl-world import FILE... --dry-run [options]

Imports building models into one vsl world (docs/world-model.md, "Import"): URDF (.urdf), SDF and
Gazebo worlds (.sdf, .world), meshes (.dae, .obj, .gltf, .glb, .stl, .ply) and VRML 2 / Open
Inventor (.wrl, .iv). Each link, node or DEF becomes an object typed by the rules; doors, drawer
fronts and windows are placed at the centre of their front face, handles at the middle of their
bar; the geometry is kept so that the simulated head can render the building.
  FILE                 a model file, in world coordinates unless --at follows it
  --at X,Y,Z,YAW       place the file before it: its origin at X,Y,Z (m), turned by YAW (rad)
  --y-up               the file before it has y up (VRML's convention, many CAD exports);
                       default z up (URDF, SDF, ROS), glTF and COLLADA files say their own
  --scale S            the file before it is in other units: metres = S x its numbers
                       (0.001 for millimetres, 0.0254 for inches)
  -o, --output WORLD   the world file to write
  --dry-run            write nothing; report what would become what
  --list               with the report, every typed object and its reference point
  --rules FILE         type rules (regular expressions on names, materials, joints), tried
                       before the built-in ones
  --package-path DIR   where package://NAME/... and model://NAME/... are found (repeatable;
                       ROS_PACKAGE_PATH and GAZEBO_MODEL_PATH are searched too)
  --joint NAME=VALUE   a joint's position (rad or m) for the pose; others at 0 (repeatable)
  --max-triangles N    triangles per object before simplification (default 20000)
  --name NAME          the world's name (default: the first file's name)
  -q, --quiet          no progress or summary
exit codes: 0 ok, 2 bad usage or a file that cannot be read
)";

struct Options {
  std::vector<world_import::ImportInput> inputs;
  world_import::ImportOptions import;
  std::string output, rules_file;
  bool dry_run = false, list = false, quiet = false;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-world import: " << what << " (see vsl-world import --help)\n";
  std::exit(2);
}

double number(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (...) {
  }
  usage_error(what + ": expected a number, got '" + text + "'");
}

world_import::Placement placement(const std::string& text) {
  std::vector<double> values;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) values.push_back(number(item, "--at"));
  if (values.size() != 4) usage_error("--at wants X,Y,Z,YAW, got '" + text + "'");
  return {Eigen::Vector3d(values[0], values[1], values[2]), values[3]};
}

void add_env_paths(const char* variable, std::vector<std::string>& paths) {
  const char* value = std::getenv(variable);
  if (value == nullptr) return;
  std::stringstream list(value);
  for (std::string item; std::getline(list, item, ':');) {
    if (!item.empty()) paths.push_back(item);
  }
}

Options parse(int argc, char** argv) {
  Options options;
  auto value = [&](int& i, const std::string& arg) -> std::string {
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    return argv[++i];
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "-o" || arg == "--output") {
      options.output = value(i, arg);
    } else if (arg == "--at") {
      if (options.inputs.empty()) usage_error("--at must follow the file it places");
      if (options.inputs.back().at) usage_error("two --at for " + options.inputs.back().path);
      options.inputs.back().at = placement(value(i, arg));
    } else if (arg == "--y-up") {
      if (options.inputs.empty()) usage_error("--y-up must follow the file it turns");
      options.inputs.back().y_up = true;
    } else if (arg == "--scale") {
      if (options.inputs.empty()) usage_error("--scale must follow the file it scales");
      const double scale = number(value(i, arg), arg);
      if (!(scale > 0.0) || scale > 1e6) usage_error("--scale must be a positive factor");
      options.inputs.back().scale = scale;
    } else if (arg == "--rules") {
      options.rules_file = value(i, arg);
    } else if (arg == "--package-path") {
      options.import.package_paths.push_back(value(i, arg));
    } else if (arg == "--joint") {
      const std::string text = value(i, arg);
      const std::size_t eq = text.find('=');
      if (eq == std::string::npos || eq == 0)
        usage_error("--joint wants NAME=VALUE, got '" + text + "'");
      options.import.joint_positions[text.substr(0, eq)] = number(text.substr(eq + 1), "--joint");
    } else if (arg == "--max-triangles") {
      const double n = number(value(i, arg), arg);
      if (n < 12 || n > 1e8 || n != std::floor(n))
        usage_error("--max-triangles must be a whole number 12..1e8");
      options.import.max_triangles_per_object = static_cast<std::size_t>(n);
    } else if (arg == "--name") {
      options.import.world_name = value(i, arg);
    } else if (arg == "--dry-run") {
      options.dry_run = true;
    } else if (arg == "--list") {
      options.list = true;
    } else if (arg == "-q" || arg == "--quiet") {
      options.quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      usage_error("unknown option " + arg);
    } else {
      options.inputs.push_back({arg, std::nullopt});
    }
  }
  if (options.inputs.empty()) usage_error("no model file given");
  if (options.output.empty() && !options.dry_run)
    usage_error("no output: give -o WORLD.yaml or --dry-run");
  add_env_paths("ROS_PACKAGE_PATH", options.import.package_paths);
  add_env_paths("GAZEBO_MODEL_PATH", options.import.package_paths);
  return options;
}

}  // namespace

int run_import(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    const auto start = std::chrono::steady_clock::now();
    const world_import::TypeRules rules = options.rules_file.empty()
                                              ? world_import::TypeRules::built_in()
                                              : world_import::TypeRules::load(options.rules_file);
    // The status line is for a person watching; logs and pipes get the report alone.
    if (!options.quiet && ::isatty(STDERR_FILENO)) {
      std::cerr << "vsl-world import: reading " << options.inputs.size() << " file"
                << (options.inputs.size() == 1 ? "" : "s") << " ...\n";
    }
    const world_import::ImportResult result =
        world_import::import_world(options.inputs, options.import, rules);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.dry_run) {
      std::cout << world_import::format_report(result.report, options.list, result.world);
      return 0;
    }
    // Written beside the target, checked by loading it back, then moved into place: a world
    // file is never left half-written or unloadable.
    const std::string partial = options.output + ".partial";
    world::write_world_file(result.world, partial);
    try {
      (void)world::load_world(partial);
    } catch (const config::Error& e) {
      std::filesystem::remove(partial);
      throw config::Error(std::string("the imported world does not load back: ") + e.what());
    }
    std::filesystem::rename(partial, options.output);
    if (!options.quiet) {
      std::cerr << world_import::format_report(result.report, options.list, result.world);
      std::fprintf(stderr, "wrote %s (%zu objects) in %.1f s\n", options.output.c_str(),
                   result.world.objects.size(), seconds);
    }
  } catch (const config::Error& e) {
    std::cerr << "vsl-world import: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vsl-world import: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace vsl::world_tool

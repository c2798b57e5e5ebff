// vsl-world: check a world-model file, or print what is in it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "door_sizes.hpp"
#include "import_command.hpp"
#include "vsl/config/node.hpp"
#include "vsl/world/world_graph.hpp"
#include "vsl/world/world_graph_options.hpp"
#include "vsl/world/world_io.hpp"

namespace {

constexpr const char* kUsage = R"(usage: vsl-world check FILE
       vsl-world stats FILE [--config FILE] [--link-threshold METRES] [--node-types T,T,...]
                       [--list TYPES]
       vsl-world door-sizes FILE [--type TYPE]
       vsl-world import FILE... -o WORLD.yaml [--rules FILE] [--dry-run] ...  (import --help)

Validates a vsl world-model file (format: docs/world-model.md).
  check   validate; prints a one-line summary, or the one-line error and exits 2
  stats   primitives by kind, mesh triangles, objects by type, world-graph links (paper
          Eq. 6) and the bounding box of all geometry (world frame, metres)
  door-sizes  the sizes of the world's doors (or --type TYPE) as the recognizer's class entry
          wants them (config/recognition_paper.yaml, stereo.door_classes; docs/recognition.md): every
          height, the RMS of the heights about the most common, the most common width and the
          RMS of the widths about it, metres; exit 2 when no such object has a size
options:
  --config FILE        read the world_graph section (link_threshold_m, node_types) of a
                       localizer config such as config/localizer.yaml
  --link-threshold M   varpi of Eq. 6, metres (default 4; overrides --config)
  --list TYPES         also list every object of these types (comma-separated), with its
                       position
  --node-types LIST    only these object types become graph nodes (default: all; overrides
                       --config)
  --type TYPE          door-sizes: the objects' type (default door)
exit codes: 0 ok, 2 bad file or usage
)";

using vsl::world::Box;
using vsl::world::Cylinder;
using vsl::world::Polyhedron;
using vsl::world::TriangleMesh;

struct Options {
  std::string command;
  std::string file;
  vsl::world::WorldGraphOptions graph;
  std::vector<std::string> list_types;  // stats --list: these types' objects, one per line
  std::string sizes_type = "door";      // door-sizes --type
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-world: " << what << " (see vsl-world --help)\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options options;
  std::vector<std::string> positional;
  std::optional<std::string> config_file, threshold, node_types, list_types;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--type") {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      options.sizes_type = argv[++i];
    } else if (arg == "--link-threshold" || arg == "--node-types" || arg == "--config" ||
               arg == "--list") {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      (arg == "--config"           ? config_file
       : arg == "--link-threshold" ? threshold
       : arg == "--list"           ? list_types
                                   : node_types) = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      usage_error("unknown option " + arg);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() != 2 ||
      (positional[0] != "check" && positional[0] != "stats" && positional[0] != "door-sizes")) {
    usage_error("expected 'check FILE', 'stats FILE' or 'door-sizes FILE'");
  }
  options.command = positional[0];
  options.file = positional[1];
  if (config_file) {
    const auto root = vsl::config::Node::load_file(*config_file);
    root.expect_map();
    if (const auto section = root.find("world_graph")) {
      options.graph = vsl::world::world_graph_options_from(*section);
    }
  }
  if (threshold) {
    try {
      std::size_t used = 0;
      options.graph.link_threshold_m = std::stod(*threshold, &used);
      if (used != threshold->size() || !(options.graph.link_threshold_m > 0)) throw 0;
    } catch (...) {
      usage_error("--link-threshold must be a positive number of metres, got '" + *threshold + "'");
    }
  }
  if (list_types) {
    std::stringstream list(*list_types);
    for (std::string type; std::getline(list, type, ',');) {
      if (!type.empty()) options.list_types.push_back(type);
    }
  }
  if (node_types) {
    options.graph.node_types.clear();
    std::stringstream list(*node_types);
    for (std::string type; std::getline(list, type, ',');) {
      if (!type.empty()) options.graph.node_types.push_back(type);
    }
  }
  return options;
}

// Corners of a primitive's bounding box in its own frame.
std::vector<Eigen::Vector3d> extreme_points(const vsl::world::Shape& shape) {
  Eigen::Vector3d half;
  if (const auto* box = std::get_if<Box>(&shape)) {
    half = box->size_m / 2;
  } else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) {
    half = {cylinder->radius_m, cylinder->radius_m, cylinder->height_m / 2};
  } else if (const auto* mesh = std::get_if<TriangleMesh>(&shape)) {
    std::vector<Eigen::Vector3d> vertices;
    vertices.reserve(mesh->vertices_m.size());
    for (const Eigen::Vector3f& v : mesh->vertices_m) vertices.push_back(v.cast<double>());
    return vertices;
  } else {
    return std::get<Polyhedron>(shape).vertices_m;
  }
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 8; ++k) {
    corners.emplace_back((k & 1 ? 1 : -1) * half.x(), (k & 2 ? 1 : -1) * half.y(),
                         (k & 4 ? 1 : -1) * half.z());
  }
  return corners;
}

void print_stats(const vsl::world::WorldModel& world, const Options& options, double load_s) {
  std::map<std::string, std::size_t> primitives_by_kind{
      {"box", 0}, {"cylinder", 0}, {"polyhedron", 0}, {"mesh", 0}};
  std::size_t mesh_triangles = 0;
  std::map<std::string, std::size_t> objects_by_type;
  Eigen::AlignedBox3d bounds;
  for (const auto& object : world.objects) {
    ++objects_by_type[object.type];
    bounds.extend(object.world_position_m);
    const Eigen::Isometry3d world_T_object = object.world_T_object();
    for (const auto& primitive : object.primitives) {
      const char* kind = std::holds_alternative<Box>(primitive.shape)          ? "box"
                         : std::holds_alternative<Cylinder>(primitive.shape)   ? "cylinder"
                         : std::holds_alternative<Polyhedron>(primitive.shape) ? "polyhedron"
                                                                               : "mesh";
      ++primitives_by_kind[kind];
      if (const auto* mesh = std::get_if<TriangleMesh>(&primitive.shape)) {
        mesh_triangles += mesh->triangles.size();
      }
      const Eigen::Isometry3d world_T_primitive = world_T_object * primitive.object_T_primitive();
      for (const Eigen::Vector3d& p : extreme_points(primitive.shape))
        bounds.extend(world_T_primitive * p);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const auto graph = vsl::world::WorldGraph::build(world, options.graph);
  const double graph_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("world: %s (%s)\n", world.name.empty() ? "(unnamed)" : world.name.c_str(),
              options.file.c_str());
  std::size_t total_primitives = 0;
  for (const auto& [kind, count] : primitives_by_kind) total_primitives += count;
  std::printf("primitives: %zu\n", total_primitives);
  for (const auto& [kind, count] : primitives_by_kind)
    std::printf("  %-20s %8zu\n", kind.c_str(), count);
  std::printf("mesh triangles: %zu\n", mesh_triangles);
  std::printf("objects: %zu\n", world.objects.size());
  for (const auto& [type, count] : objects_by_type)
    std::printf("  %-20s %8zu\n", type.c_str(), count);
  std::printf("materials: %zu\n", world.materials.size());
  std::printf("graph: %zu nodes, %zu links (link threshold %.3g m)\n", graph.node_count(),
              graph.link_count(), graph.link_threshold_m());
  if (world.objects.empty()) {
    std::printf("bounding box: empty\n");
  } else {
    const Eigen::Vector3d lo = bounds.min(), hi = bounds.max(), size = hi - lo;
    std::printf("bounding box: [%.3f, %.3f, %.3f] .. [%.3f, %.3f, %.3f] m (%.2f x %.2f x %.2f m)\n",
                lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z(), size.x(), size.y(), size.z());
  }
  std::printf("time: load %.3f s, graph %.3f s\n", load_s, graph_s);
  if (!options.list_types.empty()) {
    std::printf("objects of the listed types (id, type, position in the world frame, m):\n");
    for (const auto& object : world.objects) {
      if (std::find(options.list_types.begin(), options.list_types.end(), object.type) ==
          options.list_types.end()) {
        continue;
      }
      const Eigen::Vector3d& p = object.world_position_m;
      std::printf("  %-36s %-14s [%7.3f, %7.3f, %7.3f]\n", object.id.c_str(), object.type.c_str(),
                  p.x(), p.y(), p.z());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "import") {
    return vsl::world_tool::run_import(argc - 1, argv + 1);
  }
  try {
    const Options options = parse(argc, argv);
    const auto start = std::chrono::steady_clock::now();
    const vsl::world::WorldModel world = vsl::world::load_world(options.file);
    const double load_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.command == "check") {
      std::size_t primitives = 0;
      for (const auto& object : world.objects) primitives += object.primitives.size();
      std::printf("%s: ok (%zu objects, %zu primitives)\n", options.file.c_str(),
                  world.objects.size(), primitives);
    } else if (options.command == "door-sizes") {
      const vsl::world::ClassSizes sizes = vsl::world::class_sizes(world, options.sizes_type);
      if (sizes.objects == 0) {
        std::cerr << options.file << ": no object of type '" << options.sizes_type
                  << "' has a size\n";
        return 2;
      }
      vsl::world_tool::print_class_sizes(sizes, options.file, std::cout);
    } else {
      print_stats(world, options, load_s);
    }
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}

// Benchmarks of world import: a URDF mesh package of about 50 MB (the size of a furnished
// apartment's ROS package) through urdfdom, assimp, the type rules, the object frames and
// simplification; and the rules alone on the names of such a package.
//
// Run: build/libs/world_import/vsl_world_import_bench --benchmark_repetitions=3
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "vsl/world_import/import.hpp"

namespace {

namespace fs = std::filesystem;

// A wavy panel of n x n quads as an OBJ file: about 63 bytes per triangle.
void write_panel_obj(const fs::path& path, int n, double width_m, double height_m) {
  std::ofstream out(path);
  out << "o panel\n";
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = width_m * i / n, z = height_m * j / n;
      out << "v " << x << " " << 0.002 * std::sin(40.0 * x) * std::cos(40.0 * z) << " " << z
          << "\n";
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j + 1, b = a + n + 1;
      out << "f " << a << " " << b << " " << a + 1 << "\nf " << b << " " << b + 1 << " " << a + 1
          << "\n";
    }
  }
}

// 40 cupboards along a wall, each with a door and a handle; every door its own mesh of 39k
// triangles (about 1.2 MB of OBJ).
struct MeshPackage {
  fs::path root = fs::temp_directory_path() / ("vsl_import_bench_" + std::to_string(::getpid()));
  std::string urdf;
  std::uintmax_t bytes = 0;

  MeshPackage() {
    fs::create_directories(root / "meshes");
    std::ofstream out(root / "kitchen.urdf");
    out << "<robot name='kitchen'><link name='room'/>\n";
    for (int k = 0; k < 40; ++k) {
      const std::string mesh = "meshes/door_" + std::to_string(k) + ".obj";
      write_panel_obj(root / mesh, 140, 0.6, 0.7);
      const std::string c = "cabinet" + std::to_string(k), d = c + "_door";
      out << "<joint name='" << c << "_j' type='fixed'><parent link='room'/><child link='" << c
          << "'/><origin xyz='" << 0.62 * k << " 0 0.4'/></joint>\n"
          << "<link name='" << c << "'><visual><geometry><box size='0.6 0.5 0.8'/></geometry>"
          << "</visual></link>\n"
          << "<joint name='" << d << "_hinge' type='revolute'><parent link='" << c
          << "'/><child link='" << d << "'/><origin xyz='-0.3 -0.27 -0.35'/><axis xyz='0 0 -1'/>"
          << "<limit lower='0' upper='1.6' effort='1' velocity='1'/></joint>\n"
          << "<link name='" << d << "'><visual><geometry><mesh filename='" << mesh
          << "'/></geometry></visual></link>\n"
          << "<joint name='" << d << "_handle_j' type='fixed'><parent link='" << d
          << "'/><child link='" << d << "_handle'/><origin xyz='0.52 -0.03 0.5'/></joint>\n"
          << "<link name='" << d << "_handle'><visual><geometry><cylinder radius='0.008' "
          << "length='0.2'/></geometry></visual></link>\n";
    }
    out << "</robot>\n";
    urdf = (root / "kitchen.urdf").string();
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.is_regular_file()) bytes += entry.file_size();
    }
  }
  ~MeshPackage() { fs::remove_all(root); }
};

void BM_ImportUrdfMeshPackage(benchmark::State& state) {
  static const MeshPackage package;
  const vsl::world_import::TypeRules rules = vsl::world_import::TypeRules::built_in();
  for (auto _ : state) {
    const auto result = vsl::world_import::import_world({{package.urdf, std::nullopt}}, {}, rules);
    benchmark::DoNotOptimize(result.world.objects.size());
  }
  state.counters["package_MB"] = static_cast<double>(package.bytes) / 1e6;
}
BENCHMARK(BM_ImportUrdfMeshPackage)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_TypeRulesOnePart(benchmark::State& state) {
  const vsl::world_import::TypeRules rules = vsl::world_import::TypeRules::built_in();
  const vsl::world_import::PartFacts part{
      "cabinet12_drawer_bottom_left", {"M_Wood_Furniture"}, "prismatic"};
  for (auto _ : state) benchmark::DoNotOptimize(rules.classify(part).type.size());
}
BENCHMARK(BM_TypeRulesOnePart)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

// vsl-world as a user runs it: a separate process, its output and exit code.
#include <gtest/gtest.h>

#include <fstream>

#include "run_command.hpp"

namespace {

using vsl::testing::line_count;
using vsl::testing::run_command;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(VslWorldCli, CheckAcceptsAGoodFile) {
  const std::string path = write_temp("good_world.yaml",
                                      "- {id: d, type: door, position: [0, 0, 1]}\n"
                                      "- {id: h, type: handle, position: [0.3, 0, 1]}\n");
  const auto result = run_command({VSL_WORLD_BIN, "check", path});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out, path + ": ok (2 objects, 0 primitives)\n");
}

TEST(VslWorldCli, CheckRejectsABadFileWithOneLineAndExitCode2) {
  const std::string path = write_temp("bad_world.yaml",
                                      "objects:\n  - {id: d, type: door, position: [0, 0, 1]}\n"
                                      "  - {id: h, type: handle, position: [0.3, 0]}\n");
  const auto result = run_command({VSL_WORLD_BIN, "check", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, path + ":3: objects[1].position: expected 3 numbers, got 2\n");
  EXPECT_EQ(line_count(result.err), 1);
  EXPECT_EQ(result.out, "");
}

TEST(VslWorldCli, MissingFileAndBadUsageExit2) {
  auto result = run_command({VSL_WORLD_BIN, "check", "/nonexistent/world.yaml"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "/nonexistent/world.yaml: cannot open file\n");
  result = run_command({VSL_WORLD_BIN, "frobnicate", "x"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(line_count(result.err), 1);
  result = run_command({VSL_WORLD_BIN, "stats", "x", "--link-threshold", "-1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--link-threshold must be a positive number"), std::string::npos);
  const std::string bad_config = write_temp(
      "bad_localizer.yaml", "world_graph:\n  link_threshold_m: 4\n  node_type: [door]\n");
  result = run_command({VSL_WORLD_BIN, "stats", "x", "--config", bad_config});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, bad_config +
                            ":3: world_graph.node_type: unknown key (allowed: "
                            "link_threshold_m, node_types, edge_node_types)\n");
  result = run_command({VSL_WORLD_BIN, "--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("usage: vsl-world check FILE"), std::string::npos);
}

TEST(VslWorldCli, StatsCountsPrimitivesObjectsLinksAndBounds) {
  const std::string path =
      write_temp("stats_world.yaml",
                 "objects:\n"
                 "  - {id: d, type: door, position: [0, 0, 1], primitives: [{box: [1, 0.02, 2]}]}\n"
                 "  - {id: h, type: handle, position: [0.3, 0, 1], parent: d,\n"
                 "     primitives: [{cylinder: {radius: 0.01, height: 0.2}}]}\n"
                 "  - {id: w, type: window, position: [10, 0, 1]}\n");
  const std::string config = write_temp("localizer.yaml", "world_graph: {link_threshold_m: 0.2}\n");
  // --link-threshold overrides the config file's value.
  const auto result =
      run_command({VSL_WORLD_BIN, "stats", path, "--config", config, "--link-threshold", "2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("primitives: 2\n"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("  box                         1\n"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("  cylinder                    1\n"), std::string::npos);
  EXPECT_NE(result.out.find("objects: 3\n"), std::string::npos);
  EXPECT_NE(result.out.find("graph: 3 nodes, 1 links (link threshold 2 m)"), std::string::npos);
  EXPECT_NE(result.out.find("bounding box: [-0.500, -0.010, 0.000] .. [10.000, 0.010, 2.000] m"),
            std::string::npos)
      << result.out;
  const auto typed = run_command({VSL_WORLD_BIN, "stats", path, "--config", config});
  EXPECT_NE(typed.out.find("graph: 3 nodes, 0 links (link threshold 0.2 m)"), std::string::npos)
      << typed.out;
}

TEST(VslWorldCli, StatsCountsMeshesTheirTrianglesAndBoundsThem) {
  const std::string path =
      write_temp("mesh_world.yaml",
                 "objects:\n"
                 "  - {id: part, type: clutter, position: [1, 0, 0], primitives: [\n"
                 "     {mesh: {vertices: [[0, 0, 0], [2, 0, 0], [0, 3, 0], [0, 0, 4]],\n"
                 "             triangles: [[0, 1, 2], [0, 2, 3], [1, 1, 2]]}}]}\n");
  const auto result = run_command({VSL_WORLD_BIN, "stats", path});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("primitives: 1\n"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("  mesh                        1\n"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("mesh triangles: 3\n"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("bounding box: [1.000, 0.000, 0.000] .. [3.000, 3.000, 4.000] m"),
            std::string::npos)
      << result.out;
}

TEST(VslWorldCli, DoorSizesAsTheRecognizersClassEntry) {
  // Three doors 0.716 m tall (two 0.4 m wide, one 0.6 m) and one 1.246 m (0.4 m), a handle, and a
  // door without a size (not counted).
  const std::string path =
      write_temp("sized_world.yaml",
                 "objects:\n"
                 "  - {id: a, type: door, position: [0, 0, 0.5], size: [0.4, 0.02, 0.716]}\n"
                 "  - {id: b, type: door, position: [1, 0, 0.5], size: [0.402, 0.02, 0.716]}\n"
                 "  - {id: c, type: door, position: [2, 0, 0.5], size: [0.6, 0.02, 0.716]}\n"
                 "  - {id: d, type: door, position: [3, 0, 1.0], size: [0.4, 0.02, 1.246]}\n"
                 "  - {id: e, type: door, position: [4, 0, 1.0]}\n"
                 "  - {id: h, type: handle, position: [0, 0, 0.5], size: [0.02, 0.03, 0.16]}\n");
  const auto result = run_command({VSL_WORLD_BIN, "door-sizes", path});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // Widths 0.4 (three, within 5 mm) and 0.6: RMS about 0.4 is 0.2 / 2 = 0.1; heights about 0.716
  // 0.53 / 2 = 0.265.
  EXPECT_EQ(result.out, "# door sizes of " + path +
                            " (4 with a size): heights 0.716 x3, 1.246 x1; widths 0.400 x3, "
                            "0.600 x1\n"
                            "door: {typical_heights_m: [0.716, 1.246], height_sigma_m: 0.265, "
                            "typical_width_m: 0.400, width_sigma_m: 0.100}\n");
  // No object of the type with a size: one line, exit code 2.
  const auto none = run_command({VSL_WORLD_BIN, "door-sizes", path, "--type", "window"});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err, path + ": no object of type 'window' has a size\n");
  EXPECT_EQ(none.out, "");
}

}  // namespace

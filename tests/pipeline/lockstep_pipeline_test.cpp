// The whole pipeline in lock step on simulated time: the simulated head, recognition, fusion and
// the localizer (the daemons' own classes, with the shipped configs) in one process, on one
// runtime::SimulatedClock and an in-process bus (runtime::InProcessHub). After every event each
// daemon handles everything pending before the clock moves to the next timer deadline, and
// recognition recognizes every frame inline, so what the pipeline does depends only on its inputs
// (the world, the pose, the configs and their seeds): each case below runs once and gives the
// same pose every time. The same pipeline as processes over LCM: pipeline_test.cpp.
// The whole pipeline in lock step on simulated time (tools/vsl-lockstep/lockstep_pipeline.hpp):
// the simulated head, recognition, fusion and the localizer with the shipped configs in one
// process. What it does depends only on its inputs, so each case below runs once and gives the
// same pose every time. The same pipeline as processes over LCM: pipeline_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "lockstep_pipeline.hpp"
#include "run_command.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/world/world_model.hpp"

namespace {

using vsl::lockstep::Outcome;
using vsl::lockstep::state_names;

// Another world than the configs': the simulator's, the localizer's (`localizer_config`
// naming it) and the recognition config for it.
struct OtherWorld {
  std::string world_path;
  std::string recognition_config;
};

// The recognizer and the realism of the images it gets.
struct Recognition {
  std::string config;
  vsl::render::RealismLevel realism;
};
// The paper's recognizer on the flat images it is tuned on.
const Recognition kPaperRecognition{"config/recognition_paper.yaml",
                                    vsl::render::RealismLevel::off};
// As shipped (config/sim_head.yaml, tools/demo): the learned detector on images as varied as a
// real camera's.
const Recognition kShippedRecognition{"config/recognition.yaml", vsl::render::RealismLevel::full};

// The four daemons and a requester on one simulated clock; no daemon stops on its own.
class LockstepPipeline {
 public:
  LockstepPipeline(const std::optional<std::array<double, 4>>& pose,
                   const std::string& localizer_config,
                   const std::optional<OtherWorld>& other = std::nullopt,
                   const Recognition& recognizer = kPaperRecognition) {
    inputs_.pose = pose;
    inputs_.localizer_config = localizer_config;
    inputs_.recognition_config = other ? other->recognition_config : recognizer.config;
    inputs_.realism = recognizer.realism;
    if (other) inputs_.world_path = other->world_path;
  }

  Outcome run() const {
    vsl::lockstep::Pipeline pipeline(inputs_);
    const Outcome outcome = pipeline.run();
    for (const std::string& daemon : outcome.stopped) {
      ADD_FAILURE() << daemon << " stopped\n" << outcome.log;
    }
    return outcome;
  }

 private:
  vsl::lockstep::PipelineInputs inputs_;
};

// Issue 6's figure: LOCALIZED within 5 cm and 2 degrees of the ground truth.
void expect_localized_near_truth(const Outcome& outcome) {
  ASSERT_TRUE(outcome.pose.has_value())
      << "no POSE_ESTIMATE after " << outcome.simulated_s << " s simulated\n"
      << outcome.log;
  ASSERT_TRUE(outcome.world_T_ego_truth.has_value());
  const vsl::pose_estimate_t& pose = *outcome.pose;
  ASSERT_EQ(pose.status, vsl::pose_estimate_t::LOCALIZED) << pose.message << "\n" << outcome.log;
  const auto [position_error_m, rotation_error_deg] =
      vsl::lockstep::pose_error(pose.world_T_ego, *outcome.world_T_ego_truth);
  EXPECT_LT(position_error_m, 0.05) << state_names(outcome.states);
  EXPECT_LT(rotation_error_deg, 2.0) << state_names(outcome.states);
  std::printf("localized after %.1f s (simulated): error %.2f cm, %.3f deg\n", outcome.simulated_s,
              position_error_m * 100.0, rotation_error_deg);
}

struct PoseCase {
  const char* name;
  std::optional<std::array<double, 4>> pose;  // x, y, z (m), yaw (deg); none: the config's
};

class LockstepPipelineTest : public ::testing::TestWithParam<PoseCase> {};

TEST_P(LockstepPipelineTest, LocalizesWithinFiveCentimetresAndTwoDegrees) {
  LockstepPipeline pipeline(GetParam().pose, "config/vsl-localizer.yaml");
  const Outcome outcome = pipeline.run();
  expect_localized_near_truth(outcome);
  // The localizer reports each stage as it reaches it.
  EXPECT_EQ(state_names(outcome.states),
            "SCANNING FUSING PRUNING GENERATING VALIDATING REFINING DONE");
}

// The poses of pipeline_test.cpp's FullPipeline (vsl-scenario --seed 3, and the default one).
INSTANTIATE_TEST_SUITE_P(
    Kitchen, LockstepPipelineTest,
    ::testing::Values(
        PoseCase{"default", std::nullopt},
        PoseCase{"south_west_facing_north_east", std::array<double, 4>{1.509, 0.677, 0, 27.4}},
        PoseCase{"north_east_facing_west", std::array<double, 4>{3.799, 2.945, 0, -165.3}},
        PoseCase{"north_facing_south", std::array<double, 4>{2.013, 2.821, 0, -64.6}},
        PoseCase{"south_east_facing_north_west", std::array<double, 4>{3.645, 0.602, 0, 132.4}}),
    [](const ::testing::TestParamInfo<PoseCase>& info) { return std::string(info.param.name); });

// As shipped: the learned detector on images at full realism, from the default pose and two of
// the others.
class ShippedRecognizerTest : public ::testing::TestWithParam<PoseCase> {};

TEST_P(ShippedRecognizerTest, LocalizesWithinFiveCentimetresAndTwoDegrees) {
  LockstepPipeline pipeline(GetParam().pose, "config/vsl-localizer.yaml", std::nullopt,
                            kShippedRecognition);
  expect_localized_near_truth(pipeline.run());
}

INSTANTIATE_TEST_SUITE_P(Kitchen, ShippedRecognizerTest,
                         ::testing::Values(PoseCase{"default", std::nullopt},
                                           PoseCase{"north_east_facing_west",
                                                    std::array<double, 4>{3.799, 2.945, 0, -165.3}},
                                           PoseCase{"south_east_facing_north_west",
                                                    std::array<double, 4>{3.645, 0.602, 0, 132.4}}),
                         [](const ::testing::TestParamInfo<PoseCase>& info) {
                           return std::string(info.param.name);
                         });

// The same inputs give the same pose: lock step leaves nothing to timing.
TEST(LockstepPipeline, SameInputsGiveTheSamePose) {
  const Outcome first = LockstepPipeline(std::nullopt, "config/vsl-localizer.yaml").run();
  const Outcome second = LockstepPipeline(std::nullopt, "config/vsl-localizer.yaml").run();
  ASSERT_TRUE(first.pose && second.pose);
  EXPECT_EQ(first.pose->world_T_ego.position_m[0], second.pose->world_T_ego.position_m[0]);
  EXPECT_EQ(first.pose->world_T_ego.position_m[1], second.pose->world_T_ego.position_m[1]);
  EXPECT_EQ(first.pose->world_T_ego.orientation_wxyz[0],
            second.pose->world_T_ego.orientation_wxyz[0]);
  EXPECT_EQ(first.simulated_s, second.simulated_s);
  EXPECT_EQ(first.states, second.states);
}

// An ambiguous start: the one-gaze scan of config/vsl-localizer-ambiguous.yaml leaves several
// hypotheses from this pose, and only active validation (paper §2.4.2) resolves them: the
// localizer looks at a discriminating object and localizes within 5 cm and 2 degrees.
TEST(LockstepPipeline, AmbiguousStartResolvedByActiveValidation) {
  LockstepPipeline pipeline(std::array<double, 4>{2.504, 2.967, 0, -43.8},
                            "config/vsl-localizer-ambiguous.yaml");
  const Outcome outcome = pipeline.run();
  expect_localized_near_truth(outcome);
  const std::string states = state_names(outcome.states);
  EXPECT_NE(states.find("ACTIVE_VALIDATION"), std::string::npos) << states;
}

// tools/recognition-for-world on the world (60 views: a test's share), into dir/recognition; the
// recognition config it wrote.
std::string recognition_for(const std::string& world, const std::filesystem::path& dir) {
  const auto made = vsl::testing::run_command(
      {std::string(VSL_SOURCE_DIR) + "/tools/recognition-for-world", world,
       (dir / "recognition").string(), "--views", "60", "--build", VSL_BINARY_DIR},
      600.0);
  if (made.exit_code != 0) {
    throw std::runtime_error("tools/recognition-for-world failed: " + made.out + made.err);
  }
  return (dir / "recognition" / "recognition.yaml").string();
}

// config/vsl-localizer.yaml for another world, written into `dir`: its world and its options
// file named by absolute path.
std::string localizer_config_for(const std::string& world, const std::filesystem::path& dir) {
  std::ifstream in("config/vsl-localizer.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string localizer = text.str();
  for (const auto& [key, path] :
       {std::pair<std::string, std::string>{"world: ", world},
        {"options: ", std::string(VSL_SOURCE_DIR) + "/config/localizer.yaml"}}) {
    const std::size_t at = localizer.find(key);
    if (at == std::string::npos) throw std::runtime_error("config/vsl-localizer.yaml: no " + key);
    localizer.replace(at + key.size(),
                      localizer.find_first_of(" \n", at + key.size()) - at - key.size(), path);
  }
  const std::string localizer_config = (dir / "vsl-localizer.yaml").string();
  std::ofstream(localizer_config) << localizer;
  return localizer_config;
}

// Another look (navy fronts, brass handles), where the bundled kitchen's class models find no
// door: tools/recognition-for-world trains the models on the world's own renders and takes its
// door sizes (what tools/demo --world does), and the pipeline localizes with them.
TEST(LockstepPipeline, AnotherLookLocalizesWithClassModelsTrainedOnItsWorld) {
  const std::filesystem::path dir =
      std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "lockstep" / "navy";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string world = std::string(VSL_SOURCE_DIR) + "/config/worlds/kitchen_navy_brass.yaml";
  const std::string localizer_config = localizer_config_for(world, dir);
  const std::array<double, 4> pose{1.981, 1.428, 0, 112.4};

  const Outcome trained =
      LockstepPipeline(pose, localizer_config, OtherWorld{world, recognition_for(world, dir)})
          .run();
  expect_localized_near_truth(trained);
}

// One primitive as polygons in the world frame: vertices and faces (counter-clockwise seen from
// outside), as a CAD export would give them.
struct Polygons {
  std::vector<Eigen::Vector3d> vertices_m;
  std::vector<std::vector<std::size_t>> faces;
};

Polygons polygons_of(const vsl::world::ObjectModel& object, const vsl::world::Primitive& p) {
  Polygons out;
  std::vector<Eigen::Vector3d>& vertices = out.vertices_m;
  std::vector<std::vector<std::size_t>>& faces = out.faces;
  if (const auto* box = std::get_if<vsl::world::Box>(&p.shape)) {
    for (int k = 0; k < 8; ++k) {
      vertices.push_back(0.5 * box->size_m.cwiseProduct(Eigen::Vector3d(
                                   k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1)));
    }
    faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  } else if (const auto* cylinder = std::get_if<vsl::world::Cylinder>(&p.shape)) {
    constexpr std::size_t kSegments = 16;
    std::vector<std::size_t> bottom, top;
    for (std::size_t k = 0; k < kSegments; ++k) {
      const double a = 2.0 * M_PI * static_cast<double>(k) / kSegments;
      for (const double z : {-0.5, 0.5}) {
        vertices.emplace_back(cylinder->radius_m * std::cos(a), cylinder->radius_m * std::sin(a),
                              z * cylinder->height_m);
      }
      bottom.insert(bottom.begin(), 2 * k);
      top.push_back(2 * k + 1);
      const std::size_t n = 2 * ((k + 1) % kSegments);
      faces.push_back({2 * k, n, n + 1, 2 * k + 1});
    }
    faces.push_back(bottom);
    faces.push_back(top);
  } else if (const auto* polyhedron = std::get_if<vsl::world::Polyhedron>(&p.shape)) {
    vertices = polyhedron->vertices_m;
    for (const auto& face : polyhedron->faces) faces.emplace_back(face.begin(), face.end());
  } else if (const auto* mesh = std::get_if<vsl::world::TriangleMesh>(&p.shape)) {
    for (const Eigen::Vector3f& v : mesh->vertices_m) vertices.push_back(v.cast<double>());
    for (const auto& t : mesh->triangles) faces.push_back({t[0], t[1], t[2]});
  }
  const Eigen::Isometry3d world_T_primitive = object.world_T_object() * p.object_T_primitive();
  for (Eigen::Vector3d& v : vertices) v = world_T_primitive * v;
  return out;
}

// A world as a Wavefront OBJ file with its materials' colours (MTL): one `o` per object, named by
// its id.
void write_obj(const vsl::world::WorldModel& world, const std::filesystem::path& obj_path) {
  const std::filesystem::path mtl_path = std::filesystem::path(obj_path).replace_extension(".mtl");
  std::ofstream mtl(mtl_path);
  for (const vsl::world::Material& m : world.materials) {
    mtl << "newmtl " << m.name << "\nKd " << m.colour.r / 255.0 << " " << m.colour.g / 255.0 << " "
        << m.colour.b / 255.0 << "\n";
  }
  std::ofstream obj(obj_path);
  obj << "mtllib " << mtl_path.filename().string() << "\n";
  std::size_t next = 1;  // OBJ's vertex indices start at 1
  for (const vsl::world::ObjectModel& object : world.objects) {
    obj << "o " << object.id << "\n";
    for (const vsl::world::Primitive& p : object.primitives) {
      const Polygons polygons = polygons_of(object, p);
      if (!p.material.empty()) obj << "usemtl " << p.material << "\n";
      for (const Eigen::Vector3d& v : polygons.vertices_m) {
        obj << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
      }
      for (const auto& face : polygons.faces) {
        obj << "f";
        for (const std::size_t i : face) obj << " " << next + i;
        obj << "\n";
      }
      next += polygons.vertices_m.size();
    }
  }
}

// VRML 2 names: no '.' (the ids' separator) in a DEF.
std::string vrml_name(std::string id) {
  std::replace(id.begin(), id.end(), '.', '_');
  return id;
}

// The same world as VRML 2 (z up, as given): one DEF'd Transform per object, a Shape per primitive
// with its colour as the Material's diffuseColor.
void write_vrml(const vsl::world::WorldModel& world, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "#VRML V2.0 utf8\n";
  for (const vsl::world::ObjectModel& object : world.objects) {
    out << "DEF " << vrml_name(object.id) << " Transform { children [\n";
    for (const vsl::world::Primitive& p : object.primitives) {
      const Polygons polygons = polygons_of(object, p);
      out << "Shape { appearance Appearance { material Material { diffuseColor "
          << p.colour.r / 255.0 << " " << p.colour.g / 255.0 << " " << p.colour.b / 255.0
          << " } } geometry IndexedFaceSet { solid FALSE coord Coordinate { point [";
      for (const Eigen::Vector3d& v : polygons.vertices_m) {
        out << v.x() << " " << v.y() << " " << v.z() << ",";
      }
      out << "] } coordIndex [";
      for (const auto& face : polygons.faces) {
        for (const std::size_t i : face) out << i << ",";
        out << "-1,";
      }
      out << "] } }\n";
    }
    out << "] }\n";
  }
}

// A building from a CAD file (issue 30): the navy kitchen written as OBJ with MTL colours, and as
// VRML 2, imported with the built-in rules (each door and handle within 2 cm of where the generator
// put it), recognition made for it by tools/recognition-for-world, and the whole pipeline
// localizes in it.
class ImportedKitchenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ImportedKitchenTest, LocalizesInIt) {
  const std::string format = GetParam();
  const std::filesystem::path dir =
      std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "lockstep" / ("imported_" + format);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const vsl::world::WorldModel generated =
      vsl::world::load_world("config/worlds/kitchen_navy_brass.yaml");
  const std::filesystem::path model = dir / ("kitchen." + format);
  if (format == "obj") write_obj(generated, model);
  if (format == "wrl") write_vrml(generated, model);
  const std::string world = (dir / "kitchen.yaml").string();
  const auto imported_run =
      vsl::testing::run_command({std::string(VSL_BINARY_DIR) + "/tools/vsl-world/vsl-world",
                                 "import", model.string(), "-o", world, "-q"},
                                120.0);
  ASSERT_EQ(imported_run.exit_code, 0) << imported_run.out << imported_run.err;
  const vsl::world::WorldModel imported = vsl::world::load_world(world);
  int doors = 0, handles = 0;
  for (const vsl::world::ObjectModel& object : generated.objects) {
    if (object.type != "door" && object.type != "handle") continue;
    const auto index = imported.find(format == "wrl" ? vrml_name(object.id) : object.id);
    ASSERT_TRUE(index.has_value()) << object.id;
    const vsl::world::ObjectModel& twin = imported.objects[*index];
    EXPECT_EQ(twin.type, object.type) << object.id;
    EXPECT_LT((twin.world_position_m - object.world_position_m).norm(), 0.02)
        << object.id << " at " << twin.world_position_m.transpose() << ", generated at "
        << object.world_position_m.transpose();
    ++(object.type == "door" ? doors : handles);
  }
  EXPECT_GT(doors, 20);
  EXPECT_GT(handles, 20);

  const std::string localizer_config = localizer_config_for(world, dir);
  const Outcome outcome =
      LockstepPipeline(std::array<double, 4>{1.981, 1.428, 0, 112.4}, localizer_config,
                       OtherWorld{world, recognition_for(world, dir)})
          .run();
  expect_localized_near_truth(outcome);
}

INSTANTIATE_TEST_SUITE_P(Formats, ImportedKitchenTest, ::testing::Values("obj", "wrl"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// The script's bad usage: one line, exit code 2, nothing written.
TEST(RecognitionForWorld, BadUsageIsOneLineAndExitCodeTwo) {
  const std::string script = std::string(VSL_SOURCE_DIR) + "/tools/recognition-for-world";
  const std::filesystem::path out =
      std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "lockstep" / "bad";
  std::filesystem::remove_all(out);
  for (const std::vector<std::string>& argv : std::vector<std::vector<std::string>>{
           {script, "no/such/world.yaml", out.string(), "--build", VSL_BINARY_DIR},
           {script, "config/worlds/kitchen.yaml", out.string(), "--bogus"},
           {script, "config/worlds/kitchen.yaml", out.string(), "--views"},
           {script, "config/worlds/kitchen.yaml"}}) {
    const auto result = vsl::testing::run_command(argv);
    EXPECT_EQ(result.exit_code, 2) << argv.back() << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1)
        << argv.back() << ": " << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out / "recognition.yaml"));
}

}  // namespace

// vsl-render as a process: renders the bundled kitchen into PNG files; bad input exits 2.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <string>

#include "run_command.hpp"

namespace {

using vsl::testing::run_command;

std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::path(VSL_BINARY_DIR) / "test-output" / "vsl-render" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(VslRender, RendersTheKitchenIntoPngs) {
  const std::string prefix = (scratch_dir("kitchen") / "kitchen").string();
  const auto result = run_command({VSL_RENDER_BIN, "--world", "config/worlds/kitchen.yaml",
                                   "--pose", "2.6,2.3,0,90", "--ids", "--depth", "-o", prefix});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("sees"), std::string::npos) << result.out;
  for (const char* suffix : {"_left.png", "_right.png", "_ids.png"}) {
    const cv::Mat image = cv::imread(prefix + suffix, cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(image.empty()) << suffix;
    EXPECT_EQ(image.cols, 640) << suffix;
    EXPECT_EQ(image.rows, 480) << suffix;
    EXPECT_EQ(image.type(), CV_8UC3) << suffix;
  }
  // Many objects, so many colours: the id picture is far from uniform.
  const cv::Mat ids = cv::imread(prefix + "_ids.png", cv::IMREAD_COLOR);
  cv::Scalar mean, stddev;
  cv::meanStdDev(ids.reshape(1), mean, stddev);
  EXPECT_GT(stddev[0], 30.0);
  const cv::Mat depth = cv::imread(prefix + "_depth.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_16U);
  double min_mm = 0.0, max_mm = 0.0;
  cv::minMaxLoc(depth, &min_mm, &max_mm);
  EXPECT_GT(max_mm, 1000.0);  // the kitchen's walls are metres away
  EXPECT_LT(max_mm, 8000.0);
  // The two cameras see the scene from 90 mm apart: the images differ.
  const cv::Mat left = cv::imread(prefix + "_left.png");
  const cv::Mat right = cv::imread(prefix + "_right.png");
  EXPECT_GT(cv::norm(left, right, cv::NORM_L1) / left.total(), 5.0);
}

TEST(VslRender, JointsAndLookAtMoveTheView) {
  const auto dir = scratch_dir("joints");
  const auto a = run_command({VSL_RENDER_BIN, "--world", "config/worlds/kitchen.yaml", "--pose",
                              "2.6,2.3,0,90", "--joints", "neck_yaw=0.5", "--clean", "-o",
                              (dir / "a").string()});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_NE(a.out.find("neck_yaw=0.500"), std::string::npos) << a.out;
  const auto b = run_command({VSL_RENDER_BIN, "--world", "config/worlds/kitchen.yaml", "--pose",
                              "2.6,2.3,0,90", "--look-at", "1.0,3.9,0.8", "--clean", "-o",
                              (dir / "b").string()});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(b.out.find("neck_yaw=0.000"), std::string::npos) << b.out;
  EXPECT_GT(cv::norm(cv::imread((dir / "a_left.png").string()),
                     cv::imread((dir / "b_left.png").string()), cv::NORM_L1),
            0.0);
}

TEST(VslRender, RealismLevels) {
  const auto dir = scratch_dir("realism");
  const std::vector<std::string> view{VSL_RENDER_BIN, "--world",      "config/worlds/kitchen.yaml",
                                      "--pose",       "2.6,2.3,0,90", "--clean"};
  auto render = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> argv = view;
    argv.insert(argv.end(), extra.begin(), extra.end());
    argv.insert(argv.end(), {"-o", (dir / name).string()});
    return run_command(argv);
  };
  // off is the renderer as it always was.
  ASSERT_EQ(render("default", {}).exit_code, 0);
  const auto off = render("off", {"--realism", "off"});
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(cv::norm(cv::imread((dir / "default_left.png").string()),
                     cv::imread((dir / "off_left.png").string()), cv::NORM_INF),
            0.0);
  for (const char* level : {"materials", "full"}) {
    const auto result = render(level, {"--realism", level, "--exposure-ev", "-0.5"});
    ASSERT_EQ(result.exit_code, 0) << level << ": " << result.err;
    const cv::Mat left = cv::imread((dir / (std::string(level) + "_left.png")).string());
    EXPECT_EQ(left.size(), cv::Size(640, 480)) << level;
  }
  // --clean leaves nothing random at level full either: another seed, the same image.
  ASSERT_EQ(
      render("full_seed5", {"--realism", "full", "--exposure-ev", "-0.5", "--seed", "5"}).exit_code,
      0);
  EXPECT_EQ(cv::norm(cv::imread((dir / "full_left.png").string()),
                     cv::imread((dir / "full_seed5_left.png").string()), cv::NORM_INF),
            0.0);
  // --exposure-ev below full changes nothing, and says so.
  const auto materials = render("materials", {"--realism", "materials", "--exposure-ev", "1"});
  EXPECT_EQ(materials.err, "vsl-render: warning: --exposure-ev acts only at --realism full\n");
}

TEST(VslRender, BadInputExitsTwoWithOneLine) {
  const std::string out = (scratch_dir("bad") / "x").string();
  const std::vector<std::vector<std::string>> cases{
      {"--world", "config/worlds/kitchen.yaml", "-o", out},                       // no --pose
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,3", "-o", out},    // 3 numbers
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,x,0", "-o", out},  // not a number
      {"--world", "no/such/world.yaml", "--pose", "1,2,0,0", "-o", out},
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,0,0", "--joints", "nose=1", "-o",
       out},
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,0,0", "--bogus", "-o", out},
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,0,0", "--realism", "on", "-o", out},
      {"--world", "config/worlds/kitchen.yaml", "--pose", "1,2,0,0", "--exposure-ev", "9", "-o",
       out},
  };
  for (const auto& arguments : cases) {
    std::vector<std::string> argv{VSL_RENDER_BIN};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    const auto result = run_command(argv);
    EXPECT_EQ(result.exit_code, 2) << arguments[arguments.size() - 3];
    EXPECT_EQ(vsl::testing::line_count(result.err), 1) << result.err;
  }
  const auto help = run_command({VSL_RENDER_BIN, "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage: vsl-render"), std::string::npos);
}

TEST(VslRender, UnwritableOutputExitsOne) {
  const auto result = run_command({VSL_RENDER_BIN, "--world", "config/worlds/kitchen.yaml",
                                   "--pose", "2.6,2.3,0,90", "-o", "/nonexistent-dir/for/sure/x"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(vsl::testing::line_count(result.err), 1) << result.err;
}

}  // namespace

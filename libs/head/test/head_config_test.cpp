// The head file format: the shipped head, relative calibration paths, one-line errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "vsl/config/node.hpp"
#include "vsl/head/head_kinematics.hpp"

namespace vsl::head {
namespace {

const char* const kGood = R"(name: test_head
calibration: ../calib/test.yaml
joints:
  - name: pan
    parent: ego
    translation_m: [0.0, 0.0, 1.4]
    axis: [0, 0, 1]
    limits_rad: [-1.0, 1.0]
    max_velocity_rad_s: 1.0
  - name: tilt
    parent: pan
    translation_m: [0.0, 0.0, 0.1]
    rpy_deg: [0, 0, 0]
    axis: [0, 1, 0]
    limits_rad: [-0.5, 0.5]
    max_velocity_rad_s: 1.0
    gaze_weight: 2.0
    rest_rad: 0.1
cameras:
  left:
    parent: tilt
    translation_m: [0.0, 0.045, 0.0]
    rpy_deg: [-90, 0, -90]
  right:
    parent: tilt
)";

HeadKinematics parse(const std::string& text) {
  return HeadKinematics::from_config(config::Node::load_string(text, "heads/test.yaml"),
                                     StereoCalibration{});
}

std::string error_of(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    parse(text);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(HeadConfig, ShippedArmar3Loads) {
  const HeadKinematics head = HeadKinematics::load("config/heads/armar3.yaml");
  EXPECT_EQ(head.name(), "armar3");
  EXPECT_EQ(head.joints().size(), 5u);
  EXPECT_NEAR(head.calibration().baseline_m(), 0.09, 1e-12);
  // The calibration override replaces the file's own.
  const HeadKinematics same =
      HeadKinematics::load("config/heads/armar3.yaml", std::string("calib/armar3_sim.yaml"));
  EXPECT_EQ(same.calibration().left.fx_px, head.calibration().left.fx_px);
}

TEST(HeadConfig, ReadsEveryKey) {
  const HeadKinematics head = parse(kGood);
  ASSERT_EQ(head.joint_names(), (std::vector<std::string>{"pan", "tilt"}));
  const Joint& tilt = head.joints()[1];
  EXPECT_EQ(tilt.parent, 0);
  EXPECT_TRUE(tilt.parent_T_joint_zero.translation().isApprox(Eigen::Vector3d(0, 0, 0.1)));
  EXPECT_TRUE(tilt.axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(tilt.min_rad, -0.5);
  EXPECT_EQ(tilt.max_rad, 0.5);
  EXPECT_EQ(tilt.gaze_weight, 2.0);
  EXPECT_EQ(tilt.rest_rad, 0.1);
  EXPECT_EQ(head.joints()[0].gaze_weight, 1.0);  // defaults
  EXPECT_EQ(head.joints()[0].rest_rad, 0.0);
  EXPECT_EQ(head.rest_state().positions_rad, (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(head.left_mount().parent, 1);
  EXPECT_EQ(head.right_mount().parent, 1);
}

TEST(HeadConfig, CalibrationPathIsRelativeToTheHeadFile) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vsl_head_config_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "heads");
  std::filesystem::create_directories(dir / "calib");
  std::filesystem::copy_file("calib/armar3_sim.yaml", dir / "calib" / "test.yaml",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "heads" / "test.yaml") << kGood;
  const HeadKinematics head = HeadKinematics::load((dir / "heads" / "test.yaml").string());
  EXPECT_NEAR(head.calibration().baseline_m(), 0.09, 1e-12);

  std::filesystem::remove(dir / "calib" / "test.yaml");
  const std::string path = (dir / "heads" / "test.yaml").string();
  try {
    HeadKinematics::load(path);
    ADD_FAILURE() << "loaded without its calibration";
  } catch (const config::Error& e) {
    EXPECT_EQ(
        std::string(e.what()),
        path + ":2: calibration: " + (dir / "calib" / "test.yaml").string() + ": cannot open file");
  }
  std::filesystem::remove_all(dir);
}

TEST(HeadConfig, BadFilesAreOneLineErrors) {
  EXPECT_EQ(error_of("    parent: pan\n", "    parent: neck\n"),
            "heads/test.yaml:11: joints[1].parent: unknown parent 'neck' (ego or a joint listed "
            "before: ego, pan)");
  EXPECT_EQ(error_of("  - name: tilt", "  - name: pan"),
            "heads/test.yaml:10: joints[1].name: joint 'pan' is defined twice");
  EXPECT_EQ(error_of("limits_rad: [-0.5, 0.5]", "limits_rad: [0.5, -0.5]"),
            "heads/test.yaml:15: joints[1].limits_rad: expected [min, max] with min < max");
  EXPECT_EQ(error_of("limits_rad: [-1.0, 1.0]", "limits_rad: [-90, 90]"),
            "heads/test.yaml:8: joints[0].limits_rad: limits must lie within [-2 pi, 2 pi] rad "
            "(degrees given?)");
  EXPECT_EQ(error_of("axis: [0, 1, 0]", "axis: [0, 0, 0]"),
            "heads/test.yaml:14: joints[1].axis: the axis must not be zero");
  EXPECT_EQ(error_of("rest_rad: 0.1", "rest_rad: 0.7"),
            "heads/test.yaml:18: joints[1].rest_rad: must be in [-0.5, 0.5], got 0.7");
  EXPECT_EQ(error_of("    max_velocity_rad_s: 1.0\n  - name: tilt",
                     "    max_velocity_rad_s: 0\n  - name: tilt"),
            "heads/test.yaml:9: joints[0].max_velocity_rad_s: must be in [0.001, 100], got 0");
  EXPECT_EQ(error_of("    gaze_weight: 2.0", "    gaze_wieght: 2.0"),
            "heads/test.yaml:17: joints[1].gaze_wieght: unknown key (allowed: name, parent, "
            "translation_m, rpy_rad, rpy_deg, orientation_wxyz, axis, limits_rad, "
            "max_velocity_rad_s, gaze_weight, rest_rad)");
  EXPECT_EQ(error_of("    rpy_deg: [0, 0, 0]", "    rpy_deg: [0, 0, 0]\n    rpy_rad: [0, 0, 0]"),
            "heads/test.yaml:13: joints[1].rpy_deg: give only one of rpy_rad, rpy_deg, "
            "orientation_wxyz");
  EXPECT_EQ(error_of("  right:\n    parent: tilt\n",
                     "  right:\n    parent: tilt\n    translation_m: [0, -0.045, 0]\n"),
            "heads/test.yaml:26: cameras.right.translation_m: unknown key (allowed: parent)");
  EXPECT_EQ(error_of("  right:\n    parent: tilt\n", ""),
            "heads/test.yaml:20: cameras.right: missing required key");
  EXPECT_EQ(error_of("name: test_head", "name: test head"),
            "heads/test.yaml:1: name: names may use only letters, digits, _ and -, got 'test "
            "head'");
  EXPECT_EQ(
      error_of("    parent: ego\n", "    parent: ego\n    orientation_wxyz: [1, 0, 0, 0.5]\n"),
      "heads/test.yaml:6: joints[0].orientation_wxyz: must be a unit quaternion [w, x, y, z], "
      "norm is 1.118034");
  EXPECT_EQ(error_of("joints:\n", "joints: 3\nx:\n"),
            "heads/test.yaml:4: x: unknown key (allowed: name, calibration, joints, cameras)");
}

TEST(HeadConfig, LimitsThatExcludeZeroNeedARestPosition) {
  EXPECT_EQ(error_of("limits_rad: [-1.0, 1.0]", "limits_rad: [0.2, 1.0]"),
            "heads/test.yaml:4: joints[0]: limits_rad exclude 0, so rest_rad must be given");
}

}  // namespace
}  // namespace vsl::head

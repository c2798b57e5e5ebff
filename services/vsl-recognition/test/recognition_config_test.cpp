#include "recognition_config.hpp"

#include <gtest/gtest.h>

#include "vsl/config/node.hpp"

namespace vsl::recognition_daemon {
namespace {

RecognitionConfig read(const std::string& text, const runtime::Channels& channels = {}) {
  return read_recognition_config(config::Node::load_string(text, "dir/recognition.yaml"), channels);
}

std::string error_of(const std::string& text, const runtime::Channels& channels = {}) {
  try {
    read(text, channels);
  } catch (const config::Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(RecognitionConfigFile, PathsAreRelativeToTheFileAndOptionsReachTheLibrary) {
  const RecognitionConfig config = read(
      "recognition:\n"
      "  head: heads/armar3.yaml\n"
      "  calibration: ../calib/other.yaml\n"
      "  models: [recognition/door.yaml, /abs/handle.yaml]\n"
      "  segmentation: {min_blob_px: 30}\n"
      "  stereo: {max_depth_m: 4.5, reference_depth_offset_m: {handle: 0.006}}\n"
      "  debug_image: {enabled: true, channel: MY_DEBUG}\n"
      "  status_period_s: 2.5\n");
  EXPECT_EQ(config.head_path, "dir/heads/armar3.yaml");
  EXPECT_EQ(config.calibration_path, "calib/other.yaml");
  EXPECT_EQ(config.model_paths,
            (std::vector<std::string>{"dir/recognition/door.yaml", "/abs/handle.yaml"}));
  EXPECT_EQ(config.options.segmentation.min_blob_px, 30);
  EXPECT_EQ(config.options.stereo.max_depth_m, 4.5);
  ASSERT_EQ(config.options.stereo.reference_depth_offset_m.size(), 1u);
  EXPECT_TRUE(config.debug_image);
  EXPECT_EQ(config.debug_channel, "MY_DEBUG");
  EXPECT_EQ(config.status_period_s, 2.5);
}

TEST(RecognitionConfigFile, DefaultsAreOffAndRecognitionDebug) {
  const RecognitionConfig config =
      read("runtime: {log_level: info}\nrecognition: {head: h.yaml, models: [m.yaml]}\n");
  EXPECT_FALSE(config.debug_image);
  EXPECT_EQ(config.debug_channel, "RECOGNITION_DEBUG");
  EXPECT_FALSE(config.calibration_path.has_value());
  EXPECT_FALSE(config.max_joint_speed_rad_s.has_value());
  EXPECT_EQ(config.status_period_s, 10.0);
}

TEST(RecognitionConfigFile, AJointSpeedLimitIsReadAndChecked) {
  EXPECT_EQ(read("recognition: {head: h.yaml, models: [m.yaml], max_joint_speed_rad_s: 0.1}\n")
                .max_joint_speed_rad_s,
            0.1);
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n"
                     "  max_joint_speed_rad_s: -1\n"),
            "dir/recognition.yaml:4: recognition.max_joint_speed_rad_s: must be in [0, 100], "
            "got -1");
}

TEST(RecognitionConfigFile, BadValuesAreOneLineWithFileLineAndKey) {
  EXPECT_EQ(error_of("recognition: {head: h.yaml, models: [m.yaml]}\nfusion: {}\n"),
            "dir/recognition.yaml:2: fusion: unknown key (allowed: runtime, recognition)");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: []\n"),
            "dir/recognition.yaml:3: recognition.models: expected a list of class model files "
            "(at least one)");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n  status_period_s: 0\n"),
            "dir/recognition.yaml:4: recognition.status_period_s: must be in [0.1, 3600], got 0");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n"
                     "  debug_image: {enabled: true, channel: 'a b'}\n"),
            "dir/recognition.yaml:4: recognition.debug_image.channel: channel names may use only "
            "letters, digits and _ - . /, got 'a b'");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n"
                     "  debug_image: {enabled: true, channel: PERCEPTS}\n"),
            "dir/recognition.yaml:4: recognition.debug_image.channel: channel 'PERCEPTS' is "
            "already used for PERCEPTS");
  runtime::Channels renamed;
  renamed.heartbeat = "RECOGNITION_DEBUG";
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n"
                     "  debug_image: {enabled: true}\n",
                     renamed),
            "dir/recognition.yaml:4: recognition.debug_image: channel 'RECOGNITION_DEBUG' is "
            "already used for VSL_HEARTBEAT");
  EXPECT_NE(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n"
                     "  segmentation: {min_blob_pixels: 3}\n")
                .find("dir/recognition.yaml:4: recognition.segmentation.min_blob_pixels: "),
            std::string::npos);
  EXPECT_NE(error_of("recognition:\n  models: [m.yaml]\n").find("recognition.head"),
            std::string::npos);
}

TEST(RecognitionConfigFile, TheLearnedRecognizerTakesItsDetectorAndBoxStereo) {
  const RecognitionConfig config = read(
      "recognition:\n  head: h.yaml\n  recognizer: learned\n  detector: d/door_handle.yaml\n"
      "  box_stereo: {min_correlation: 0.7, height_range_m: {door: [0.4, 2.2]}}\n");
  EXPECT_EQ(config.recognizer, "learned");
  EXPECT_EQ(config.detector_path, "dir/d/door_handle.yaml");
  EXPECT_EQ(config.box_stereo.min_correlation, 0.7);
  ASSERT_EQ(config.box_stereo.height_range_m.size(), 1u);
  EXPECT_EQ(config.box_stereo.height_range_m[0].min_m, 0.4);
  EXPECT_TRUE(config.model_paths.empty());
  EXPECT_EQ(read("recognition: {head: h.yaml, models: [m.yaml]}\n").recognizer, "paper");
}

TEST(RecognitionConfigFile, EachRecognizersKeysOnly) {
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  recognizer: neural\n"),
            "dir/recognition.yaml:3: recognition.recognizer: expected learned or paper, got "
            "'neural'");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  recognizer: learned\n  detector: d.yaml\n"
                     "  models: [m.yaml]\n"),
            "dir/recognition.yaml:5: recognition.models: not used by the learned recognizer "
            "(recognizer: paper uses it)");
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  models: [m.yaml]\n  detector: d.yaml\n"),
            "dir/recognition.yaml:4: recognition.detector: not used by the paper recognizer "
            "(recognizer: learned uses it)");
  EXPECT_NE(error_of("recognition:\n  head: h.yaml\n  recognizer: learned\n")
                .find("recognition.detector"),
            std::string::npos);
  EXPECT_EQ(error_of("recognition:\n  head: h.yaml\n  recognizer: learned\n  detector: d.yaml\n"
                     "  box_stereo: {min_depth_m: 3, max_depth_m: 2}\n"),
            "dir/recognition.yaml:5: recognition.box_stereo.max_depth_m: min_depth_m must be below "
            "max_depth_m");
  EXPECT_NE(error_of("recognition:\n  head: h.yaml\n  recognizer: learned\n  detector: d.yaml\n"
                     "  box_stereo: {snap: 1}\n")
                .find("dir/recognition.yaml:5: recognition.box_stereo.snap: unknown key"),
            std::string::npos);
}

}  // namespace
}  // namespace vsl::recognition_daemon

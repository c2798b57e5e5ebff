// RecognitionDaemon on an in-memory bus (memq://): the daemon's plumbing (worker, outbox,
// publishing, counting, logging) without processes. Over real LCM between processes:
// tests/recognition.
#include "recognition_daemon.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <limits>
#include <mutex>

#include "fake_recognizer.hpp"
#include "test_frames.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"

namespace vsl::recognition_daemon {
namespace {

using namespace std::chrono_literals;

struct Log {
  runtime::Logger logger() {
    return runtime::Logger("vsl-recognition", runtime::Level::kInfo, [this](std::string_view line) {
      std::lock_guard lock(mutex);
      text += line;
    });
  }
  std::string all() {
    std::lock_guard lock(mutex);
    return text;
  }
  std::mutex mutex;
  std::string text;
};

RecognitionSetup fake_setup(bool debug_image) {
  RecognitionSetup setup;
  setup.config.model_paths = {"fake"};
  setup.config.debug_image = debug_image;
  setup.config.status_period_s = 0.05;
  setup.recognizer = std::make_unique<recognition::FrameRecognizer>(
      recognition::FrameRecognizerOptions{}, testing::small_armar3(),
      testing::fake_door_recognizers());
  return setup;
}

TEST(RecognitionDaemonLoop, PublishesAListPerGoodFrameAndSurvivesBadOnes) {
  Log log;
  runtime::RuntimeConfig config;
  config.lcm_url = "memq://";
  config.heartbeat_period_s = 0.05;
  runtime::Daemon daemon(config, log.logger(),
                         std::make_unique<runtime::LcmBus>("memq://", log.logger()));
  RecognitionDaemon recognition(daemon, fake_setup(true));

  cv::Mat left(120, 160, CV_8UC3, cv::Scalar(200, 200, 200));
  cv::Mat right = left.clone();
  cv::rectangle(left, cv::Rect(60, 40, 30, 40), testing::door_bgr(), cv::FILLED);
  cv::rectangle(right, cv::Rect(54, 40, 30, 40), testing::door_bgr(), cv::FILLED);
  const head::HeadKinematics head = testing::small_armar3();
  std::vector<std::vector<std::uint8_t>> inputs;
  inputs.push_back(testing::encode(testing::stereo_frame(head, left, right, 0)));
  inputs.push_back(std::vector<std::uint8_t>(64, 0xff));  // not a stereo_frame_t
  vsl::stereo_frame_t nan = testing::stereo_frame(head, left, right, 2);
  nan.head.joint_velocities_rad_s[3] = std::numeric_limits<double>::quiet_NaN();
  inputs.push_back(testing::encode(nan));
  vsl::stereo_frame_t other = testing::stereo_frame(head, left, right, 3);
  other.head_name = "other";
  inputs.push_back(testing::encode(other));
  vsl::stereo_frame_t rgb = testing::stereo_frame(head, left, right, 4);
  rgb.left = testing::image_in_format(left, vsl::image_t::RGB8, 2);
  inputs.push_back(testing::encode(rgb));

  std::vector<vsl::percept_list_t> lists;
  std::vector<vsl::image_t> debug_images;
  std::vector<vsl::daemon_heartbeat_t> beats;
  daemon.subscribe<vsl::percept_list_t>(
      "PERCEPTS", [&](const vsl::percept_list_t& m, std::int64_t) { lists.push_back(m); });
  daemon.subscribe<vsl::image_t>(
      "RECOGNITION_DEBUG", [&](const vsl::image_t& m, std::int64_t) { debug_images.push_back(m); });
  daemon.subscribe<vsl::daemon_heartbeat_t>(
      "VSL_HEARTBEAT", [&](const vsl::daemon_heartbeat_t& m, std::int64_t) { beats.push_back(m); });
  // The next input once the previous one is out (recognized or rejected): none supersedes
  // another, whatever the build's speed. Stop once a status line counted them all, or at the
  // watchdog.
  const auto status_seen = [&] {
    for (const auto& beat : beats) {
      if (beat.state.rfind("running: 5 frames in, 2 processed", 0) == 0) return true;
    }
    return false;
  };
  std::size_t next = 0;
  int ticks = 0;
  daemon.every(10ms, [&] {
    ++ticks;
    const RecognitionStats& stats = recognition.stats();
    if (next < inputs.size()) {
      if (stats.processed + stats.invalid == static_cast<std::int64_t>(next)) {
        daemon.bus().publish("STEREO_FRAME", runtime::Bytes(inputs[next++]));
      }
    } else if (status_seen()) {
      daemon.stop();
    }
    if (ticks > 6000) {
      ADD_FAILURE() << "watchdog";
      daemon.stop(99);
    }
  });
  ASSERT_EQ(daemon.run(), 0) << log.all();

  ASSERT_EQ(lists.size(), 2u) << log.all();
  EXPECT_EQ(lists[0].frame_id, 0);
  EXPECT_EQ(lists[1].frame_id, 4);
  for (const auto& list : lists) {
    ASSERT_EQ(list.num_percepts, 1);
    EXPECT_EQ(list.percepts[0].type, "door");
  }
  ASSERT_EQ(debug_images.size(), 2u);
  EXPECT_EQ(debug_images[0].width, 160);

  const RecognitionStats& stats = recognition.stats();
  EXPECT_EQ(stats.frames_in, 5);
  EXPECT_EQ(stats.processed, 2);
  EXPECT_EQ(stats.invalid, 3);
  EXPECT_EQ(stats.percepts, 2);
  EXPECT_EQ(daemon.bus().counters().decode_errors, 1);

  const std::string text = log.all();
  EXPECT_NE(text.find("STEREO_FRAME: cannot decode 64 bytes as vsl.stereo_frame_t"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("WARN STEREO_FRAME: skipped frame 2: velocity of joint 'left_eye_pan' is "
                      "not finite (2 invalid so far)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("WARN STEREO_FRAME: skipped frame 3: head_name 'other', this recognizer is "
                      "configured for 'armar3' (3 invalid so far)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("INFO 5 frames in, 2 processed, 0 dropped, 3 invalid, 2 percepts"),
            std::string::npos)
      << text;
  EXPECT_TRUE(status_seen());
}

}  // namespace
}  // namespace vsl::recognition_daemon

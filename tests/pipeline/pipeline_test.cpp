// The whole system in simulation (issue 6): the four daemons as real processes over loopback
// multicast LCM (ttl=0, a port per test), a localization requested with vsl-request, the pose
// compared with the simulator's ground truth. Also: fusion killed with SIGKILL during a scan and
// restarted; a recorded session replayed with lcm-logplayer into recognition, fusion and a
// passive localizer; and every recorded channel decoded by lcm-spy's own classes under Xvfb.
// Every wait is bounded; nothing is timed.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "loopback.hpp"
#include "run_command.hpp"

namespace {

using namespace std::chrono_literals;
using vsl::testing::ChildProcess;

using vsl::testing::udpm_url;

// The numbers of vsl-request's "result: status=... key=value ..." line.
struct RequestResult {
  std::string status;
  std::map<std::string, double> values;
};

std::optional<RequestResult> parse_result(const std::string& out) {
  const std::size_t at = out.rfind("result: status=");
  if (at == std::string::npos) return std::nullopt;
  std::istringstream line(out.substr(at + 8, out.find('\n', at) - at - 8));
  RequestResult result;
  for (std::string field; line >> field;) {
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = field.substr(0, eq), value = field.substr(eq + 1);
    if (key == "status") {
      result.status = value;
    } else {
      result.values[key] = std::stod(value);
    }
  }
  return result;
}

// The milliseconds of vsl-request's "from the last scan frame's <what> to the pose: N ms" line.
std::optional<double> latency_ms(const std::string& out, const std::string& what) {
  const std::string key = "from the last scan frame's " + what + " to the pose: ";
  const std::size_t at = out.rfind(key);
  if (at == std::string::npos) return std::nullopt;
  return std::stod(out.substr(at + key.size()));
}

std::string describe(const ChildProcess& p) {
  return "stdout:\n" + p.out() + "\nstderr:\n" + p.err();
}

// The daemons of one test on one port; stopped with SIGTERM (clean exit checked) at the end.
class Pipeline {
 public:
  struct Options {
    int port = 0;
    std::string pose;  // X,Y,Z,YAW_DEG for vsl-sim-head; empty: config/sim_head.yaml's
    std::string localizer_config = "config/vsl-localizer.yaml";
    bool simulator = true;
    bool passive = false;  // a replay: localizer --passive, no simulator
    // The paper's recognizer on the flat images it is tuned on (fast, and what the recovery and
    // fault tests need); the shipped default is the learned one at realism full (shipped()).
    std::string recognition_config = "config/recognition_paper.yaml";
    std::string realism = "off";  // --realism for vsl-sim-head; empty: config/sim_head.yaml's
  };
  // The live pipeline at the default (or `pose`) robot pose.
  static Options live(int port, std::string pose = "") {
    Options options;
    options.port = port;
    options.pose = std::move(pose);
    return options;
  }
  // The live pipeline as shipped and as tools/demo runs it: the learned recognizer
  // (config/recognition.yaml) on images at config/sim_head.yaml's realism (full).
  static Options shipped(int port, std::string pose = "") {
    Options options = live(port, std::move(pose));
    options.recognition_config = "config/recognition.yaml";
    options.realism.clear();
    return options;
  }
  // A replay: no simulator, a passive localizer.
  static Options replay(int port) {
    Options options;
    options.port = port;
    options.simulator = false;
    options.passive = true;
    return options;
  }

  explicit Pipeline(Options options) : options_(std::move(options)) {
    const std::string url = udpm_url(options_.port);
    if (options_.simulator) {
      std::vector<std::string> argv = {VSL_SIM_HEAD, "--config", "config/sim_head.yaml",
                                       "--lcm-url", url};
      if (!options_.pose.empty()) argv.insert(argv.end(), {"--pose", options_.pose});
      if (!options_.realism.empty()) argv.insert(argv.end(), {"--realism", options_.realism});
      start("vsl-sim-head", argv);
    }
    start("vsl-recognition",
          {VSL_RECOGNITION, "--config", options_.recognition_config, "--lcm-url", url});
    start_fusion();
    std::vector<std::string> localizer = {VSL_LOCALIZER, "--config", options_.localizer_config,
                                          "--lcm-url", url};
    if (options_.passive) localizer.push_back("--passive");
    start("vsl-localizer", localizer);
  }
  ~Pipeline() {
    for (auto& [name, process] : processes_) {
      if (process) ::kill(process->pid(), SIGTERM);
    }
    for (auto& [name, process] : processes_) {
      if (!process) continue;
      const std::optional<int> status = process->wait(20s);
      EXPECT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
          << name << " did not stop cleanly on SIGTERM\n"
          << process->err();
    }
  }

  void start_fusion() {
    start("vsl-fusion",
          {VSL_FUSION, "--config", "config/fusion.yaml", "--lcm-url", udpm_url(options_.port)});
  }
  void kill_fusion() { kill("vsl-fusion"); }
  // SIGKILL to one daemon; it is gone when this returns.
  void kill(const std::string& name) {
    ChildProcess& process = *processes_.at(name);
    ::kill(process.pid(), SIGKILL);
    const std::optional<int> status = process.wait(10s);
    ASSERT_TRUE(status && WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL) << name;
    processes_.at(name).reset();
  }
  // SIGTERM to one daemon: it must stop cleanly (exit code 0); its stderr is returned.
  std::string terminate(const std::string& name) {
    ChildProcess& process = *processes_.at(name);
    ::kill(process.pid(), SIGTERM);
    const std::optional<int> status = process.wait(20s);
    EXPECT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << process.err();
    std::string err = process.err();
    processes_.at(name).reset();
    return err;
  }
  void start_localizer() { restart("vsl-localizer"); }
  // Each running daemon's stderr so far, for a failure message.
  std::string daemon_logs() {
    std::string logs;
    for (auto& [name, process] : processes_) {
      if (!process) continue;
      process->read_available();
      logs += "--- " + name + " stderr:\n" + process->err() + "\n";
    }
    return logs;
  }
  // Starts a daemon again with the arguments it first had.
  void restart(const std::string& name) { start(name, argv_.at(name)); }
  // Sends `signal` to a running daemon (SIGSTOP, SIGCONT: it stays in the pipeline).
  void signal(const std::string& name, int signal) { ::kill(processes_.at(name)->pid(), signal); }

  // vsl-request with `extra` arguments, started (not waited for).
  std::unique_ptr<ChildProcess> request(const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> argv = {VSL_REQUEST, "--lcm-url", udpm_url(options_.port), "--timeout",
                                     "240"};
    if (!options_.passive) {
      argv.insert(argv.end(),
                  {"--wait-for", options_.simulator
                                     ? "vsl-sim-head,vsl-recognition,vsl-fusion,vsl-localizer"
                                     : "vsl-recognition,vsl-fusion,vsl-localizer"});
    }
    argv.insert(argv.end(), extra.begin(), extra.end());
    return std::make_unique<ChildProcess>(argv);
  }

  // Runs one request to its end; the parsed result line (nullopt: none, with the output logged).
  static std::optional<RequestResult> finish(ChildProcess& request) {
    const std::optional<int> status = request.wait(300s);
    EXPECT_TRUE(status.has_value()) << "vsl-request did not finish\n" << describe(request);
    std::optional<RequestResult> result = parse_result(request.out());
    EXPECT_TRUE(result.has_value()) << describe(request);
    return result;
  }

 private:
  void start(const std::string& name, const std::vector<std::string>& argv) {
    argv_[name] = argv;
    processes_[name] = std::make_unique<ChildProcess>(argv);
  }

  Options options_;
  std::map<std::string, std::unique_ptr<ChildProcess>> processes_;
  std::map<std::string, std::vector<std::string>> argv_;
};

void expect_localized_near_truth(const std::optional<RequestResult>& result,
                                 const std::string& what) {
  ASSERT_TRUE(result.has_value()) << what;
  ASSERT_EQ(result->status, "LOCALIZED") << what;
  ASSERT_TRUE(result->values.contains("position_error_m")) << what << ": no ground truth seen";
  // Issue 6: within 5 cm and 2 degrees of the ground truth.
  EXPECT_LT(result->values.at("position_error_m"), 0.05) << what;
  EXPECT_LT(result->values.at("rotation_error_deg"), 2.0) << what;
}

// --- The full pipeline from several robot poses in the kitchen. ---------------------------------

struct PoseCase {
  const char* name;
  const char* pose;  // X,Y,Z,YAW_DEG; "" for config/sim_head.yaml's default
  int port;
  bool shipped;  // the shipped recognizer and realism (Pipeline::shipped), else the paper's
};

class FullPipeline : public ::testing::TestWithParam<PoseCase> {};

TEST_P(FullPipeline, LocalizesWithinFiveCentimetresAndTwoDegrees) {
  const PoseCase& c = GetParam();
  Pipeline pipeline(c.shipped ? Pipeline::shipped(c.port, c.pose) : Pipeline::live(c.port, c.pose));
  const auto request = pipeline.request();
  const std::optional<RequestResult> result = Pipeline::finish(*request);
  // On a failure, vsl-request's whole progress and pose table tell what went wrong.
  expect_localized_near_truth(result, c.name + std::string("\n") + request->out());
  // The latency from the frame's capture stamp counts the simulated head's rendering too; from
  // its arrival on STEREO_FRAME only recognition, fusion and the localizer.
  const std::optional<double> from_capture = latency_ms(request->out(), "capture");
  const std::optional<double> from_arrival = latency_ms(request->out(), "arrival");
  ASSERT_TRUE(from_capture && from_arrival) << request->out();
  EXPECT_GT(*from_arrival, 0.0);
  EXPECT_LE(*from_arrival, *from_capture);
}

// The default pose of config/sim_head.yaml, as processes over real LCM: as shipped (the learned
// recognizer at realism full, what tools/demo runs) and with the paper's recognizer on flat
// images. The other poses of vsl-scenario --seed 3 and the ambiguous start resolved by active
// validation run in lock step on simulated time (lockstep_pipeline_test.cpp): deterministic,
// once each.
INSTANTIATE_TEST_SUITE_P(Kitchen, FullPipeline,
                         ::testing::Values(PoseCase{"shipped", "", 17840, true},
                                           PoseCase{"paper", "", 17841, false}),
                         [](const ::testing::TestParamInfo<PoseCase>& info) {
                           return std::string(info.param.name);
                         });

// --- Fusion killed during a scan and restarted. -------------------------------------------------

TEST(PipelineRecovery, FusionKilledDuringTheScanAndRestartedStillLocalizes) {
  Pipeline pipeline(Pipeline::live(17850));
  const auto request = pipeline.request();
  // Kill fusion once the scan is past its first gaze target (progress lines on stderr).
  bool killed = false;
  for (int i = 0; i < 600 && !killed; ++i) {
    request->wait_for_stdout("\x01", 100ms);  // pumps both pipes
    if (request->err().find("step 2 of") != std::string::npos) {
      pipeline.kill_fusion();
      killed = true;
    }
  }
  ASSERT_TRUE(killed) << "the scan never reached its second gaze target\n" << describe(*request);
  pipeline.start_fusion();  // adopts the request from LOCALIZER_STATUS (docs/fusion.md)
  const std::optional<RequestResult> result = Pipeline::finish(*request);
  expect_localized_near_truth(result, "after fusion's restart\n" + request->out());
}

// --- The localizer stopped or killed mid-request: the request is still answered. ---------------

// Pumps `request`'s output until its progress shows the scan past its first gaze target.
bool wait_for_second_gaze(ChildProcess& request) {
  for (int i = 0; i < 600; ++i) {
    request.wait_for_stdout("\x01", 100ms);  // pumps both pipes
    if (request.err().find("step 2 of") != std::string::npos) return true;
  }
  return false;
}

TEST(PipelineRecovery, LocalizerStoppedMidRequestAnswersFailedAtOnce) {
  Pipeline pipeline(Pipeline::live(17856));
  const auto request = pipeline.request();
  ASSERT_TRUE(wait_for_second_gaze(*request)) << describe(*request);
  const auto stopped_at = std::chrono::steady_clock::now();
  pipeline.terminate("vsl-localizer");
  const std::optional<RequestResult> result = Pipeline::finish(*request);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->status, "FAILED");
  EXPECT_NE(request->out().find("the localizer stopped before it finished"), std::string::npos)
      << describe(*request);
  // Answered, not timed out (the request allows 240 s).
  EXPECT_LT(std::chrono::steady_clock::now() - stopped_at, 30s) << describe(*request);
}

TEST(PipelineRecovery, LocalizerKilledMidRequestAndRestartedAnswersTheRequest) {
  Pipeline pipeline(Pipeline::live(17857));
  const auto request = pipeline.request();
  ASSERT_TRUE(wait_for_second_gaze(*request)) << describe(*request);
  pipeline.kill("vsl-localizer");
  pipeline.start_localizer();  // a new pid: vsl-request sends the request again
  const std::optional<RequestResult> result = Pipeline::finish(*request);
  expect_localized_near_truth(result, "after the localizer's restart\n" + request->out());
  EXPECT_NE(request->err().find("the localizer restarted"), std::string::npos)
      << describe(*request);
}

// Each daemon frozen (SIGSTOP) past every timeout of the request, or killed and restarted, once
// the scan has begun: the request is always answered within its timeout, and never with a
// confident pose that is wrong.
struct FaultCase {
  const char* name;
  const char* daemon;
  int signal;  // SIGSTOP (then SIGCONT once answered) or SIGKILL (then a restart)
  int port;
};

class PipelineFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(PipelineFault, EveryRequestIsAnswered) {
  const FaultCase& c = GetParam();
  Pipeline pipeline(Pipeline::live(c.port));
  const auto request = pipeline.request();
  ASSERT_TRUE(wait_for_second_gaze(*request)) << describe(*request);
  if (c.signal == SIGKILL) {
    pipeline.kill(c.daemon);
    pipeline.restart(c.daemon);
  } else {
    pipeline.signal(c.daemon, SIGSTOP);
  }
  const std::optional<RequestResult> result = Pipeline::finish(*request);
  if (c.signal == SIGSTOP) pipeline.signal(c.daemon, SIGCONT);  // for the clean stop at the end
  ASSERT_TRUE(result.has_value()) << c.name;
  EXPECT_TRUE(result->status == "LOCALIZED" || result->status == "AMBIGUOUS" ||
              result->status == "FAILED")
      << c.name << ": " << result->status;
  if (result->status == "LOCALIZED") expect_localized_near_truth(result, c.name);
}

INSTANTIATE_TEST_SUITE_P(
    Daemons, PipelineFault,
    ::testing::Values(FaultCase{"sim_head_frozen", "vsl-sim-head", SIGSTOP, 17860},
                      FaultCase{"recognition_frozen", "vsl-recognition", SIGSTOP, 17861},
                      FaultCase{"fusion_frozen", "vsl-fusion", SIGSTOP, 17862},
                      FaultCase{"sim_head_killed", "vsl-sim-head", SIGKILL, 17863},
                      FaultCase{"recognition_killed", "vsl-recognition", SIGKILL, 17864}),
    [](const ::testing::TestParamInfo<FaultCase>& info) { return std::string(info.param.name); });

// --- Record, replay into a passive localizer, decode every channel with lcm-spy. ----------------

// A live localization at the default pose recorded with lcm-logger on `port`. Each test records
// its own session on its own port (ctest runs them in parallel, each in a process of its own).
class RecordedSession : public ::testing::Test {
 protected:
  void record(int port) {
    dir_ = std::filesystem::temp_directory_path() /
           ("vsl_pipeline_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    log_ = (dir_ / "session.lcmlog").string();
    ChildProcess logger({"/usr/bin/lcm-logger", "--lcm-url=" + udpm_url(port), "--force", log_});
    {
      Pipeline pipeline(Pipeline::live(port));
      const auto request = pipeline.request();
      live_ = Pipeline::finish(*request);
      live_request_log_ = describe(*request);
    }
    std::this_thread::sleep_for(500ms);  // the last messages reach the log
    ::kill(logger.pid(), SIGINT);
    logger.wait(10s);
    ASSERT_TRUE(std::filesystem::exists(log_));
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }

  std::filesystem::path dir_;
  std::string log_;
  std::optional<RequestResult> live_;
  std::string live_request_log_;  // the live vsl-request's output
};

TEST_F(RecordedSession, ReplayIntoAPassiveLocalizerReproducesThePose) {
  ASSERT_NO_FATAL_FAILURE(record(17852));
  expect_localized_near_truth(live_, "the recorded live run");
  // Only the inputs are replayed: what recognition, fusion and the localizer made live is in the
  // log too and must not reach the replayed ones. Half speed leaves recognition time to spare
  // on a loaded machine (sanitizer builds), as the live run had.
  Pipeline replay(Pipeline::replay(17853));
  const auto follower = replay.request({"--follow", "--pose-channel", "PASSIVE_POSE_ESTIMATE",
                                        "--status-channel", "PASSIVE_LOCALIZER_STATUS"});
  std::this_thread::sleep_for(2s);  // the replayed daemons subscribe
  ChildProcess player({"/usr/bin/lcm-logplayer", "--speed=0.5", "--lcm-url=" + udpm_url(17853),
                       "--regexp=^(STEREO_FRAME|HEAD_STATE|LOCALIZE_REQUEST|LOCALIZER_STATUS)$",
                       log_});
  const std::optional<RequestResult> replayed = Pipeline::finish(*follower);
  player.wait(120s);
  ASSERT_TRUE(replayed.has_value());
  ASSERT_EQ(replayed->status, "LOCALIZED") << describe(*follower) << "\n"
                                           << replay.daemon_logs() << "--- the recorded run:\n"
                                           << live_request_log_;
  // Issue 6: the replay reproduces the pose within 1 cm and 0.5 degrees.
  const double dx = replayed->values.at("x_m") - live_->values.at("x_m");
  const double dy = replayed->values.at("y_m") - live_->values.at("y_m");
  const double dz = replayed->values.at("z_m") - live_->values.at("z_m");
  EXPECT_LT(std::sqrt(dx * dx + dy * dy + dz * dz), 0.01);
  EXPECT_LT(
      std::abs(std::remainder(replayed->values.at("yaw_deg") - live_->values.at("yaw_deg"), 360.0)),
      0.5);
}

TEST_F(RecordedSession, LcmSpyDecodesEveryChannelUnderXvfb) {
  ASSERT_NO_FATAL_FAILURE(record(17854));
  const vsl::testing::CommandResult result = vsl::testing::run_command(
      {"/bin/bash", "tests/pipeline/spy_decodes_log.sh", VSL_TYPES_JAR, log_}, 180.0);
  const std::string output = result.out + result.err;
  EXPECT_EQ(result.exit_code, 0) << output;
  for (const char* channel :
       {"STEREO_FRAME", "HEAD_STATE", "GAZE_COMMAND", "PERCEPTS", "FUSED_PERCEPTS", "POSE_ESTIMATE",
        "LOCALIZER_STATUS", "LOCALIZE_REQUEST", "GROUND_TRUTH_POSE", "VSL_HEARTBEAT"}) {
    EXPECT_NE(result.out.find(std::string("ok: ") + channel + " "), std::string::npos)
        << channel << " not decoded by lcm-spy\n"
        << output;
  }
}

}  // namespace

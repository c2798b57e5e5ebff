#include "vsl/runtime/command_line.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

namespace vsl::runtime {
namespace {

CommandLine parse(std::vector<const char*> args) {
  args.insert(args.begin(), "vsl-test");
  return parse_command_line(static_cast<int>(args.size()), args.data());
}

std::string usage_error(std::vector<const char*> args) {
  try {
    parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(runtime_command_line, ParsesBothOptionForms) {
  const CommandLine a = parse({"--config", "config/fusion.yaml", "--lcm-url", "memq://"});
  EXPECT_EQ(a.config_path, "config/fusion.yaml");
  EXPECT_EQ(a.lcm_url, "memq://");
  EXPECT_FALSE(a.help);
  const CommandLine b = parse({"--config=x.yaml", "--lcm-url=udpm://239.255.76.67:7667?ttl=0"});
  EXPECT_EQ(b.config_path, "x.yaml");
  EXPECT_EQ(b.lcm_url, "udpm://239.255.76.67:7667?ttl=0");
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"-h"}).help);
  const CommandLine none = parse({});
  EXPECT_FALSE(none.config_path);
  EXPECT_FALSE(none.lcm_url);
}

TEST(runtime_command_line, ErrorsAreOneLine) {
  EXPECT_EQ(usage_error({"--frobnicate"}), "unknown option '--frobnicate'");
  EXPECT_EQ(usage_error({"--configs=x"}), "unknown option '--configs=x'");
  EXPECT_EQ(usage_error({"--config"}), "option --config needs a value");
  EXPECT_EQ(usage_error({"--config="}), "option --config needs a file name");
  EXPECT_EQ(usage_error({"extra"}), "unexpected argument 'extra'");
  EXPECT_EQ(usage_error({"--lcm-url", "localhost:7667"}),
            "option --lcm-url: expected an LCM URL such as "
            "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304, got "
            "'localhost:7667'");
}

TEST(runtime_command_line, UsageNamesProgramAndDescription) {
  const std::string text = usage({"vsl-fusion", "Fuses percepts per type.", true});
  EXPECT_EQ(text.rfind(
                "Usage: vsl-fusion --config FILE [--lcm-url URL]\n\nFuses percepts per type.\n", 0),
            0u)
      << text;
  EXPECT_NE(text.find("--help"), std::string::npos);
}

// daemon_main end to end, in this process (memq://).
class runtime_daemon_main : public ::testing::Test {
 protected:
  void TearDown() override {
    if (!config_path_.empty()) std::filesystem::remove(config_path_);
  }

  std::string write_config(const std::string& yaml) {
    config_path_ = std::filesystem::temp_directory_path() /
                   ("vsl_runtime_main_" + std::to_string(::getpid()) + "_" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
    std::ofstream(config_path_) << yaml;
    return config_path_.string();
  }

  int run(std::vector<std::string> args) {
    args.insert(args.begin(), "vsl-test");
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const ProgramInfo program{"vsl-test", "A daemon for the tests.", false};
    return daemon_main(static_cast<int>(args.size()), argv.data(), program,
                       [this](Daemon& daemon, const config::Node& config) {
                         ++body_calls_;
                         config.expect_keys({"runtime", "test"});
                         seen_url_ = daemon.bus().url();
                         seen_percepts_ = daemon.channels().percepts;
                         seen_value_ = config.get("test", std::int64_t{0});
                         daemon.stop();
                         return daemon.run();
                       });
  }

  std::filesystem::path config_path_;
  int body_calls_ = 0;
  std::string seen_url_;
  std::string seen_percepts_;
  std::int64_t seen_value_ = -1;
};

TEST_F(runtime_daemon_main, HelpPrintsUsageAndExits0) {
  ::testing::internal::CaptureStdout();
  EXPECT_EQ(run({"--help"}), 0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("Usage: vsl-test [--config FILE] [--lcm-url URL]"), std::string::npos);
  EXPECT_NE(out.find("A daemon for the tests."), std::string::npos);
  EXPECT_EQ(body_calls_, 0);
}

TEST_F(runtime_daemon_main, UnknownOptionIsOneLineAndExit2) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--verbose"}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "vsl-test: unknown option '--verbose' (try --help)\n");
  EXPECT_EQ(body_calls_, 0);
}

// systemd's RestartPreventExitStatus=2 keeps a daemon down on a usage error; a bad URL is one.
TEST_F(runtime_daemon_main, MalformedLcmUrlIsOneLineAndExit2) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--lcm-url", "udpm://239.255.76.67:99999"}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "vsl-test: option --lcm-url 'udpm://239.255.76.67:99999': expected a port 1-65535, "
            "got '99999' (try --help)\n");
  EXPECT_EQ(body_calls_, 0);
}

TEST_F(runtime_daemon_main, BadRuntimeSectionIsOneLineAndExit2) {
  const std::string path = write_config("runtime:\n  lcm_url: memq://\n  log_levle: debug\n");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--config", path}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            path +
                ":3: runtime.log_levle: unknown key (allowed: lcm_url, heartbeat_period_s, "
                "log_level, channels)\n");
  EXPECT_EQ(body_calls_, 0);
}

TEST_F(runtime_daemon_main, BadDaemonSectionIsOneLineAndExit2) {
  const std::string path = write_config("runtime:\n  lcm_url: memq://\ntest: many\n");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--config", path}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            path + ":3: test: expected an integer, got 'many'\n");
}

TEST_F(runtime_daemon_main, MissingConfigFileExits2) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--config", "/nonexistent/vsl.yaml"}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "/nonexistent/vsl.yaml: cannot open file\n");
}

TEST_F(runtime_daemon_main, RunsBodyWithConfigAndUrlOverride) {
  const std::string path = write_config(
      "runtime:\n  lcm_url: udpm://239.255.76.67:17612?ttl=0\n  log_level: warn\n"
      "  channels: {PERCEPTS: P2}\ntest: 5\n");
  EXPECT_EQ(run({"--config", path, "--lcm-url", "memq://"}), 0);
  EXPECT_EQ(body_calls_, 1);
  EXPECT_EQ(seen_url_, "memq://");
  EXPECT_EQ(seen_percepts_, "P2");
  EXPECT_EQ(seen_value_, 5);
}

TEST_F(runtime_daemon_main, NoConfigMeansDefaults) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--lcm-url=memq://"}), 0);
  ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(seen_percepts_, "PERCEPTS");
  EXPECT_EQ(seen_value_, 0);
}

// A well-formed URL liblcm cannot open (here a log file that is not there) is a start-up
// failure, not a usage error: exit code 1, one line with liblcm's reason.
TEST_F(runtime_daemon_main, UnopenableBusExits1WithOneLine) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--lcm-url", "file:///nonexistent/session.lcmlog?mode=r"}), 1);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(
      err.rfind("vsl-test: cannot open LCM URL 'file:///nonexistent/session.lcmlog?mode=r'", 0), 0u)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(body_calls_, 0);
}

TEST_F(runtime_daemon_main, UnknownLcmProviderIsAUsageError) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run({"--lcm-url", "bogus://x"}), 2);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "vsl-test: option --lcm-url 'bogus://x': unknown provider 'bogus' (liblcm has udpm, "
            "mpudpm, memq, file, tcpq) (try --help)\n");
}

}  // namespace
}  // namespace vsl::runtime

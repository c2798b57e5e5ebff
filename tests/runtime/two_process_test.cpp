// The runtime across real processes over loopback multicast LCM (ttl=0): runtime_peer publisher ->
// runtime_peer subscriber, and clean shutdown on SIGTERM/SIGINT. Every test has a UDP port of its
// own (176xx) so that ctest -j never cross-talks. Children are always reaped; every wait is
// bounded so that a hung child fails the test instead of hanging ctest.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "child_process.hpp"
#include "loopback.hpp"
#include "peer_protocol.hpp"
#include "vsl/daemon_heartbeat_t.hpp"
#include "vsl/runtime/lcm_bus.hpp"
#include "vsl/runtime/typed.hpp"

namespace vsl::runtime {
namespace {

using namespace std::chrono_literals;
using vsl::testing::ChildProcess;

// recv_buf_size: with the kernel's default socket buffer (rmem_default, 208 KiB) liblcm 1.3.1
// loses a message of about 200 kB (several UDP fragments) on this box; stereo frames are larger.
using vsl::testing::describe;
using vsl::testing::udpm_url;

class runtime_two_process : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const auto& path : files_) std::filesystem::remove(path);
  }

  // Writes a peer config; returns its path.
  std::string peer_config(int port, const std::string& mode, int count,
                          const std::string& channel = "LOCALIZE_REQUEST") {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("vsl_runtime_peer_" + std::to_string(::getpid()) + "_" + mode + "_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
    std::ofstream(path) << "runtime:\n"
                        << "  lcm_url: " << udpm_url(port) << "\n"
                        << "  heartbeat_period_s: 0.05\n"
                        << "  channels: {LOCALIZE_REQUEST: " << channel << "}\n"
                        << "peer:\n"
                        << "  mode: " << mode << "\n"
                        << "  count: " << count << "\n"
                        << "  period_s: 0.005\n";
    files_.push_back(path);
    return path.string();
  }

  // Starts a subscriber peer that runs until signalled, waits for its heartbeat, sends `signal`
  // and checks a prompt, clean exit with code 0 and a last "stopped" heartbeat.
  void expect_clean_exit_on(int signal, const char* signal_name, int port) {
    LcmBus bus(udpm_url(port), Logger("test"));
    std::vector<vsl::daemon_heartbeat_t> beats;
    subscribe<vsl::daemon_heartbeat_t>(
        bus, "VSL_HEARTBEAT",
        [&](const vsl::daemon_heartbeat_t& m, std::int64_t) { beats.push_back(m); });
    ChildProcess peer({VSL_RUNTIME_PEER, "--config", peer_config(port, "subscriber", 0)});
    const auto has_state = [&](const std::string& state) {
      for (const auto& beat : beats) {
        if (beat.pid == peer.pid() && beat.state == state) return true;
      }
      return false;
    };

    // Its heartbeat says it is up (and proves it talks over this port).
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (!has_state("running") && std::chrono::steady_clock::now() < deadline) {
      bus.handle(100ms);
    }
    ASSERT_TRUE(has_state("running")) << "no heartbeat from the peer; stderr:\n" << peer.err();
    EXPECT_EQ(beats.front().process, "runtime_peer");

    const auto sent = std::chrono::steady_clock::now();
    ASSERT_EQ(::kill(peer.pid(), signal), 0);
    const std::optional<int> status = peer.wait(5s);
    ASSERT_TRUE(status.has_value()) << "peer still running 5 s after " << signal_name;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
        << describe(*status) << "; stderr:\n"
        << peer.err();
    EXPECT_LT(seconds, 1.0);
    EXPECT_NE(peer.err().find(std::string("INFO received ") + signal_name + ", shutting down\n"),
              std::string::npos)
        << peer.err();
    EXPECT_NE(peer.err().find("INFO clean shutdown, exit code 0"), std::string::npos) << peer.err();

    // The last heartbeat went out before the exit; it is already in this socket's queue.
    const auto late = std::chrono::steady_clock::now() + 2s;
    while (!has_state("stopped") && std::chrono::steady_clock::now() < late) bus.handle(100ms);
    EXPECT_TRUE(has_state("stopped"));
  }

  std::vector<std::filesystem::path> files_;
};

TEST_F(runtime_two_process, PublisherToSubscriberOverUdpm) {
  constexpr int kPort = 17621;
  constexpr int kCount = 40;
  // A channel name of its own too (runtime.channels override, seen by both processes).
  ChildProcess subscriber(
      {VSL_RUNTIME_PEER, "--config", peer_config(kPort, "subscriber", kCount, "PEER_17621")});
  ASSERT_TRUE(subscriber.wait_for_stdout("ready\n", 10s)) << subscriber.err();

  ChildProcess publisher(
      {VSL_RUNTIME_PEER, "--config", peer_config(kPort, "publisher", kCount, "PEER_17621")});
  const std::optional<int> published = publisher.wait(20s);
  ASSERT_TRUE(published.has_value()) << "publisher hung; stderr:\n" << publisher.err();
  EXPECT_TRUE(WIFEXITED(*published) && WEXITSTATUS(*published) == 0)
      << describe(*published) << "; stderr:\n"
      << publisher.err();

  const std::optional<int> received = subscriber.wait(10s);
  ASSERT_TRUE(received.has_value()) << "subscriber did not get all messages; stdout:\n"
                                    << subscriber.out() << "stderr:\n"
                                    << subscriber.err();
  EXPECT_TRUE(WIFEXITED(*received) && WEXITSTATUS(*received) == 0)
      << describe(*received) << "; stderr:\n"
      << subscriber.err();

  std::string expected = "ready\n";
  for (int id = 1; id <= kCount; ++id) expected += peer::line(peer::message(id, kCount));
  EXPECT_EQ(subscriber.out(), expected);
  EXPECT_NE(subscriber.err().find("decode errors 0)"), std::string::npos) << subscriber.err();
}

TEST_F(runtime_two_process, SigtermExitsCleanly) {
  expect_clean_exit_on(SIGTERM, "SIGTERM", 17622);
}

TEST_F(runtime_two_process, SigintExitsCleanly) {
  expect_clean_exit_on(SIGINT, "SIGINT", 17623);
}

TEST_F(runtime_two_process, BadConfigExits2WithOneLine) {
  const std::string path = peer_config(17624, "listener", 1);
  ChildProcess peer({VSL_RUNTIME_PEER, "--config", path});
  const std::optional<int> status = peer.wait(10s);
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
  EXPECT_EQ(peer.err(), path + ":6: peer.mode: expected publisher or subscriber, got 'listener'\n");
}

TEST_F(runtime_two_process, CommandLineErrorsAndHelp) {
  {
    ChildProcess peer({VSL_RUNTIME_PEER, "--bogus"});
    const std::optional<int> status = peer.wait(10s);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
    EXPECT_EQ(peer.err(), "runtime_peer: unknown option '--bogus' (try --help)\n");
  }
  {
    ChildProcess peer({VSL_RUNTIME_PEER});
    const std::optional<int> status = peer.wait(10s);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 2) << describe(*status);
    EXPECT_EQ(peer.err(), "runtime_peer: option --config FILE is required (try --help)\n");
  }
  {
    ChildProcess peer({VSL_RUNTIME_PEER, "--help"});
    const std::optional<int> status = peer.wait(10s);
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << describe(*status);
    EXPECT_EQ(peer.out().rfind("Usage: runtime_peer --config FILE [--lcm-url URL]\n", 0), 0u)
        << peer.out();
    EXPECT_NE(peer.out().find("Test peer of the vsl runtime"), std::string::npos);
    EXPECT_EQ(peer.err(), "");
  }
}

}  // namespace
}  // namespace vsl::runtime

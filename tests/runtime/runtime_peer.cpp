// A tiny daemon on the vsl runtime for the two-process tests (tests/runtime/two_process_test.cpp).
//   peer: {mode: publisher | subscriber, count: N, period_s: S}
// publisher: publishes messages 1..N on LOCALIZE_REQUEST, one every S seconds, then exits 0.
// subscriber: prints "ready" once subscribed, then one line per message received; exits 0 after
// N messages (N = 0: runs until SIGINT/SIGTERM).
#include <cstdio>
#include <string>

#include "peer_protocol.hpp"
#include "vsl/config/node.hpp"
#include "vsl/runtime/main.hpp"

namespace {

using vsl::runtime::Daemon;

void print(const std::string& text) {
  std::fputs(text.c_str(), stdout);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const vsl::runtime::ProgramInfo program{
      "runtime_peer",
      "Test peer of the vsl runtime: publishes or receives vsl.localize_request_t on\n"
      "LOCALIZE_REQUEST. Config key peer: {mode: publisher|subscriber, count: N, period_s: S}.",
      true};
  return vsl::runtime::daemon_main(
      argc, argv, program, [](Daemon& daemon, const vsl::config::Node& config) {
        config.expect_keys({"runtime", "peer"});
        const vsl::config::Node peer = config.at("peer");
        peer.expect_keys({"mode", "count", "period_s"});
        const std::string mode = peer.at("mode").as_string();
        const std::int64_t count = peer.get("count", std::int64_t{10});
        if (count < 0) peer.at("count").fail("must be >= 0");
        const double period_s =
            peer.has("period_s") ? peer.at("period_s").as_positive_double() : 0.01;
        const std::string channel = daemon.channels().localize_request;

        std::int64_t next = 1;
        std::int64_t received = 0;
        if (mode == "publisher") {
          daemon.set_state("publishing");
          daemon.every_seconds(period_s, [&] {
            if (next > count) {
              daemon.stop();
              return;
            }
            daemon.publish(channel, vsl::runtime::peer::message(next, count));
            ++next;
          });
        } else if (mode == "subscriber") {
          daemon.subscribe<vsl::localize_request_t>(
              channel, [&](const vsl::localize_request_t& m, std::int64_t) {
                print(vsl::runtime::peer::line(m));
                if (++received == count) daemon.stop();
              });
          print("ready\n");
        } else {
          peer.at("mode").fail("expected publisher or subscriber, got '" + mode + "'");
        }
        return daemon.run();
      });
}

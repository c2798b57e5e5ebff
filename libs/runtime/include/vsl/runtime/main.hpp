// The whole main() of a daemon:
//
//   int main(int argc, char** argv) {
//     const vsl::runtime::ProgramInfo program{"vsl-fusion", "Fuses percepts ... (for --help)"};
//     return vsl::runtime::daemon_main(argc, argv, program,
//         [](vsl::runtime::Daemon& daemon, const vsl::config::Node& config) {
//           config.expect_keys({"runtime", "fusion"});
//           const FusionParams params = read_fusion_params(config.at("fusion"));
//           Fusion fusion(params);                          // lives as long as run()
//           daemon.subscribe<vsl::percepts_t>(daemon.channels().percepts, ...);
//           return daemon.run();
//         });
//   }
//
// Exit codes: 0 clean shutdown or --help; 2 bad command line or bad configuration (one line on
// stderr: "file:line: key: what", also for vsl::config::Error thrown by the body before run());
// 1 any other failure (bus cannot be opened, a handler threw).
#pragma once

#include <functional>

#include "vsl/runtime/command_line.hpp"
#include "vsl/runtime/daemon.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::runtime {

// Sets up handlers on the daemon and returns daemon.run().
using DaemonBody = std::function<int(Daemon& daemon, const config::Node& config)>;

// Parses the command line, loads the configuration (--config, or an empty one), reads its
// runtime: section (--lcm-url overrides lcm_url), opens the daemon and calls `body`.
int daemon_main(int argc, char** argv, const ProgramInfo& program, const DaemonBody& body);

}  // namespace vsl::runtime

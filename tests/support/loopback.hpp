// What the process tests share about loopback LCM and child processes.
#pragma once

#include <string>

namespace vsl::testing {

// LCM's multicast URL on `port` that never leaves this host (ttl=0), with the 4 MiB receive buffer
// a 1.8 MB stereo frame needs (docs/ARCHITECTURE.md). Each test uses a port of its own.
std::string udpm_url(int port);

// A wait status in words: "exit code 2", "killed by signal 9".
std::string describe(int wait_status);

}  // namespace vsl::testing

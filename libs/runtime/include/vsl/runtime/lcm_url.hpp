// Checking an LCM URL before liblcm sees it. liblcm reports a URL it cannot use on stderr in its
// own words and then fails, which a daemon could only pass on as a generic start-up failure
// (exit code 1: systemd restarts it forever). A malformed URL is a usage error (exit code 2).
#pragma once

#include <string>
#include <string_view>

namespace vsl::runtime {

// What is wrong with `url` as an LCM URL (provider://network?key=value&...), or "" when nothing
// is: the provider is one liblcm 1.4 has (udpm, mpudpm, memq, file, tcpq); udpm's network is an
// IPv4 multicast address (224.0.0.0/4) with a port 1-65535; its options are ttl (0-255),
// recv_buf_size (bytes, positive) and transmit_only (true/false); file's are mode (r, w, a),
// speed (a non-negative number) and start_timestamp (an integer); tcpq's network is host:port.
std::string lcm_url_problem(std::string_view url);

}  // namespace vsl::runtime

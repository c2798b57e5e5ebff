// What runtime_peer publishes and prints, shared with the test that checks it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "vsl/localize_request_t.hpp"

namespace vsl::runtime::peer {

// Message `id` of `count` (ids 1..count). Sizes vary; the last one spans several UDP fragments.
inline vsl::localize_request_t message(std::int64_t id, std::int64_t count) {
  vsl::localize_request_t m;
  m.utime = 1700000000000000 + 1000 * id;
  m.request_id = id;
  m.source = "runtime_peer";
  const std::size_t size = id == count ? 200000 : 10 + static_cast<std::size_t>(id * 131 % 2000);
  m.reason.resize(size);
  for (std::size_t i = 0; i < size; ++i) {
    m.reason[i] = static_cast<char>('a' + (static_cast<std::size_t>(id) * 7 + i * 13) % 26);
  }
  return m;
}

// FNV-1a, to compare large payloads in one line.
inline std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

// The line the subscriber prints for a received message.
inline std::string line(const vsl::localize_request_t& m) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(m.reason)));
  return "received " + std::to_string(m.request_id) + " " + std::to_string(m.utime) + " " +
         m.source + " " + std::to_string(m.reason.size()) + " " + hash + "\n";
}

}  // namespace vsl::runtime::peer

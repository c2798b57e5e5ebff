// Typed publish/subscribe for lcm-gen C++ types (vsl::percepts_t, ...) over any Bus. A message that
// does not decode as the expected type (wrong fingerprint, truncated, trailing bytes) is logged in
// one line, counted as a decode error and never reaches the handler.
#pragma once

#include <climits>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include "vsl/runtime/bus.hpp"

namespace vsl::runtime {

// Handler of a typed message and its receive time (utime).
template <class T>
using Handler = std::function<void(const T& message, std::int64_t receive_utime)>;

// "vsl.percepts_t" for vsl::percepts_t (the LCM package-qualified name).
std::string lcm_type_name(const std::type_info& type);

// Decodes `bytes` as a whole T, or reports a decode error on `bus` and returns nullopt.
template <class T>
std::optional<T> decode(Bus& bus, const std::string& channel, Bytes bytes) {
  std::optional<T> message(std::in_place);
  bool ok = bytes.size() <= static_cast<std::size_t>(INT_MAX);
  if (ok) {
    const int size = static_cast<int>(bytes.size());
    try {
      // A corrupt length field can make the generated code allocate and throw.
      ok = message->decode(bytes.data(), 0, size) == size;
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok) {
    bus.report_decode_error(channel, bytes.size(), typeid(T));
    return std::nullopt;
  }
  return message;
}

// Encodes and publishes; false when encoding or sending fails (counted in publish_errors).
template <class T>
bool publish(Bus& bus, const std::string& channel, const T& message) {
  const int size = message.getEncodedSize();
  std::vector<std::uint8_t> buffer(static_cast<std::size_t>(size < 0 ? 0 : size));
  if (size < 0 || message.encode(buffer.data(), 0, size) != size) {
    ++bus.counters().publish_errors;
    bus.log().error(channel, ": cannot encode ", lcm_type_name(typeid(T)));
    return false;
  }
  return bus.publish(channel, Bytes(buffer));
}

// Calls `handler` with every message on `channel` that decodes as T.
template <class T>
void subscribe(Bus& bus, const std::string& channel, Handler<T> handler,
               int queue_capacity = kDefaultQueueCapacity) {
  bus.subscribe(
      channel,
      [&bus, channel, handler = std::move(handler)](Bytes bytes, std::int64_t utime) {
        if (const std::optional<T> message = decode<T>(bus, channel, bytes)) {
          handler(*message, utime);
        }
      },
      queue_capacity);
}

}  // namespace vsl::runtime

#include "vsl/runtime/lcm_url.hpp"

#include <charconv>
#include <cstdint>
#include <vector>

namespace vsl::runtime {
namespace {

bool whole_number(std::string_view text, std::int64_t min, std::int64_t max) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && value >= min && value <= max;
}

bool non_negative_number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && value >= 0.0 && value < 1e9;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == separator) {
      out.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

// "A.B.C.D:PORT" with A in 224..239 (multicast); empty takes liblcm's default.
std::string multicast_problem(std::string_view network) {
  if (network.empty()) return "";
  const std::size_t colon = network.rfind(':');
  if (colon == std::string_view::npos)
    return "expected ADDRESS:PORT, got '" + std::string(network) + "'";
  const std::vector<std::string_view> octets = split(network.substr(0, colon), '.');
  bool address_ok = octets.size() == 4;
  for (const std::string_view octet : octets)
    address_ok = address_ok && whole_number(octet, 0, 255);
  if (!address_ok || !whole_number(octets[0], 224, 239)) {
    return "expected an IPv4 multicast address (224.0.0.0 to 239.255.255.255), got '" +
           std::string(network.substr(0, colon)) + "'";
  }
  if (!whole_number(network.substr(colon + 1), 1, 65535)) {
    return "expected a port 1-65535, got '" + std::string(network.substr(colon + 1)) + "'";
  }
  return "";
}

std::string option_problem(std::string_view provider, std::string_view key,
                           std::string_view value) {
  const std::string what = "option " + std::string(key) + "=" + std::string(value);
  if (provider == "udpm" || provider == "mpudpm") {
    if (key == "ttl") return whole_number(value, 0, 255) ? "" : what + ": expected 0-255";
    if (key == "recv_buf_size") {
      return whole_number(value, 1, std::int64_t{1} << 32) ? ""
                                                           : what + ": expected a size in bytes";
    }
    if (key == "transmit_only") {
      return value == "true" || value == "false" ? "" : what + ": expected true or false";
    }
  } else if (provider == "file") {
    if (key == "mode")
      return value == "r" || value == "w" || value == "a" ? "" : what + ": expected r, w or a";
    if (key == "speed")
      return non_negative_number(value) ? "" : what + ": expected a non-negative number";
    if (key == "start_timestamp") {
      return whole_number(value, INT64_MIN, INT64_MAX) ? "" : what + ": expected an integer";
    }
  }
  return "unknown option '" + std::string(key) + "' for " + std::string(provider) + "://";
}

}  // namespace

std::string lcm_url_problem(std::string_view url) {
  const std::size_t scheme_end = url.find("://");
  if (scheme_end == std::string_view::npos) return "expected provider://network?options";
  const std::string_view provider = url.substr(0, scheme_end);
  const std::string_view rest = url.substr(scheme_end + 3);
  const std::size_t query = rest.find('?');
  const std::string_view network = rest.substr(0, query);
  if (provider == "udpm" || provider == "mpudpm") {
    if (std::string problem = multicast_problem(network); !problem.empty()) return problem;
  } else if (provider == "file") {
    if (network.empty()) return "file:// needs a path";
  } else if (provider == "tcpq") {
    const std::size_t colon = network.rfind(':');
    if (!network.empty() &&
        (colon == std::string_view::npos || !whole_number(network.substr(colon + 1), 1, 65535))) {
      return "expected HOST:PORT, got '" + std::string(network) + "'";
    }
  } else if (provider != "memq") {
    return "unknown provider '" + std::string(provider) +
           "' (liblcm has udpm, mpudpm, memq, file, tcpq)";
  }
  if (query == std::string_view::npos) return "";
  for (const std::string_view pair : split(rest.substr(query + 1), '&')) {
    if (pair.empty()) continue;
    const std::size_t eq = pair.find('=');
    if (eq == std::string_view::npos) return "option '" + std::string(pair) + "' needs a value";
    if (std::string problem = option_problem(provider, pair.substr(0, eq), pair.substr(eq + 1));
        !problem.empty()) {
      return problem;
    }
  }
  return "";
}

}  // namespace vsl::runtime

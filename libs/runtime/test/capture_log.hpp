// A logger whose lines the test can read.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "vsl/runtime/logger.hpp"

namespace vsl::runtime::testing {

struct CaptureLog {
  std::shared_ptr<std::vector<std::string>> lines = std::make_shared<std::vector<std::string>>();

  Logger logger(const std::string& process = "test", Level level = Level::kDebug) const {
    return Logger(process, level,
                  [lines = lines](std::string_view line) { lines->emplace_back(line); });
  }
  // Lines containing `text`.
  int count(const std::string& text) const {
    int n = 0;
    for (const std::string& line : *lines) n += line.find(text) != std::string::npos ? 1 : 0;
    return n;
  }
  std::string all() const {
    std::string out;
    for (const std::string& line : *lines) out += line;
    return out;
  }
};

}  // namespace vsl::runtime::testing

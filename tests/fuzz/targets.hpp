// What vsl-fuzz feeds: every YAML loader and every LCM decode-and-validate path, each with the
// inputs its mutations start from.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace vsl::fuzz {

struct Target {
  std::string name;
  std::vector<std::string> seeds;  // valid inputs (file texts or encoded messages)
  // Runs the loader or decoder on one input. Rejecting it with config::Error (or a decode
  // failure) is the expected outcome; any other exception, a crash or a hang is a finding.
  std::function<void(const std::string& input)> run;
};

// Seeds come from the shipped files under `source_dir` where there are any.
std::vector<Target> all_targets(const std::string& source_dir);

}  // namespace vsl::fuzz

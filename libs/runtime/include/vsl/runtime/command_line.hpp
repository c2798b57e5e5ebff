// The command line every daemon shares:
//   <name> [--config FILE] [--lcm-url URL] [--help]
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace vsl::runtime {

struct ProgramInfo {
  std::string name;         // "vsl-fusion"
  std::string description;  // one paragraph for --help
  bool config_required = false;
};

struct CommandLine {
  std::optional<std::string> config_path;  // --config FILE
  std::optional<std::string> lcm_url;      // --lcm-url URL, overrides runtime.lcm_url
  bool help = false;                       // --help, -h
};

// A bad command line; what() is the one-line message.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Accepts "--opt VALUE" and "--opt=VALUE". Throws UsageError.
CommandLine parse_command_line(int argc, const char* const* argv);
// The --help text.
std::string usage(const ProgramInfo& program);

}  // namespace vsl::runtime

#include "vsl/runtime/command_line.hpp"

#include "vsl/runtime/lcm_url.hpp"

#include <string_view>

#include "vsl/runtime/config.hpp"

namespace vsl::runtime {

namespace {

// "--name VALUE" or "--name=VALUE" at argv[i]; advances i past the value.
std::optional<std::string> option_value(std::string_view name, int argc, const char* const* argv,
                                        int& i) {
  const std::string_view arg = argv[i];
  if (arg == name) {
    if (i + 1 >= argc) throw UsageError("option " + std::string(name) + " needs a value");
    return std::string(argv[++i]);
  }
  if (arg.size() > name.size() && arg.substr(0, name.size()) == name && arg[name.size()] == '=') {
    return std::string(arg.substr(name.size() + 1));
  }
  return std::nullopt;
}

}  // namespace

CommandLine parse_command_line(int argc, const char* const* argv) {
  CommandLine out;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      out.help = true;
    } else if (auto config = option_value("--config", argc, argv, i)) {
      if (config->empty()) throw UsageError("option --config needs a file name");
      out.config_path = std::move(config);
    } else if (auto url = option_value("--lcm-url", argc, argv, i)) {
      if (url->find("://") == std::string::npos) {
        throw UsageError("option --lcm-url: expected an LCM URL such as " +
                         std::string(kDefaultLcmUrl) + ", got '" + *url + "'");
      }
      if (const std::string problem = lcm_url_problem(*url); !problem.empty()) {
        throw UsageError("option --lcm-url '" + *url + "': " + problem);
      }
      out.lcm_url = std::move(url);
    } else if (arg.rfind("-", 0) == 0) {
      throw UsageError("unknown option '" + std::string(arg) + "'");
    } else {
      throw UsageError("unexpected argument '" + std::string(arg) + "'");
    }
  }
  return out;
}

std::string usage(const ProgramInfo& program) {
  std::string text = "Usage: " + program.name +
                     (program.config_required ? " --config FILE" : " [--config FILE]") +
                     " [--lcm-url URL]\n\n";
  if (!program.description.empty()) text += program.description + "\n\n";
  text +=
      "Options:\n"
      "  --config FILE  YAML configuration. Its runtime: section sets lcm_url,\n"
      "                 heartbeat_period_s, log_level (debug|info|warn|error) and channels\n"
      "                 (overrides of the default channel names).\n"
      "  --lcm-url URL  LCM URL, overriding runtime.lcm_url (default " +
      std::string(kDefaultLcmUrl) +
      ").\n"
      "                 Replay a log with file:///path/to/log?speed=1; memq:// stays in-process.\n"
      "  -h, --help     Print this text.\n\n"
      "SIGINT or SIGTERM shuts down cleanly (exit code 0). Exit code 2: bad command line or\n"
      "configuration; 1: any other failure.\n";
  return text;
}

}  // namespace vsl::runtime

#include "command_line.hpp"

#include <cmath>
#include <optional>
#include <string_view>

#include "realism_config.hpp"
#include "vsl/runtime/command_line.hpp"

namespace vsl::sim_head {
namespace {

using runtime::UsageError;

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

std::array<double, 4> parse_pose(const std::string& text) {
  std::array<double, 4> out{};
  std::size_t at = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t end = k < 3 ? text.find(',', at) : text.size();
    bool ok = end != std::string::npos && end > at;
    if (ok) {
      const std::string item = text.substr(at, end - at);
      try {
        std::size_t used = 0;
        out[k] = std::stod(item, &used);
        ok = used == item.size() && std::isfinite(out[k]);
      } catch (const std::exception&) {
        ok = false;
      }
    }
    if (!ok || (k == 3 && text.find(',', at) != std::string::npos)) {
      throw UsageError("option --pose: expected X,Y,Z,YAW_DEG (4 finite numbers), got '" + text +
                       "'");
    }
    at = end + 1;
  }
  return out;
}

}  // namespace

SplitCommandLine split_command_line(int argc, const char* const* argv) {
  SplitCommandLine out;
  if (argc > 0) out.rest.emplace_back(argv[0]);
  for (int i = 1; i < argc; ++i) {
    if (auto world = option_value("--world", argc, argv, i)) {
      if (world->empty()) throw UsageError("option --world needs a file name");
      out.overrides.world_path = std::move(world);
    } else if (auto pose = option_value("--pose", argc, argv, i)) {
      out.overrides.pose = parse_pose(*pose);
    } else if (auto realism = option_value("--realism", argc, argv, i)) {
      out.overrides.realism_level = realism_level_from_name(*realism);
      if (!out.overrides.realism_level) {
        throw UsageError("option --realism: expected off, materials or full, got '" + *realism +
                         "'");
      }
    } else {
      out.rest.emplace_back(argv[i]);
    }
  }
  return out;
}

}  // namespace vsl::sim_head

#include "vsl/runtime/main.hpp"

#include <cstdio>
#include <exception>
#include <optional>

#include "vsl/config/node.hpp"
#include "vsl/runtime/config.hpp"

namespace vsl::runtime {

namespace {

void print_line(std::FILE* stream, const std::string& line) {
  std::fputs(line.c_str(), stream);
  std::fputc('\n', stream);
  std::fflush(stream);
}

}  // namespace

int daemon_main(int argc, char** argv, const ProgramInfo& program, const DaemonBody& body) {
  CommandLine command_line;
  try {
    command_line = parse_command_line(argc, argv);
    if (!command_line.help && program.config_required && !command_line.config_path) {
      throw UsageError("option --config FILE is required");
    }
  } catch (const UsageError& e) {
    print_line(stderr, program.name + ": " + e.what() + " (try --help)");
    return 2;
  }
  if (command_line.help) {
    std::fputs(usage(program).c_str(), stdout);
    std::fflush(stdout);
    return 0;
  }

  std::optional<config::Node> config;
  RuntimeConfig runtime_config;
  try {
    config = command_line.config_path ? config::Node::load_file(*command_line.config_path)
                                      : config::Node::load_string("{}", "(no --config)");
    runtime_config = read_runtime_config(*config);
  } catch (const config::Error& e) {
    print_line(stderr, e.what());
    return 2;
  }
  if (command_line.lcm_url) runtime_config.lcm_url = *command_line.lcm_url;

  std::optional<Daemon> daemon;
  try {
    daemon.emplace(program.name, std::move(runtime_config));
  } catch (const std::exception& e) {
    print_line(stderr, program.name + ": " + e.what());
    return 1;
  }
  try {
    return body(*daemon, *config);
  } catch (const config::Error& e) {
    print_line(stderr, e.what());
    return 2;
  } catch (const std::exception& e) {
    daemon->log().error(e.what());
    return 1;
  }
}

}  // namespace vsl::runtime

// Runs a program as a separate process and captures what it printed, for tests of command-line
// tools and daemons.
#pragma once

#include <string>
#include <vector>

namespace vsl::testing {

struct CommandResult {
  int exit_code = -1;  // the exit status, or 128 + signal when killed
  std::string out;     // standard output
  std::string err;     // standard error
};

// Runs argv[0] with the arguments (no shell), waiting at most `timeout_s` seconds before killing
// it.
CommandResult run_command(const std::vector<std::string>& argv, double timeout_s = 60.0);

// Number of lines in `text` (a final line without newline counts).
int line_count(const std::string& text);

}  // namespace vsl::testing

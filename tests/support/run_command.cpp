#include "run_command.hpp"

#include <signal.h>
#include <sys/wait.h>

#include "child_process.hpp"

namespace vsl::testing {

CommandResult run_command(const std::vector<std::string>& argv, double timeout_s) {
  ChildProcess child(argv);
  CommandResult result;
  std::optional<int> status =
      child.wait(std::chrono::milliseconds(static_cast<std::int64_t>(timeout_s * 1000)));
  const bool timed_out = !status;
  if (timed_out) {
    ::kill(child.pid(), SIGKILL);
    status = child.wait(std::chrono::seconds(5));
  }
  result.out = child.out();
  result.err = child.err();
  if (timed_out) result.err += "\n[run_command: killed after timeout]";
  if (status && WIFEXITED(*status)) {
    result.exit_code = WEXITSTATUS(*status);
  } else if (status && WIFSIGNALED(*status)) {
    result.exit_code = 128 + WTERMSIG(*status);
  }
  return result;
}

int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines;
}

}  // namespace vsl::testing

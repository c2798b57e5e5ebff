// A child process for tests: spawned with posix_spawn, stdout and stderr captured through pipes,
// always reaped (killed first if still running when the object goes away), every wait bounded.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace vsl::testing {

class ChildProcess {
 public:
  // argv[0] is the executable's path. Throws std::system_error when it cannot be spawned.
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  // Reads output until stdout contains `text`; false on timeout or when the child exits first.
  bool wait_for_stdout(const std::string& text, std::chrono::milliseconds timeout);
  // Waits for the child to exit and returns its wait status; nullopt on timeout.
  std::optional<int> wait(std::chrono::milliseconds timeout);
  // Reads what the pipes hold now, without waiting (for a look at a running child's output).
  void read_available();
  // Output so far (all of it once wait() returned a status).
  const std::string& out() const { return out_; }
  const std::string& err() const { return err_; }

 private:
  // Reads whatever the pipes hold, waiting at most `timeout_ms` for something to arrive.
  void pump(int timeout_ms);
  bool reap(bool block);

  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
  int out_fd_ = -1;
  int err_fd_ = -1;
  std::string out_;
  std::string err_;
};

}  // namespace vsl::testing

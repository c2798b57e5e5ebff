// Termination signals as a pollable descriptor, without handlers or global state: the signals are
// blocked in the calling thread (threads created afterwards, such as liblcm's, inherit the mask)
// and read from a signalfd. Create it before anything starts threads.
#pragma once

#include <signal.h>

#include <initializer_list>

namespace vsl::runtime {

class SignalFd {
 public:
  // Throws std::system_error.
  explicit SignalFd(std::initializer_list<int> signals);
  ~SignalFd();  // closes the descriptor and restores the previous signal mask
  SignalFd(const SignalFd&) = delete;
  SignalFd& operator=(const SignalFd&) = delete;

  int fd() const { return fd_; }
  // The number of one pending signal, or 0 when none is pending. Never blocks.
  int read_signal();

 private:
  int fd_ = -1;
  sigset_t old_mask_{};
};

}  // namespace vsl::runtime

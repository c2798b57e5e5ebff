// urdfdom (through console_bridge) and sdformat print their complaints to the terminal from
// process-wide loggers. vsl reports a bad file in one line of its own, so while a reader parses,
// this guard keeps their output off the terminal and keeps the first error console_bridge
// reported. One guard at a time: the loggers are global, so the guard holds a mutex.
#pragma once

#include <memory>
#include <string>

namespace vsl::world_import {

class QuietParsers {
 public:
  QuietParsers();
  ~QuietParsers();
  QuietParsers(const QuietParsers&) = delete;
  QuietParsers& operator=(const QuietParsers&) = delete;

  // The first error console_bridge reported since the guard was made, or "".
  const std::string& first_error() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vsl::world_import

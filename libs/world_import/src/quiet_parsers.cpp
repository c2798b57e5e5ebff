#include "quiet_parsers.hpp"

#include <console_bridge/console.h>
#include <sdf/Console.hh>

#include <mutex>

namespace vsl::world_import {
namespace {

std::mutex& parsers_mutex() {
  static std::mutex mutex;
  return mutex;
}

class CapturedLog : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty()) {
      first_error = text;
    }
  }
  std::string first_error;
};

}  // namespace

struct QuietParsers::State {
  std::unique_lock<std::mutex> lock{parsers_mutex()};
  CapturedLog log;
};

QuietParsers::QuietParsers() : state_(std::make_unique<State>()) {
  console_bridge::useOutputHandler(&state_->log);
  sdf::Console::Instance()->SetQuiet(true);
}

QuietParsers::~QuietParsers() {
  sdf::Console::Instance()->SetQuiet(false);
  console_bridge::restorePreviousOutputHandler();
}

const std::string& QuietParsers::first_error() const {
  return state_->log.first_error;
}

}  // namespace vsl::world_import

// A small logger object (there is no global one): one line per message,
//   [2025-01-31T12:00:00.123456Z] [vsl-fusion] INFO fused 12 percepts
// written to stderr with a single write() so that lines from several processes do not interleave.
// Copyable: the bus and the daemon hold copies that share the sink.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace vsl::runtime {

enum class Level { kDebug, kInfo, kWarn, kError };

// "debug", "info", "warn", "error" -> Level; nullopt for anything else.
std::optional<Level> parse_level(std::string_view name);
std::string_view level_name(Level level);  // "DEBUG", "INFO", "WARN", "ERROR"

enum class TimeFormat { kIso, kUtime };  // ISO 8601 UTC with microseconds, or utime

namespace detail {
void append(std::string& out, std::string_view text);
void append(std::string& out, const char* text);
void append(std::string& out, char c);
void append(std::string& out, bool value);
void append_signed(std::string& out, long long value);
void append_unsigned(std::string& out, unsigned long long value);
void append_double(std::string& out, double value);
template <class T>
requires std::is_arithmetic_v<T>
void append(std::string& out, T value) {
  if constexpr (std::is_floating_point_v<T>) {
    append_double(out, static_cast<double>(value));
  } else if constexpr (std::is_signed_v<T>) {
    append_signed(out, value);
  } else {
    append_unsigned(out, value);
  }
}
}  // namespace detail

class Logger {
 public:
  // Receives one complete line, '\n' included.
  using Sink = std::function<void(std::string_view line)>;

  // An empty sink writes to stderr.
  explicit Logger(std::string process, Level level = Level::kInfo, Sink sink = {},
                  TimeFormat time_format = TimeFormat::kIso);

  const std::string& process() const { return process_; }
  Level level() const { return level_; }
  bool enabled(Level level) const { return level >= level_; }

  // Writes one line; newlines inside `message` are escaped so that it stays one line.
  // Warnings and errors are rate-limited per subject (the text before the first ": ", such as
  // a channel name): at most kLinesPerInterval lines per subject in kInterval; the rest are
  // counted and summed up in one line when the interval has passed (flush_suppressed).
  void write(Level level, std::string_view message) const;

  static constexpr int kLinesPerInterval = 5;
  static constexpr std::chrono::seconds kInterval{10};

  // Writes the summary line of every subject whose interval has passed with lines held back
  // ("WARN FUSED_PERCEPTS: 1995 more like this in the last 10 s"); with `all`, of every subject
  // with lines held back (at shutdown). The daemon calls it with each heartbeat.
  void flush_suppressed(bool all = false) const;

  // log.info("fused ", n, " percepts in ", seconds, " s"): the arguments are concatenated (numbers
  // in their shortest exact form) only when the level is enabled.
  template <class... Args>
  void log(Level level, const Args&... args) const {
    if (!enabled(level)) return;
    std::string text;
    (detail::append(text, args), ...);
    write(level, text);
  }
  template <class... Args>
  void debug(const Args&... args) const {
    log(Level::kDebug, args...);
  }
  template <class... Args>
  void info(const Args&... args) const {
    log(Level::kInfo, args...);
  }
  template <class... Args>
  void warn(const Args&... args) const {
    log(Level::kWarn, args...);
  }
  template <class... Args>
  void error(const Args&... args) const {
    log(Level::kError, args...);
  }

 private:
  std::string process_;
  Level level_;
  Sink sink_;
  TimeFormat time_format_;
  struct RateLimit;  // shared by the copies of one logger
  std::shared_ptr<RateLimit> limit_;

  void emit(Level level, std::string_view message) const;
};

}  // namespace vsl::runtime

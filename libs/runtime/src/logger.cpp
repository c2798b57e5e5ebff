#include "vsl/runtime/logger.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <ctime>

#include "vsl/runtime/clock.hpp"

namespace vsl::runtime {

std::optional<Level> parse_level(std::string_view name) {
  if (name == "debug") return Level::kDebug;
  if (name == "info") return Level::kInfo;
  if (name == "warn") return Level::kWarn;
  if (name == "error") return Level::kError;
  return std::nullopt;
}

std::string_view level_name(Level level) {
  switch (level) {
    case Level::kDebug:
      return "DEBUG";
    case Level::kInfo:
      return "INFO";
    case Level::kWarn:
      return "WARN";
    case Level::kError:
      return "ERROR";
  }
  return "?";
}

namespace detail {

void append(std::string& out, std::string_view text) {
  out.append(text);
}
void append(std::string& out, const char* text) {
  out.append(text ? text : "(null)");
}
void append(std::string& out, char c) {
  out.push_back(c);
}
void append(std::string& out, bool value) {
  out.append(value ? "true" : "false");
}

void append_signed(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_unsigned(std::string& out, unsigned long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_double(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace detail

namespace {

void write_stderr(std::string_view line) {
  while (!line.empty()) {
    const ssize_t n = ::write(STDERR_FILENO, line.data(), line.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // nowhere left to complain
    line.remove_prefix(static_cast<std::size_t>(n));
  }
}

void append_time(std::string& out, TimeFormat format) {
  const std::int64_t utime = wall_utime();
  if (format == TimeFormat::kUtime) {
    detail::append_signed(out, utime);
    return;
  }
  const std::time_t seconds = static_cast<std::time_t>(utime / 1000000);
  std::tm parts{};
  gmtime_r(&seconds, &parts);
  char buffer[40];
  const std::size_t n = std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S", &parts);
  out.append(buffer, n);
  // ".uuuuuu": six digits, zero-padded.
  char micros[7] = {'.', '0', '0', '0', '0', '0', '0'};
  std::int64_t rest = utime % 1000000;
  for (int i = 6; i >= 1; --i, rest /= 10) micros[i] = static_cast<char>('0' + rest % 10);
  out.append(micros, sizeof micros);
  out.push_back('Z');
}

}  // namespace

Logger::Logger(std::string process, Level level, Sink sink, TimeFormat time_format)
    : process_(std::move(process)),
      level_(level),
      sink_(std::move(sink)),
      time_format_(time_format) {}

void Logger::write(Level level, std::string_view message) const {
  if (!enabled(level)) return;
  std::string line;
  line.reserve(message.size() + process_.size() + 48);
  line.push_back('[');
  append_time(line, time_format_);
  line.append("] [");
  line.append(process_);
  line.append("] ");
  line.append(level_name(level));
  line.push_back(' ');
  for (const char c : message) {
    if (c == '\n') {
      line.append("\\n");
    } else if (c == '\r') {
      line.append("\\r");
    } else {
      line.push_back(c);
    }
  }
  line.push_back('\n');
  if (sink_) {
    sink_(line);
  } else {
    write_stderr(line);
  }
}

}  // namespace vsl::runtime

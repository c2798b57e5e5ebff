#include "vsl/runtime/logger.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

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

struct Logger::RateLimit {
  struct Subject {
    std::chrono::steady_clock::time_point interval_start;
    int written = 0;
    long long held_back = 0;
    Level level = Level::kWarn;
  };
  std::mutex mutex;
  std::map<std::string, Subject, std::less<>> subjects;
};

Logger::Logger(std::string process, Level level, Sink sink, TimeFormat time_format)
    : process_(std::move(process)),
      level_(level),
      sink_(std::move(sink)),
      time_format_(time_format),
      limit_(std::make_shared<RateLimit>()) {}

void Logger::write(Level level, std::string_view message) const {
  if (!enabled(level)) return;
  if (level >= Level::kWarn) {
    // 2,000 malformed messages must not be 2,000 lines: the subject is what a message is about.
    const std::string_view subject = message.substr(0, message.find(": "));
    const auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(limit_->mutex);
    auto it = limit_->subjects.find(subject);
    if (it == limit_->subjects.end() && limit_->subjects.size() >= 256) {
      // Subjects that vary (a number before the colon) must not grow the table without end.
      std::erase_if(limit_->subjects, [&](const auto& entry) {
        return entry.second.held_back == 0 && now - entry.second.interval_start >= kInterval;
      });
    }
    if (it == limit_->subjects.end()) {
      it = limit_->subjects.emplace(std::string(subject), RateLimit::Subject{now, 0, 0, level})
               .first;
    }
    RateLimit::Subject& state = it->second;
    if (now - state.interval_start >= kInterval) {
      lock.unlock();
      flush_suppressed();
      lock.lock();
      state.interval_start = now;
      state.written = 0;
    }
    if (state.written >= kLinesPerInterval) {
      ++state.held_back;
      state.level = std::max(state.level, level);
      return;
    }
    ++state.written;
  }
  emit(level, message);
}

void Logger::flush_suppressed(bool all) const {
  std::vector<std::pair<Level, std::string>> summaries;
  {
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard lock(limit_->mutex);
    for (auto& [subject, state] : limit_->subjects) {
      if (state.held_back == 0 || (!all && now - state.interval_start < kInterval)) continue;
      const double seconds =
          std::chrono::duration<double>(
              std::min<std::chrono::steady_clock::duration>(now - state.interval_start, kInterval))
              .count();
      std::string line =
          subject + ": " + std::to_string(state.held_back) + " more like this in the last ";
      detail::append_double(line, std::round(seconds * 10.0) / 10.0);
      line += " s (at most " + std::to_string(kLinesPerInterval) + " lines per subject every " +
              std::to_string(kInterval.count()) + " s)";
      summaries.emplace_back(state.level, std::move(line));
      state.held_back = 0;
      state.written = 0;
      state.interval_start = now;
    }
  }
  for (const auto& [level, line] : summaries) emit(level, line);
}

void Logger::emit(Level level, std::string_view message) const {
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

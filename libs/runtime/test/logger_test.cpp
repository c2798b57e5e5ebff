#include "vsl/runtime/logger.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vsl::runtime {
namespace {

// True when `text` matches `pattern`, where '#' stands for one decimal digit.
bool matches(const std::string& text, const std::string& pattern) {
  if (text.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (pattern[i] == '#' ? (text[i] < '0' || text[i] > '9') : text[i] != pattern[i]) return false;
  }
  return true;
}

struct Capture {
  std::shared_ptr<std::vector<std::string>> lines = std::make_shared<std::vector<std::string>>();
  Logger::Sink sink() {
    return [lines = lines](std::string_view line) { lines->emplace_back(line); };
  }
};

TEST(runtime_logger, IsoLineFormat) {
  Capture capture;
  const Logger log("vsl-test", Level::kInfo, capture.sink());
  log.info("fused ", 12, " percepts in ", 0.25, " s, ok=", true, ", id ", std::int64_t{-7},
           ", mode ", 'x');
  ASSERT_EQ(capture.lines->size(), 1u);
  EXPECT_TRUE(matches(capture.lines->front(),
                      "[####-##-##T##:##:##.######Z] [vsl-test] INFO fused 12 percepts in 0.25 s, "
                      "ok=true, id -7, mode x\n"))
      << capture.lines->front();
}

TEST(runtime_logger, UtimeLineFormat) {
  Capture capture;
  const Logger log("p", Level::kDebug, capture.sink(), TimeFormat::kUtime);
  log.warn("careful");
  ASSERT_EQ(capture.lines->size(), 1u);
  EXPECT_TRUE(matches(capture.lines->front(), "[################] [p] WARN careful\n"))
      << capture.lines->front();
}

// 2,000 malformed messages once gave 2,000 warning lines.
TEST(runtime_logger, RepeatedWarningsAreHeldBackAndSummedUp) {
  Capture capture;
  const Logger log("p", Level::kInfo, capture.sink());
  const Logger copy = log;  // the bus's copy shares the count
  for (int i = 0; i < 1000; ++i) {
    log.warn("FUSED_PERCEPTS: cannot decode ", i, " bytes as vsl.fused_percept_list_t");
    copy.warn("FUSED_PERCEPTS: cannot decode ", i, " bytes as vsl.fused_percept_list_t");
  }
  log.warn("PERCEPTS: skipped frame 3");                  // another subject has its own lines
  for (int i = 0; i < 10; ++i) log.info("progress ", i);  // information is never held back
  EXPECT_EQ(capture.lines->size(), static_cast<std::size_t>(Logger::kLinesPerInterval + 1 + 10));
  log.flush_suppressed();  // the interval has not passed: nothing yet
  EXPECT_EQ(capture.lines->size(), static_cast<std::size_t>(Logger::kLinesPerInterval + 11));
  log.flush_suppressed(true);
  ASSERT_EQ(capture.lines->size(), static_cast<std::size_t>(Logger::kLinesPerInterval + 12));
  EXPECT_NE(capture.lines->back().find("] WARN FUSED_PERCEPTS: 1995 more like this in the last "),
            std::string::npos)
      << capture.lines->back();
  log.flush_suppressed(true);  // said once
  EXPECT_EQ(capture.lines->size(), static_cast<std::size_t>(Logger::kLinesPerInterval + 12));
}

TEST(runtime_logger, LevelFiltersLowerLevels) {
  Capture capture;
  const Logger log("p", Level::kWarn, capture.sink());
  log.debug("d");
  log.info("i");
  log.warn("w");
  log.error("e");
  ASSERT_EQ(capture.lines->size(), 2u);
  EXPECT_NE(capture.lines->at(0).find("] WARN w\n"), std::string::npos);
  EXPECT_NE(capture.lines->at(1).find("] ERROR e\n"), std::string::npos);
  EXPECT_FALSE(log.enabled(Level::kInfo));
}

TEST(runtime_logger, MessageStaysOneLine) {
  Capture capture;
  const Logger log("p", Level::kInfo, capture.sink());
  log.error("first\nsecond\r");
  ASSERT_EQ(capture.lines->size(), 1u);
  const std::string& line = capture.lines->front();
  EXPECT_NE(line.find("ERROR first\\nsecond\\r\n"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), line.size() - 1);
}

TEST(runtime_logger, ParsesLevelNames) {
  EXPECT_EQ(parse_level("debug"), Level::kDebug);
  EXPECT_EQ(parse_level("info"), Level::kInfo);
  EXPECT_EQ(parse_level("warn"), Level::kWarn);
  EXPECT_EQ(parse_level("error"), Level::kError);
  EXPECT_EQ(parse_level("INFO"), std::nullopt);
  EXPECT_EQ(parse_level("warning"), std::nullopt);
}

}  // namespace
}  // namespace vsl::runtime

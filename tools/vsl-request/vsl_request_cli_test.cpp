// vsl-request's usage errors: one line, exit code 2, nothing sent.
#include <gtest/gtest.h>

#include "run_command.hpp"

namespace {

using vsl::testing::line_count;
using vsl::testing::run_command;

TEST(VslRequestCli, ARequestIdThatDoesNotFitIsAUsageErrorNotClamped) {
  for (const char* id : {"99999999999999999999", "-5", "0", "12x", ""}) {
    const auto result = run_command({VSL_REQUEST_BIN, "--request-id", id, "--timeout", "1"});
    EXPECT_EQ(result.exit_code, 2) << id << ": " << result.err;
    EXPECT_EQ(line_count(result.err), 1) << result.err;
    EXPECT_NE(result.err.find("--request-id"), std::string::npos) << result.err;
  }
}

}  // namespace

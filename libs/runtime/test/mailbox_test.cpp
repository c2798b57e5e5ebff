#include "vsl/runtime/mailbox.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vsl::runtime {
namespace {

Bytes bytes_of(const std::string& text) {
  return Bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

std::string text_of(Bytes bytes) {
  return std::string(bytes.begin(), bytes.end());
}

TEST(runtime_mailbox, EmptyBoxHasNothingToTake) {
  Mailbox box;
  EXPECT_TRUE(box.empty());
  EXPECT_FALSE(box.take([](Bytes, std::int64_t) { FAIL() << "handler called on an empty box"; }));
  EXPECT_EQ(box.superseded(), 0);
}

TEST(runtime_mailbox, KeepsOnlyTheNewestAndCountsTheOthers) {
  Mailbox box;
  EXPECT_FALSE(box.put(bytes_of("first"), 10));
  EXPECT_TRUE(box.put(bytes_of("second"), 20));
  EXPECT_TRUE(box.put(bytes_of("third, longer than the others"), 30));
  EXPECT_EQ(box.superseded(), 2);

  std::vector<std::pair<std::string, std::int64_t>> taken;
  EXPECT_TRUE(box.take(
      [&](Bytes bytes, std::int64_t utime) { taken.emplace_back(text_of(bytes), utime); }));
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_EQ(taken[0].first, "third, longer than the others");
  EXPECT_EQ(taken[0].second, 30);
  EXPECT_TRUE(box.empty());
  EXPECT_FALSE(box.take([](Bytes, std::int64_t) { FAIL() << "taken twice"; }));

  // After a take, the next message supersedes nothing.
  EXPECT_FALSE(box.put(bytes_of("fourth"), 40));
  EXPECT_EQ(box.superseded(), 2);
}

TEST(runtime_mailbox, MessagePutWhileHandlingIsKeptForNextTake) {
  Mailbox box;
  box.put(bytes_of("a"), 1);
  std::string seen;
  box.take([&](Bytes bytes, std::int64_t) {
    box.put(bytes_of("b"), 2);  // arrives while the slow handler runs
    seen = text_of(bytes);      // the bytes being handled are not overwritten
  });
  EXPECT_EQ(seen, "a");
  EXPECT_FALSE(box.empty());
  box.take([&](Bytes bytes, std::int64_t utime) {
    seen = text_of(bytes);
    EXPECT_EQ(utime, 2);
  });
  EXPECT_EQ(seen, "b");
  EXPECT_EQ(box.superseded(), 0);
}

}  // namespace
}  // namespace vsl::runtime

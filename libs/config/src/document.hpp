// The parsed, read-only YAML document behind vsl::config::Node (private to vsl_config).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vsl::config {

struct Document {
  enum class Kind : std::uint8_t { kNull, kScalar, kMap, kSequence };
  static constexpr std::uint32_t kNone = 0xffffffffu;

  struct Entry {
    Kind kind = Kind::kNull;
    std::uint32_t line = 0;         // 1-based line of the node's first character
    std::uint32_t parent = kNone;   // containing map or sequence; kNone for the root
    std::uint32_t slot = 0;         // in a map: the entry index of its key; in a list: position
    std::uint32_t first_child = 0;  // into `children`; maps hold key, value, key, value, ...
    std::uint32_t child_count = 0;  // number of values (pairs for maps)
    std::uint64_t text_offset = 0;  // a scalar's text (or a map key's): text[offset, +length)
    std::uint32_t text_length = 0;
  };

  std::string source;  // file name used in messages
  std::vector<Entry> entries;
  std::string text;  // every scalar's text, back to back: one allocation, not one per scalar
  std::vector<std::uint32_t> children;
  std::uint32_t root = kNone;

  std::string_view scalar(std::uint32_t index) const {
    const Entry& entry = entries[index];
    return std::string_view(text).substr(entry.text_offset, entry.text_length);
  }

  // Parses with libyaml. Throws Error naming source:line for syntax errors and duplicate keys.
  // `first_line` is the line of `text`'s first character in the file (for documents cut out of a
  // multi-document stream).
  static Document parse(std::string_view text, const std::string& source_name,
                        std::uint32_t first_line = 1);
};

}  // namespace vsl::config

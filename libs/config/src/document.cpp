#include "document.hpp"

#include <yaml.h>

#include <algorithm>
#include <memory>
#include <string_view>
#include <unordered_map>

#include "vsl/config/node.hpp"

namespace vsl::config {

// How deeply maps and lists may nest in any file vsl reads (a world file needs about ten).
constexpr std::size_t kMaxNestingDepth = 100;
namespace {

struct ParserDeleter {
  void operator()(yaml_parser_t* parser) const {
    yaml_parser_delete(parser);
    delete parser;
  }
};

struct EventGuard {
  yaml_event_t event{};
  ~EventGuard() { yaml_event_delete(&event); }
};

bool is_plain_null(const yaml_event_t& event, std::string_view text) {
  if (event.data.scalar.style != YAML_PLAIN_SCALAR_STYLE) return false;
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

// A container being filled: its entry, and where its children start in the shared pending stack.
struct Open {
  std::uint32_t entry;
  std::size_t first_pending;
};

// `keys` are the entry indices of one map's keys. Config and world maps are small; the rare big one
// (a material palette) is sorted.
void check_duplicate_keys(const Document& doc, const std::uint32_t* keys, std::size_t count) {
  auto report = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t later = std::max(a, b);
    throw Error(format_error(doc.source, static_cast<int>(doc.entries[later].line),
                             std::string(doc.scalar(later)), "duplicate key"));
  };
  if (count <= 16) {
    for (std::size_t i = 1; i < count; ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (doc.scalar(keys[i]) == doc.scalar(keys[j])) report(keys[j], keys[i]);
      }
    }
    return;
  }
  std::vector<std::uint32_t> sorted(keys, keys + count);
  std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
    return doc.scalar(a) < doc.scalar(b) || (doc.scalar(a) == doc.scalar(b) && a < b);
  });
  for (std::size_t i = 1; i < count; ++i) {
    if (doc.scalar(sorted[i]) == doc.scalar(sorted[i - 1])) report(sorted[i - 1], sorted[i]);
  }
}

// Builds a Document from libyaml's events, one at a time.
class Builder {
 public:
  Builder(Document& doc, std::size_t text_size, std::uint32_t first_line)
      : doc_(doc), first_line_(first_line) {
    doc_.text.reserve(text_size / 2);
  }

  // True at the end of the stream.
  bool on_event(const yaml_event_t& event) {
    switch (event.type) {
      case YAML_STREAM_END_EVENT:
        finish();
        return true;
      case YAML_DOCUMENT_START_EVENT:
        if (document_done_) fail(event, "only one YAML document per file is supported");
        break;
      case YAML_DOCUMENT_END_EVENT:
        document_done_ = true;
        break;
      case YAML_SCALAR_EVENT:
        on_scalar(event);
        break;
      case YAML_ALIAS_EVENT: {
        const auto found = anchors_.find(reinterpret_cast<const char*>(event.data.alias.anchor));
        if (found == anchors_.end()) fail(event, "unknown alias");
        attach(found->second, true);
        break;
      }
      case YAML_SEQUENCE_START_EVENT:
      case YAML_MAPPING_START_EVENT:
        on_container_start(event);
        break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT:
        on_container_end();
        break;
      default:
        break;
    }
    return false;
  }

 private:
  [[noreturn]] void fail(const yaml_event_t& event, const std::string& what) const {
    throw Error(
        format_error(doc_.source, static_cast<int>(event.start_mark.line + first_line_), "", what));
  }

  std::uint32_t new_entry(Document::Kind kind, const yaml_event_t& event) {
    Document::Entry entry;
    entry.kind = kind;
    entry.line = static_cast<std::uint32_t>(event.start_mark.line + first_line_);
    doc_.entries.push_back(std::move(entry));
    return static_cast<std::uint32_t>(doc_.entries.size() - 1);
  }

  void remember_anchor(const yaml_char_t* anchor, std::uint32_t index) {
    if (anchor != nullptr) anchors_[reinterpret_cast<const char*>(anchor)] = index;
  }

  // Adds a finished node to the container on top of the stack (or makes it the root), recording
  // where it sits so that a path can be rebuilt for error messages.
  void attach(std::uint32_t index, bool is_alias) {
    if (stack_.empty()) {
      if (doc_.root == Document::kNone) doc_.root = index;
      return;
    }
    const Open& top = stack_.back();
    const Document::Entry& container = doc_.entries[top.entry];
    const std::size_t seen = pending_.size() - top.first_pending;
    const bool is_map = container.kind == Document::Kind::kMap;
    if (is_map && seen % 2 == 0) {
      // This node is a key: keys must be plain text.
      const Document::Kind kind = doc_.entries[index].kind;
      if (kind != Document::Kind::kScalar && kind != Document::Kind::kNull) {
        throw Error(format_error(doc_.source, static_cast<int>(doc_.entries[index].line), "",
                                 "map keys must be text"));
      }
    }
    if (!is_alias) {
      Document::Entry& entry = doc_.entries[index];
      entry.parent = top.entry;
      entry.slot =
          is_map ? (seen % 2 == 1 ? pending_.back() : index) : static_cast<std::uint32_t>(seen);
    }
    pending_.push_back(index);
  }

  void on_scalar(const yaml_event_t& event) {
    const std::string_view value(reinterpret_cast<const char*>(event.data.scalar.value),
                                 event.data.scalar.length);
    const bool null = is_plain_null(event, value);
    const std::uint32_t index =
        new_entry(null ? Document::Kind::kNull : Document::Kind::kScalar, event);
    doc_.entries[index].text_offset = doc_.text.size();
    doc_.entries[index].text_length = static_cast<std::uint32_t>(value.size());
    doc_.text.append(value);
    remember_anchor(event.data.scalar.anchor, index);
    attach(index, false);
  }

  void on_container_start(const yaml_event_t& event) {
    const bool is_map = event.type == YAML_MAPPING_START_EVENT;
    const std::uint32_t index =
        new_entry(is_map ? Document::Kind::kMap : Document::Kind::kSequence, event);
    remember_anchor(is_map ? event.data.mapping_start.anchor : event.data.sequence_start.anchor,
                    index);
    attach(index, false);
    // No vsl file nests deeper than about ten levels; 100,000 levels once kept the parser busy
    // for more than 30 s. Stop at the limit, before libyaml reads further.
    if (stack_.size() >= kMaxNestingDepth) {
      fail(event, "nested deeper than " + std::to_string(kMaxNestingDepth) + " levels");
    }
    stack_.push_back(Open{index, pending_.size()});
  }

  void on_container_end() {
    const Open top = stack_.back();
    stack_.pop_back();
    const std::size_t count = pending_.size() - top.first_pending;
    Document::Entry& entry = doc_.entries[top.entry];
    const bool is_map = entry.kind == Document::Kind::kMap;
    entry.first_child = static_cast<std::uint32_t>(doc_.children.size());
    entry.child_count = static_cast<std::uint32_t>(is_map ? count / 2 : count);
    doc_.children.insert(doc_.children.end(),
                         pending_.begin() + static_cast<std::ptrdiff_t>(top.first_pending),
                         pending_.end());
    pending_.resize(top.first_pending);
    if (!is_map) return;
    // Keys are every other child.
    std::uint32_t keys_small[16];
    std::vector<std::uint32_t> keys_big;
    std::uint32_t* keys = keys_small;
    if (entry.child_count > 16) {
      keys_big.resize(entry.child_count);
      keys = keys_big.data();
    }
    for (std::uint32_t i = 0; i < entry.child_count; ++i) {
      keys[i] = doc_.children[entry.first_child + 2 * i];
    }
    check_duplicate_keys(doc_, keys, entry.child_count);
  }

  void finish() {
    if (doc_.root != Document::kNone) return;
    // An empty file is an empty document: a null root.
    Document::Entry entry;
    entry.line = first_line_;
    doc_.entries.push_back(entry);
    doc_.root = 0;
  }

  Document& doc_;
  const std::uint32_t first_line_;
  std::vector<Open> stack_;
  // Children of all open containers, innermost last: one buffer instead of a vector per
  // container.
  std::vector<std::uint32_t> pending_;
  std::unordered_map<std::string, std::uint32_t> anchors_;
  bool document_done_ = false;
};

}  // namespace

Document Document::parse(std::string_view text, const std::string& source_name,
                         std::uint32_t first_line) {
  Document doc;
  doc.source = source_name;
  std::unique_ptr<yaml_parser_t, ParserDeleter> parser(new yaml_parser_t);
  if (!yaml_parser_initialize(parser.get())) {
    delete parser.release();
    throw Error(format_error(source_name, 0, "", "cannot initialise the YAML parser"));
  }
  yaml_parser_set_input_string(parser.get(), reinterpret_cast<const unsigned char*>(text.data()),
                               text.size());
  Builder builder(doc, text.size(), first_line);
  while (true) {
    EventGuard guard;
    if (!yaml_parser_parse(parser.get(), &guard.event)) {
      std::string what = "YAML syntax error: ";
      what += parser->problem != nullptr ? parser->problem : "unknown problem";
      if (parser->context != nullptr) what += std::string(" ") + parser->context;
      throw Error(format_error(source_name,
                               static_cast<int>(parser->problem_mark.line + first_line), "", what));
    }
    if (builder.on_event(guard.event)) return doc;
  }
}

}  // namespace vsl::config

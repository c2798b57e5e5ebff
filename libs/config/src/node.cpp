#include "vsl/config/node.hpp"

#include "document.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace vsl::config {
namespace {

// prefix + text + suffix, appended piecewise: GCC 12 warns falsely (-Wrestrict, GCC bug 105651) on
// `"literal" + std::string` once inlined at -O2.
std::string enclosed(std::string_view prefix, std::string_view text, std::string_view suffix = {}) {
  std::string out;
  out.reserve(prefix.size() + text.size() + suffix.size());
  out.append(prefix).append(text).append(suffix);
  return out;
}

}  // namespace

std::string format_error(const std::string& source, int line, const std::string& path,
                         const std::string& what) {
  std::string out = source;
  if (line > 0) out += enclosed(":", std::to_string(line));
  if (!out.empty()) out += ": ";
  if (!path.empty()) out += path + ": ";
  out += what;
  return out;
}

namespace {

std::string join_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

using Kind = Document::Kind;

}  // namespace

Node::Node(std::shared_ptr<const Document> document, std::uint32_t index)
    : document_(std::move(document)), index_(index) {}

namespace {

std::string read_file(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw Error(format_error(path, 0, "", "is a directory, not a file"));
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error(format_error(path, 0, "", "cannot open file"));
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(format_error(path, 0, "", "cannot read file"));
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  if (!in.read(text.data(), static_cast<std::streamsize>(text.size()))) {
    throw Error(format_error(path, 0, "", "cannot read file"));
  }
  return text;
}

// A line that starts a document: `---` followed by a blank or the end of the line. YAML forbids
// such a line inside any node (c-forbidden), so cutting the stream there never splits a node.
bool is_document_marker(std::string_view text, std::size_t at) {
  if (text.compare(at, 3, "---") != 0) return false;
  if (at + 3 == text.size()) return true;
  const char next = text[at + 3];
  return next == ' ' || next == '\t' || next == '\n' || next == '\r';
}

struct Piece {
  std::string_view text;
  std::uint32_t first_line;
};

std::vector<Piece> split_documents(std::string_view text) {
  std::vector<Piece> pieces;
  std::size_t start = 0;
  std::uint32_t start_line = 1, line = 1;
  for (std::size_t at = 0; at < text.size();) {
    if (at != start && is_document_marker(text, at)) {
      pieces.push_back({text.substr(start, at - start), start_line});
      start = at;
      start_line = line;
    }
    const std::size_t newline = text.find('\n', at);
    if (newline == std::string_view::npos) break;
    at = newline + 1;
    ++line;
  }
  pieces.push_back({text.substr(start), start_line});
  return pieces;
}

}  // namespace

Node Node::load_file(const std::string& path) {
  return load_string(read_file(path), path);
}

std::vector<Node> Node::load_file_documents(const std::string& path, unsigned threads) {
  return load_string_documents(read_file(path), path, threads);
}

std::vector<Node> Node::load_string_documents(const std::string& text,
                                              const std::string& source_name, unsigned threads) {
  const std::vector<Piece> pieces = split_documents(text);
  std::vector<std::shared_ptr<const Document>> documents(pieces.size());
  std::vector<std::exception_ptr> errors(pieces.size());
  const std::size_t workers = std::max<std::size_t>(
      1, std::min<std::size_t>(threads ? threads : std::thread::hardware_concurrency(),
                               pieces.size()));
  auto parse_every_nth = [&](std::size_t worker) {
    for (std::size_t k = worker; k < pieces.size(); k += workers) {
      try {
        documents[k] = std::make_shared<const Document>(
            Document::parse(pieces[k].text, source_name, pieces[k].first_line));
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(parse_every_nth, w);
    parse_every_nth(0);
  }
  // The first error in file order is the one reported, whichever thread met it first.
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  std::vector<Node> nodes;
  for (const auto& document : documents) {
    Node node(document, document->root);
    if (!node.is_null()) nodes.push_back(node);
  }
  if (nodes.empty()) nodes.push_back(Node(documents.front(), documents.front()->root));
  return nodes;
}

Node Node::load_string(const std::string& text, const std::string& source_name) {
  auto document = std::make_shared<const Document>(Document::parse(text, source_name));
  const std::uint32_t root = document->root;
  return Node(std::move(document), root);
}

const std::string& Node::source() const {
  return document_->source;
}
int Node::line() const {
  return static_cast<int>(document_->entries[index_].line);
}

std::string Node::path() const {
  // Rebuilt from parent links only when a message needs it: the hot path never pays for it.
  std::vector<std::string> parts;
  std::uint32_t index = index_;
  while (document_->entries[index].parent != Document::kNone) {
    const Document::Entry& entry = document_->entries[index];
    const Document::Entry& parent = document_->entries[entry.parent];
    if (parent.kind == Kind::kMap) {
      parts.push_back(enclosed(".", document_->scalar(entry.slot)));
    } else {
      parts.push_back(enclosed("[", std::to_string(entry.slot), "]"));
    }
    index = entry.parent;
  }
  std::string out;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) out += *it;
  if (!out.empty() && out.front() == '.') out.erase(0, 1);
  return out;
}

bool Node::is_map() const {
  return document_->entries[index_].kind == Kind::kMap;
}
bool Node::is_sequence() const {
  return document_->entries[index_].kind == Kind::kSequence;
}
bool Node::is_scalar() const {
  return document_->entries[index_].kind == Kind::kScalar;
}
bool Node::is_null() const {
  return document_->entries[index_].kind == Kind::kNull;
}
std::string_view Node::scalar() const {
  return document_->scalar(index_);
}

void Node::fail(const std::string& what) const {
  throw Error(format_error(source(), line(), path(), what));
}

std::string Node::describe_kind() const {
  switch (document_->entries[index_].kind) {
    case Kind::kNull:
      return "nothing";
    case Kind::kMap:
      return "a map";
    case Kind::kSequence:
      return "a list";
    case Kind::kScalar:
      break;
  }
  return enclosed("'", scalar(), "'");
}

void Node::expect_map() const {
  if (!is_map()) fail("expected a map of keys, got " + describe_kind());
}

Node Node::at(const std::string& key) const {
  std::optional<Node> child = find(key);
  if (!child) {
    expect_map();
    throw Error(format_error(source(), line(), join_path(path(), key), "missing required key"));
  }
  return *child;
}

std::optional<Node> Node::find(const std::string& key) const {
  if (is_null()) return std::nullopt;
  expect_map();
  const Document::Entry& entry = document_->entries[index_];
  for (std::uint32_t i = 0; i < entry.child_count; ++i) {
    const std::uint32_t key_index = document_->children[entry.first_child + 2 * i];
    if (document_->scalar(key_index) == key) {
      const std::uint32_t value = document_->children[entry.first_child + 2 * i + 1];
      if (document_->entries[value].kind == Kind::kNull) return std::nullopt;
      return Node(document_, value);
    }
  }
  return std::nullopt;
}

std::vector<std::string> Node::keys() const {
  expect_map();
  const Document::Entry& entry = document_->entries[index_];
  std::vector<std::string> out;
  out.reserve(entry.child_count);
  for (std::uint32_t i = 0; i < entry.child_count; ++i) {
    const std::uint32_t key_index = document_->children[entry.first_child + 2 * i];
    const Document::Entry& key = document_->entries[key_index];
    if (key.kind != Kind::kScalar) {
      throw Error(
          format_error(source(), static_cast<int>(key.line), path(), "map key must be text"));
    }
    out.emplace_back(document_->scalar(key_index));
  }
  return out;
}

void Node::expect_keys(std::initializer_list<const char*> allowed) const {
  if (is_null()) return;
  expect_map();
  const Document::Entry& entry = document_->entries[index_];
  for (std::uint32_t i = 0; i < entry.child_count; ++i) {
    const std::uint32_t key_index = document_->children[entry.first_child + 2 * i];
    const Document::Entry& key_entry = document_->entries[key_index];
    const std::string_view key = document_->scalar(key_index);
    const bool known =
        std::any_of(allowed.begin(), allowed.end(), [&](const char* name) { return key == name; });
    if (!known) {
      std::string list;
      for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      throw Error(format_error(source(), static_cast<int>(key_entry.line),
                               join_path(path(), std::string(key)),
                               "unknown key (allowed: " + list + ")"));
    }
  }
}

std::size_t Node::size() const {
  if (!is_sequence()) fail("expected a list, got " + describe_kind());
  return document_->entries[index_].child_count;
}

Node Node::operator[](std::size_t index) const {
  if (index >= size()) fail("index " + std::to_string(index) + " out of range");
  return Node(document_, document_->children[document_->entries[index_].first_child + index]);
}

double Node::as_double() const {
  if (!is_scalar()) fail("expected a number, got " + describe_kind());
  const std::string_view text = scalar();
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || begin == end) {
    fail("expected a number, got '" + std::string(text) + "'");
  }
  if (!std::isfinite(value)) fail("expected a finite number, got '" + std::string(text) + "'");
  return value;
}

std::int64_t Node::as_int() const {
  if (!is_scalar()) fail("expected an integer, got " + describe_kind());
  const std::string_view text = scalar();
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || text.empty()) {
    fail("expected an integer, got '" + std::string(text) + "'");
  }
  return value;
}

bool Node::as_bool() const {
  if (is_scalar()) {
    const std::string_view text = scalar();
    if (text == "true" || text == "True" || text == "yes" || text == "on") return true;
    if (text == "false" || text == "False" || text == "no" || text == "off") return false;
  }
  fail("expected true or false, got " + describe_kind());
}

std::string Node::as_string() const {
  if (!is_scalar()) fail("expected text, got " + describe_kind());
  return std::string(scalar());
}

std::vector<double> Node::as_doubles() const {
  const std::size_t count = is_sequence() ? size() : 0;
  if (!is_sequence()) fail("expected a list of numbers, got " + describe_kind());
  std::vector<double> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.push_back((*this)[i].as_double());
  return out;
}

std::vector<double> Node::as_doubles_of_size(std::size_t n) const {
  if (!is_sequence()) {
    fail("expected a list of " + std::to_string(n) + " numbers, got " + describe_kind());
  }
  if (size() != n) {
    fail("expected " + std::to_string(n) + " numbers, got " + std::to_string(size()));
  }
  return as_doubles();
}

double Node::as_double_in(double min, double max) const {
  const double value = as_double();
  if (value < min || value > max) {
    std::ostringstream what;
    what << "must be in [" << min << ", " << max << "], got " << value;
    fail(what.str());
  }
  return value;
}

double Node::as_positive_double() const {
  const double value = as_double();
  if (!(value > 0.0)) fail("must be positive, got " + std::string(scalar()));
  return value;
}

double Node::get(const std::string& key, double fallback) const {
  const auto child = find(key);
  return child ? child->as_double() : fallback;
}
std::int64_t Node::get(const std::string& key, std::int64_t fallback) const {
  const auto child = find(key);
  return child ? child->as_int() : fallback;
}
int Node::get(const std::string& key, int fallback) const {
  const auto child = find(key);
  if (!child) return fallback;
  const std::int64_t value = child->as_int();
  if (value < INT32_MIN || value > INT32_MAX) child->fail("integer out of range");
  return static_cast<int>(value);
}
bool Node::get(const std::string& key, bool fallback) const {
  const auto child = find(key);
  return child ? child->as_bool() : fallback;
}
std::string Node::get(const std::string& key, const std::string& fallback) const {
  const auto child = find(key);
  return child ? child->as_string() : fallback;
}
std::string Node::get(const std::string& key, const char* fallback) const {
  return get(key, std::string(fallback));
}

}  // namespace vsl::config

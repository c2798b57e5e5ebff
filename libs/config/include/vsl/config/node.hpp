// Validated reading of YAML files: every error names the file, the line, the key path and what is
// wrong, in one line ("config/worlds/kitchen.yaml:12: objects[3].position: expected 3 numbers,
// got 2"). Used by the world-model loader and by every daemon's configuration.
//
// Parsing is libyaml's (the reference C implementation) into a compact read-only document: a
// 100k-object building (30 MB) parses in about 2 s here, where yaml-cpp took 12.7 s and 2 GB
// (measured on this machine; see docs/ARCHITECTURE.md).
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace vsl::config {

// The one error type of validated input. what() is the whole one-line message.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Document;  // the parsed file, shared by all nodes of it

// A YAML node together with where it came from (file name, key path, line), so that any
// complaint about it can say where. Cheap to copy: a shared document and an index.
class Node {
 public:
  // Parses a whole file. Throws Error for a missing/unreadable file or a YAML syntax error.
  static Node load_file(const std::string& path);
  // Parses text; `source_name` stands in for the file name in messages.
  static Node load_string(const std::string& text, const std::string& source_name);

  // A file that may hold several YAML documents (a stream separated by `---` lines; a big world
  // is written as a header document and chunks of objects). The documents are parsed in parallel
  // on up to `threads` threads (0: one per hardware thread); every node still reports its line in
  // the whole file. Documents holding nothing (only comments) are left out unless all are empty.
  static std::vector<Node> load_file_documents(const std::string& path, unsigned threads = 0);
  static std::vector<Node> load_string_documents(const std::string& text,
                                                 const std::string& source_name,
                                                 unsigned threads = 0);

  const std::string& source() const;
  std::string path() const;  // "objects[3].position", "" for the root
  int line() const;          // 1-based

  bool is_map() const;
  bool is_sequence() const;
  bool is_scalar() const;  // a non-null scalar
  bool is_null() const;    // `~`, `null` or an empty value

  // Map access. `at` requires the key; `find` returns nullopt when the key is absent or null.
  Node at(const std::string& key) const;
  std::optional<Node> find(const std::string& key) const;
  bool has(const std::string& key) const { return find(key).has_value(); }
  std::vector<std::string> keys() const;
  // Rejects keys outside `allowed` (typos must not pass silently), naming the first offender.
  void expect_keys(std::initializer_list<const char*> allowed) const;
  void expect_map() const;

  // Sequence access.
  std::size_t size() const;  // requires a sequence
  Node operator[](std::size_t index) const;

  // Scalars. Numbers must be finite.
  double as_double() const;
  std::int64_t as_int() const;
  bool as_bool() const;
  std::string as_string() const;  // requires a non-empty scalar
  std::vector<double> as_doubles() const;
  template <std::size_t N>
  std::array<double, N> as_array() const {
    const std::vector<double> values = as_doubles_of_size(N);
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = values[i];
    return out;
  }

  // Optional keys with defaults.
  double get(const std::string& key, double fallback) const;
  std::int64_t get(const std::string& key, std::int64_t fallback) const;
  int get(const std::string& key, int fallback) const;
  bool get(const std::string& key, bool fallback) const;
  std::string get(const std::string& key, const std::string& fallback) const;
  std::string get(const std::string& key, const char* fallback) const;

  // Range checks that throw with this node's location.
  double as_double_in(double min, double max) const;
  double as_positive_double() const;

  // Throws Error("<source>:<line>: <path>: <what>").
  [[noreturn]] void fail(const std::string& what) const;

 private:
  Node(std::shared_ptr<const Document> document, std::uint32_t index);
  std::vector<double> as_doubles_of_size(std::size_t n) const;
  std::string describe_kind() const;
  std::string_view scalar() const;

  std::shared_ptr<const Document> document_;
  std::uint32_t index_ = 0;
};

// "<source>:<line>: <path>: <what>" with empty parts left out.
std::string format_error(const std::string& source, int line, const std::string& path,
                         const std::string& what);

}  // namespace vsl::config

// A minimal streaming JSON writer for the command-line tools' --json output (RFC 8259 strings,
// shortest round-trip numbers, non-finite numbers as null).
#pragma once

#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

namespace vsl::tools {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }
  JsonWriter& key(const std::string& name);
  JsonWriter& string(const std::string& value);
  JsonWriter& number(double value);
  JsonWriter& numbers(std::initializer_list<double> values);
  JsonWriter& boolean(bool value);

 private:
  JsonWriter& open(char bracket);
  JsonWriter& close(char bracket);
  void separate();  // a comma before every element but the first of a container
  void raw_string(const std::string& value);

  std::ostream& out_;
  std::vector<bool> first_;  // per open container: nothing written in it yet
  bool after_key_ = false;
};

}  // namespace vsl::tools

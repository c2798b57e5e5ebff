#include "vsl/config/node.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace vsl::config {
namespace {

// Runs `body` and returns the one-line message it throws; fails the test if it does not throw.
template <typename Body>
std::string error_of(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected vsl::config::Error";
  return "";
}

TEST(ConfigNode, ReadsScalarsListsAndMaps) {
  const Node root = Node::load_string(
      "name: kitchen\nrate_hz: 15\nscale: 2.5e-1\nenabled: true\nposition: [1, -2.5, 3]\n"
      "items:\n  - a\n  - b\n",
      "test.yaml");
  EXPECT_EQ(root.at("name").as_string(), "kitchen");
  EXPECT_EQ(root.at("rate_hz").as_int(), 15);
  EXPECT_DOUBLE_EQ(root.at("scale").as_double(), 0.25);
  EXPECT_TRUE(root.at("enabled").as_bool());
  const auto position = root.at("position").as_array<3>();
  EXPECT_DOUBLE_EQ(position[1], -2.5);
  ASSERT_EQ(root.at("items").size(), 2u);
  EXPECT_EQ(root.at("items")[1].as_string(), "b");
  EXPECT_EQ(root.at("items")[1].path(), "items[1]");
  EXPECT_EQ(root.at("items")[1].line(), 8);
  EXPECT_EQ(root.get("missing", 4.0), 4.0);
  EXPECT_EQ(root.get("rate_hz", 1), 15);
  EXPECT_EQ(root.get("name", "x"), "kitchen");
  EXPECT_FALSE(root.has("missing"));
}

TEST(ConfigNode, NullsAndEmptyValuesAreAbsent) {
  const Node root = Node::load_string("a: ~\nb:\nc: null\nd: 'null'\n", "t.yaml");
  EXPECT_FALSE(root.has("a"));
  EXPECT_FALSE(root.has("b"));
  EXPECT_FALSE(root.has("c"));
  EXPECT_EQ(root.at("d").as_string(), "null");  // quoted: text, not null
  EXPECT_TRUE(Node::load_string("", "empty.yaml").is_null());
}

TEST(ConfigNode, ErrorsNameFileLineKeyAndWhat) {
  const Node root = Node::load_string(
      "objects:\n  - id: a\n    position: [1, 2]\n  - id: b\n    position: [1, x, 3]\n", "w.yaml");
  const Node objects = root.at("objects");
  EXPECT_EQ(error_of([&] { objects[0].at("position").as_array<3>(); }),
            "w.yaml:3: objects[0].position: expected 3 numbers, got 2");
  EXPECT_EQ(error_of([&] { objects[1].at("position").as_array<3>(); }),
            "w.yaml:5: objects[1].position[1]: expected a number, got 'x'");
  EXPECT_EQ(error_of([&] { objects[1].at("type"); }),
            "w.yaml:4: objects[1].type: missing required key");
  EXPECT_EQ(error_of([&] { objects[0].expect_keys({"id"}); }),
            "w.yaml:3: objects[0].position: unknown key (allowed: id)");
  EXPECT_EQ(error_of([&] { root.at("objects").as_string(); }),
            "w.yaml:2: objects: expected text, got a list");
}

TEST(ConfigNode, RejectsNonFiniteAndOutOfRange) {
  const Node root = Node::load_string("a: nan\nb: 1e999\nc: -1\nd: 1.5x\n", "r.yaml");
  EXPECT_EQ(error_of([&] { root.at("a").as_double(); }),
            "r.yaml:1: a: expected a finite number, got 'nan'");
  EXPECT_EQ(error_of([&] { root.at("b").as_double(); }),
            "r.yaml:2: b: expected a number, got '1e999'");
  EXPECT_EQ(error_of([&] { root.at("c").as_positive_double(); }),
            "r.yaml:3: c: must be positive, got -1");
  EXPECT_EQ(error_of([&] { root.at("c").as_double_in(0, 1); }),
            "r.yaml:3: c: must be in [0, 1], got -1");
  EXPECT_EQ(error_of([&] { root.at("d").as_int(); }),
            "r.yaml:4: d: expected an integer, got '1.5x'");
}

TEST(ConfigNode, SyntaxErrorsAndDuplicateKeysGiveTheLine) {
  EXPECT_EQ(error_of([] { Node::load_string("a: [1, 2\nb: 3\n", "s.yaml"); }).rfind("s.yaml:", 0),
            0u);
  EXPECT_EQ(error_of([] { Node::load_string("a: 1\nb: 2\na: 3\n", "d.yaml"); }),
            "d.yaml:3: a: duplicate key");
  EXPECT_EQ(error_of([] { Node::load_string("a: 1\n---\nb: 2\n", "m.yaml"); }),
            "m.yaml:2: only one YAML document per file is supported");
}

// 100,000 levels of nesting (600 kB) once kept any loader busy for more than 30 s.
TEST(ConfigNode, DeepNestingStopsAtTheLimit) {
  const std::string deep = "a: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  EXPECT_EQ(error_of([&] { Node::load_string(deep, "deep.yaml"); }),
            "deep.yaml:1: nested deeper than 100 levels");
  EXPECT_EQ(error_of([&] { Node::load_string_documents("a: 1\n---\n" + deep, "deep.yaml", 2); }),
            "deep.yaml:3: nested deeper than 100 levels");
  // A hundred levels are fine.
  const std::string fine = std::string(99, '[') + std::string(99, ']') + "\n";
  EXPECT_TRUE(Node::load_string(fine, "fine.yaml").is_sequence());
}

TEST(ConfigNode, DocumentStreamsKeepFileLines) {
  const std::string text =
      "# header comment only\n---\na: 1\n---\n- x\n- y\n--- # trailing comment\nb: [1, 2]\n"
      "--- \n";
  for (unsigned threads : {1u, 2u, 5u}) {
    const std::vector<Node> documents = Node::load_string_documents(text, "s.yaml", threads);
    ASSERT_EQ(documents.size(), 3u);  // the comment-only and the empty document are left out
    EXPECT_EQ(documents[0].at("a").line(), 3);
    EXPECT_EQ(documents[1][1].as_string(), "y");
    EXPECT_EQ(documents[1][1].line(), 6);
    EXPECT_EQ(documents[2].at("b").line(), 8);
  }
  // A line that merely starts with dashes is not a document marker.
  const auto one = Node::load_string_documents("a: |\n  ---x\nb: 2\n", "t.yaml");
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].at("a").as_string(), "---x\n");
  EXPECT_TRUE(Node::load_string_documents("", "e.yaml")[0].is_null());
  // The first error in file order is reported, whatever thread parsed it.
  EXPECT_EQ(error_of([] {
              Node::load_string_documents("a: [\n---\nb: [\n", "x.yaml", 2);
            }).rfind("x.yaml:2: YAML syntax error", 0),
            0u);
}

TEST(ConfigNode, AliasesResolveToTheAnchoredNode) {
  const Node root = Node::load_string("base: &b [1, 2, 3]\ncopy: *b\n", "a.yaml");
  EXPECT_EQ(root.at("copy").as_array<3>()[2], 3.0);
}

TEST(ConfigNode, MissingFileIsOneLine) {
  EXPECT_EQ(error_of([] { Node::load_file("/nonexistent/vsl.yaml"); }),
            "/nonexistent/vsl.yaml: cannot open file");
  EXPECT_EQ(error_of([] { Node::load_file("/tmp"); }), "/tmp: is a directory, not a file");
}

TEST(ConfigNode, LoadsFromFile) {
  const std::string path = testing::TempDir() + "/vsl_config_node_test.yaml";
  {
    std::ofstream out(path);
    out << "rate: 10\n";
  }
  EXPECT_EQ(Node::load_file(path).at("rate").as_int(), 10);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vsl::config

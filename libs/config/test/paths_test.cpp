#include "vsl/config/paths.hpp"

#include <gtest/gtest.h>

#include "vsl/config/node.hpp"

namespace vsl::config {
namespace {

TEST(PathRelativeToFile, RelativePathsResolveAgainstTheFilesDirectory) {
  const Node root = Node::load_string("world: ../worlds/kitchen.yaml\nabsolute: /etc/./vsl\n",
                                      "/opt/vsl/config/sub/x.yaml");
  EXPECT_EQ(path_relative_to_file(root.at("world")), "/opt/vsl/config/worlds/kitchen.yaml");
  EXPECT_EQ(path_relative_to_file(root.at("absolute")), "/etc/vsl");
}

TEST(PathRelativeToFile, AFileInTheWorkingDirectoryGivesARelativePath) {
  const Node root = Node::load_string("head: heads/armar3.yaml\n", "sim_head.yaml");
  EXPECT_EQ(path_relative_to_file(root.at("head")), "heads/armar3.yaml");
}

}  // namespace
}  // namespace vsl::config

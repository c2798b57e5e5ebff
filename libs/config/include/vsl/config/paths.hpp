// File paths in config files: relative to the file that names them, so that a config works from
// any working directory.
#pragma once

#include <string>

namespace vsl::config {

class Node;

// The path `node` holds (a non-empty string): an absolute one as it is, a relative one resolved
// against the directory of the file the node was read from; both lexically normalized.
std::string path_relative_to_file(const Node& node);

}  // namespace vsl::config

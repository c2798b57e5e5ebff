// Union-find over the indices 0 .. n - 1 (path halving; a set's root is its smallest index, so
// that what is built from the roots does not depend on the order of the unions). Internal to
// vsl_recognition.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace vsl::recognition::detail {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];  // path halving
      i = parent_[i];
    }
    return i;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace vsl::recognition::detail

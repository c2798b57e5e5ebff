// Seeded mutations of a text or a byte string: what a fuzzer tries on a loader. Deterministic for
// a seed, so that a finding reproduces with `vsl-fuzz --target T --seed S --executions N`.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace vsl::fuzz {

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  // 1 to 4 edits of `input`: bit flips, random bytes, insertions and deletions, repeated spans,
  // and tokens that upset parsers (extreme numbers, YAML structure, anchors, huge counts).
  std::string mutate(const std::string& input);

  std::size_t below(std::size_t n) { return n == 0 ? 0 : random_() % n; }

 private:
  std::mt19937_64 random_;
};

}  // namespace vsl::fuzz

// A small seeded random source for scenarios: the same seed gives the same numbers on every
// platform (std:: distributions are implementation-defined, so they are not used), and each part
// of a scenario draws from its own stream so that changing, say, the miss rate does not move the
// sampled poses.
#pragma once

#include <cstddef>
#include <cstdint>

namespace vsl::scenario {

// The independent streams of one scenario.
enum class Stream : std::uint64_t {
  pose = 1,
  noise = 2,
  misses = 3,
  false_positives = 4,
  order = 5,
  active = 6
};

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  // The stream `stream` of scenario `index` under `seed`: a hash of the three, so scenario k is the
  // same whatever the number of scenarios generated with it.
  static Rng for_scenario(std::uint64_t seed, std::uint64_t index, Stream stream);

  std::uint64_t next();                  // splitmix64
  double uniform();                      // [0, 1), 53 random bits
  double uniform(double lo, double hi);  // [lo, hi)
  std::size_t below(std::size_t n);      // [0, n), n > 0
  bool chance(double p) { return uniform() < p; }
  double normal();  // standard normal (Box-Muller)

 private:
  std::uint64_t state_;
};

}  // namespace vsl::scenario

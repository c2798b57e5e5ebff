#include "vsl/scenario/random.hpp"

#include <cmath>
#include <numbers>

namespace vsl::scenario {
namespace {

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

Rng Rng::for_scenario(std::uint64_t seed, std::uint64_t index, Stream stream) {
  const std::uint64_t a = mix(seed + 0x9e3779b97f4a7c15ull);
  const std::uint64_t b = mix(a ^ (index * 0xd1b54a32d192ed03ull + 0x632be59bd9b4e019ull));
  return Rng(mix(b ^ (static_cast<std::uint64_t>(stream) * 0x8cb92ba72f3d8dd7ull)));
}

std::uint64_t Rng::next() {
  return mix(state_ += 0x9e3779b97f4a7c15ull);
}

double Rng::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform();
}

std::size_t Rng::below(std::size_t n) {
  // Multiply-shift keeps the draw unbiased enough for n << 2^32 and identical everywhere.
  return static_cast<std::size_t>((next() >> 32) * static_cast<std::uint64_t>(n) >> 32);
}

double Rng::normal() {
  // 1 - u is in (0, 1], so the logarithm is finite.
  const double u1 = 1.0 - uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace vsl::scenario

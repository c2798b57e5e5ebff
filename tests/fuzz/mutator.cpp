#include "mutator.hpp"

#include <array>

namespace vsl::fuzz {
namespace {

constexpr std::array<const char*, 30> kTokens = {"1e308",       "-1e308",     "nan",
                                                 ".inf",        "-0",         "0",
                                                 "-1",          "4294967296", "9223372036854775808",
                                                 "[",           "]",          "{",
                                                 "}",           ": ",         "- ",
                                                 "\n",          "\n  ",       "&a ",
                                                 "*a",          "~",          "''",
                                                 "\"\\u0000\"", "!!binary ",  "---\n",
                                                 "? ",          ",",          "#",
                                                 "\t",          "true",       "\xff\xfe"};

}  // namespace

std::string Mutator::mutate(const std::string& input) {
  std::string out = input;
  const int edits = 1 + static_cast<int>(below(4));
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = below(out.size() + 1);
    switch (below(8)) {
      case 0:  // flip a bit
        if (!out.empty()) out[at % out.size()] ^= static_cast<char>(1 << below(8));
        break;
      case 1:  // a random byte
        if (!out.empty()) out[at % out.size()] = static_cast<char>(below(256));
        break;
      case 2:  // insert random bytes
        out.insert(at, std::string(1 + below(4), static_cast<char>(below(256))));
        break;
      case 3:  // delete a span
        if (!out.empty()) out.erase(at % out.size(), 1 + below(16));
        break;
      case 4: {  // repeat a span (deep nesting, long lists)
        if (out.empty()) break;
        const std::size_t from = at % out.size();
        const std::string span = out.substr(from, 1 + below(32));
        std::string repeated;
        for (std::size_t n = 1 + below(64); n > 0; --n) repeated += span;
        out.insert(from, repeated);
        break;
      }
      case 5:
      case 6:  // a token parsers dislike
        out.insert(at, kTokens[below(kTokens.size())]);
        break;
      default: {  // replace a number with an extreme one
        const std::size_t digit = out.find_first_of("0123456789", at);
        if (digit == std::string::npos) break;
        const std::size_t end = out.find_first_not_of("0123456789.e-+", digit);
        out.replace(digit, (end == std::string::npos ? out.size() : end) - digit,
                    kTokens[below(9)]);
        break;
      }
    }
    if (out.size() > 1 << 20) out.resize(1 << 20);  // keep inputs to a megabyte
  }
  return out;
}

}  // namespace vsl::fuzz

// vsl-fuzz: a seeded mutation fuzzer of every YAML loader and every LCM decode-and-validate path
// (tests/fuzz/targets.cpp). Each execution mutates one seed; a loader may reject the input with
// config::Error, a decoder may refuse it, anything else is a finding: another exception, a
// crash (the sanitizer build reports it), or one execution slower than --max-ms.
//
//   vsl-fuzz [--target NAME] [--executions N] [--seed S] [--max-ms T] [--source-dir DIR]
//
// tools/test runs a short pass (ctest: vsl_fuzz_short); a long one is on demand, e.g.
//   build-asan/tests/fuzz/vsl-fuzz --executions 1000000
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "mutator.hpp"
#include "targets.hpp"
#include "vsl/config/node.hpp"

namespace {

struct Options {
  std::string target;  // empty: all
  long long executions = 10000;
  unsigned long long seed = 1;
  double max_ms = 2000.0;
  std::string source_dir = VSL_SOURCE_DIR;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-fuzz: " << what
            << " (usage: vsl-fuzz [--target NAME] [--executions N] [--seed S] [--max-ms T] "
               "[--source-dir DIR])\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage_error(arg + " needs a value");
    const std::string value = argv[++i];
    try {
      if (arg == "--target") {
        options.target = value;
      } else if (arg == "--executions") {
        options.executions = std::stoll(value);
      } else if (arg == "--seed") {
        options.seed = std::stoull(value);
      } else if (arg == "--max-ms") {
        options.max_ms = std::stod(value);
      } else if (arg == "--source-dir") {
        options.source_dir = value;
      } else {
        usage_error("unknown option " + arg);
      }
    } catch (const std::logic_error&) {
      usage_error(arg + ": bad value '" + value + "'");
    }
  }
  if (options.executions < 1) usage_error("--executions must be positive");
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  int findings = 0;
  bool matched = false;
  for (const vsl::fuzz::Target& target : vsl::fuzz::all_targets(options.source_dir)) {
    if (!options.target.empty() && target.name != options.target) continue;
    matched = true;
    vsl::fuzz::Mutator mutator(options.seed);
    long long rejected = 0;
    double slowest_ms = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (long long n = 0; n < options.executions; ++n) {
      const std::string& seed = target.seeds[mutator.below(target.seeds.size())];
      const std::string input = n == 0 ? seed : mutator.mutate(seed);
      const auto begin = std::chrono::steady_clock::now();
      try {
        target.run(input);
      } catch (const vsl::config::Error& e) {
        ++rejected;
        if (n == 0) {  // the seed itself must load, or the mutations explore nothing
          ++findings;
          std::fprintf(stderr, "vsl-fuzz: %s: the seed is rejected: %s\n", target.name.c_str(),
                       e.what());
        }
      } catch (const std::exception& e) {
        ++findings;
        std::fprintf(stderr, "vsl-fuzz: %s: execution %lld (seed %llu): %s\n", target.name.c_str(),
                     n, options.seed, e.what());
      }
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
              .count();
      slowest_ms = std::max(slowest_ms, ms);
      if (ms > options.max_ms) {
        ++findings;
        std::fprintf(stderr, "vsl-fuzz: %s: execution %lld (seed %llu) took %.0f ms\n",
                     target.name.c_str(), n, options.seed, ms);
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-24s %10lld executions  %8.0f/s  %5.1f%% rejected  slowest %.1f ms\n",
                target.name.c_str(), options.executions, options.executions / seconds,
                100.0 * static_cast<double>(rejected) / static_cast<double>(options.executions),
                slowest_ms);
  }
  if (!matched) usage_error("no target named '" + options.target + "'");
  std::printf("findings: %d\n", findings);
  return findings == 0 ? 0 : 1;
}

// vsl-worldgen: generate world-model files (a kitchen from a layout, buildings for scaling tests).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/world/world_io.hpp"
#include "vsl/worldgen/building.hpp"
#include "vsl/worldgen/inspect.hpp"
#include "vsl/worldgen/kitchen.hpp"

namespace {

constexpr const char* kUsage = R"(usage: vsl-worldgen kitchen LAYOUT.yaml -o OUT.yaml
       vsl-worldgen building [LAYOUT.yaml] [--objects N] [--seed S] -o OUT.yaml
       vsl-worldgen --help

Generates vsl world-model files (format: docs/world-model.md; generators: docs/worldgen.md).
  kitchen    a kitchen from a short layout (walls, runs of units, windows, table), e.g.
             config/layouts/kitchen.yaml; this is how config/worlds/kitchen.yaml is made
  building   storeys of corridors with furnished rooms, exactly N objects, for scaling tests;
             an optional layout (e.g. config/layouts/building.yaml) sets room sizes and mix
options:
  -o, --output FILE   where to write the world ("-" for standard output); required
  --objects N         building: number of objects (default 1000, or the layout's)
  --seed S            building: random seed (default 1, or the layout's); same seed, same world
  -q, --quiet         no status lines on standard error
exit codes: 0 ok, 2 bad layout or usage
)";

[[noreturn]] void usage_error(const std::string& what) {
  std::cerr << "vsl-worldgen: " << what << " (see vsl-worldgen --help)\n";
  std::exit(2);
}

struct Options {
  std::string command;
  std::optional<std::string> layout;
  std::string output;
  std::optional<std::size_t> objects;
  std::optional<std::uint64_t> seed;
  bool quiet = false;
  std::string command_line;  // as given, for the generated file's header
};

std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t max) {
  std::uint64_t value = 0;
  bool ok = !text.empty() && text.size() <= 19;
  for (char c : text) {
    ok = ok && c >= '0' && c <= '9';
    if (ok) value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (!ok || value > max) {
    usage_error(option + " expects a whole number in [0, " + std::to_string(max) + "], got '" +
                text + "'");
  }
  return value;
}

std::string quoted(const std::string& arg) {
  if (!arg.empty() && arg.find_first_of(" \t'\"\\$") == std::string::npos) return arg;
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

Options parse(int argc, char** argv) {
  Options o;
  o.command_line = "vsl-worldgen";
  for (int i = 1; i < argc; ++i) o.command_line += " " + quoted(argv[i]);
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "-o" || arg == "--output") {
      o.output = value();
    } else if (arg == "--objects") {
      o.objects = parse_count(arg, value(), 10'000'000);
      if (*o.objects == 0) usage_error("--objects must be at least 1");
    } else if (arg == "--seed") {
      o.seed = parse_count(arg, value(), 9'223'372'036'854'775'807ull);
    } else if (arg == "-q" || arg == "--quiet") {
      o.quiet = true;
    } else if (arg.size() > 1 && arg[0] == '-') {
      usage_error("unknown option " + arg);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.empty()) usage_error("expected a command: kitchen or building");
  o.command = positional[0];
  if (o.command == "kitchen") {
    if (positional.size() != 2) usage_error("expected 'kitchen LAYOUT.yaml -o OUT.yaml'");
    if (o.objects || o.seed) usage_error("--objects and --seed are for buildings");
    o.layout = positional[1];
  } else if (o.command == "building") {
    if (positional.size() > 2)
      usage_error("expected 'building [LAYOUT.yaml] [--objects N] [--seed S] -o OUT.yaml'");
    if (positional.size() == 2) o.layout = positional[1];
  } else {
    usage_error("unknown command '" + o.command + "' (kitchen or building)");
  }
  if (o.output.empty()) usage_error("missing -o OUT.yaml");
  return o;
}

// "# " + text, wrapped at about 100 columns on ", ".
void comment(std::ostream& out, const std::string& text) {
  std::string line = "#";
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(", ", start);
    end = end == std::string::npos ? text.size() : end + 2;
    const std::string part = text.substr(start, end - start);
    if (line.size() + 1 + part.size() > 100 && line.size() > 2) {
      while (!line.empty() && line.back() == ' ') line.pop_back();
      out << line << "\n";
      line = "#  ";
    }
    line += (line == "#" ? " " : line.back() == ' ' ? "" : " ") + part;
    start = end;
  }
  out << line << "\n";
}

void write_output(const Options& o, const vsl::world::WorldModel& world, const std::string& what) {
  const vsl::worldgen::WorldCounts counts = vsl::worldgen::count_world(world);
  auto write = [&](std::ostream& out) {
    out << "# Generated by vsl-worldgen (" << what << "): do not edit by hand.\n";
    out << "# Regenerate with:\n";
    out << "#   " << o.command_line << "\n";
    comment(out, vsl::worldgen::describe(counts));
    vsl::world::write_world(world, out);
  };
  if (o.output == "-") {
    write(std::cout);
    std::cout.flush();
    if (!std::cout) throw vsl::config::Error("-: write failed");
    return;
  }
  std::error_code status_error;
  const auto status = std::filesystem::status(o.output, status_error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    // A device or pipe: write straight to it.
    std::ofstream out(o.output, std::ios::binary);
    if (!out) throw vsl::config::Error(o.output + ": cannot open for writing");
    write(out);
    out.flush();
    if (!out) throw vsl::config::Error(o.output + ": write failed");
    return;
  }
  // A regular file: write beside it and rename, so that a failed run never leaves half a file.
  const std::string temporary = o.output + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw vsl::config::Error(o.output + ": cannot open for writing");
    write(out);
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary);
      throw vsl::config::Error(o.output + ": write failed");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, o.output, error);
  if (error) {
    std::filesystem::remove(temporary);
    throw vsl::config::Error(o.output + ": cannot write (" + error.message() + ")");
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const bool tty = !o.quiet && isatty(STDERR_FILENO) != 0;
  try {
    const auto start = std::chrono::steady_clock::now();
    vsl::world::WorldModel world;
    std::string what;
    if (o.command == "kitchen") {
      world = vsl::worldgen::generate_kitchen(vsl::worldgen::load_kitchen_layout(*o.layout));
      what = "kitchen from " + *o.layout;
    } else {
      vsl::worldgen::BuildingOptions options;
      if (o.layout) options = vsl::worldgen::load_building_layout(*o.layout);
      if (o.objects) options.objects = *o.objects;
      if (o.seed) options.seed = *o.seed;
      vsl::worldgen::Progress progress;
      if (tty) {
        progress = [](std::size_t done, std::size_t total) {
          std::fprintf(stderr, "\rvsl-worldgen: generating %zu/%zu objects", done, total);
          std::fflush(stderr);
        };
      }
      world = vsl::worldgen::generate_building(options, progress);
      if (tty) std::fprintf(stderr, "\r\033[K");
      what = "building of " + std::to_string(options.objects) + " objects, seed " +
             std::to_string(options.seed) + (o.layout ? " from " + *o.layout : "");
    }
    const double generate_s = seconds_since(start);
    if (tty && world.objects.size() >= 20000) {
      std::fprintf(stderr, "vsl-worldgen: writing %s", o.output.c_str());
      std::fflush(stderr);
    }
    const auto write_start = std::chrono::steady_clock::now();
    write_output(o, world, what);
    if (tty && world.objects.size() >= 20000) std::fprintf(stderr, "\r\033[K");
    if (!o.quiet) {
      std::string size;
      if (o.output != "-" && std::filesystem::is_regular_file(o.output)) {
        std::error_code error;
        const auto bytes = std::filesystem::file_size(o.output, error);
        if (!error) {
          char text[32];
          std::snprintf(text, sizeof text, ", %.1f MB", static_cast<double>(bytes) / 1e6);
          size = text;
        }
      }
      const vsl::worldgen::WorldCounts counts = vsl::worldgen::count_world(world);
      std::fprintf(stderr,
                   "vsl-worldgen: wrote %s: %zu objects, %zu boxes, %zu cylinders, %zu polyhedra%s "
                   "(generate %.2f s, write %.2f s)\n",
                   o.output.c_str(), counts.objects, counts.boxes, counts.cylinders,
                   counts.polyhedra, size.c_str(), generate_s, seconds_since(write_start));
    }
  } catch (const vsl::config::Error& e) {
    if (tty) std::fprintf(stderr, "\r\033[K");
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}

// vsl-train-detector as a process: a user's labelled images (here a few rendered ones, as
// box-label YAML) fine-tune the shipped model and its box refiner for a few steps; the tool
// writes the ONNX models, the weights and a description with provenance that
// vsl-eval-recognition (C++, OpenCV's dnn) loads and runs; bad input is one line and exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::run_command;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(VSL_BINARY_DIR) / "test-output" / "vsl-train-detector" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VslTrainDetector, FineTunesOnABoxLabelFileAndTheModelRunsInCpp) {
  const fs::path dir = scratch("fine-tune");
  const auto dataset =
      run_command({VSL_MAKE_DATASET_BIN, "--world", "config/worlds/kitchen.yaml", "--views", "6",
                   "--seed", "5", "--realism", "off", "--out", (dir / "data").string(), "-q"},
                  300.0);
  ASSERT_EQ(dataset.exit_code, 0) << dataset.err;
  const auto trained =
      run_command({VSL_TRAIN_DETECTOR, "--labels", (dir / "data" / "labels.yaml").string(), "--out",
                   (dir / "model").string(), "--iterations", "3", "--batch", "2", "--threads", "1",
                   "--refiner-steps", "3", "-q"},
                  600.0);
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  for (const char* file : {"door_handle.onnx", "door_handle.pt", "door_handle.yaml",
                           "box_refiner.onnx", "box_refiner.pt"}) {
    EXPECT_TRUE(fs::exists(dir / "model" / file)) << file;
  }
  const std::string description = read(dir / "model" / "door_handle.yaml");
  for (const char* text : {"model: door_handle.onnx",
                           "min_confidence: {door: ", "refiner:\n    model: box_refiner.onnx",
                           "provenance:", "command: \"vsl-train-detector --labels",
                           "init: \"door_handle.pt\"", "refiner_steps: 3", "held_out:"}) {
    EXPECT_NE(description.find(text), std::string::npos) << text << "\n" << description;
  }
  // 12 images: 2 held out (0.2) for the thresholds.
  EXPECT_NE(description.find("images: {real_or_own: 10, rendered: 0, held_out: 2}"),
            std::string::npos)
      << description;
  const auto evaluated =
      run_command({VSL_EVAL_RECOGNITION_BIN, "--images", (dir / "data" / "images").string(),
                   "--yolo-labels", (dir / "data" / "labels").string(), "--detector",
                   (dir / "model" / "door_handle.yaml").string(), "--json", "-", "-q"},
                  120.0);
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
  EXPECT_NE(evaluated.out.find("\"images\":12"), std::string::npos) << evaluated.out;
  EXPECT_NE(evaluated.out.find("\"type\":\"handle\""), std::string::npos) << evaluated.out;
}

// Every number of the classes' precision-recall curves in vsl-eval-recognition's JSON, in order:
// per detection its confidence, then the precision and recall down to it.
std::vector<double> curve_numbers(const std::string& json) {
  std::vector<double> values;
  for (std::size_t at = json.find("\"curve\":["); at != std::string::npos;
       at = json.find("\"curve\":[", at + 1)) {
    const std::size_t end = json.find("]]", at);
    std::string text = json.substr(at + 9, end == std::string::npos ? 0 : end - at - 9);
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '[' || c == ']' || c == ','; }, ' ');
    std::istringstream in(text);
    for (double v = 0.0; in >> v;) values.push_back(v);
  }
  return values;
}

// A network grown from a smaller one (wider and deeper stride-16 and stride-32 stages, a box per
// class where the smaller one shares one box) computes what the smaller one does until it is
// trained: the same detections with the same confidences, in C++. Narrowed back, it is the
// smaller one again.
TEST(VslTrainDetector, GrowsTheNetworkKeepingWhatItDetects) {
  const fs::path dir = scratch("grow");
  const auto dataset =
      run_command({VSL_MAKE_DATASET_BIN, "--world", "config/worlds/kitchen_galley.yaml", "--views",
                   "6", "--seed", "7", "--out", (dir / "data").string(), "-q"},
                  300.0);
  ASSERT_EQ(dataset.exit_code, 0) << dataset.err;
  // A few steps from random weights: the older shape (128 and 192 channels, a shared box).
  const auto small =
      run_command({VSL_TRAIN_DETECTOR, "--sim", (dir / "data").string(), "--iterations", "20",
                   "--batch", "2", "--threads", "1", "--out", (dir / "small").string(), "-q"},
                  600.0);
  ASSERT_EQ(small.exit_code, 0) << small.err;
  const auto grown =
      run_command({VSL_TRAIN_DETECTOR, "--labels", (dir / "data" / "labels.yaml").string(),
                   "--init", (dir / "small" / "door_handle.pt").string(), "--deep", "192,256",
                   "--deep-blocks", "4,3", "--box-per-class", "--iterations", "0", "--threads", "1",
                   "--out", (dir / "grown").string(), "-q"},
                  600.0);
  ASSERT_EQ(grown.exit_code, 0) << grown.err;
  EXPECT_NE(read(dir / "grown" / "door_handle.yaml")
                .find("architecture: {deep: [192, 256], deep_blocks: [4, 3], box_per_class: true}"),
            std::string::npos);
  EXPECT_GT(fs::file_size(dir / "grown" / "door_handle.onnx"),
            fs::file_size(dir / "small" / "door_handle.onnx"));
  // Narrowed back to the small network's channels (its blocks kept), the grown one drops the
  // channels it added, which nothing reads yet (detector_prune.py), and detects as the small one.
  const auto narrowed = run_command(
      {VSL_TRAIN_DETECTOR, "--labels", (dir / "data" / "labels.yaml").string(), "--init",
       (dir / "grown" / "door_handle.pt").string(), "--deep", "128,192", "--iterations", "0",
       "--threads", "1", "--out", (dir / "narrowed").string(), "-q"},
      600.0);
  ASSERT_EQ(narrowed.exit_code, 0) << narrowed.err;
  EXPECT_NE(read(dir / "narrowed" / "door_handle.yaml")
                .find("architecture: {deep: [128, 192], deep_blocks: [4, 3], box_per_class: true}"),
            std::string::npos);
  std::vector<std::vector<double>> curves;
  for (const char* model : {"small", "grown", "narrowed"}) {
    const auto evaluated =
        run_command({VSL_EVAL_RECOGNITION_BIN, "--images", (dir / "data" / "images").string(),
                     "--yolo-labels", (dir / "data" / "labels").string(), "--detector",
                     (dir / model / "door_handle.yaml").string(), "--json", "-", "-q"},
                    120.0);
    ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
    curves.push_back(curve_numbers(evaluated.out));
  }
  ASSERT_GT(curves[0].size(), 30u);  // detections to compare: at least ten
  for (std::size_t model = 1; model < curves.size(); ++model) {
    ASSERT_EQ(curves[model].size(), curves[0].size()) << "model " << model;
    for (std::size_t i = 0; i < curves[0].size(); ++i) {
      ASSERT_NEAR(curves[model][i], curves[0][i], 1e-4) << "model " << model << ", number " << i;
    }
  }
  // Fewer blocks than the weights' are one line, exit code 2.
  const auto shrink = [&](const std::string& option, const std::string& value) {
    return run_command({VSL_TRAIN_DETECTOR, "--labels", (dir / "data" / "labels.yaml").string(),
                        "--init", (dir / "grown" / "door_handle.pt").string(), option, value,
                        "--iterations", "0", "--out", (dir / "shrunk").string()},
                       600.0);
  };
  const auto fewer = shrink("--deep-blocks", "3,2");
  EXPECT_EQ(fewer.exit_code, 2);
  EXPECT_NE(fewer.err.find("not in the network"), std::string::npos) << fewer.err;
}

TEST(VslTrainDetector, BadInputIsOneLineAndExitCodeTwo) {
  const fs::path dir = scratch("bad");
  const auto missing = run_command(
      {VSL_TRAIN_DETECTOR, "--labels", "no/such/labels.yaml", "--out", (dir / "m").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "vsl-train-detector: no/such/labels.yaml: no such file or folder\n");
  fs::create_directories(dir);
  std::ofstream(dir / "broken.yaml") << "images: [{boxes: []}]\n";
  const auto broken = run_command({VSL_TRAIN_DETECTOR, "--labels", (dir / "broken.yaml").string(),
                                   "--out", (dir / "m").string()});
  EXPECT_EQ(broken.exit_code, 2);
  EXPECT_NE(broken.err.find("broken.yaml: images[0]: expected a map with 'image'"),
            std::string::npos)
      << broken.err;
  const auto usage = run_command({VSL_TRAIN_DETECTOR, "--out", (dir / "m").string()});
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_NE(usage.err.find("no training data"), std::string::npos) << usage.err;
  const auto input = run_command({VSL_TRAIN_DETECTOR, "--sim", dir.string(), "--input", "300x200",
                                  "--out", (dir / "m").string()});
  EXPECT_EQ(input.exit_code, 2);
  EXPECT_NE(input.err.find("multiples of 32"), std::string::npos) << input.err;
  const auto stop = run_command({VSL_TRAIN_DETECTOR, "--sim", dir.string(), "--iterations", "10",
                                 "--stop-after", "11", "--out", (dir / "m").string()});
  EXPECT_EQ(stop.exit_code, 2);
  EXPECT_NE(stop.err.find("--stop-after must be in [1, --iterations]"), std::string::npos)
      << stop.err;
  const auto deep = run_command(
      {VSL_TRAIN_DETECTOR, "--sim", dir.string(), "--deep", "192", "--out", (dir / "m").string()});
  EXPECT_EQ(deep.exit_code, 2);
  EXPECT_NE(deep.err.find("--deep: '192' is not two positive integers A,B"), std::string::npos)
      << deep.err;
  const auto refiner = run_command({VSL_TRAIN_DETECTOR, "--sim", dir.string(), "--no-refiner",
                                    "--refiner-steps", "5", "--out", (dir / "m").string()});
  EXPECT_EQ(refiner.exit_code, 2);
  EXPECT_NE(refiner.err.find("--no-refiner and --refiner-steps exclude each other"),
            std::string::npos)
      << refiner.err;
}

// The training layouts' variants: each one a layout vsl-worldgen generates, the same files for the
// same seed, and together more than one door style and handle kind.
TEST(LayoutVariants, WritesLayoutsTheGeneratorMakesDeterministically) {
  const fs::path dir = scratch("variants");
  const auto written =
      run_command({VSL_LAYOUT_VARIANTS, "--per-layout", "6", "--seed", "3", "--out",
                   (dir / "a").string(), "-q", "config/layouts/kitchen.yaml"});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const auto again = run_command({VSL_LAYOUT_VARIANTS, "--per-layout", "6", "--seed", "3", "--out",
                                  (dir / "b").string(), "-q", "config/layouts/kitchen.yaml"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  std::string styles, kinds;
  for (int k = 0; k < 6; ++k) {
    const std::string name = "kitchen_v" + std::to_string(k) + ".yaml";
    const std::string layout = read(dir / "a" / name);
    EXPECT_EQ(layout, read(dir / "b" / name)) << name;
    const auto generated = run_command({VSL_WORLDGEN_BIN, "kitchen", (dir / "a" / name).string(),
                                        "-o", (dir / ("world_" + name)).string(), "-q"});
    EXPECT_EQ(generated.exit_code, 0) << name << ": " << generated.err;
    const auto style = layout.find("doors: {style: ");
    const auto kind = layout.find("handles: {kind: ");
    ASSERT_NE(style, std::string::npos) << layout;
    ASSERT_NE(kind, std::string::npos) << layout;
    if (styles.find(layout.substr(style + 15, 4)) == std::string::npos)
      styles += layout.substr(style + 15, 4) + " ";
    if (kinds.find(layout.substr(kind + 16, 4)) == std::string::npos)
      kinds += layout.substr(kind + 16, 4) + " ";
  }
  EXPECT_GE(styles.size(), 10u) << styles;  // at least two of slab, shaker, glass, framed
  EXPECT_GE(kinds.size(), 10u) << kinds;    // at least two of bar, knob, cup_pull, rail
  const auto bad =
      run_command({VSL_LAYOUT_VARIANTS, "--out", (dir / "c").string(), "no/such/layout.yaml"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no/such/layout.yaml"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// --colours: each variant also draws its palette, and the generator takes it (the kitchen's own
// colours: entry is replaced by materials).
TEST(LayoutVariants, ColoursDrawsEachVariantsPalette) {
  const fs::path dir = scratch("variant-colours");
  const auto written =
      run_command({VSL_LAYOUT_VARIANTS, "--per-layout", "2", "--seed", "7", "--colours", "--out",
                   dir.string(), "-q", "config/layouts/kitchen.yaml"});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  std::string doors;
  for (int k = 0; k < 2; ++k) {
    const std::string name = "kitchen_v" + std::to_string(k) + ".yaml";
    const std::string layout = read(dir / name);
    EXPECT_EQ(layout.find("\ncolours:"), std::string::npos) << layout;
    for (const char* material : {"door", "handle", "carcass", "wall", "countertop", "floor"}) {
      EXPECT_NE(layout.find("  " + std::string(material) + ": {colour: '#"), std::string::npos)
          << material << "\n"
          << layout;
    }
    const auto door = layout.find("  door: {colour: '#");
    if (door != std::string::npos) doors += layout.substr(door + 19, 6) + " ";
    const auto generated = run_command({VSL_WORLDGEN_BIN, "kitchen", (dir / name).string(), "-o",
                                        (dir / ("world_" + name)).string(), "-q"});
    EXPECT_EQ(generated.exit_code, 0) << name << ": " << generated.err;
  }
  ASSERT_EQ(doors.size(), 14u) << doors;
  EXPECT_NE(doors.substr(0, 6), doors.substr(7, 6)) << doors;   // two palettes
  EXPECT_EQ(doors.find("2f5f8f"), std::string::npos) << doors;  // not the kitchen's blue
}

}  // namespace

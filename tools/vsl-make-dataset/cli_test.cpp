// vsl-make-dataset as a process: labels that agree with the written id images, well-formed YOLO
// files, DoorDetect classes, truncation at the border, the same files whatever the thread count,
// one-line errors.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "run_command.hpp"
#include "vsl/recognition/box_labels.hpp"
#include "vsl/world/world_io.hpp"

namespace {

namespace fs = std::filesystem;
using vsl::testing::run_command;

constexpr const char* kKitchen = "config/worlds/kitchen.yaml";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(VSL_BINARY_DIR) / "test-output" / "vsl-make-dataset" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// FNV-1a of every file under `dir`, by relative path.
std::map<std::string, std::uint64_t> file_hashes(const fs::path& dir) {
  std::map<std::string, std::uint64_t> hashes;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const char c : read(entry.path())) {
      hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    }
    hashes[fs::relative(entry.path(), dir).string()] = hash;
  }
  return hashes;
}

vsl::testing::CommandResult make_dataset(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), VSL_MAKE_DATASET_BIN);
  return run_command(arguments, 300.0);
}

// Whether object `index` is `labelled` or one of its descendants, by the world's parent ids.
bool in_visible_part(const vsl::world::WorldModel& world, std::size_t index, std::size_t labelled) {
  for (std::size_t steps = 0; steps <= world.objects.size(); ++steps) {
    if (index == labelled) return true;
    const std::string& parent = world.objects[index].parent_id;
    if (parent.empty()) return false;
    index = *world.find(parent);
  }
  return false;
}

int expected_class(const vsl::world::WorldModel& world, const vsl::world::ObjectModel& object) {
  if (object.type == "room_door") return 0;
  if (object.type == "handle") return 1;
  const auto parent = world.find(object.parent_id);
  return parent && world.objects[*parent].type == "fridge" ? 3 : 2;
}

// Checks one image's boxes against its id image and its YOLO file; returns the number of boxes.
int check_image(const vsl::world::WorldModel& world, const fs::path& dir,
                const vsl::recognition::LabelledImage& image) {
  const std::string stem = fs::path(image.image_path).stem().string();
  const cv::Mat ids = cv::imread((dir / "ids" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(ids.type(), CV_16U) << stem;
  const cv::Mat depth =
      cv::imread((dir / "depth" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(cv::countNonZero(depth == 0), cv::countNonZero(ids == 0)) << stem;  // nothing: no depth
  std::istringstream yolo(read(dir / "labels" / (stem + ".txt")));
  for (const vsl::recognition::LabelBox& box : image.boxes) {
    const std::size_t labelled = *world.find(box.object_id);
    EXPECT_EQ(box.type, world.objects[labelled].type);
    EXPECT_EQ(box.class_id, expected_class(world, world.objects[labelled])) << box.object_id;
    // The visible part, re-derived from the id image: the object's and its descendants' pixels
    // (clutter, appended to the randomized world, lies beyond the world's objects).
    std::vector<bool> part(world.objects.size());
    for (std::size_t i = 0; i < part.size(); ++i) part[i] = in_visible_part(world, i, labelled);
    int pixels = 0, u_min = ids.cols, v_min = ids.rows, u_max = -1, v_max = -1;
    for (int v = 0; v < ids.rows; ++v) {
      for (int u = 0; u < ids.cols; ++u) {
        const std::size_t id = ids.at<std::uint16_t>(v, u);
        if (id == 0 || id > part.size() || !part[id - 1]) continue;
        ++pixels;
        u_min = std::min(u_min, u), v_min = std::min(v_min, v);
        u_max = std::max(u_max, u), v_max = std::max(v_max, v);
      }
    }
    EXPECT_EQ(box.visible_px, pixels) << stem << " " << box.object_id;
    EXPECT_EQ(cv::Vec4i(box.u_min, box.v_min, box.u_max, box.v_max),
              cv::Vec4i(u_min, v_min, u_max, v_max))
        << stem << " " << box.object_id;
    // What reaches the border is cut by it.
    if (u_min == 0 || v_min == 0 || u_max == ids.cols - 1 || v_max == ids.rows - 1) {
      EXPECT_EQ(box.truncated, true) << stem << " " << box.object_id;
    }
    EXPECT_TRUE(*box.occluded >= 0.0 && *box.occluded <= 0.8) << box.object_id;
    // The YOLO line says the same.
    int class_id = -1;
    double cx = 0, cy = 0, w = 0, h = 0;
    EXPECT_TRUE(yolo >> class_id >> cx >> cy >> w >> h) << stem;
    EXPECT_EQ(class_id, *box.class_id);
    EXPECT_NEAR(cx, (box.u_min + box.u_max + 1) / 2.0 / ids.cols, 1e-6);
    EXPECT_NEAR(cy, (box.v_min + box.v_max + 1) / 2.0 / ids.rows, 1e-6);
    EXPECT_NEAR(w, (box.u_max - box.u_min + 1.0) / ids.cols, 1e-6);
    EXPECT_NEAR(h, (box.v_max - box.v_min + 1.0) / ids.rows, 1e-6);
  }
  std::string rest;
  EXPECT_FALSE(yolo >> rest) << stem << ": more YOLO lines than boxes";
  return static_cast<int>(image.boxes.size());
}

TEST(VslMakeDataset, LabelsAgreeWithTheWrittenIdImages) {
  const fs::path dir = scratch("labels");
  const fs::path preview = dir.string() + "_preview.png";
  const auto result =
      make_dataset({"--world", kKitchen, "--views", "3", "--seed", "4", "--randomize", "--ids",
                    "--depth", "--preview", preview.string(), "--out", dir.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const cv::Mat sheet = cv::imread(preview.string());
  EXPECT_EQ(sheet.size(), cv::Size(3 * 320, 240));  // three left images at half size
  EXPECT_NE(result.err.find("wrote 6 images"), std::string::npos) << result.err;
  EXPECT_EQ(read(dir / "classes.txt"), "door\nhandle\ncabinet door\nrefrigerator door\n");
  const vsl::recognition::BoxLabels labels =
      vsl::recognition::load_box_labels((dir / "labels.yaml").string());
  ASSERT_EQ(labels.images.size(), 6u);
  EXPECT_EQ(fs::path(labels.images[1].image_path).filename(), "view000000_right.jpg");
  const vsl::world::WorldModel world = vsl::world::load_world(kKitchen);
  int boxes = 0;
  for (const auto& image : labels.images) {
    const cv::Mat picture = cv::imread(image.image_path);
    EXPECT_EQ(picture.cols, 640);
    EXPECT_EQ(picture.rows, 480);
    boxes += check_image(world, dir, image);
  }
  EXPECT_GT(boxes, 12);  // the views look at cupboards: doors and handles in every image
}

TEST(VslMakeDataset, TheSameSeedGivesTheSameFilesWhateverTheThreads) {
  const fs::path one = scratch("one_thread"), two = scratch("two_threads"), other = scratch("seed");
  const std::vector<std::string> common{"--world", kKitchen, "--randomize", "--ids", "-q"};
  auto run = [&](const fs::path& dir, const std::string& threads, const std::string& seed,
                 const std::string& views) {
    std::vector<std::string> arguments = common;
    arguments.insert(arguments.end(), {"--views", views, "--threads", threads, "--seed", seed,
                                       "--out", dir.string()});
    const auto result = make_dataset(arguments);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "");  // quiet
  };
  run(one, "1", "9", "3");
  run(two, "2", "9", "3");
  run(other, "2", "10", "1");
  const auto hashes = file_hashes(one);
  EXPECT_EQ(hashes.size(), 3u + 6 * 3);  // classes, dataset, labels; image, YOLO, ids per image
  EXPECT_EQ(hashes, file_hashes(two));
  EXPECT_NE(hashes.at("labels.yaml"), file_hashes(other).at("labels.yaml"));
  EXPECT_NE(hashes.at("images/view000000_left.jpg"),
            file_hashes(other).at("images/view000000_left.jpg"));
}

TEST(VslMakeDataset, ViewsCanShareALook) {
  const fs::path a = scratch("per_look_a"), b = scratch("per_look_b");
  for (const auto& [dir, threads] : {std::pair{a, "1"}, std::pair{b, "2"}}) {
    const auto result =
        make_dataset({"--world", kKitchen, "--views", "3", "--randomize", "--views-per-look", "2",
                      "--threads", threads, "-q", "--out", dir.string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  EXPECT_EQ(vsl::recognition::load_box_labels((a / "labels.yaml").string()).images.size(), 6u);
  EXPECT_EQ(file_hashes(a), file_hashes(b));
}

TEST(VslMakeDataset, WritesPngImagesOfTheWorldAsItIs) {
  const fs::path dir = scratch("png");
  const auto result = make_dataset({"--world", kKitchen, "--views", "2", "--realism", "off",
                                    "--format", "png", "--out", dir.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const cv::Mat image = cv::imread((dir / "images" / "view000001_right.png").string());
  EXPECT_EQ(image.cols, 640);
  const vsl::recognition::BoxLabels labels =
      vsl::recognition::load_box_labels((dir / "labels.yaml").string());
  EXPECT_EQ(labels.images.size(), 4u);
  EXPECT_FALSE(fs::exists(dir / "ids"));
}

TEST(VslMakeDataset, BadUsageExitsTwoWithOneLine) {
  const fs::path dir = scratch("bad");
  fs::create_directories(dir / "full");
  std::ofstream(dir / "full" / "old.txt") << "an older dataset";
  const std::string out = (dir / "out").string();
  const std::vector<std::vector<std::string>> cases{
      {"--views", "2", "--out", out},                       // no --world
      {"--world", kKitchen, "--out", out},                  // no --views
      {"--world", kKitchen, "--views", "2"},                // no --out
      {"--world", kKitchen, "--views", "0", "--out", out},  // no view
      {"--world", kKitchen, "--views", "x", "--out", out},  // not a number
      {"--world", kKitchen, "--views", "2", "--realism", "high", "--out", out},
      {"--world", kKitchen, "--views", "2", "--format", "gif", "--out", out},
      {"--world", kKitchen, "--views", "2", "--max-occluded", "2", "--out", out},
      {"--world", kKitchen, "--views", "2", "--bogus", "--out", out},
      {"--world", "no/such/world.yaml", "--views", "2", "--out", out},
      {"--world", kKitchen, "--views", "2", "--head", "no/such/head.yaml", "--out", out},
      {"--world", kKitchen, "--views", "2", "--out", (dir / "full").string()},  // not empty
  };
  for (const auto& arguments : cases) {
    const auto result = make_dataset(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments[arguments.size() - 2] << "\n" << result.err;
    EXPECT_EQ(vsl::testing::line_count(result.err), 1) << result.err;
  }
  EXPECT_FALSE(fs::exists(out));
  const auto help = make_dataset({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("usage: vsl-make-dataset"), std::string::npos);
}

TEST(VslMakeDataset, UnwritableOutputExitsOne) {
  const fs::path dir = scratch("unwritable");
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "not a directory";
  const auto result = make_dataset(
      {"--world", kKitchen, "--views", "1", "--out", (dir / "file" / "dataset").string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(vsl::testing::line_count(result.err), 1) << result.err;
}

}  // namespace

// One view of the dataset (dataset_view.hpp).
#include "dataset_view.hpp"

#include <time.h>

#include <optional>

#include "dataset_files.hpp"
#include "image_labels.hpp"
#include "label_formats.hpp"
#include "vsl/scenario/random.hpp"
#include "vsl/worldgen/randomize_looks.hpp"

namespace vsl::tools {
namespace {

// No floor clutter within this distance of the robot's centre: its base (0.3 m) and a margin.
constexpr double kRobotClearance_m = 0.5;

// CPU time of the calling thread, so that stage times mean the same on a busy machine.
class StageClock {
 public:
  StageClock() : last_s_(now_s()) {}
  double lap() {
    const double now = now_s();
    const double elapsed = now - last_s_;
    last_s_ = now;
    return elapsed;
  }

 private:
  static double now_s() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  double last_s_;
};

// Per view camera randomization (--randomize): exposure compensation, daylight (a fifth of the
// views at night), its colour, and the MJPEG quality real UVC drivers vary. Always drawn, so
// that the other draws do not depend on --randomize.
void randomize_camera(render::RealismOptions& realism, scenario::Rng& rng, bool apply) {
  const double exposure_ev = rng.uniform(-1.0, 1.0);
  const double daylight = rng.chance(0.2) ? 0.0 : rng.uniform(0.1, 1.5);
  const double daylight_k = rng.uniform(5000.0, 7500.0);
  const int jpeg_quality = 40 + static_cast<int>(rng.below(56));  // 40-95
  if (!apply) return;
  realism.exposure_compensation_ev = exposure_ev;
  realism.daylight = daylight;
  realism.daylight_colour_temperature_k = daylight_k;
  realism.jpeg_quality = jpeg_quality;
}

// A view's random numbers, drawn from its own stream so that view k is the same whatever the
// number of views, threads or views per look.
struct ViewSeeds {
  std::uint64_t looks = 0, left = 0, right = 0;
  render::RenderOptions render_options;
};

ViewSeeds view_seeds(const DatasetOptions& options, std::uint64_t view) {
  scenario::Rng rng = scenario::Rng::for_scenario(options.seed, view, scenario::Stream::noise);
  ViewSeeds seeds;
  seeds.looks = rng.next();
  seeds.left = rng.next();
  seeds.right = rng.next();
  seeds.render_options = dataset_render_options(options);
  randomize_camera(seeds.render_options.realism, rng, options.randomize);
  return seeds;
}

struct Camera {
  const char* name;
  const head::CameraIntrinsics& intrinsics;
  Eigen::Isometry3d world_T_camera;
  std::uint64_t noise_seed;
};

// Renders, labels and writes one camera's image; returns its labels.yaml entry.
std::string make_image(const DatasetContext& c, const render::Renderer& renderer,
                       const Camera& camera, std::uint64_t view, ViewResult& result,
                       StageClock& clock) {
  render::RenderedImage rendered;
  renderer.render(camera.intrinsics, camera.world_T_camera, camera.noise_seed, rendered);
  result.times.render_s += clock.lap();

  const std::vector<BoxLabel> boxes = label_image(
      c.plan, rendered.object_ids,
      [&](std::size_t label) {
        return c.coverage.cover(label, camera.intrinsics, camera.world_T_camera);
      },
      c.options.filter);
  result.boxes += static_cast<int>(boxes.size());
  const std::string stem = image_stem(view, camera.name);
  const std::string image_name = image_file_name(stem, c.options);
  const std::string yolo = yolo_text(c.plan, boxes, rendered.image.cols, rendered.image.rows);
  std::string entry = box_label_entry(c.world, c.plan, "images/" + image_name, boxes);
  result.times.labels_s += clock.lap();

  write_image_file(c.out_dir / "images" / image_name, rendered.image, c.options);
  write_text_file(c.out_dir / "labels" / (stem + ".txt"), yolo);
  if (c.options.depth) write_depth_file(c.out_dir / "depth" / (stem + ".png"), rendered.depth_m);
  if (c.options.ids) write_ids_file(c.out_dir / "ids" / (stem + ".png"), rendered.object_ids);
  result.times.write_s += clock.lap();
  return entry;
}

}  // namespace

render::RenderOptions dataset_render_options(const DatasetOptions& options) {
  render::RenderOptions render_options = simulated_camera_options();
  render_options.realism.level = options.realism;
  return render_options;
}

ViewTimes& ViewTimes::operator+=(const ViewTimes& other) {
  looks_s += other.looks_s;
  renderer_s += other.renderer_s;
  render_s += other.render_s;
  labels_s += other.labels_s;
  write_s += other.write_s;
  return *this;
}

std::vector<ViewResult> make_views(const DatasetContext& c, std::uint64_t first,
                                   std::uint64_t count) {
  std::vector<ViewResult> results(count);
  StageClock clock;
  std::vector<ViewSeeds> seeds;
  std::vector<ViewPose> poses;
  for (std::uint64_t k = 0; k < count; ++k) {
    poses.push_back(c.sampler.sample(c.options.seed, first + k));
    seeds.push_back(view_seeds(c.options, first + k));
  }
  // The views share the first view's look and camera settings.
  const render::Renderer* renderer = c.shared_renderer;
  std::optional<render::Renderer> own_renderer;
  if (c.options.randomize) {
    worldgen::LookRandomization looks;
    for (const ViewPose& pose : poses) {
      looks.keep_clear.push_back({pose.world_T_ego.translation().head<2>(), kRobotClearance_m});
    }
    const world::WorldModel world = worldgen::randomize_looks(c.world, seeds[0].looks, looks);
    results[0].times.looks_s = clock.lap();
    own_renderer.emplace(world, seeds[0].render_options);
    renderer = &*own_renderer;
    results[0].times.renderer_s = clock.lap();
  }
  for (std::uint64_t k = 0; k < count; ++k) {
    Eigen::Isometry3d ego_T_left, ego_T_right;
    c.head.ego_T_cameras(poses[k].joints.positions_rad, ego_T_left, ego_T_right);
    const Camera cameras[] = {
        {"left", c.head.calibration().left, poses[k].world_T_ego * ego_T_left, seeds[k].left},
        {"right", c.head.calibration().right, poses[k].world_T_ego * ego_T_right, seeds[k].right}};
    for (const Camera& camera : cameras) {
      results[k].label_entries += make_image(c, *renderer, camera, first + k, results[k], clock);
    }
  }
  return results;
}

}  // namespace vsl::tools

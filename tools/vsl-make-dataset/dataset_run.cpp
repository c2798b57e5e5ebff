// A whole vsl-make-dataset run (dataset_run.hpp).
#include "dataset_run.hpp"

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "dataset_files.hpp"
#include "dataset_view.hpp"
#include "label_formats.hpp"
#include "parallel_views.hpp"
#include "preview_sheet.hpp"
#include "vsl/world/world_io.hpp"

namespace vsl::tools {
namespace {

// Ids images hold index + 1 in 16 bits; randomized clutter adds far fewer objects than this margin.
constexpr std::size_t kMaxObjectsForIds = 65535 - 1000;

// The views look at what gets labelled: cupboard doors, drawer fronts, handles, room doors.
ViewSamplingOptions sampling_options() {
  ViewSamplingOptions options;
  options.target_types = {"door", "drawer_front", "handle", "room_door"};
  return options;
}

std::string labels_yaml(const DatasetOptions& o, const std::vector<ViewResult>& results) {
  std::string text =
      "# Box labels written by vsl-make-dataset (docs/dataset.md); format: "
      "vsl/recognition/box_labels.hpp.\n"
      "# world " +
      o.world_file + ", " + std::to_string(o.views) + " views, seed " + std::to_string(o.seed) +
      (o.randomize ? ", randomized looks" : "") + ", realism " +
      render::realism_level_name(o.realism) +
      ".\n# Corners inclusive (pixel centres at integers); class: 0 door, 1 handle, 2 cabinet "
      "door, 3 refrigerator door;\n# occluded: fraction of the object's in-image pixels other "
      "objects hide; truncated: cut by the image border.\nimages:\n";
  for (const ViewResult& result : results) text += result.label_entries;
  return text;
}

void print_summary(const DatasetOptions& o, const std::vector<ViewResult>& results, double wall_s) {
  ViewTimes total;
  long boxes = 0;
  for (const ViewResult& result : results) {
    total += result.times;
    boxes += result.boxes;
  }
  const double views = static_cast<double>(results.size());
  auto ms = [&](double seconds) { return 1000.0 * seconds / views; };
  std::fprintf(
      stderr,
      "vsl-make-dataset: wrote %zu images with %ld boxes to %s in %.1f s (%.0f images/min); "
      "CPU ms per view: looks %.1f, renderer %.1f, render %.1f, labels %.1f, write %.1f\n",
      2 * results.size(), boxes, o.out_dir.c_str(), wall_s,
      wall_s > 0.0 ? 120.0 * views / wall_s : 0.0, ms(total.looks_s), ms(total.renderer_s),
      ms(total.render_s), ms(total.labels_s), ms(total.write_s));
}

}  // namespace

void run_dataset(const DatasetOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const world::WorldModel world = world::load_world(o.world_file);
  const head::HeadKinematics head = head::HeadKinematics::load(o.head_file);
  if (o.ids && world.objects.size() > kMaxObjectsForIds) {
    throw UsageError("--ids: the world has " + std::to_string(world.objects.size()) +
                     " objects, more than a 16-bit id image holds");
  }
  const ViewSampler sampler(world, head, sampling_options());
  const LabelPlan plan = make_label_plan(world);
  const render::RenderOptions render_options = dataset_render_options(o);
  const render::ObjectCoverage coverage(world, plan.groups, render_options);
  std::optional<render::Renderer> shared_renderer;
  if (!o.randomize) shared_renderer.emplace(world, render_options);

  prepare_output_dir(o.out_dir, o);
  write_text_file(std::filesystem::path(o.out_dir) / "classes.txt", classes_text());
  write_text_file(std::filesystem::path(o.out_dir) / "dataset.yaml", yolo_dataset_yaml());

  const DatasetContext context{
      o,        world, head, sampler, plan, coverage, shared_renderer ? &*shared_renderer : nullptr,
      o.out_dir};
  std::vector<ViewResult> results(o.views);
  ProgressLine progress(o.views, !o.quiet);
  const unsigned threads =
      o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  // One job per look: --views-per-look views that share a randomized world and its renderer.
  const std::uint64_t per_look = o.randomize ? o.views_per_look : 1;
  const std::uint64_t jobs = (o.views + per_look - 1) / per_look;
  run_parallel(
      jobs, static_cast<unsigned>(std::min<std::uint64_t>(threads, jobs)),
      [&](std::uint64_t job) {
        const std::uint64_t first = job * per_look;
        std::vector<ViewResult> made =
            make_views(context, first, std::min(per_look, o.views - first));
        for (std::size_t k = 0; k < made.size(); ++k) results[first + k] = std::move(made[k]);
      },
      [&](std::uint64_t done) { progress.update(std::min(o.views, done * per_look)); },
      std::chrono::milliseconds(500));
  progress.finish();
  write_text_file_atomically(std::filesystem::path(o.out_dir) / "labels.yaml",
                             labels_yaml(o, results));
  if (!o.preview_file.empty()) {
    const cv::Mat sheet =
        preview_sheet((std::filesystem::path(o.out_dir) / "labels.yaml").string());
    write_image_file(o.preview_file, sheet, o);
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet) print_summary(o, results, wall_s);
}

}  // namespace vsl::tools

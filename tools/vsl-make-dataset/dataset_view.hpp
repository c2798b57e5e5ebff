// Views of the dataset (docs/dataset.md): their seeded poses, their look (with --randomize), their
// stereo renderings, the labels of both images and their files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dataset_options.hpp"
#include "label_plan.hpp"
#include "recognition_views.hpp"
#include "vsl/head/head_kinematics.hpp"
#include "vsl/render/object_coverage.hpp"
#include "vsl/render/renderer.hpp"
#include "vsl/world/world_model.hpp"

namespace vsl::tools {

// What every view shares; read-only, so that views run on any thread.
struct DatasetContext {
  const DatasetOptions& options;
  const world::WorldModel& world;
  const head::HeadKinematics& head;
  const ViewSampler& sampler;
  const LabelPlan& plan;
  const render::ObjectCoverage& coverage;             // of the plan's groups
  const render::Renderer* shared_renderer = nullptr;  // without --randomize: one for every view
  std::filesystem::path out_dir;
};

// The render options of the dataset's images: the simulated head's (noise, 2 x 2 area sampling)
// at the chosen realism level.
render::RenderOptions dataset_render_options(const DatasetOptions& options);

// CPU time of a view's stages, seconds.
struct ViewTimes {
  double looks_s = 0.0;     // randomize_looks
  double renderer_s = 0.0;  // Renderer construction (triangulation, light baking)
  double render_s = 0.0;    // the two images
  double labels_s = 0.0;    // boxes from the id buffers, with the unoccluded coverage
  double write_s = 0.0;     // encoding and writing the files

  ViewTimes& operator+=(const ViewTimes& other);
};

struct ViewResult {
  std::string label_entries;  // the two images' items of labels.yaml
  int boxes = 0;
  ViewTimes times;
};

// Makes the views first .. first + count - 1 and writes their files. With --randomize they share
// one look, the first view's (--views-per-look). Deterministic in the seed and the views alone.
// Throws IoError when a file cannot be written.
std::vector<ViewResult> make_views(const DatasetContext& context, std::uint64_t first,
                                   std::uint64_t count);

}  // namespace vsl::tools

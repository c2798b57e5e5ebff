// A whole vsl-make-dataset run (docs/dataset.md): loads the world and head, makes the views in
// parallel and writes the dataset-wide files.
#pragma once

#include "dataset_options.hpp"

namespace vsl::tools {

// Throws UsageError or config::Error (bad usage, world or head: exit 2) and IoError (exit 1).
void run_dataset(const DatasetOptions& options);

}  // namespace vsl::tools

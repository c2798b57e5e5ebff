// A contact sheet of a written dataset, to check its labels at a glance (--preview): the first
// left images with their boxes in the colours of their classes.
#pragma once

#include <opencv2/core/mat.hpp>

#include <string>

namespace vsl::tools {

// Reads `labels_file` (labels.yaml) and draws up to `count` of its left images, `columns` per row,
// each with its boxes (room door red, handle yellow, cabinet door green, fridge door magenta) and
// scaled by `scale`. Throws config::Error for a bad label file and IoError for an unreadable
// image.
cv::Mat preview_sheet(const std::string& labels_file, int count = 6, int columns = 3,
                      double scale = 0.5);

}  // namespace vsl::tools

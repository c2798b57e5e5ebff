// Contact sheet of labelled images (preview_sheet.hpp).
#include "preview_sheet.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <array>
#include <vector>

#include "dataset_files.hpp"
#include "vsl/recognition/box_labels.hpp"

namespace vsl::tools {
namespace {

// BGR per DoorDetect class: door, handle, cabinet door, refrigerator door.
const std::array<cv::Scalar, 4> kClassColours{cv::Scalar(40, 40, 230), cv::Scalar(0, 220, 255),
                                              cv::Scalar(60, 200, 60), cv::Scalar(220, 60, 220)};

cv::Mat labelled(const recognition::LabelledImage& image) {
  cv::Mat picture = cv::imread(image.image_path, cv::IMREAD_COLOR);
  if (picture.empty()) throw IoError("cannot read " + image.image_path);
  for (const recognition::LabelBox& box : image.boxes) {
    const cv::Scalar colour = kClassColours.at(static_cast<std::size_t>(box.class_id.value_or(2)));
    cv::rectangle(picture, cv::Point(box.u_min, box.v_min), cv::Point(box.u_max, box.v_max), colour,
                  2);
  }
  return picture;
}

}  // namespace

cv::Mat preview_sheet(const std::string& labels_file, int count, int columns, double scale) {
  const recognition::BoxLabels labels = recognition::load_box_labels(labels_file);
  std::vector<cv::Mat> tiles;
  for (const recognition::LabelledImage& image : labels.images) {
    if (static_cast<int>(tiles.size()) >= count) break;
    if (image.image_path.find("_left.") == std::string::npos) continue;
    cv::Mat tile;
    cv::resize(labelled(image), tile, cv::Size(), scale, scale, cv::INTER_AREA);
    tiles.push_back(tile);
  }
  if (tiles.empty()) throw IoError("no left image in " + labels_file);
  std::vector<cv::Mat> rows;
  for (std::size_t first = 0; first < tiles.size(); first += static_cast<std::size_t>(columns)) {
    std::vector<cv::Mat> row;
    for (int k = 0; k < columns; ++k) {
      const std::size_t i = first + static_cast<std::size_t>(k);
      row.push_back(i < tiles.size() ? tiles[i] : cv::Mat::zeros(tiles[0].size(), CV_8UC3));
    }
    cv::Mat joined;
    cv::hconcat(row, joined);
    rows.push_back(joined);
  }
  cv::Mat sheet;
  cv::vconcat(rows, sheet);
  return sheet;
}

}  // namespace vsl::tools

// The thin-line barrier (SegmentationOptions::min_line_contrast_rgb, line_bridge_px), computed
// once per image before region growing: the pixels of the faint line that the reveal between two
// flush doors or drawer fronts renders as, which regions neither join nor grow across
// (docs/recognition.md, Segmentation).
#pragma once

namespace cv {
class Mat;
}

namespace vsl::recognition {

struct SegmentationOptions;

// The barrier map (CV_8U, 1 on line pixels) of a CV_8UC3 (BGR) image.
cv::Mat line_barrier(const cv::Mat& bgr, const SegmentationOptions& options);

// The direction of the lines a map's 1-D morphology runs along.
enum class LineDirection { along_rows, along_columns };

// In place on a CV_8U map of 0 and 1: a closing with a line of 2 close_half + 1 pixels, an opening
// with one of 2 open_half + 1 and a dilation with one of 2 dilate_half + 1, all along rows or all
// along columns; the same as cv::morphologyEx (MORPH_CLOSE, MORPH_OPEN) and cv::dilate with those
// rectangles and their default border, computed on the runs of each row or column instead of on
// every pixel (the barrier's line maps are sparse: about ten times faster).
void close_open_dilate(cv::Mat& map, LineDirection direction, int close_half, int open_half,
                       int dilate_half);

}  // namespace vsl::recognition

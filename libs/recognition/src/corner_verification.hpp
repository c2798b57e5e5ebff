// Shi-Tomasi verification of a handle blob (paper §2.1): "two parallel edges meeting at clear
// corners on both ends". Private to vsl_recognition (and its tests).
#pragma once

#include "vsl/recognition/blob.hpp"
#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/handle_recognizer.hpp"

namespace vsl::recognition {

struct CornerVerification {
  bool accepted = false;
  double contrast_grey = 0.0;       // |mean grey inside - mean grey around|, 0..255
  double end_fraction[2] = {0, 0};  // each end's response / an ideal corner's of this contrast
  double side_fraction = 0.0;       // median response along the middle / the weaker end's
};

// Works on the blob's bounding box plus a margin only (the grey conversion and the
// cv::cornerMinEigenVal response of that region of interest), so it costs about as much as the
// blob is large. `axes` = blob_axes(blob); `bgr_image` CV_8UC3. `cut_end` 0 or 1: the image
// border cuts the bar at that end (0 the a_min end, 1 the a_max one): it needs no corner, and the
// sides are compared with the other end's response; -1: both ends are the bar's.
CornerVerification verify_handle_corners(const cv::Mat& bgr_image, const Blob& blob,
                                         const BlobAxes& axes,
                                         const CornerVerificationParameters& parameters,
                                         int cut_end = -1);

}  // namespace vsl::recognition

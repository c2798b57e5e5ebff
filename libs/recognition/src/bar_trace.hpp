// A handle's bar in one image, followed from a detector's box that may hold only a piece of it.
// Internal to vsl_recognition.
//
// Why. A long bar (a rail of 30-60 cm) seen at an angle is boxed by the detector in pieces: on a
// rails layout, 45 of 63 misplaced handle percepts were boxes around part of a rail, placed at
// the piece's middle, 10-50 cm from the bar's. The bar's ends are what both images agree on.
//
// Model. The box and a margin around it (a quarter of its smaller side, at least 3 px) hold the
// bar and its background. Two colours separate them: two-means over the region's colours, started
// from the margin's median colour (background) and from the colour in the box's middle farthest
// from it (the bar). The bar's pixels inside the box give its image line: their centroid c and
// principal direction d (elongated: the major axis' variance at least four times the minor's,
// else it is a knob, not a bar); the minor variance gives the bar's thickness t (t^2 / 12 for a
// strip) and K = t / 2 + 2 px, the distance of the background beside it. Along the line, the
// ridge at a point is how far the colour there stands out from the mean of the colours K px to
// either side, projected on the direction from the background's colour to the bar's (a highlight
// on the bar stands out further, plain background not at all), the largest of three points across
// the line. From c the line is followed each way while the ridge stays above 0.35 of its median
// over the box and the colour there is nearer the bar's than the background's; it ends after
// max(3, K) steps off the bar. The end to a fraction of a pixel: where the ridge falls through half
// its median, between the last step on the bar and the next (colours sampled bilinearly). An end
// is cut when the line leaves the image, or runs `max_length_px` from c, while on the bar.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>

#include "vsl/recognition/learned_detector.hpp"

namespace cv {
class Mat;
}

namespace vsl::recognition::detail {

struct TracedBar {
  // The bar's ends on its centre line (continuous pixels: pixel (u, v) spans [u, u + 1) x
  // [v, v + 1)), in order along the line's direction.
  std::array<Eigen::Vector2d, 2> ends_px;
  std::array<bool, 2> cut{false, false};  // the image border (or the length limit) cuts this end
  double contrast = 0.0;                  // of the bar's colour against the background, L1
};

// The bar in `bgr` (CV_8UC3) boxed by `box` (continuous pixels). nullopt when the box shows no
// bar: its two colours differ by less than `min_contrast` (L1 over the channels, 0 .. 765), the
// bar's pixels are fewer than 6 or not elongated, its ridge's median is below a quarter of
// `min_contrast`, or the box lies outside the image.
std::optional<TracedBar> trace_bar(const cv::Mat& bgr, const BoxDetection& box,
                                   double max_length_px, double min_contrast);

}  // namespace vsl::recognition::detail

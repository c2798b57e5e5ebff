// Following a handle's bar from a box around a piece of it (bar_trace.hpp), on drawn images of
// known bars: the ends to a fraction of a pixel whatever piece the box holds, level or at an angle,
// with highlights along the bar; an end at the border is cut; knobs, faint bars and empty boxes
// give no bar.
#include "../src/bar_trace.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <random>

namespace vsl::recognition::detail {
namespace {

const cv::Scalar kDoor(150, 80, 30);  // BGR: a navy door
const cv::Scalar kBrass(40, 150, 200);

// A door with a bar from a to b (continuous pixels), `thickness` px, anti-aliased, on seeded
// sensor noise; every `highlight_every` px along the bar a short highlight (0: none).
cv::Mat bar_image(const Eigen::Vector2d& a, const Eigen::Vector2d& b, int thickness,
                  const cv::Scalar& bar = kBrass, int highlight_every = 0) {
  cv::Mat image(240, 320, CV_8UC3, kDoor);
  // cv::line takes pixel centres in fixed point (shift 4): continuous p is pixel centre p - 0.5.
  const auto fixed = [](const Eigen::Vector2d& p) {
    return cv::Point(int(std::lround((p.x() - 0.5) * 16)), int(std::lround((p.y() - 0.5) * 16)));
  };
  cv::line(image, fixed(a), fixed(b), bar, thickness, cv::LINE_AA, 4);
  if (highlight_every > 0) {
    const double length = (b - a).norm();
    for (double t = highlight_every; t + 3 < length; t += highlight_every) {
      const Eigen::Vector2d p = a + (b - a) * (t / length);
      const Eigen::Vector2d q = a + (b - a) * ((t + 3) / length);
      cv::line(image, fixed(p), fixed(q), cv::Scalar(230, 240, 245), 1, cv::LINE_AA, 4);
    }
  }
  cv::Mat noise(image.size(), CV_16SC3);
  cv::theRNG().state = 7;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(3));
  cv::Mat out;
  image.convertTo(out, CV_16SC3);
  out += noise;
  out.convertTo(out, CV_8UC3);
  return out;
}

BoxDetection box_around(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double pad_px) {
  BoxDetection box;
  box.type = "handle";
  box.min_px = a.cwiseMin(b) - Eigen::Vector2d(pad_px, pad_px);
  box.max_px = a.cwiseMax(b) + Eigen::Vector2d(pad_px, pad_px);
  return box;
}

// The traced ends, in the order of (a, b).
std::array<Eigen::Vector2d, 2> ends_towards(const TracedBar& bar, const Eigen::Vector2d& a) {
  return (bar.ends_px[0] - a).norm() <= (bar.ends_px[1] - a).norm()
             ? bar.ends_px
             : std::array<Eigen::Vector2d, 2>{bar.ends_px[1], bar.ends_px[0]};
}

TEST(TraceBar, FindsALevelBarsEndsFromABoxAroundAPiece) {
  const Eigen::Vector2d a(60.0, 120.0), b(260.0, 120.0);
  const cv::Mat image = bar_image(a, b, 3);
  // The box holds 60 px of the 200 px bar, off its middle.
  const auto bar = trace_bar(image, box_around({90.0, 120.0}, {150.0, 120.0}, 4.0), 640.0, 60.0);
  ASSERT_TRUE(bar);
  const auto ends = ends_towards(*bar, a);
  // A line drawn from centre to centre with round caps reaches half its thickness beyond them,
  // and its anti-aliasing a little further; the middle, which places the handle, is exact.
  EXPECT_NEAR(ends[0].x(), a.x() - 1.5, 1.0);
  EXPECT_NEAR(ends[1].x(), b.x() + 1.5, 1.0);
  EXPECT_NEAR(0.5 * (ends[0].x() + ends[1].x()), 0.5 * (a.x() + b.x()), 0.2);
  EXPECT_NEAR(ends[0].y(), 120.0, 0.5);
  EXPECT_FALSE(bar->cut[0] || bar->cut[1]);
}

TEST(TraceBar, FollowsABarAtAnAngleThroughHighlights) {
  const Eigen::Vector2d a(50.0, 200.0), b(250.0, 60.0);
  const cv::Mat image = bar_image(a, b, 3, kBrass, 12);
  const Eigen::Vector2d piece_from = a + 0.55 * (b - a), piece_to = a + 0.75 * (b - a);
  const auto bar = trace_bar(image, box_around(piece_from, piece_to, 3.0), 640.0, 60.0);
  ASSERT_TRUE(bar);
  const auto ends = ends_towards(*bar, a);
  const Eigen::Vector2d along = (b - a).normalized();
  EXPECT_NEAR((ends[0] - a).dot(along), -1.5, 1.0);
  EXPECT_NEAR((ends[1] - b).dot(along), 1.5, 1.0);
  EXPECT_NEAR((0.5 * (ends[0] + ends[1]) - 0.5 * (a + b)).dot(along), 0.0, 0.3);
  // On the bar's line across it.
  const Eigen::Vector2d across(-along.y(), along.x());
  EXPECT_NEAR((ends[0] - a).dot(across), 0.0, 0.7);
  EXPECT_NEAR((ends[1] - b).dot(across), 0.0, 0.7);
}

TEST(TraceBar, AnEndAtTheImageBorderIsCut) {
  const Eigen::Vector2d a(-40.0, 100.0), b(180.0, 100.0);
  const cv::Mat image = bar_image(a, b, 3);
  const auto bar = trace_bar(image, box_around({100.0, 100.0}, {160.0, 100.0}, 4.0), 640.0, 60.0);
  ASSERT_TRUE(bar);
  const auto ends = ends_towards(*bar, a);
  const bool a_first = (bar->ends_px[0] - a).norm() <= (bar->ends_px[1] - a).norm();
  EXPECT_TRUE(bar->cut[a_first ? 0 : 1]);
  EXPECT_FALSE(bar->cut[a_first ? 1 : 0]);
  EXPECT_NEAR(ends[1].x(), b.x() + 1.5, 1.0);
}

TEST(TraceBar, KnobsFaintBarsAndEmptyBoxesGiveNoBar) {
  // A knob: a disc, not elongated.
  cv::Mat knob(240, 320, CV_8UC3, kDoor);
  cv::circle(knob, cv::Point(160, 120), 6, kBrass, cv::FILLED, cv::LINE_AA);
  EXPECT_FALSE(trace_bar(knob, box_around({150.0, 110.0}, {170.0, 130.0}, 2.0), 640.0, 60.0));
  // A bar of nearly the door's colour.
  const cv::Mat faint = bar_image({60.0, 120.0}, {260.0, 120.0}, 3, cv::Scalar(160, 90, 40));
  EXPECT_FALSE(trace_bar(faint, box_around({90.0, 120.0}, {150.0, 120.0}, 4.0), 640.0, 60.0));
  // Nothing in the box but the door.
  const cv::Mat plain(240, 320, CV_8UC3, kDoor);
  EXPECT_FALSE(trace_bar(plain, box_around({90.0, 120.0}, {150.0, 120.0}, 4.0), 640.0, 60.0));
  // A box outside the image.
  EXPECT_FALSE(trace_bar(plain, box_around({400.0, 120.0}, {450.0, 120.0}, 4.0), 640.0, 60.0));
}

}  // namespace
}  // namespace vsl::recognition::detail

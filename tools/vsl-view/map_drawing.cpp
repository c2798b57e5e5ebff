#include "map_drawing.hpp"

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <tuple>
#include <variant>

#include "view_style.hpp"

namespace vsl::view {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

// Corners of a primitive in the world frame: a box's 8, a cylinder's two rims (24 points each),
// a polyhedron's vertices, a mesh's bounding box's 8. Their floor projection's convex hull is the
// footprint.
std::vector<Eigen::Vector3d> world_corners(const world::ObjectModel& object,
                                           const world::Primitive& primitive) {
  const Eigen::Isometry3d world_T_primitive =
      object.world_T_object() * primitive.object_T_primitive();
  std::vector<Eigen::Vector3d> local;
  if (const auto* box = std::get_if<world::Box>(&primitive.shape)) {
    const Eigen::Vector3d half = 0.5 * box->size_m;
    for (int i = 0; i < 8; ++i) {
      local.emplace_back((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(),
                         (i & 4 ? 1 : -1) * half.z());
    }
  } else if (const auto* cylinder = std::get_if<world::Cylinder>(&primitive.shape)) {
    constexpr int kSides = 24;
    for (int i = 0; i < kSides; ++i) {
      const double a = 2.0 * std::numbers::pi * i / kSides;
      for (const double z : {-0.5 * cylinder->height_m, 0.5 * cylinder->height_m}) {
        local.emplace_back(cylinder->radius_m * std::cos(a), cylinder->radius_m * std::sin(a), z);
      }
    }
  } else if (const auto* polyhedron = std::get_if<world::Polyhedron>(&primitive.shape)) {
    local = polyhedron->vertices_m;
  } else if (const auto* mesh = std::get_if<world::TriangleMesh>(&primitive.shape)) {
    // The 8 corners of its own-frame bounding box: a hull of 100k vertices would be slow for a
    // footprint that is only a hint of where the part is.
    if (!mesh->vertices_m.empty()) {
      Eigen::AlignedBox3f bounds;
      for (const Eigen::Vector3f& v : mesh->vertices_m) bounds.extend(v);
      for (int i = 0; i < 8; ++i) {
        local.push_back(
            bounds.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i)).cast<double>());
      }
    }
  }
  for (Eigen::Vector3d& p : local) p = world_T_primitive * p;
  return local;
}

std::vector<cv::Point> footprint_px(const std::vector<Eigen::Vector3d>& world_points,
                                    const MapFrame& frame) {
  std::vector<cv::Point> points;
  points.reserve(world_points.size());
  for (const Eigen::Vector3d& p : world_points) {
    const cv::Point2d px = frame.to_pixel(p.head<2>());
    points.emplace_back(static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y)));
  }
  std::vector<cv::Point> hull;
  if (!points.empty()) cv::convexHull(points, hull);
  return hull;
}

cv::Scalar to_bgr(const world::Colour& c) {
  return {double(c.b), double(c.g), double(c.r)};
}

// A colour moved `amount` (0..1) toward white (positive) or black (negative).
cv::Scalar shade(const cv::Scalar& c, double amount) {
  cv::Scalar out;
  for (int i = 0; i < 3; ++i) {
    out[i] = amount >= 0 ? c[i] + (255.0 - c[i]) * amount : c[i] * (1.0 + amount);
  }
  return out;
}

bool is_highlighted(const std::string& type) {
  return type == "door" || type == "handle" || type == "drawer_front" || type == "window";
}

// Clamped first: a far-off point (a wild hypothesis) must not overflow the integer conversion;
// OpenCV clips what lies outside the image.
cv::Point rounded(const cv::Point2d& p) {
  constexpr double kFar = 1e6;
  return {static_cast<int>(std::lround(std::clamp(p.x, -kFar, kFar))),
          static_cast<int>(std::lround(std::clamp(p.y, -kFar, kFar)))};
}

// Yaw (radians, about world z) of the ego x axis.
double yaw_of(const Eigen::Isometry3d& world_T_ego) {
  const Eigen::Vector3d forward = world_T_ego.linear() * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

// The robot as seen from above: its base circle and a heading arrow along ego x.
void draw_robot(cv::Mat& image, const MapFrame& frame, const Eigen::Isometry3d& world_T_ego,
                const cv::Scalar& colour, int thickness, double radius_m = kRobotRadiusM) {
  const Eigen::Vector2d centre = world_T_ego.translation().head<2>();
  const double yaw = yaw_of(world_T_ego);
  const Eigen::Vector2d ahead =
      centre + 1.5 * radius_m * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
  const cv::Point c = rounded(frame.to_pixel(centre));
  cv::circle(image, c, static_cast<int>(std::lround(radius_m * frame.px_per_m)), colour, thickness,
             cv::LINE_AA);
  cv::arrowedLine(image, c, rounded(frame.to_pixel(ahead)), colour, thickness, cv::LINE_AA, 0,
                  0.25);
  cv::circle(image, c, 3 + thickness, colour, cv::FILLED, cv::LINE_AA);
}

void draw_ellipse(cv::Mat& image, const MapFrame& frame, const Eigen::Vector2d& centre_m,
                  const Ellipse2& e, const cv::Scalar& colour, int thickness) {
  // At least a pixel, so that a very certain estimate still shows its ellipse as a dot.
  auto axis_px = [&](double m) {
    return static_cast<int>(std::lround(std::clamp(m * frame.px_per_m, 1.0, 1e5)));
  };
  const cv::Size axes(axis_px(e.major_m), axis_px(e.minor_m));
  // Image v points down, so a world angle turns the other way in the picture.
  cv::ellipse(image, rounded(frame.to_pixel(centre_m)), axes,
              -e.angle_rad * 180.0 / std::numbers::pi, 0, 360, colour, thickness, cv::LINE_AA);
}

void dashed_line(cv::Mat& image, cv::Point2d a, cv::Point2d b, const cv::Scalar& colour,
                 int thickness, double dash_px) {
  const double length = cv::norm(b - a);
  const int dashes = std::max(1, static_cast<int>(length / dash_px));
  for (int i = 0; i < dashes; i += 2) {
    const cv::Point2d from = a + (b - a) * (double(i) / dashes);
    const cv::Point2d to = a + (b - a) * (std::min(double(i + 1), double(dashes)) / dashes);
    cv::line(image, rounded(from), rounded(to), colour, thickness, cv::LINE_AA);
  }
}

void put_text(cv::Mat& image, const std::string& text, cv::Point at, double scale,
              const cv::Scalar& colour, int thickness = 1) {
  cv::putText(image, text, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

// `text`, shortened with "..." until it is at most `width_px` wide.
std::string fit_text(std::string text, int width_px, double scale, int thickness) {
  int base = 0;
  bool cut = false;
  while (!text.empty() &&
         cv::getTextSize(text + (cut ? "..." : ""), kFont, scale, thickness, &base).width >
             width_px) {
    text.pop_back();
    cut = true;
  }
  return cut ? text + "..." : text;
}

// The legend in the last row of the caption strip: one symbol and word per overlay element.
void draw_legend(cv::Mat& image, int baseline_v) {
  int u = 12;
  auto item = [&](const std::string& text, auto&& symbol) {
    symbol(cv::Point(u + 8, baseline_v - 5));
    put_text(image, text, {u + 18, baseline_v}, 0.42, colour::kText);
    int base = 0;
    u += 26 + cv::getTextSize(text, kFont, 0.42, 1, &base).width;
  };
  item("estimate (3 sigma)",
       [&](cv::Point p) { cv::circle(image, p, 6, colour::kEstimate, 2, cv::LINE_AA); });
  item("ground truth",
       [&](cv::Point p) { cv::circle(image, p, 6, colour::kTruth, 2, cv::LINE_AA); });
  item("hypothesis",
       [&](cv::Point p) { cv::circle(image, p, 6, colour::kHypothesis, 1, cv::LINE_AA); });
  item("gaze", [&](cv::Point p) {
    cv::drawMarker(image, p, colour::kGaze, cv::MARKER_CROSS, 12, 2, cv::LINE_AA);
  });
  for (const char* type : {"door", "handle"}) {
    item(std::string(type), [&](cv::Point p) {
      cv::circle(image, p, 5, type_colour(type), cv::FILLED, cv::LINE_AA);
      cv::circle(image, p, 5, colour::kText, 1, cv::LINE_AA);
    });
  }
  item("unmatched", [&](cv::Point p) {
    cv::circle(image, p, 5, cv::Scalar(255, 255, 255), cv::FILLED, cv::LINE_AA);
    cv::circle(image, p, 5, colour::kText, 2, cv::LINE_AA);
  });
}

}  // namespace

cv::Point2d MapFrame::to_pixel(const Eigen::Vector2d& world_xy_m) const {
  return {margin_px + (world_xy_m.x() - world_min_m.x()) * px_per_m,
          height_px - margin_px - (world_xy_m.y() - world_min_m.y()) * px_per_m};
}

MapFrame map_frame_for(const world::WorldModel& world, double px_per_m) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const world::ObjectModel& object : world.objects) {
    if (object.type == "ceiling") continue;
    for (const world::Primitive& primitive : object.primitives) {
      for (const Eigen::Vector3d& p : world_corners(object, primitive)) {
        lo = lo.cwiseMin(p.head<2>());
        hi = hi.cwiseMax(p.head<2>());
      }
    }
  }
  if (!(lo.array() <= hi.array()).all()) {  // nothing to draw: a 1 m square at the origin
    lo = Eigen::Vector2d::Zero();
    hi = Eigen::Vector2d::Ones();
  }
  MapFrame frame;
  frame.px_per_m = px_per_m;
  frame.world_min_m = lo;
  const Eigen::Vector2d extent = hi - lo;
  frame.width_px = static_cast<int>(std::ceil(extent.x() * px_per_m)) + 2 * frame.margin_px;
  frame.height_px =
      static_cast<int>(std::ceil(extent.y() * px_per_m)) + 2 * frame.margin_px + frame.caption_px;
  return frame;
}

ScaleBar scale_bar_for(const MapFrame& frame) {
  const double wanted_m = (frame.width_px - 2 * frame.margin_px) / 6.0 / frame.px_per_m;
  ScaleBar bar;
  for (const double length_m : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    bar.length_m = length_m;
    if (length_m >= wanted_m) break;
  }
  const int v = frame.height_px - frame.margin_px / 2;
  bar.start_px = {frame.margin_px, v};
  bar.end_px = {frame.margin_px + static_cast<int>(std::lround(bar.length_m * frame.px_per_m)), v};
  return bar;
}

cv::Mat draw_world(const world::WorldModel& world, const MapFrame& frame) {
  cv::Mat image(frame.height_px, frame.width_px, CV_8UC3, colour::kBackground);
  struct Footprint {
    double top_z_m;
    bool highlighted;
    std::vector<cv::Point> hull;
    cv::Scalar fill;
    cv::Scalar outline;
  };
  std::vector<Footprint> footprints;
  for (const world::ObjectModel& object : world.objects) {
    if (object.type == "ceiling") continue;
    for (const world::Primitive& primitive : object.primitives) {
      const std::vector<Eigen::Vector3d> corners = world_corners(object, primitive);
      if (corners.empty()) continue;
      Footprint f;
      f.top_z_m = -std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& p : corners) f.top_z_m = std::max(f.top_z_m, p.z());
      f.hull = footprint_px(corners, frame);
      f.highlighted = is_highlighted(object.type);
      if (object.type == "floor") {
        f.fill = colour::kFloor;
        f.outline = shade(colour::kFloor, -0.2);
        f.top_z_m = -std::numeric_limits<double>::infinity();  // below everything
      } else if (object.type == "wall") {
        f.fill = colour::kWall;
        f.outline = colour::kWall;
      } else if (f.highlighted) {
        // Outlined in their own colour, 2 px: a door panel is 2 cm thick, a handle bar 1.5 cm,
        // and a darker outline alone would hide the type colour.
        f.fill = type_colour(object.type);
        f.outline = f.fill;
      } else {
        // Furniture in its own colour, washed out so that the overlay stands out.
        f.fill = shade(to_bgr(primitive.colour), 0.55);
        f.outline = shade(to_bgr(primitive.colour), -0.35);
      }
      footprints.push_back(std::move(f));
    }
  }
  // Higher hides lower, as seen from above; highlighted types last so that they always show.
  std::stable_sort(footprints.begin(), footprints.end(), [](const auto& a, const auto& b) {
    return std::tie(a.highlighted, a.top_z_m) < std::tie(b.highlighted, b.top_z_m);
  });
  for (const Footprint& f : footprints) {
    cv::fillConvexPoly(image, f.hull, f.fill, cv::LINE_AA);
    cv::polylines(image, f.hull, true, f.outline, f.highlighted ? 2 : 1, cv::LINE_AA);
  }

  // Scale bar with end ticks and its length.
  const ScaleBar bar = scale_bar_for(frame);
  cv::line(image, bar.start_px, bar.end_px, colour::kText, 3);
  for (const cv::Point& end : {bar.start_px, bar.end_px}) {
    cv::line(image, end + cv::Point(0, -6), end + cv::Point(0, 6), colour::kText, 2);
  }
  char label[32];
  std::snprintf(label, sizeof label, "%g m", bar.length_m);
  put_text(image, label, bar.end_px + cv::Point(10, 5), 0.5, colour::kText);
  // World axes at the bottom right, so that poses can be read off the picture.
  const cv::Point origin(frame.width_px - frame.margin_px - 40,
                         frame.height_px - frame.margin_px / 2);
  cv::arrowedLine(image, origin, origin + cv::Point(30, 0), colour::kText, 1, cv::LINE_AA, 0, 0.3);
  cv::arrowedLine(image, origin, origin + cv::Point(0, -30), colour::kText, 1, cv::LINE_AA, 0, 0.3);
  put_text(image, "x", origin + cv::Point(33, 5), 0.45, colour::kText);
  put_text(image, "y", origin + cv::Point(-4, -34), 0.45, colour::kText);
  return image;
}

std::optional<Eigen::Isometry3d> drawing_pose(const MapOverlay& overlay) {
  if (overlay.world_T_ego_estimate) return overlay.world_T_ego_estimate;
  return overlay.world_T_ego_truth;
}

Ellipse2 sigma_ellipse(const Eigen::Matrix2d& covariance_m2, double n_sigma) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(
      0.5 * (covariance_m2 + covariance_m2.transpose()));
  // Eigenvalues ascending; clamp tiny negative round-off.
  const Eigen::Vector2d values = solver.eigenvalues().cwiseMax(0.0);
  const Eigen::Vector2d major_axis = solver.eigenvectors().col(1);
  Ellipse2 e;
  e.major_m = n_sigma * std::sqrt(values(1));
  e.minor_m = n_sigma * std::sqrt(values(0));
  e.angle_rad = std::atan2(major_axis.y(), major_axis.x());
  return e;
}

cv::Mat draw_map(const cv::Mat& world_picture, const MapFrame& frame, const MapOverlay& overlay) {
  cv::Mat image = world_picture.clone();

  // Hypotheses other than the best, which is drawn as the estimate (or, without an estimate, here
  // with the others, thicker).
  for (std::size_t i = overlay.hypotheses.size(); i-- > 0;) {
    if (i == 0 && overlay.world_T_ego_estimate) continue;
    const Hypothesis& h = overlay.hypotheses[i];
    draw_robot(image, frame, h.world_T_ego, colour::kHypothesis, i == 0 ? 2 : 1);
    const cv::Point2d c = frame.to_pixel(h.world_T_ego.translation().head<2>());
    put_text(image, std::to_string(i + 1), rounded(c) + cv::Point(8, -8), 0.45,
             colour::kHypothesis);
  }

  if (overlay.world_T_ego_truth) {
    // A little larger than the estimate, so that both show when they agree.
    draw_robot(image, frame, *overlay.world_T_ego_truth, colour::kTruth, 2, 1.2 * kRobotRadiusM);
  }

  if (const std::optional<Eigen::Isometry3d> pose = drawing_pose(overlay)) {
    const Eigen::Matrix3d world_R_ego = pose->linear();
    // Percept uncertainty at 1 sigma, translucent: Eq. 7's noise grows along the viewing ray,
    // and 3-sigma needles across the room would hide the map.
    cv::Mat layer = image.clone();
    for (const FusedPercept& p : overlay.fused_percepts) {
      const Eigen::Vector3d world_p = *pose * p.ego_position_m;
      const Eigen::Matrix2d cov =
          (world_R_ego * p.ego_covariance_m2 * world_R_ego.transpose()).topLeftCorner<2, 2>();
      draw_ellipse(layer, frame, world_p.head<2>(), sigma_ellipse(cov, 1.0), type_colour(p.type),
                   cv::FILLED);
    }
    cv::addWeighted(layer, 0.4, image, 0.6, 0.0, image);
    for (const FusedPercept& p : overlay.fused_percepts) {
      const Eigen::Vector3d world_p = *pose * p.ego_position_m;
      const cv::Point px = rounded(frame.to_pixel(world_p.head<2>()));
      if (p.match == FusedPercept::Match::kUnmatched) {
        cv::circle(image, px, 5, cv::Scalar(255, 255, 255), cv::FILLED, cv::LINE_AA);
        cv::circle(image, px, 5, type_colour(p.type), 2, cv::LINE_AA);
      } else {
        cv::circle(image, px, 5, type_colour(p.type), cv::FILLED, cv::LINE_AA);
        cv::circle(image, px, 5, colour::kText, 1, cv::LINE_AA);
      }
    }
    if (overlay.ego_gaze_target_m) {
      // From the head (about 1.5 m above the ego origin) to the target.
      const Eigen::Vector3d target = *pose * *overlay.ego_gaze_target_m;
      const cv::Point2d from = frame.to_pixel(pose->translation().head<2>());
      const cv::Point2d to = frame.to_pixel(target.head<2>());
      dashed_line(image, from, to, colour::kGaze, 1, 8.0);
      cv::drawMarker(image, rounded(to), colour::kGaze, cv::MARKER_CROSS, 16, 2, cv::LINE_AA);
    }
  }

  if (overlay.world_T_ego_estimate) {
    const Eigen::Isometry3d& pose = *overlay.world_T_ego_estimate;
    if (overlay.estimate_covariance) {
      const Eigen::Matrix<double, 6, 6>& cov = *overlay.estimate_covariance;
      draw_ellipse(image, frame, pose.translation().head<2>(),
                   sigma_ellipse(cov.topLeftCorner<2, 2>(), 3.0), colour::kCovariance, 2);
      // The 3-sigma yaw uncertainty as a wedge around the heading, a little beyond the base.
      const double yaw = yaw_of(pose);
      const double spread = 3.0 * std::sqrt(std::max(0.0, cov(5, 5)));
      const double r = 2.0 * kRobotRadiusM;
      for (const double a : {yaw - spread, yaw + spread}) {
        const Eigen::Vector2d end =
            pose.translation().head<2>() + r * Eigen::Vector2d(std::cos(a), std::sin(a));
        cv::line(image, rounded(frame.to_pixel(pose.translation().head<2>())),
                 rounded(frame.to_pixel(end)), colour::kCovariance, 1, cv::LINE_AA);
      }
    }
    draw_robot(image, frame, pose, colour::kEstimate, 2);
  }

  // Caption strip: the given lines and the legend.
  cv::rectangle(image, cv::Rect(0, 0, frame.width_px, frame.caption_px), cv::Scalar(255, 255, 255),
                cv::FILLED);
  cv::line(image, {0, frame.caption_px - 1}, {frame.width_px, frame.caption_px - 1},
           shade(colour::kText, 0.7), 1);
  int v = 20;
  for (const std::string& line : overlay.caption) {
    if (v > frame.caption_px - 30) break;
    const int thickness = v == 20 ? 2 : 1;
    put_text(image, fit_text(line, frame.width_px - 24, 0.5, thickness), {12, v}, 0.5,
             colour::kText, thickness);
    v += 22;
  }
  draw_legend(image, frame.caption_px - 12);
  return image;
}

}  // namespace vsl::view

#include "chessboard_scene.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "vsl/render/renderer.hpp"

namespace vsl::calibration::testing {
namespace {

constexpr double kThicknessM = 0.002;
const world::Colour kBlack{20, 20, 20};
const world::Colour kWhite{225, 225, 225};

world::Primitive box(Eigen::Vector3d centre, Eigen::Vector3d size, world::Colour colour) {
  world::Primitive out;
  out.shape = world::Box{size};
  out.object_position_m = centre;
  out.colour = colour;
  return out;
}

// A camera with intrinsics `in` at board_T_camera sees the point p (board frame) inside its image
// with `margin_px` to spare.
bool sees(const head::CameraIntrinsics& in, const Eigen::Isometry3d& board_T_camera,
          const Eigen::Vector3d& p, double margin_px) {
  const Eigen::Vector3d c = board_T_camera.inverse() * p;
  if (c.z() < 0.1) return false;
  const double u = in.fx_px * c.x() / c.z() + in.cx_px;
  const double v = in.fy_px * c.y() / c.z() + in.cy_px;
  return u >= margin_px && v >= margin_px && u <= in.width_px - 1 - margin_px &&
         v <= in.height_px - 1 - margin_px;
}

}  // namespace

world::WorldModel chessboard_world(const BoardSpec& board) {
  world::WorldModel world;
  world.name = "chessboard";
  world::ObjectModel object;
  object.id = "board";
  object.type = "chessboard";
  const double s = board.square_m;
  // (columns + 1) x (rows + 1) squares around the inner corners.
  for (int j = 0; j <= board.rows; ++j) {
    for (int i = 0; i <= board.columns; ++i) {
      const Eigen::Vector3d centre((i - 0.5) * s, (j - 0.5) * s, kThicknessM / 2);
      object.primitives.push_back(
          box(centre, Eigen::Vector3d(s, s, kThicknessM), (i + j) % 2 == 0 ? kBlack : kWhite));
    }
  }
  // A white margin of one square around the board (the quiet zone the detector needs): four
  // strips in the squares' plane, so that no face lies behind another.
  const double x0 = -2 * s, x1 = (board.columns + 1) * s, y0 = -2 * s, y1 = (board.rows + 1) * s;
  auto strip = [&](double xa, double xb, double ya, double yb) {
    object.primitives.push_back(box(Eigen::Vector3d((xa + xb) / 2, (ya + yb) / 2, kThicknessM / 2),
                                    Eigen::Vector3d(xb - xa, yb - ya, kThicknessM), kWhite));
  };
  strip(x0, x1, y0, -s);                             // above the squares
  strip(x0, x1, board.rows * s, y1);                 // below
  strip(x0, -s, -s, board.rows * s);                 // left
  strip(board.columns * s, x1, -s, board.rows * s);  // right
  world.objects.push_back(std::move(object));
  world.index_ids();
  return world;
}

std::vector<RenderedPair> render_chessboard_views(const BoardSpec& board,
                                                  const head::StereoCalibration& camera, int count,
                                                  std::uint64_t seed) {
  render::RenderOptions options;
  options.samples = 4;
  options.world_light_direction = Eigen::Vector3d(0.1, -0.2, -1.0);  // from the camera's side
  const render::Renderer renderer(chessboard_world(board), options);

  const double s = board.square_m;
  const Eigen::Vector3d centre((board.columns - 1) * s / 2, (board.rows - 1) * s / 2, 0.0);
  // The margin's outer corners must be in view.
  std::vector<Eigen::Vector3d> outline;
  for (const double x : {-2 * s, (board.columns + 1) * s}) {
    for (const double y : {-2 * s, (board.rows + 1) * s}) outline.emplace_back(x, y, 0.0);
  }
  const Eigen::Isometry3d left_T_right = camera.left_T_right();

  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> distance(0.45, 0.9), tilt(-35.0, 35.0), roll(-20.0, 20.0),
      shift(-0.06, 0.06);
  const double deg = std::numbers::pi / 180.0;
  std::vector<RenderedPair> out;
  std::uint64_t noise_seed = seed * 1000;
  while (static_cast<int>(out.size()) < count) {
    // Look at a point near the centre from a direction tilted away from the board's normal.
    const Eigen::Vector3d target = centre + Eigen::Vector3d(shift(rng), shift(rng), 0.0);
    const Eigen::Matrix3d tilt_R = (Eigen::AngleAxisd(tilt(rng) * deg, Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(tilt(rng) * deg, Eigen::Vector3d::UnitY()))
                                       .toRotationMatrix();
    const Eigen::Vector3d forward = tilt_R * Eigen::Vector3d::UnitZ();  // camera z, board frame
    const Eigen::Vector3d position = target - distance(rng) * forward;
    Eigen::Vector3d x_axis = tilt_R * Eigen::Vector3d::UnitX();
    x_axis = Eigen::AngleAxisd(roll(rng) * deg, forward) * x_axis;
    Eigen::Isometry3d board_T_left = Eigen::Isometry3d::Identity();
    board_T_left.linear().col(0) = x_axis;
    board_T_left.linear().col(1) = forward.cross(x_axis);
    board_T_left.linear().col(2) = forward;
    board_T_left.translation() = position;
    const Eigen::Isometry3d board_T_right = board_T_left * left_T_right;
    bool visible = true;
    for (const Eigen::Vector3d& p : outline) {
      visible = visible && sees(camera.left, board_T_left, p, 8.0) &&
                sees(camera.right, board_T_right, p, 8.0);
    }
    if (!visible) continue;
    RenderedPair pair;
    pair.board_T_left = board_T_left;
    pair.left = renderer.render(camera.left, board_T_left, noise_seed++).image;
    pair.right = renderer.render(camera.right, board_T_right, noise_seed++).image;
    out.push_back(std::move(pair));
  }
  return out;
}

}  // namespace vsl::calibration::testing

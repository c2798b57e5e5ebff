// The realism levels: textured finishes, lamps and window light with shadows, highlights, and the
// camera (auto-exposure, vignetting, noise, motion blur, compression), each checked on a small
// room built for it. Ground truth (depth, ids) must stay exact whatever the realism.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

#include "../src/camera_effects.hpp"
#include "../src/colour_science.hpp"
#include "test_scenes.hpp"

namespace vsl::render {
namespace {

using test::box_object;
using test::camera_pose;

// A closed 4 x 4 x 2.6 m room (floor, ceiling, four walls) with a lamp at the ceiling's centre.
struct Room {
  world::WorldModel world;
  Eigen::Isometry3d camera;  // at (2, 0.3, 1.5), looking along +y at the far wall, a little down
};

world::ObjectModel lamp(const std::string& id, const Eigen::Vector3d& position) {
  world::ObjectModel object;
  object.id = id;
  object.type = "lamp";
  object.world_position_m = position;
  world::Primitive primitive;
  primitive.shape = world::Cylinder{0.05, 0.01};
  primitive.material = "lamp";
  primitive.colour = {240, 240, 234};
  object.primitives.push_back(primitive);
  return object;
}

Room room(double flux_lm = 800.0, world::Finish wall_finish = world::Finish::matte) {
  Room r;
  world::Material wall{"wall", {200, 200, 196}};
  wall.finish = wall_finish;
  world::Material light{"lamp", {240, 240, 234}};
  light.light = world::MaterialLight{flux_lm, 4000.0, 1.2};
  r.world.materials = {wall, light};
  const world::Colour c{200, 200, 196};
  std::vector<world::ObjectModel> objects{
      box_object("floor", "floor", {2, 2, -0.05}, {4.2, 4.2, 0.1}, c),
      box_object("ceiling", "ceiling", {2, 2, 2.65}, {4.2, 4.2, 0.1}, c),
      box_object("wall.n", "wall", {2, 4.05, 1.3}, {4.2, 0.1, 2.6}, c),
      box_object("wall.s", "wall", {2, -0.05, 1.3}, {4.2, 0.1, 2.6}, c),
      box_object("wall.e", "wall", {4.05, 2, 1.3}, {0.1, 4.2, 2.6}, c),
      box_object("wall.w", "wall", {-0.05, 2, 1.3}, {0.1, 4.2, 2.6}, c),
      lamp("lamp", {2, 2, 2.595})};
  for (auto& o : objects) {
    for (auto& p : o.primitives) {
      if (p.material.empty()) p.material = "wall";
    }
  }
  r.world.objects = std::move(objects);
  r.world.index_ids();
  r.camera = camera_pose({2, 0.3, 1.5}, Eigen::Vector3d(0, 1, -0.35));
  return r;
}

RenderOptions realistic(RealismLevel level) {
  RenderOptions options = test::clean_options();
  options.realism.level = level;
  return options;
}

double grey_mean(const cv::Mat& image, const cv::Rect& area) {
  const cv::Scalar m = cv::mean(image(area));
  return (m[0] + m[1] + m[2]) / 3.0;
}

double grey_stddev(const cv::Mat& image, const cv::Rect& area) {
  cv::Mat grey;
  cv::cvtColor(image(area), grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, stddev;
  cv::meanStdDev(grey, mean, stddev);
  return stddev[0];
}

TEST(Realism, LampsAreFoundFromTheirMaterialAndAFallbackLightOtherwise) {
  Room r = room();
  EXPECT_EQ(Renderer(r.world, realistic(RealismLevel::materials)).light_count(), 1u);
  r.world.objects.push_back(lamp("lamp2", {1, 1, 2.595}));
  r.world.index_ids();
  EXPECT_EQ(Renderer(r.world, realistic(RealismLevel::materials)).light_count(), 2u);
  r.world.materials[1].light.reset();
  EXPECT_EQ(Renderer(r.world, realistic(RealismLevel::materials)).light_count(), 1u);  // fallback
  EXPECT_EQ(Renderer(r.world, test::clean_options()).light_count(), 0u);  // level off: none
}

TEST(Realism, DepthAndIdsStayExact) {
  const Room r = room();
  const head::CameraIntrinsics intrinsics;
  const RenderedImage flat =
      Renderer(r.world, test::clean_options()).render(intrinsics, r.camera, 1);
  for (const RealismLevel level : {RealismLevel::materials, RealismLevel::full}) {
    const RenderedImage real = Renderer(r.world, realistic(level)).render(intrinsics, r.camera, 1);
    EXPECT_EQ(cv::norm(flat.depth_m, real.depth_m, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::countNonZero(flat.object_ids != real.object_ids), 0);
  }
}

TEST(Realism, TheLampLightsTheFloorBelowItMoreThanTheCorners) {
  const Room r = room();
  const Renderer renderer(r.world, realistic(RealismLevel::materials));
  const head::CameraIntrinsics intrinsics;
  // Look straight down from 2.4 m, off-centre so the lamp is not in view.
  const Eigen::Isometry3d down =
      camera_pose({2.0, 2.0, 2.4}, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  const RenderedImage image = renderer.render(intrinsics, down, 1);
  const Eigen::Vector2d below = test::project(intrinsics, down, {2.0, 2.0, 0.0});
  const Eigen::Vector2d corner = test::project(intrinsics, down, {0.9, 1.1, 0.0});
  const cv::Rect below_area(static_cast<int>(below.x()) - 10, static_cast<int>(below.y()) - 10, 20,
                            20);
  const cv::Rect corner_area(static_cast<int>(corner.x()) - 10, static_cast<int>(corner.y()) - 10,
                             20, 20);
  EXPECT_GT(grey_mean(image.image, below_area), grey_mean(image.image, corner_area) + 15.0);
}

TEST(Realism, ABoxCastsAShadowOnTheFloor) {
  Room r = room();
  // A 0.6 m cube on the floor, 0.9 m beside the lamp's foot: its shadow falls away from the lamp.
  r.world.objects.push_back(
      box_object("box", "clutter", {2.9, 2.0, 0.3}, {0.6, 0.6, 0.6}, {120, 60, 40}));
  r.world.objects.back().primitives[0].material = "wall";
  r.world.index_ids();
  const Renderer renderer(r.world, realistic(RealismLevel::materials));
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d down =
      camera_pose({2.0, 2.0, 2.4}, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  const RenderedImage image = renderer.render(intrinsics, down, 1);
  // Behind the box (x = 3.3, in its shadow) and as far from the lamp on the other side (x = 0.7).
  const Eigen::Vector2d shadowed = test::project(intrinsics, down, {3.3, 2.0, 0.0});
  const Eigen::Vector2d open = test::project(intrinsics, down, {0.7, 2.0, 0.0});
  const cv::Rect s(static_cast<int>(shadowed.x()) - 4, static_cast<int>(shadowed.y()) - 4, 8, 8);
  const cv::Rect o(static_cast<int>(open.x()) - 4, static_cast<int>(open.y()) - 4, 8, 8);
  EXPECT_LT(grey_mean(image.image, s), 0.75 * grey_mean(image.image, o));
}

// The floor right under the lamp, seen from 1 m above: evenly lit, so any variation in the
// image is the surface's pattern or the camera's doing.
Eigen::Isometry3d floor_view() {
  return camera_pose({2.0, 2.0, 1.0}, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
}

TEST(Realism, WoodGrainIsAPatternAndMatteIsFlat) {
  const head::CameraIntrinsics intrinsics;
  auto variation = [&](world::Finish finish) {
    const Room r = room(800.0, finish);
    const Renderer renderer(r.world, realistic(RealismLevel::materials));
    const RenderedImage image = renderer.render(intrinsics, floor_view(), 1);
    return grey_stddev(image.image, cv::Rect(300, 220, 40, 40));
  };
  const double matte = variation(world::Finish::matte);
  const double wood = variation(world::Finish::wood);
  EXPECT_LT(matte, 1.5);
  EXPECT_GT(wood, matte + 3.0);
}

TEST(Realism, AutoExposureKeepsTheImageLevelWhateverTheLamp) {
  const head::CameraIntrinsics intrinsics;
  auto mean_of = [&](double flux) {
    const Room r = room(flux);
    RenderOptions options = realistic(RealismLevel::full);
    options.realism.jpeg_quality = 0;
    const RenderedImage image = Renderer(r.world, options).render(intrinsics, r.camera, 3);
    return grey_mean(image.image, cv::Rect(0, 0, 640, 480)) / 255.0;
  };
  const double dim = mean_of(200.0), bright = mean_of(4000.0);
  EXPECT_NEAR(dim, bright, 0.05);
  EXPECT_NEAR(bright, RealismOptions{}.exposure_target_grey, 0.15);
  // Without auto-exposure, twenty times the light is a much brighter image.
  RenderOptions fixed = realistic(RealismLevel::materials);
  fixed.realism.auto_exposure = false;
  fixed.realism.exposure_compensation_ev = -10.0;
  const Room dim_room = room(200.0), bright_room = room(4000.0);
  const double fixed_dim =
      grey_mean(Renderer(dim_room.world, fixed).render(intrinsics, dim_room.camera, 3).image,
                cv::Rect(0, 0, 640, 480));
  const double fixed_bright =
      grey_mean(Renderer(bright_room.world, fixed).render(intrinsics, bright_room.camera, 3).image,
                cv::Rect(0, 0, 640, 480));
  EXPECT_GT(fixed_bright, fixed_dim + 20.0);
}

TEST(Realism, TheSameSeedGivesTheSameImageAndNoiseDependsOnIt) {
  const Room r = room();
  const Renderer renderer(r.world, realistic(RealismLevel::full));
  const head::CameraIntrinsics intrinsics;
  const RenderedImage a = renderer.render(intrinsics, r.camera, 7);
  const RenderedImage b = renderer.render(intrinsics, r.camera, 7);
  const RenderedImage c = renderer.render(intrinsics, r.camera, 8);
  EXPECT_EQ(cv::norm(a.image, b.image, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.image, c.image, cv::NORM_L1), 0.0);
}

TEST(Realism, VignettingDarkensTheCorners) {
  const Room r = room();
  RenderOptions options = realistic(RealismLevel::full);
  options.realism.full_well_electrons = 0.0;  // no noise
  options.realism.jpeg_quality = 0;
  options.realism.aperture_m = 0.0;
  options.realism.white_balance_error = 0.0;
  options.realism.vignetting = 0.5;
  const head::CameraIntrinsics intrinsics;
  const RenderedImage with = Renderer(r.world, options).render(intrinsics, floor_view(), 1);
  options.realism.vignetting = 0.0;
  const RenderedImage without = Renderer(r.world, options).render(intrinsics, floor_view(), 1);
  const cv::Rect corner(0, 0, 24, 24), centre(308, 228, 24, 24);
  const double ratio_with = grey_mean(with.image, corner) / grey_mean(with.image, centre);
  const double ratio_without = grey_mean(without.image, corner) / grey_mean(without.image, centre);
  EXPECT_GT(ratio_without, 0.8);  // the floor is evenly lit
  EXPECT_LT(ratio_with, ratio_without - 0.15);
}

TEST(Realism, ATurningHeadBlursTheImageAlongItsMotion) {
  Room r = room(800.0, world::Finish::tiles);
  RenderOptions options = realistic(RealismLevel::full);
  options.realism.jpeg_quality = 0;
  options.realism.full_well_electrons = 0.0;
  options.realism.aperture_m = 0.0;
  const Renderer renderer(r.world, options);
  const head::CameraIntrinsics intrinsics;
  const Eigen::Isometry3d near = camera_pose({2.0, 3.2, 1.3}, Eigen::Vector3d::UnitY());
  const RenderedImage still = renderer.render(intrinsics, near, 1);
  CameraMotion pan;
  pan.camera_angular_velocity_rad_s = {0.0, 1.0, 0.0};  // about the camera's y: image moves along u
  auto gradient_energy = [](const cv::Mat& image, int dx, int dy) {
    cv::Mat grey, shifted;
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    grey.convertTo(grey, CV_32F);
    const cv::Rect a(10, 10, 600, 440), b(10 + dx, 10 + dy, 600, 440);
    return cv::norm(grey(a) - grey(b), cv::NORM_L1);
  };
  RenderedImage moved;
  renderer.render(intrinsics, near, 1, pan, moved);
  // Along the motion the blur smooths the grout lines away; across it they stay sharp.
  EXPECT_LT(gradient_energy(moved.image, 1, 0), 0.7 * gradient_energy(still.image, 1, 0));
  EXPECT_GT(gradient_energy(moved.image, 0, 1), 0.7 * gradient_energy(still.image, 0, 1));
  const Eigen::Vector2d px = motion_blur_px(intrinsics, pan, 0.015);
  EXPECT_NEAR(std::abs(px.x()), intrinsics.fx_px * 0.015, 1e-9);
  EXPECT_NEAR(px.y(), 0.0, 1e-12);
}

TEST(Realism, CompressionLeavesJpegArtefacts) {
  const Room r = room(800.0, world::Finish::wood);
  RenderOptions options = realistic(RealismLevel::full);
  options.realism.full_well_electrons = 0.0;
  const head::CameraIntrinsics intrinsics;
  options.realism.jpeg_quality = 0;
  const RenderedImage raw = Renderer(r.world, options).render(intrinsics, r.camera, 1);
  options.realism.jpeg_quality = 30;
  const RenderedImage jpeg = Renderer(r.world, options).render(intrinsics, r.camera, 1);
  const double difference = cv::norm(raw.image, jpeg.image, cv::NORM_L1) / raw.image.total();
  EXPECT_GT(difference, 1.0);
  EXPECT_LT(difference, 40.0);
}

TEST(Realism, ColourTemperatureAndDefocusFormulas) {
  const auto warm = black_body_rgb(2700.0), daylight = black_body_rgb(6500.0);
  EXPECT_GT(warm[0], 1.3 * warm[2]);
  EXPECT_NEAR(daylight[0], daylight[2], 0.1);
  EXPECT_NEAR(luminance(warm[0], warm[1], warm[2]), 1.0f, 1e-5);
  EXPECT_NEAR(circle_of_confusion_px(0.002, 500.0, 2.0, 2.0), 0.0, 1e-12);
  EXPECT_NEAR(circle_of_confusion_px(0.002, 500.0, 2.0, 1.0), 0.5, 1e-12);
  EXPECT_EQ(linear_to_srgb(0.0f), 0);
  EXPECT_EQ(linear_to_srgb(1.0f), 255);
  EXPECT_EQ(linear_to_srgb(srgb_to_linear(128)), 128);
}

TEST(Realism, OutOfRangeOptionsAreRefused) {
  const Room r = room();
  RenderOptions options = realistic(RealismLevel::full);
  options.realism.jpeg_quality = 101;
  EXPECT_THROW(Renderer(r.world, options), std::invalid_argument);
  options = realistic(RealismLevel::full);
  options.realism.light_map_texel_m = 0.0;
  EXPECT_THROW(Renderer(r.world, options), std::invalid_argument);
}

}  // namespace
}  // namespace vsl::render

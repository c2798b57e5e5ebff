#include "vsl/localization/segment_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/synthetic_percepts.hpp"
#include "support/test_worlds.hpp"
#include "vsl/localization/localizer.hpp"

namespace vsl::localization {
namespace {

using testing::rails_kitchen;

world::ObjectModel sized(const std::string& id, const std::string& type,
                         const Eigen::Vector3d& position, const Eigen::Vector3d& size,
                         double yaw_rad) {
  world::ObjectModel o;
  o.id = id;
  o.type = type;
  o.world_position_m = position;
  o.size_m = size;
  o.world_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return o;
}

TEST(NodeSegments, ARailLiesAlongItsWidthAnUprightBarAlongItsHeightOtherTypesArePoints) {
  world::WorldModel w;
  w.objects.push_back(
      sized("rail", "handle", {1, 2, 0.8}, {0.5, 0.04, 0.014}, std::numbers::pi / 2));
  w.objects.push_back(sized("upright", "handle", {2, 2, 0.9}, {0.02, 0.04, 0.3}, 0.0));
  w.objects.push_back(sized("door", "door", {1, 2, 0.5}, {0.5, 0.02, 0.7}, 0.0));
  world::ObjectModel unsized = sized("knob", "handle", {3, 2, 0.9}, {0, 0, 0}, 0.0);
  unsized.size_m.reset();
  w.objects.push_back(unsized);
  w.index_ids();
  const LocalizerOptions options = testing::test_options();
  const world::WorldGraph graph = world::WorldGraph::build(w, options.graph);
  const NodeSegments segments = node_segments(w, graph, {"handle"});
  const std::vector<Eigen::Vector3d>& axes = segments.half_axes_m;
  EXPECT_DOUBLE_EQ(segments.longest_half_length_m, 0.25);
  ASSERT_EQ(axes.size(), graph.node_count());
  for (world::NodeIndex n = 0; n < graph.node_count(); ++n) {
    const std::string& id = w.objects[graph.object_index(n)].id;
    const std::string& type = graph.type_name(graph.type(n));
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();  // doors, edge nodes, the sizeless knob
    if (id == "rail" && type == "handle") expected = Eigen::Vector3d(0, 0.25, 0);
    if (id == "upright" && type == "handle") expected = Eigen::Vector3d(0, 0, 0.15);
    EXPECT_TRUE(axes[n].isApprox(expected, 1e-9) || (expected.isZero() && axes[n].isZero()))
        << id << " (" << type << "): " << axes[n].transpose();
  }
  // No bar types: every node a point.
  const NodeSegments points = node_segments(w, graph, {});
  for (const Eigen::Vector3d& a : points.half_axes_m) EXPECT_TRUE(a.isZero());
  EXPECT_EQ(points.longest_half_length_m, 0.0);
}

TEST(NearestOnSegment, ProjectsOntoTheAxisAndClampsToTheEnds) {
  const Eigen::Vector3d c(1, 2, 3), h(0.2, 0, 0);
  EXPECT_TRUE(nearest_on_segment(c, h, {1.1, 5, 3}).isApprox(Eigen::Vector3d(1.1, 2, 3)));
  EXPECT_TRUE(nearest_on_segment(c, h, {1.5, 2, 0}).isApprox(Eigen::Vector3d(1.2, 2, 3)));
  EXPECT_TRUE(nearest_on_segment(c, h, {0.0, 2, 3}).isApprox(Eigen::Vector3d(0.8, 2, 3)));
  EXPECT_TRUE(nearest_on_segment(c, Eigen::Vector3d::Zero(), {7, 7, 7}).isApprox(c));
}

// A view of the rails kitchen in which every rail's percept is a piece of it, placed 60 % of
// the way from the rail's middle to an end (as the learned recognizer places a rail boxed in
// pieces); everything else exact, with a covariance of 1 cm.
struct PiecesView {
  testing::SyntheticView view;
  int pieces = 0;
};

PiecesView view_with_rail_pieces(const Eigen::Isometry3d& truth) {
  testing::SyntheticOptions o;
  o.noise = false;
  o.miss_rate = 0.0;
  o.false_positive_rate = 0.0;
  PiecesView out{testing::synthesize_view(rails_kitchen(), truth, o), 0};
  for (std::size_t i = 0; i < out.view.percepts.size(); ++i) {
    // A stereo head's 1 cm, not Eq. 7's several: a piece 15 cm off is then no point of its bar.
    out.view.percepts[i].ego_covariance_m2 = 1e-4 * Eigen::Matrix3d::Identity();
    const world::ObjectModel& object = rails_kitchen().objects[*out.view.truth[i]];
    if (object.type != "handle" || !object.size_m || object.size_m->x() < 0.3) continue;
    const Eigen::Vector3d half_axis =
        object.world_orientation * Eigen::Vector3d(0.5 * object.size_m->x(), 0, 0);
    out.view.percepts[i].ego_position_m += truth.linear().transpose() * (0.6 * half_axis);
    ++out.pieces;
  }
  return out;
}

TEST(BarPieces, PiecesOfRailsAreSetAsideNotHeldAgainstTheTruePose) {
  const Eigen::Isometry3d truth = testing::upright_pose(2.3, 1.2, std::numbers::pi / 2);
  const PiecesView v = view_with_rail_pieces(truth);
  ASSERT_GE(v.pieces, 3);
  // Demanding a share of the percepts explained that only the pieces' set-aside meets.
  LocalizerOptions options = testing::test_options();
  const double n = static_cast<double>(v.view.percepts.size());
  options.validation.min_explained_fraction = (n - v.pieces + 0.5) / n;

  options.validation.segment_types = {};
  const LocalizationResult as_points =
      Localizer(rails_kitchen(), options).localize(v.view.percepts);
  EXPECT_NE(as_points.status, Status::kLocalized) << as_points.message;

  options.validation.segment_types = {"handle"};
  const LocalizationResult as_bars = Localizer(rails_kitchen(), options).localize(v.view.percepts);
  ASSERT_EQ(as_bars.status, Status::kLocalized) << as_bars.message;
  EXPECT_LT(testing::position_error_m(as_bars.world_T_ego, truth), 0.01);
  EXPECT_NE(as_bars.message.find(std::to_string(v.pieces) + " more, pieces of bars, set aside"),
            std::string::npos)
      << as_bars.message;
  // The pieces take no part in the pose: no association holds a rail pieces were seen of.
  for (const Association& a : as_bars.associations) {
    const world::ObjectModel& object = rails_kitchen().objects[a.object_index];
    EXPECT_FALSE(object.type == "handle" && object.size_m->x() >= 0.3) << object.id;
  }
}

}  // namespace
}  // namespace vsl::localization

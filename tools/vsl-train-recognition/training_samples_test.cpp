// The class model's fit and threshold rules (training_samples.hpp) on seeded synthetic samples.
#include "training_samples.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace {

using vsl::tools::ClassSamples;
using vsl::tools::train_class;
using vsl::tools::TrainedModel;

// No samples yet, for the recognizer ("door" or "handle") with a placeholder model.
ClassSamples samples_for(const std::string& recognizer) {
  ClassSamples s;
  s.file.recognizer = recognizer;
  const auto& names = vsl::recognition::descriptor_names_of(recognizer);
  const auto k = static_cast<Eigen::Index>(names.size());
  s.file.model = vsl::recognition::GaussianClassModel(recognizer, names, Eigen::VectorXd::Zero(k),
                                                      Eigen::MatrixXd::Identity(k, k), 1.0);
  return s;
}

// Handle samples: positives around one descriptor, negatives some near them and most far away.
ClassSamples handle_samples() {
  ClassSamples s = samples_for("handle");
  const auto k = static_cast<Eigen::Index>(s.file.model.component_names().size());
  std::mt19937 rng(5);
  std::normal_distribution<double> unit(0.0, 1.0);
  const auto draw = [&](double centre, double spread) {
    Eigen::VectorXd v(k);
    for (Eigen::Index i = 0; i < k; ++i) v(i) = centre + spread * unit(rng);
    return v;
  };
  for (int i = 0; i < 400; ++i) s.positives.push_back(draw(1.0, 0.1));
  for (int i = 0; i < 60; ++i) s.negatives.push_back(draw(1.25, 0.1));  // crowding the class
  for (int i = 0; i < 400; ++i) s.negatives.push_back(draw(3.0, 0.3));
  s.positive_colours.assign(s.positives.size(), Eigen::Vector3d(0.7, 0.7, 0.7));
  s.negative_colours.assign(s.negatives.size(), Eigen::Vector3d(0.2, 0.4, 0.6));
  return s;
}

double f1(const TrainedModel& t, std::size_t positives) {
  const double tp = t.kept_fraction * static_cast<double>(positives);
  return 2.0 * tp /
         (2.0 * tp + static_cast<double>(t.accepted_negatives) + static_cast<double>(positives) -
          tp);
}

TEST(TrainClass, KeepSetsTheShareOfPositivesWithin) {
  const ClassSamples s = handle_samples();
  const TrainedModel t = train_class(s, 0.9);
  EXPECT_GE(t.kept_fraction, 0.9);
  EXPECT_LT(t.kept_fraction, 0.905);
}

TEST(TrainClass, Chi2KeepsTheFitsOwnQuantile) {
  const TrainedModel t = train_class(handle_samples(), 0.0);
  EXPECT_DOUBLE_EQ(t.model.max_mahalanobis2(), t.chi_square_threshold);
}

// The F1 rule's threshold scores at least as well as every share-of-positives or chi-square one.
TEST(TrainClass, BestF1ThresholdBeatsTheOtherRules) {
  const ClassSamples s = handle_samples();
  const TrainedModel best = train_class(s, vsl::tools::kKeepBestF1);
  for (const double keep : {0.0, 0.8, 0.9, 0.95, 0.98, 0.998, 1.0}) {
    EXPECT_GE(f1(best, s.positives.size()), f1(train_class(s, keep), s.positives.size()))
        << "keep " << keep;
  }
  // The crowding negatives make it give up some positives: neither all nor the chi-square's.
  EXPECT_LT(best.kept_fraction, 1.0);
}

// Without negatives F1 would keep every positive: the fit's chi-square quantile instead.
TEST(TrainClass, BestF1WithoutNegativesIsTheChiSquareQuantile) {
  ClassSamples s = handle_samples();
  s.negatives.clear();
  s.negative_colours.clear();
  const TrainedModel t = train_class(s, vsl::tools::kKeepBestF1);
  EXPECT_DOUBLE_EQ(t.model.max_mahalanobis2(), t.chi_square_threshold);
  EXPECT_THROW(train_class(s, -0.5), std::invalid_argument);
  EXPECT_THROW(train_class(s, 1.5), std::invalid_argument);
}

// A door's ideal colour: its one colour component, the angle.
TEST(LearnIdealColour, DoorsAngleComponent) {
  ClassSamples s = samples_for("door");
  const auto k = static_cast<Eigen::Index>(s.file.model.component_names().size());
  s.positives.assign(2, Eigen::VectorXd::Constant(k, 0.5));
  s.positive_colours = {Eigen::Vector3d(0.1, 0.2, 0.5), Eigen::Vector3d(0.1, 0.2, 0.3)};
  s.negatives.assign(1, Eigen::VectorXd::Constant(k, 0.5));
  s.negative_colours = {Eigen::Vector3d(0.5, 0.2, 0.1)};
  ASSERT_TRUE(vsl::tools::learn_ideal_colour(s));
  const Eigen::Vector3d q(0.1, 0.2, 0.4);
  EXPECT_TRUE(s.file.door.ideal_colour_rgb.isApprox(q, 1e-12));
  const int c = vsl::recognition::kDoorColourAngleComponent;
  EXPECT_NEAR(s.negatives[0](c),
              vsl::recognition::colour_angle_rad(q, Eigen::Vector3d(0.5, 0.2, 0.1)), 1e-12);
  EXPECT_DOUBLE_EQ(s.positives[0](0), 0.5);  // the shape components stay
  // A black mean has no chromaticity: nothing learned.
  s.positive_colours.assign(2, Eigen::Vector3d::Zero());
  EXPECT_FALSE(vsl::tools::learn_ideal_colour(s));
}

TEST(LearnIdealColour, TheMeanOfThePositivesColoursWithTheirComponentsRecomputed) {
  ClassSamples s = handle_samples();
  s.positive_colours[0] = Eigen::Vector3d(0.6, 0.6, 0.6);
  s.positive_colours[1] = Eigen::Vector3d(0.8, 0.8, 0.8);
  ASSERT_TRUE(vsl::tools::learn_ideal_colour(s));
  EXPECT_TRUE(s.file.handle.ideal_colour_rgb.isApprox(Eigen::Vector3d(0.7, 0.7, 0.7), 1e-12));
  // A positive of the ideal colour: angle and distance 0; a negative: its own.
  EXPECT_NEAR(s.positives[5](vsl::recognition::kHandleColourAngleComponent), 0.0, 1e-6);
  EXPECT_NEAR(s.positives[5](vsl::recognition::kHandleColourDistanceComponent), 0.0, 1e-12);
  EXPECT_NEAR(s.negatives[0](vsl::recognition::kHandleColourDistanceComponent),
              (Eigen::Vector3d(0.7, 0.7, 0.7) - Eigen::Vector3d(0.2, 0.4, 0.6)).norm(), 1e-12);
  // Nothing to learn from: unchanged.
  ClassSamples none = handle_samples();
  none.positives.clear();
  none.positive_colours.clear();
  const Eigen::Vector3d before = none.file.handle.ideal_colour_rgb;
  EXPECT_FALSE(vsl::tools::learn_ideal_colour(none));
  EXPECT_EQ(none.file.handle.ideal_colour_rgb, before);
}

}  // namespace

// Gaussian class models: chi-square, fit, Mahalanobis threshold, held-out samples, model files.
#include "vsl/recognition/class_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "vsl/config/node.hpp"
#include "vsl/recognition/descriptors.hpp"
#include "vsl/recognition/recognizer_factory.hpp"

namespace vsl::recognition {
namespace {

const std::vector<std::string> kNames{"x", "y", "z"};

// `count` samples of N(mean, covariance), seeded.
std::vector<Eigen::VectorXd> gaussian_samples(const Eigen::VectorXd& mean,
                                              const Eigen::MatrixXd& covariance, int count,
                                              unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  const Eigen::MatrixXd l = covariance.llt().matrixL();
  std::vector<Eigen::VectorXd> out;
  for (int i = 0; i < count; ++i) {
    Eigen::VectorXd z(mean.size());
    for (Eigen::Index j = 0; j < z.size(); ++j) z(j) = normal(rng);
    out.push_back(mean + l * z);
  }
  return out;
}

Eigen::MatrixXd test_covariance() {
  Eigen::MatrixXd c(3, 3);
  c << 0.04, 0.01, 0.0,   //
      0.01, 0.09, -0.02,  //
      0.0, -0.02, 0.25;
  return c;
}

TEST(ChiSquare, KnownValues) {
  // k = 2: P(chi^2 >= x) = exp(-x / 2) exactly.
  for (const double x : {0.1, 1.0, 5.0, 30.0}) {
    EXPECT_NEAR(chi_square_survival(x, 2), std::exp(-x / 2.0), 1e-13);
  }
  EXPECT_NEAR(chi_square_survival(3.841458820694124, 1), 0.05, 1e-12);
  EXPECT_NEAR(chi_square_survival(11.344866730144373, 3), 0.01, 1e-12);
  EXPECT_NEAR(chi_square_quantile(0.99, 7), 18.475306906582357, 1e-8);
  EXPECT_NEAR(chi_square_quantile(0.95, 1), 3.841458820694124, 1e-8);
  EXPECT_DOUBLE_EQ(chi_square_survival(0.0, 3), 1.0);
  EXPECT_THROW(chi_square_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(chi_square_survival(1.0, 0), std::invalid_argument);
}

TEST(ClassModel, FitRecoversTheDistribution) {
  const Eigen::Vector3d mean(1.0, -2.0, 0.5);
  const auto samples = gaussian_samples(mean, test_covariance(), 20000, 1);
  ClassModelFitOptions options;
  options.min_stddev = {1e-4, 1e-4, 1e-4};
  const GaussianClassModel model = fit_class_model("thing", kNames, samples, options);
  EXPECT_EQ(model.type(), "thing");
  EXPECT_EQ(model.dimension(), 3);
  EXPECT_LT((model.mean() - mean).norm(), 0.01);
  EXPECT_LT((model.covariance() - test_covariance()).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_NEAR(model.max_mahalanobis2(), chi_square_quantile(0.99, 3), 1e-9);
  EXPECT_NEAR(model.mahalanobis2(model.mean()), 0.0, 1e-20);
  EXPECT_NEAR(model.confidence(0.0), 1.0, 1e-12);
  // One standard deviation along an eigenvector of the covariance is D^2 = 1.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(model.covariance());
  const Eigen::VectorXd one_sigma =
      model.mean() + std::sqrt(eigen.eigenvalues()(2)) * eigen.eigenvectors().col(2);
  EXPECT_NEAR(model.mahalanobis2(one_sigma), 1.0, 1e-9);
  EXPECT_TRUE(model.accepts(model.max_mahalanobis2()));
  EXPECT_FALSE(model.accepts(model.max_mahalanobis2() * 1.0001));
  EXPECT_NEAR(model.confidence(model.max_mahalanobis2()), 0.01, 1e-9);
  EXPECT_THROW(model.mahalanobis2(Eigen::VectorXd::Zero(2)), std::invalid_argument);
}

TEST(ClassModel, VarianceFloorKeepsFewSamplesRegular) {
  const std::vector<Eigen::VectorXd> one{Eigen::Vector3d(1.0, 2.0, 3.0)};
  ClassModelFitOptions options;
  options.min_stddev = {0.1, 0.2, 0.3};
  const GaussianClassModel model = fit_class_model("thing", kNames, one, options);
  EXPECT_NEAR(model.covariance()(0, 0), 0.01, 1e-15);
  EXPECT_NEAR(model.covariance()(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(model.covariance()(2, 2), 0.09, 1e-15);
  EXPECT_NEAR(model.mahalanobis2(Eigen::Vector3d(1.1, 2.0, 3.0)), 1.0, 1e-9);
  // A constant component in many samples is floored too.
  const std::vector<Eigen::VectorXd> constant(10, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_NO_THROW(fit_class_model("thing", kNames, constant, options));
  // Bad input.
  EXPECT_THROW(fit_class_model("thing", kNames, {}, options), std::invalid_argument);
  EXPECT_THROW(fit_class_model("thing", kNames, {Eigen::Vector2d(1, 2)}, options),
               std::invalid_argument);
  options.min_stddev = {0.1, 0.2};
  EXPECT_THROW(fit_class_model("thing", kNames, one, options), std::invalid_argument);
  options.min_stddev = {0.1, 0.0, 0.1};
  EXPECT_THROW(fit_class_model("thing", kNames, one, options), std::invalid_argument);
}

TEST(ClassModel, HeldOutSamplesAcceptedShiftedOnesRejected) {
  const Eigen::Vector3d mean(1.0, -2.0, 0.5);
  const GaussianClassModel model =
      fit_class_model("thing", kNames, gaussian_samples(mean, test_covariance(), 300, 7));
  const auto accepted_fraction = [&](const std::vector<Eigen::VectorXd>& samples) {
    int accepted = 0;
    for (const Eigen::VectorXd& sample : samples) {
      accepted += model.accepts(model.mahalanobis2(sample)) ? 1 : 0;
    }
    return static_cast<double>(accepted) / static_cast<double>(samples.size());
  };
  EXPECT_GE(accepted_fraction(gaussian_samples(mean, test_covariance(), 2000, 8)), 0.95);
  // Six standard deviations away along the first component.
  const Eigen::Vector3d shifted = mean + Eigen::Vector3d(6.0 * 0.2, 0.0, 0.0);
  EXPECT_LE(accepted_fraction(gaussian_samples(shifted, test_covariance(), 2000, 9)), 0.05);
}

TEST(ClassModel, ConstructorValidates) {
  const Eigen::Vector3d mean(0, 0, 0);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  EXPECT_NO_THROW(GaussianClassModel("t", kNames, mean, identity, 1.0));
  EXPECT_THROW(GaussianClassModel("t", {"x", "y"}, mean, identity, 1.0), std::invalid_argument);
  Eigen::Matrix3d asymmetric = identity;
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(GaussianClassModel("t", kNames, mean, asymmetric, 1.0), std::invalid_argument);
  Eigen::Matrix3d singular = identity;
  singular(2, 2) = 0.0;
  EXPECT_THROW(GaussianClassModel("t", kNames, mean, singular, 1.0), std::invalid_argument);
  EXPECT_THROW(GaussianClassModel("t", kNames, Eigen::Vector3d(0, NAN, 0), identity, 1.0),
               std::invalid_argument);
  EXPECT_THROW(GaussianClassModel("t", kNames, mean, identity, 0.0), std::invalid_argument);
}

// --- Model files -------------------------------------------------------------------------

RecognizerFile handle_file() {
  RecognizerFile file;
  file.recognizer = "handle";
  const auto samples = gaussian_samples(Eigen::Vector3d(5.0, 0.05, 0.1),
                                        Eigen::Vector3d(0.3, 0.001, 0.002).asDiagonal(), 50, 3);
  ClassModelFitOptions options = default_fit_options("handle");
  options.provenance = "test \"quoted\" provenance, with: colons";
  file.model = fit_class_model("handle", handle_descriptor_names(), samples, options);
  file.handle.min_blob_px = 20;
  file.handle.corners.block_size_px = 4;
  file.handle.corners.min_end_corner_fraction = 0.1234567890123;
  file.handle.verify_corners = false;
  file.handle.ideal_colour_rgb = Eigen::Vector3d(0.7, 0.6, 0.2);
  return file;
}

TEST(ModelFile, RoundTripIsExact) {
  const RecognizerFile file = handle_file();
  std::ostringstream text;
  write_recognizer_file(text, file);
  const RecognizerFile back =
      recognizer_file_from(config::Node::load_string(text.str(), "handle.yaml"));
  EXPECT_EQ(back.recognizer, "handle");
  EXPECT_EQ(back.model.type(), "handle");
  EXPECT_EQ(back.model.provenance(), file.model.provenance());
  EXPECT_EQ(back.model.component_names(), handle_descriptor_names());
  EXPECT_EQ(back.model.mean(), file.model.mean());              // bit for bit
  EXPECT_EQ(back.model.covariance(), file.model.covariance());  // bit for bit
  EXPECT_EQ(back.model.max_mahalanobis2(), file.model.max_mahalanobis2());
  EXPECT_EQ(back.handle.min_blob_px, 20);
  EXPECT_EQ(back.handle.corners.block_size_px, 4);
  EXPECT_EQ(back.handle.corners.min_end_corner_fraction, 0.1234567890123);
  EXPECT_FALSE(back.handle.verify_corners);
  EXPECT_EQ(back.handle.ideal_colour_rgb, file.handle.ideal_colour_rgb);

  // And through a file on disk, for a door model.
  RecognizerFile door;
  door.recognizer = "door";
  door.model = fit_class_model("door", door_descriptor_names(),
                               {Eigen::VectorXd::Constant(kDoorDescriptorSize, 1.0)},
                               default_fit_options("door"));
  door.door.min_blob_px = 123;
  door.door.detect_border_cut = true;
  const std::string path =
      (std::filesystem::path(testing::TempDir()) / "vsl_class_model_test_door.yaml").string();
  save_recognizer_file(door, path);
  const RecognizerFile door_back = read_recognizer_file(path);
  EXPECT_EQ(door_back.recognizer, "door");
  EXPECT_EQ(door_back.model.covariance(), door.model.covariance());
  EXPECT_EQ(door_back.door.min_blob_px, 123);
  EXPECT_TRUE(door_back.door.detect_border_cut);
  std::filesystem::remove(path);
  EXPECT_THROW(save_recognizer_file(door, "/nonexistent-dir/door.yaml"), std::runtime_error);
}

TEST(ModelFile, ShippedModelsLoad) {
  const auto recognizers =
      load_recognizers({"config/recognition/door.yaml", "config/recognition/handle.yaml"});
  ASSERT_EQ(recognizers.size(), 2u);
  EXPECT_EQ(recognizers[0]->type(), "door");
  EXPECT_EQ(recognizers[1]->type(), "handle");
  EXPECT_NE(dynamic_cast<const DoorRecognizer*>(recognizers[0].get()), nullptr);
  EXPECT_NE(dynamic_cast<const HandleRecognizer*>(recognizers[1].get()), nullptr);
  EXPECT_FALSE(read_recognizer_file("config/recognition/door.yaml").model.provenance().empty());
}

TEST(ModelFile, SameTypeTwiceIsAnError) {
  try {
    load_recognizers({"config/recognition/door.yaml", "config/recognition/door.yaml"});
    FAIL() << "no error";
  } catch (const config::Error& e) {
    EXPECT_NE(std::string(e.what()).find("config/recognition/door.yaml:4: type: type 'door' is "
                                         "already recognized by config/recognition/door.yaml"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(load_recognizer("config/recognition/no_such_model.yaml"), config::Error);
}

// The text of a valid handle model file, for the validation cases to break.
std::string valid_text() {
  std::ostringstream text;
  write_recognizer_file(text, handle_file());
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Loading `text` fails with a one-line message starting "m.yaml:<line>: <key>: " and containing
// `what`.
void expect_error(const std::string& text, const std::string& key, const std::string& what) {
  try {
    recognizer_file_from(config::Node::load_string(text, "m.yaml"));
    ADD_FAILURE() << "no error for " << key << ": " << what;
  } catch (const config::Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("m.yaml:", 0), 0u) << message;
    EXPECT_NE(message.find(": " + key + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

TEST(ModelFile, EveryValidationError) {
  const std::string text = valid_text();
  EXPECT_NO_THROW(recognizer_file_from(config::Node::load_string(text, "m.yaml")));
  expect_error(text + "colour: red\n", "colour", "unknown key");
  expect_error(replaced(text, "recognizer: handle", "recognizer: window"), "recognizer",
               "unknown recognizer 'window'");
  expect_error(replaced(text, "recognizer: handle\n", ""), "recognizer", "missing required key");
  expect_error(replaced(text, "type: handle\n", ""), "type", "missing required key");
  expect_error(replaced(text, "colour_angle_rad, colour_distance", "colour_distance"),
               "model.descriptor", "expected the components");
  expect_error(replaced(text, "log_eigenvalue_ratio, colour_angle_rad",
                        "colour_angle_rad, log_eigenvalue_ratio"),
               "model.descriptor", "in this order");
  expect_error(replaced(text, "  mean: [", "  mean: [1, "), "model.mean",
               "expected 3 numbers, got 4");
  expect_error(replaced(text, "  mean: [", "  mean: [.nan, "), "model.mean[0]",
               "expected a number");
  // Covariance: a missing row, a short row, asymmetric, not positive definite, non-finite.
  const std::string covariance_block = text.substr(
      text.find("  covariance:\n"), text.find("  max_mahalanobis2") - text.find("  covariance:\n"));
  expect_error(
      replaced(text, covariance_block, "  covariance:\n    - [1, 0, 0]\n    - [0, 1, 0]\n"),
      "model.covariance", "expected 3 rows of 3 numbers");
  expect_error(replaced(text, covariance_block,
                        "  covariance:\n    - [1, 0, 0]\n    - [0, 1]\n    - [0, 0, 1]\n"),
               "model.covariance[1]", "expected 3 numbers, got 2");
  expect_error(replaced(text, covariance_block,
                        "  covariance:\n    - [1, 0.5, 0]\n    - [0, 1, 0]\n    - [0, 0, 1]\n"),
               "model.covariance", "must be symmetric, element [0][1] is 0.5 but [1][0] is 0");
  expect_error(replaced(text, covariance_block,
                        "  covariance:\n    - [1, 2, 0]\n    - [2, 1, 0]\n    - [0, 0, 1]\n"),
               "model.covariance", "must be positive definite, its smallest eigenvalue is -0.99");
  expect_error(replaced(text, covariance_block,
                        "  covariance:\n    - [1, 0, 0]\n    - [0, .inf, 0]\n    - [0, 0, 1]\n"),
               "model.covariance[1][1]", "expected a number");
  expect_error(replaced(text, covariance_block, "  covariance: 3\n"), "model.covariance",
               "expected 3 rows");
  expect_error(replaced(text, "max_mahalanobis2: ", "max_mahalanobis2: -"),
               "model.max_mahalanobis2", "must be > 0");
  expect_error(replaced(text, "model:\n", "model:\n  extra: 1\n"), "model.extra", "unknown key");
  // Parameters.
  expect_error(replaced(text, "parameters:\n", "parameters:\n  colour: 1\n"), "parameters.colour",
               "unknown key");
  expect_error(replaced(text, "ideal_colour_rgb: [0.7,", "ideal_colour_rgb: [1.7,"),
               "parameters.ideal_colour_rgb", "expected RGB in [0, 1]");
  expect_error(replaced(text, "ideal_colour_rgb: [0.7, 0.6, 0.2]", "ideal_colour_rgb: [0, 0, 0]"),
               "parameters.ideal_colour_rgb", "must not be black");
  expect_error(replaced(text, "min_blob_px: 20", "min_blob_px: 0"), "parameters.min_blob_px",
               "must be an integer in [1, ");
  expect_error(replaced(text, "max_blob_px: 20000", "max_blob_px: 10"), "parameters.max_blob_px",
               "must be an integer in [20, ");
  expect_error(replaced(text, "block_size_px: 4", "block_size_px: 9"),
               "parameters.corner_verification.block_size_px", "must be an integer in [2, 7]");
  expect_error(replaced(text, "verify_corners: false", "verify_corners: maybe"),
               "parameters.verify_corners", "");
  expect_error(replaced(text, "  corner_verification:\n", "  corner_verification:\n    x: 1\n"),
               "parameters.corner_verification.x", "unknown key");
  // A door file's parameters.
  std::ostringstream door_text;
  RecognizerFile door;
  door.recognizer = "door";
  door.model = fit_class_model("door", door_descriptor_names(),
                               {Eigen::VectorXd::Constant(kDoorDescriptorSize, 1.0)},
                               default_fit_options("door"));
  write_recognizer_file(door_text, door);
  expect_error(replaced(door_text.str(), "min_border_distance_px: 1", "min_border_distance_px: -1"),
               "parameters.min_border_distance_px", "must be an integer in [0, 1000]");
  expect_error(replaced(door_text.str(), "recognizer: door", "recognizer: handle"),
               "model.descriptor", "expected the components");
  // Border-cut doors: a boolean, off unless given.
  EXPECT_FALSE(recognizer_file_from(config::Node::load_string(door_text.str(), "m.yaml"))
                   .door.detect_border_cut);
  expect_error(replaced(door_text.str(), "min_border_distance_px: 1",
                        "min_border_distance_px: 1\n  detect_border_cut: 3"),
               "parameters.detect_border_cut", "expected true or false");
  // Border-cut blobs are the ones min_border_distance_px finds at the border: 0 finds none.
  expect_error(replaced(door_text.str(), "min_border_distance_px: 1",
                        "min_border_distance_px: 0\n  detect_border_cut: true"),
               "parameters.detect_border_cut", "needs min_border_distance_px >= 1");
}

}  // namespace
}  // namespace vsl::recognition

// Gaussian class model (paper §2.1: "gaussian classification over characteristic feature
// spaces"): a class is the normal distribution N(mean, covariance) of its descriptor (Eq. 2 for
// doors, Eq. 3 for handles). A blob is accepted when the squared Mahalanobis distance of its
// descriptor, D^2 = (V - mean)^T covariance^-1 (V - mean), is at most max_mahalanobis2; its
// confidence is the chi-square survival probability P(chi^2_k >= D^2), k the descriptor size:
// the fraction of true class members that lie farther out than this blob.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

class GaussianClassModel {
 public:
  GaussianClassModel() = default;
  // Throws std::invalid_argument unless the sizes agree (names, mean, square covariance), every
  // value is finite, the covariance is symmetric positive definite and the threshold positive.
  GaussianClassModel(std::string type, std::vector<std::string> component_names,
                     Eigen::VectorXd mean, Eigen::MatrixXd covariance, double max_mahalanobis2,
                     std::string provenance = "");

  const std::string& type() const { return type_; }
  const std::vector<std::string>& component_names() const { return component_names_; }
  int dimension() const { return static_cast<int>(mean_.size()); }
  const Eigen::VectorXd& mean() const { return mean_; }
  const Eigen::MatrixXd& covariance() const { return covariance_; }
  double max_mahalanobis2() const { return max_mahalanobis2_; }
  // Free text: how the model was made (hand-set, or trained on which images by which tool).
  const std::string& provenance() const { return provenance_; }
  void set_provenance(std::string provenance) { provenance_ = std::move(provenance); }
  void set_max_mahalanobis2(double max_mahalanobis2);

  // D^2 of a descriptor of this model's dimension (throws std::invalid_argument otherwise).
  double mahalanobis2(const Eigen::VectorXd& descriptor) const;
  bool accepts(double mahalanobis2) const { return mahalanobis2 <= max_mahalanobis2_; }
  // P(chi^2_k >= D^2), 0 .. 1.
  double confidence(double mahalanobis2) const;

 private:
  std::string type_;
  std::vector<std::string> component_names_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd covariance_;
  Eigen::LLT<Eigen::MatrixXd> covariance_llt_;
  double max_mahalanobis2_ = 0.0;
  std::string provenance_;
};

struct ClassModelFitOptions {
  // Floor on the standard deviation of each component (descriptor units), added as a variance to
  // the diagonal of the sample covariance: a model fitted from few (even one) samples, or from a
  // component that happens to be constant in the training set, stays positive definite and does
  // not reject the first slightly different blob. Empty: 1e-3 for every component; otherwise one
  // value per component, each > 0.
  std::vector<double> min_stddev;
  // The threshold is the chi-square quantile of this probability: the fraction of the class's
  // own members (if the class is Gaussian) that the model accepts.
  double acceptance_probability = 0.99;
  std::string provenance;
};

// Fits mean and (regularized) covariance to positive samples, all of size component_names.size().
// Throws std::invalid_argument for no samples, mismatching sizes or non-finite values.
GaussianClassModel fit_class_model(std::string type, std::vector<std::string> component_names,
                                   const std::vector<Eigen::VectorXd>& samples,
                                   const ClassModelFitOptions& options = {});

// Chi-square distribution with k degrees of freedom: survival function P(chi^2_k >= x) and its
// inverse (the x with P(chi^2_k <= x) = p), by the regularized incomplete gamma function.
double chi_square_survival(double x, int degrees_of_freedom);
double chi_square_quantile(double p, int degrees_of_freedom);

// Reads a model section of a model file (format: config/recognition/door.yaml):
//   descriptor: [names...]        the component names, which must equal `expected_names`
//   mean: [...]                   one number per component
//   covariance: [[...], ...]      k x k, symmetric positive definite
//   max_mahalanobis2: 18.5        > 0
// `type` and `provenance` come from the file's top level. Errors: config::Error
// "file:line: key: what".
GaussianClassModel class_model_from(const config::Node& section, const std::string& type,
                                    const std::string& provenance,
                                    const std::vector<std::string>& expected_names);

// Writes the same keys, each line prefixed by `indent`, numbers in their shortest exact form (so
// that a written model reads back bit for bit).
void write_class_model(std::ostream& out, const GaussianClassModel& model,
                       const std::string& indent);

// Shortest text that reads back to exactly `value` (std::to_chars), for the model files.
std::string exact_number(double value);

}  // namespace vsl::recognition

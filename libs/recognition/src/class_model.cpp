// Gaussian class model: fit, Mahalanobis distance, chi-square confidence, YAML reading and
// writing (class_model.hpp).
#include "vsl/recognition/class_model.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include "vsl/config/node.hpp"

namespace vsl::recognition {
namespace {

// Regularized lower incomplete gamma P(a, x) by its series (x < a + 1) and the upper one
// Q(a, x) by Lentz's continued fraction otherwise (Numerical Recipes §6.2); both to 1e-15.
double gamma_p_series(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < 1000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-16) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double gamma_q_continued_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

void check_finite(const Eigen::MatrixXd& m, const char* what) {
  if (!m.allFinite())
    throw std::invalid_argument(std::string("GaussianClassModel: ") + what +
                                " has a non-finite value");
}

// Empty when `covariance` is a symmetric positive definite matrix, else what is wrong.
std::string covariance_problem(const Eigen::MatrixXd& covariance) {
  for (Eigen::Index i = 0; i < covariance.rows(); ++i) {
    for (Eigen::Index j = i + 1; j < covariance.cols(); ++j) {
      const double a = covariance(i, j);
      const double b = covariance(j, i);
      if (std::abs(a - b) > 1e-9 * std::max({std::abs(a), std::abs(b), 1e-300})) {
        return "must be symmetric, element [" + std::to_string(i) + "][" + std::to_string(j) +
               "] is " + exact_number(a) + " but [" + std::to_string(j) + "][" + std::to_string(i) +
               "] is " + exact_number(b);
      }
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance, Eigen::EigenvaluesOnly);
  const double smallest = eigen.eigenvalues().minCoeff();
  if (!(smallest > 0.0)) {
    return "must be positive definite, its smallest eigenvalue is " + exact_number(smallest);
  }
  return "";
}

}  // namespace

std::string exact_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

double chi_square_survival(double x, int degrees_of_freedom) {
  if (degrees_of_freedom < 1) throw std::invalid_argument("chi_square_survival: k < 1");
  if (!(x > 0.0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  const double a = 0.5 * degrees_of_freedom;
  const double half_x = 0.5 * x;
  if (half_x < a + 1.0) return std::clamp(1.0 - gamma_p_series(a, half_x), 0.0, 1.0);
  return std::clamp(gamma_q_continued_fraction(a, half_x), 0.0, 1.0);
}

double chi_square_quantile(double p, int degrees_of_freedom) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("chi_square_quantile: p not in (0, 1)");
  // Bisection on the monotone CDF; the bracket doubles until it holds the quantile.
  double low = 0.0;
  double high = std::max(1.0, 2.0 * degrees_of_freedom);
  while (1.0 - chi_square_survival(high, degrees_of_freedom) < p) high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
    const double mid = 0.5 * (low + high);
    if (1.0 - chi_square_survival(mid, degrees_of_freedom) < p) {
      low = mid;
    } else {
      high = mid;
    }
  }
  return 0.5 * (low + high);
}

GaussianClassModel::GaussianClassModel(std::string type, std::vector<std::string> component_names,
                                       Eigen::VectorXd mean, Eigen::MatrixXd covariance,
                                       double max_mahalanobis2, std::string provenance)
    : type_(std::move(type)),
      component_names_(std::move(component_names)),
      mean_(std::move(mean)),
      covariance_(std::move(covariance)),
      provenance_(std::move(provenance)) {
  const auto k = static_cast<Eigen::Index>(component_names_.size());
  if (k == 0 || mean_.size() != k || covariance_.rows() != k || covariance_.cols() != k) {
    throw std::invalid_argument("GaussianClassModel: " + std::to_string(k) +
                                " component names, a mean of size " + std::to_string(mean_.size()) +
                                " and a " + std::to_string(covariance_.rows()) + "x" +
                                std::to_string(covariance_.cols()) + " covariance do not agree");
  }
  check_finite(mean_, "the mean");
  check_finite(covariance_, "the covariance");
  if (const std::string problem = covariance_problem(covariance_); !problem.empty()) {
    throw std::invalid_argument("GaussianClassModel: the covariance " + problem);
  }
  covariance_llt_.compute(covariance_);
  set_max_mahalanobis2(max_mahalanobis2);
}

void GaussianClassModel::set_max_mahalanobis2(double max_mahalanobis2) {
  if (!(max_mahalanobis2 > 0.0) || !std::isfinite(max_mahalanobis2)) {
    throw std::invalid_argument("GaussianClassModel: max_mahalanobis2 must be finite and > 0");
  }
  max_mahalanobis2_ = max_mahalanobis2;
}

double GaussianClassModel::mahalanobis2(const Eigen::VectorXd& descriptor) const {
  if (descriptor.size() != mean_.size()) {
    throw std::invalid_argument("GaussianClassModel::mahalanobis2: descriptor of size " +
                                std::to_string(descriptor.size()) + ", model of size " +
                                std::to_string(mean_.size()));
  }
  // D^2 = |L^-1 (V - mean)|^2 with covariance = L L^T.
  const Eigen::VectorXd whitened = covariance_llt_.matrixL().solve(descriptor - mean_);
  return whitened.squaredNorm();
}

double GaussianClassModel::confidence(double mahalanobis2) const {
  return chi_square_survival(mahalanobis2, dimension());
}

GaussianClassModel fit_class_model(std::string type, std::vector<std::string> component_names,
                                   const std::vector<Eigen::VectorXd>& samples,
                                   const ClassModelFitOptions& options) {
  const auto k = static_cast<Eigen::Index>(component_names.size());
  if (samples.empty()) throw std::invalid_argument("fit_class_model: no samples");
  if (!options.min_stddev.empty() && static_cast<Eigen::Index>(options.min_stddev.size()) != k) {
    throw std::invalid_argument("fit_class_model: min_stddev needs one value per component");
  }
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(k);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].size() != k || !samples[i].allFinite()) {
      throw std::invalid_argument("fit_class_model: sample " + std::to_string(i) +
                                  " is not a finite vector of size " + std::to_string(k));
    }
    mean += samples[i];
  }
  mean /= static_cast<double>(samples.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(k, k);
  for (const Eigen::VectorXd& sample : samples) {
    const Eigen::VectorXd d = sample - mean;
    covariance += d * d.transpose();
  }
  // Unbiased; a single sample has no spread of its own and gets the floor alone.
  if (samples.size() > 1) covariance /= static_cast<double>(samples.size() - 1);
  for (Eigen::Index i = 0; i < k; ++i) {
    const double floor = options.min_stddev.empty() ? 1e-3 : options.min_stddev[i];
    if (!(floor > 0.0) || !std::isfinite(floor)) {
      throw std::invalid_argument("fit_class_model: min_stddev must be finite and > 0");
    }
    covariance(i, i) += floor * floor;
  }
  if (!(options.acceptance_probability > 0.0 && options.acceptance_probability < 1.0)) {
    throw std::invalid_argument("fit_class_model: acceptance_probability not in (0, 1)");
  }
  const double threshold = chi_square_quantile(options.acceptance_probability, static_cast<int>(k));
  return GaussianClassModel(std::move(type), std::move(component_names), std::move(mean),
                            std::move(covariance), threshold, options.provenance);
}

GaussianClassModel class_model_from(const config::Node& section, const std::string& type,
                                    const std::string& provenance,
                                    const std::vector<std::string>& expected_names) {
  section.expect_map();
  section.expect_keys({"descriptor", "mean", "covariance", "max_mahalanobis2"});
  const config::Node names_node = section.at("descriptor");
  if (!names_node.is_sequence()) names_node.fail("expected a list of component names");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < names_node.size(); ++i) names.push_back(names_node[i].as_string());
  if (names != expected_names) {
    std::string expected;
    for (const std::string& name : expected_names)
      expected += (expected.empty() ? "" : ", ") + name;
    names_node.fail("expected the components [" + expected + "] in this order");
  }
  const auto k = static_cast<Eigen::Index>(names.size());

  const config::Node mean_node = section.at("mean");
  const std::vector<double> mean_values = mean_node.as_doubles();
  if (static_cast<Eigen::Index>(mean_values.size()) != k) {
    mean_node.fail("expected " + std::to_string(k) + " numbers, got " +
                   std::to_string(mean_values.size()));
  }
  const Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd>(mean_values.data(), k);

  const config::Node covariance_node = section.at("covariance");
  if (!covariance_node.is_sequence() || static_cast<Eigen::Index>(covariance_node.size()) != k) {
    covariance_node.fail("expected " + std::to_string(k) + " rows of " + std::to_string(k) +
                         " numbers");
  }
  Eigen::MatrixXd covariance(k, k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const config::Node row_node = covariance_node[static_cast<std::size_t>(i)];
    const std::vector<double> row = row_node.as_doubles();
    if (static_cast<Eigen::Index>(row.size()) != k) {
      row_node.fail("expected " + std::to_string(k) + " numbers, got " +
                    std::to_string(row.size()));
    }
    for (Eigen::Index j = 0; j < k; ++j) covariance(i, j) = row[static_cast<std::size_t>(j)];
  }
  if (const std::string problem = covariance_problem(covariance); !problem.empty()) {
    covariance_node.fail(problem);
  }
  const config::Node threshold_node = section.at("max_mahalanobis2");
  const double threshold = threshold_node.as_double();
  if (!(threshold > 0.0)) threshold_node.fail("must be > 0");
  return GaussianClassModel(type, std::move(names), mean, covariance, threshold, provenance);
}

void write_class_model(std::ostream& out, const GaussianClassModel& model,
                       const std::string& indent) {
  out << indent << "descriptor: [";
  for (std::size_t i = 0; i < model.component_names().size(); ++i) {
    out << (i > 0 ? ", " : "") << model.component_names()[i];
  }
  out << "]\n" << indent << "mean: [";
  for (Eigen::Index i = 0; i < model.mean().size(); ++i) {
    out << (i > 0 ? ", " : "") << exact_number(model.mean()(i));
  }
  out << "]\n" << indent << "covariance:\n";
  for (Eigen::Index i = 0; i < model.covariance().rows(); ++i) {
    out << indent << "  - [";
    for (Eigen::Index j = 0; j < model.covariance().cols(); ++j) {
      out << (j > 0 ? ", " : "") << exact_number(model.covariance()(i, j));
    }
    out << "]\n";
  }
  out << indent << "max_mahalanobis2: " << exact_number(model.max_mahalanobis2()) << "\n";
}

}  // namespace vsl::recognition

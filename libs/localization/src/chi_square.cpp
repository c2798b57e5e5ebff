#include "vsl/localization/chi_square.hpp"

#include <cmath>
#include <stdexcept>

namespace vsl::localization {
namespace {

// The chi^2(k) CDF, P(k / 2, x / 2), the regularized lower incomplete gamma function from its
// series P(a, y) = y^a e^-y sum_n y^n / Gamma(a + n + 1), which converges for every y (slowly
// beyond y ~ 50, far past any quantile asked for here).
double chi_square_cdf(int dof, double x) {
  const double a = 0.5 * dof, y = 0.5 * x;
  if (y <= 0.0) return 0.0;
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 1000 && term > 1e-16 * sum; ++n) {
    term *= y / (a + n);
    sum += term;
  }
  return std::exp(a * std::log(y) - y - std::lgamma(a)) * sum;
}

}  // namespace

double chi_square_quantile(int dof, double alpha) {
  if (dof < 1 || dof > 20 || !(alpha > 0.0 && alpha < 1.0)) {
    throw std::invalid_argument("chi_square_quantile: dof in [1, 20] and alpha in (0, 1)");
  }
  double lo = 0.0, hi = 200.0;  // the CDF increases in x; 200 lies beyond every quantile asked
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (chi_square_cdf(dof, mid) < 1.0 - alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace vsl::localization

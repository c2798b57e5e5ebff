// Quantiles of the chi-square distribution, the thresholds of the localizer's consistency tests
// (deleted_residuals.hpp, pose_agreement.hpp).
#pragma once

namespace vsl::localization {

// The chi^2(dof) quantile of probability 1 - alpha: the threshold a test with false-alarm
// probability alpha compares a squared Mahalanobis distance of `dof` dimensions with.
// Throws std::invalid_argument unless dof in [1, 20] and alpha in (0, 1).
double chi_square_quantile(int dof, double alpha);

}  // namespace vsl::localization

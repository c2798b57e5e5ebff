// A least-squares fit of six parameters to a few dozen residuals, as the fits of partly seen
// objects and the learned recognizer's door fit solve it (partly_seen_door.cpp,
// partly_seen_bar.cpp, door_rectangle_fit.cpp): Ceres' TinySolver (dense
// Levenberg-Marquardt on one functor of all residuals, without the general solver's set-up per
// problem), and the inverse information matrix (J^T J)^-1 at the solution for the covariance.
// Internal to vsl_recognition.
#pragma once

#include <ceres/tiny_solver.h>
#include <ceres/tiny_solver_autodiff_function.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <optional>

namespace vsl::recognition::detail {

struct SmallFit {
  Eigen::Matrix<double, 6, 1> x;
  Eigen::VectorXd residuals;
  // (J^T J)^-1 at x; nullopt where J^T J is singular (a direction of x no residual measures).
  std::optional<Eigen::Matrix<double, 6, 6>> inverse_information;
};

// Minimizes the squared residuals of `cost` from `start`: Cost has NumResiduals() and a templated
// bool operator()(const T* x, T* residuals). nullopt when the solution is not finite or the functor
// fails there.
template <class Cost>
std::optional<SmallFit> solve_small(const Cost& cost, const Eigen::Matrix<double, 6, 1>& start,
                                    int max_iterations) {
  using Function = ceres::TinySolverAutoDiffFunction<Cost, Eigen::Dynamic, 6>;
  const Function function(cost);
  ceres::TinySolver<Function> solver;
  solver.options.max_num_iterations = max_iterations;
  SmallFit fit;
  fit.x = start;
  solver.Solve(function, &fit.x);
  fit.residuals.resize(function.NumResiduals());
  Eigen::MatrixXd jacobian(function.NumResiduals(), 6);
  if (!fit.x.allFinite() || !function(fit.x.data(), fit.residuals.data(), jacobian.data())) {
    return std::nullopt;
  }
  const Eigen::Matrix<double, 6, 6> information = jacobian.transpose() * jacobian;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(information);
  if (ldlt.info() == Eigen::Success && ldlt.isPositive() &&
      ldlt.vectorD().minCoeff() > 1e-9 * ldlt.vectorD().maxCoeff()) {
    fit.inverse_information = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  }
  return fit;
}

}  // namespace vsl::recognition::detail

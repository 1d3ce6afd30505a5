#pragma once
// Levenberg-Marquardt least squares for the identifications (rail_identification,
// dc_axis_identification): minimises ||r(p)||^2 over a few parameters, each step an Eigen LDLT
// solve of the damped normal equations (J'J + lambda diag(J'J)) dp = J'r, the Jacobian by
// forward differences (the models are simulations with stick-slip, not closed forms).
#include <Eigen/Dense>
#include <functional>

namespace trilho {

struct LeastSquaresFit {
    Eigen::VectorXd parameters;
    double cost = 0.0;  ///< ||r||^2 at the parameters
    int iterations = 0;
};

/// residuals(p): the vector whose squared norm is minimised; bound(p): p held inside the
/// parameters' physical ranges (applied to every trial step). At most maxIterations steps.
LeastSquaresFit fitLevenbergMarquardt(
    Eigen::VectorXd start, const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals,
    const std::function<Eigen::VectorXd(Eigen::VectorXd)>& bound, int maxIterations = 40);

}  // namespace trilho

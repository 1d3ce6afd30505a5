#include "core/tuning/levenberg_marquardt.h"

#include <algorithm>
#include <cmath>

namespace trilho {

LeastSquaresFit fitLevenbergMarquardt(
    Eigen::VectorXd p, const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals,
    const std::function<Eigen::VectorXd(Eigen::VectorXd)>& bound, int maxIterations) {
    LeastSquaresFit fit;
    const Eigen::Index n = p.size();
    Eigen::VectorXd r = residuals(p);
    double cost = r.squaredNorm();
    double lambda = 1e-3;
    for (int it = 0; it < maxIterations; ++it) {
        fit.iterations = it + 1;
        Eigen::MatrixXd J(r.size(), n);
        for (Eigen::Index j = 0; j < n; ++j) {
            Eigen::VectorXd q = p;
            const double h = std::max(std::abs(p[j]) * 1e-4, 1e-6);
            q[j] += h;
            J.col(j) = (r - residuals(q)) / h;  // d(model)/dp = -dr/dp
        }
        const Eigen::MatrixXd JtJ = J.transpose() * J;
        const Eigen::VectorXd Jtr = J.transpose() * r;
        bool improved = false;
        for (int tries = 0; tries < 10 && !improved; ++tries) {
            Eigen::MatrixXd damped = JtJ;
            for (Eigen::Index j = 0; j < n; ++j)
                damped(j, j) += lambda * std::max(JtJ(j, j), 1e-12);
            const Eigen::VectorXd q = bound(p + damped.ldlt().solve(Jtr));
            const Eigen::VectorXd rq = residuals(q);
            const double c = rq.squaredNorm();
            if (c < cost) {
                const double gain = (cost - c) / cost;
                p = q, r = rq, cost = c, improved = true;
                lambda = std::max(lambda * 0.3, 1e-9);
                if (gain < 1e-9) it = maxIterations;  // converged
            } else {
                lambda *= 10.0;
            }
        }
        if (!improved) break;
    }
    fit.parameters = p;
    fit.cost = cost;
    return fit;
}

}  // namespace trilho

// The eigenvalue analyses of analysis/linear_stability.hpp, compiled once: Eigen's eigensolver and
// SVD are instantiated here only.
#include "geomint/analysis/linear_stability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace geomint {

double spectral_radius(const Mat<2>& M) { return Eigen::EigenSolver<Mat<2>>(M).eigenvalues().cwiseAbs().maxCoeff(); }

double eigenvector_condition(const Mat<2>& M) {
  const Eigen::Vector2d s = Eigen::JacobiSVD<Eigen::Matrix2cd>(Eigen::EigenSolver<Mat<2>>(M).eigenvectors()).singularValues();
  return s[0] / s[1];
}

std::vector<StableInterval> stable_intervals(const std::vector<double>& x, const std::vector<double>& rho,
                                             double tolerance) {
  std::vector<StableInterval> set;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const bool stable = rho[i] <= 1.0 + tolerance, was = i > 0 && rho[i - 1] <= 1.0 + tolerance;
    if (stable && !was) set.push_back({x[i], x[i]});
    if (stable) set.back().hi = x[i];
  }
  return set;
}

}  // namespace geomint

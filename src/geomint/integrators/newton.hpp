#pragma once
// Newton's method for the small implicit stages of symplectic methods.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geomint/core/dense_solve.hpp"
#include "geomint/core/numerical_failure.hpp"
#include "geomint/core/state.hpp"

namespace geomint {

struct IntegrationError : NumericalFailure {
  using NumericalFailure::NumericalFailure;
};

// Solves r(x) = 0 from the guess x, where rj(x) returns the pair (r(x), r'(x)).
// Stops after the first update not larger than 4 ulp of |x|_inf, or, for an
// ill-conditioned Jacobian whose round-off keeps the updates above that, once
// an update below 1e-8 |x|_inf fails to shrink to half the previous one (the
// iterate is then at the round-off plateau: Newton converges quadratically
// before it). The result is a deterministic function of the input. Throws
// IntegrationError if the iteration produces a non-finite value or does not
// converge in 50 steps. If `iterations` is given, the count is stored there.
template <int D, class ResidualJacobian>
Vec<D> newton_solve(const ResidualJacobian& rj, Vec<D> x, const char* what, int* iterations = nullptr) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double previous = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 50; ++it) {
    if (iterations) *iterations = it + 1;
    const auto [r, J] = rj(x);
    Vec<D> dx;
    if constexpr (D == 1) {
      dx[0] = r[0] / J(0, 0);
    } else {
      dx = lu_solve<D>(J, r);
    }
    x -= dx;
    if (!x.allFinite()) {
      throw IntegrationError(std::string(what) + ": Newton iteration left the domain (non-finite iterate)");
    }
    const double step = dx.template lpNorm<Eigen::Infinity>(), scale = std::max(1.0, x.template lpNorm<Eigen::Infinity>());
    if (step <= 4 * eps * scale || (step <= 1e-8 * scale && step > 0.5 * previous)) return x;
    previous = step;
  }
  throw IntegrationError(std::string(what) + ": Newton iteration did not converge in 50 steps");
}

}  // namespace geomint

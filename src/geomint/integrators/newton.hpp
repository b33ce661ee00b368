#pragma once
// Newton's method for the small implicit stages of symplectic methods.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "geomint/core/state.hpp"

namespace geomint {

struct IntegrationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Solves r(x) = 0 from the guess x, where rj(x) returns the pair (r(x), r'(x)).
// Stops after the first update not larger than 4 ulp of |x|_inf (the iterate is
// then converged to round-off: Newton converges quadratically), so the result
// is a deterministic function of the input. Throws IntegrationError if the
// iteration produces a non-finite value or does not converge in 50 steps.
template <int D, class ResidualJacobian>
Vec<D> newton_solve(const ResidualJacobian& rj, Vec<D> x, const char* what) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (int it = 0; it < 50; ++it) {
    const auto [r, J] = rj(x);
    Vec<D> dx;
    if constexpr (D == 1) {
      dx[0] = r[0] / J(0, 0);
    } else {
      dx = J.partialPivLu().solve(r);
    }
    x -= dx;
    if (!x.allFinite()) {
      throw IntegrationError(std::string(what) + ": Newton iteration left the domain (non-finite iterate)");
    }
    if (dx.template lpNorm<Eigen::Infinity>() <= 4 * eps * std::max(1.0, x.template lpNorm<Eigen::Infinity>())) {
      return x;
    }
  }
  throw IntegrationError(std::string(what) + ": Newton iteration did not converge in 50 steps");
}

}  // namespace geomint

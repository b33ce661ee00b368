// Verification (verification.hpp): the declared linear-stability bounds of a method with a generic binding.
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/methods/dispatch.hpp"
#include "verification.hpp"

namespace geomint::verification {

// Spectral radius of the kernel's one-step matrix on q'' = -q, and a run at 0.99x the bound over
// 1e4 periods; on the saddle, R(-h) along its stable direction.
void check_bounds(const MethodInfo& m) {
  const double b = m.oscillatory_bound;
  const auto radius = [&](double wh) {
    return with_kernel(m.name, oscillator, [&](const auto& k) { return spectral_radius(one_step_matrix(k, wh)); });
  };
  if (b == 0) {
    EXPECT_GT(radius(1e-2), 1.0) << "unstable for every h";
  } else if (std::isinf(b)) {
    for (double wh : {10.0, 100.0}) {
      EXPECT_LE(radius(wh), 1 + 1e-12) << "w h = " << wh;
    }
  } else if (std::isfinite(b)) {
    EXPECT_CASE("spectral radius at 0.99 x the oscillatory bound", radius(0.99 * b), "<=", 1 + 1e-12);
    EXPECT_CASE("spectral radius at 1.01 x the oscillatory bound", radius(1.01 * b), ">", 1 + 1e-6);
    // A run at 0.99 x the bound over 1e4 periods from |z0| = 1 stays within the condition number
    // of the eigenvectors (not small there: symplectic Euler's orbit p^2 + q^2 + h p q = 1 reaches |z| = 10).
    const double h = 0.99 * b;
    const auto n = static_cast<std::int64_t>(std::ceil(1e4 * 2 * std::numbers::pi / h));
    double largest = 0, kappa = 0;
    with_kernel(m.name, oscillator, [&](const auto& k) {
      kappa = eigenvector_condition(one_step_matrix(k, h));
      integrate(k, make_state(1.0, 0.0), h, n, [&](std::int64_t, const PhaseState<1>& z) {
        largest = std::max(largest, std::hypot(z.q[0], z.p[0]));
      });
    });
    EXPECT_CASE("max |z| over 1e4 periods at 0.99 x the oscillatory bound, |z0| = 1 (bound: the condition number "
                "of the eigenvectors)", largest, "<=", kappa * (1 + 1e-6));
  }

  const double r = m.real_bound;
  if (std::isnan(r)) return;
  const auto R = [&](double h) {  // z_1 = R(-h) (1, -1)
    const PhaseState<1> z = with_kernel(m.name, Saddle{}, [&](const auto& k) { return integrate(k, make_state(1.0, -1.0), h, 1); });
    EXPECT_NEAR(z.p[0], -z.q[0], 1e-12 * std::max(1.0, std::abs(z.q[0])));
    return std::abs(z.q[0]);
  };
  if (std::isinf(r)) {
    for (double h : {10.0, 100.0}) {
      EXPECT_LE(R(h), 1.0) << "h |lambda| = " << h;
    }
  } else {
    EXPECT_CASE("|R(-h)| at 0.99 x the real bound", R(0.99 * r), "<=", 1.0);
    EXPECT_CASE("|R(-h)| at 1.01 x the real bound", R(1.01 * r), ">", 1.0 + 1e-6);
  }
}

}  // namespace geomint::verification

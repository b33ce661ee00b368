// Verification (verification.hpp): the declared properties of a method with a generic binding.
#include "geomint/methods/dispatch.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "verification.hpp"

namespace geomint::verification {

namespace {

// J of one kernel step at a generic point of a nonlinear problem, by
// Richardson-extrapolated central differences, d = 1e-3: truncation O(d^4) ~ 1e-12,
// round-off ~ eps/d ~ 1e-13, so the defects below are good to ~1e-11.
template <class Sys>
void check_kernel_properties(const MethodInfo& m, const Sys& sys, const PhaseState<2>& z, double h) {
  const Mat<4> J = with_kernel(m.name, sys, [&](const auto& k) { return step_jacobian_richardson(k, z, h, 1e-3); });
  const double defect = symplecticity_defect(J);
  if (m.has(property::symplectic)) {
    EXPECT_CASE("symplecticity defect max |J^T Omega J - Omega| of one step", defect, "<", 1e-10);
  } else {
    report("symplecticity defect max |J^T Omega J - Omega|", defect);
  }
  if (m.has(property::volume_preserving)) {
    EXPECT_CASE("|det J - 1| of one step", std::abs(J.determinant() - 1), "<", 1e-10);
    // 004 Sect. 1.3: volume preserving but, for two degrees of freedom, not symplectic.
    if (!m.has(property::symplectic)) {
      EXPECT_CASE("symplecticity defect of a volume-preserving, not symplectic method", defect, ">", 1e-6);
    }
  }
  if (m.has(property::time_reversible)) {
    const PhaseState<2> back = with_kernel(m.name, sys, [&](const auto& k) {
      return integrate(k, integrate(k, z, h, 1), -h, 1);
    });
    EXPECT_CASE("|kernel(kernel(z, h), -h) - z| / |z|", phase_distance(back, z) / phase_distance(z, PhaseState<2>{}),
                "<", 1e-13);
  }
}

}  // namespace

// The properties on Henon-Heiles at a generic point; of a variational method, its exact Jacobian as well.
void check_properties(const MethodInfo& m) {
  check_kernel_properties(m, henon_heiles, generic_point, property_h);
  if (m.family == Family::variational) {  // the exact Jacobian (implicit function theorem) as well
    const auto J = m.name == "lobatto" ? galerkin_step_jacobian(lobatto_rule(), henon_heiles, generic_point, property_h)
                                       : galerkin_step_jacobian(simpson_rule(), henon_heiles, generic_point, property_h);
    EXPECT_CASE("symplecticity defect of the exact Jacobian", symplecticity_defect(J), "<", 1e-12);
    const Mat<4> fd = with_method(m.name, henon_heiles, [&](const auto& k) {
      return step_jacobian_richardson(k, generic_point, property_h, 1e-3);
    });
    EXPECT_CASE("max |J_fd - J_exact|", (fd - J).cwiseAbs().maxCoeff(), "<", 1e-10);
  }
}

}  // namespace geomint::verification

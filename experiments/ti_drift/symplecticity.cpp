// 004 Sect. 1.3: symplecticity against volume preservation: the one-step Jacobian (central differences) of
// each named method's kernel on Henon-Heiles, its symplecticity defect and its determinant (TI symplectic,
// the simplified TI only volume-preserving); and the remainder of Sect. 3.3's expansion of (1.6) about (1.4).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint::ti_drift {
namespace {

using Z2 = PhaseState<2>;

HenonHeiles symplecticity_system(const Scene& s) { return {{}, static_cast<int>(s.integer("symplecticity.k"))}; }

// 004 Sect. 3.3 as printed: q_{n+1} of (1.6) = q_{n+1} of (1.4) + 1/4 h^6 alpha^2 f''(f, f)(q_{n+1/2}) + O(h^8),
// both from the same (p_n, q_n). The remainder after the printed term, one step at h / 2^j (j < 4) from z,
// with the term at q_{n+1/2} = (q_n + q_{n+1}) / 2 as printed, and at q_n.
Value sect33_remainders(const HenonHeiles& hh, const Z2& z, double h) {
  std::vector<double> hs, at_mid, at_start;
  for (int j = 0; j < 4; ++j) {
    const double hj = h / std::pow(2.0, j);
    const Z2 ti = integrate(takahashi_imada_method(hh, false), z, hj, 1);
    const Z2 sti = integrate(simplified_ti_method(hh, false), z, hj, 1);
    const Vec<2> mid = (z.q + sti.q) / 2;
    hs.push_back(hj);
    at_mid.push_back((sti.q - ti.q - simplified_ti_q_correction(hh, mid, hj, takahashi_imada_alpha)).norm());
    at_start.push_back((sti.q - ti.q - simplified_ti_q_correction(hh, z.q, hj, takahashi_imada_alpha)).norm());
  }
  return {{"steps", range_of(hs)},
          {"order_at_midpoint", fit_order(hs, at_mid, 0.0, "Sect. 3.3 remainder").order},
          {"largest_at_q_n", *std::max_element(at_start.begin(), at_start.end())}};
}

void run_symplecticity(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("symplecticity");
  const HenonHeiles hh = symplecticity_system(s);
  const Z2 z = hh.start(s.real("symplecticity.q2"), s.real("symplecticity.p2"), s.real("hh.H0"));
  const double h = s.real("h"), d = s.real("symplecticity.fd_step");
  Value reproduced;
  for (const auto& m : s.texts("symplecticity.methods")) {
    const Mat<4> J = step_jacobian_fd(one_step_by_name(m, hh, Bind::kernel), z, h, d);
    reproduced[label_of(m) + "_symplecticity_defect"] = symplecticity_defect(J);
    reproduced[label_of(m) + "_det_minus_one"] = J.determinant() - 1.0;
  }
  merge(ctx.summary, "reproduced", reproduced);
  const Value sect33 = sect33_remainders(hh, z, h);
  ctx.summary["sect33"] = sect33;
  record_unfittable(ctx.summary, "sect33.order_at_midpoint", "the one-step remainders of Sect. 3.3 are not written to a CSV");
  ctx.summary["symplecticity"] = {{"p1", z.p[0]}};
}

StudyPlan plan_symplecticity(const Scene& s) {
  // per method: 16 central differences of one step; Sect. 3.3: 4 steps of each of two methods
  const double m = static_cast<double>(s.texts("symplecticity.methods").size());
  const PlanRate& rate = plan_rate("henon-heiles splitting");
  return {16 * m + 8, 2 * (16 * m + 8), 1e4, rate.ns_per_step, rate.note};
}

}  // namespace

Study symplecticity_study() {
  return {.name = "symplecticity",
          .about = "004 Sect. 1.3: TI symplectic, the simplified TI only volume-preserving",
          .keys = Schema()
                      .texts("symplecticity.methods", MethodsOn<HenonHeiles>::choices(), 1,
                             "methods whose one-step Jacobian (of the kernel) is checked (registry names or labels)")
                      .integer("symplecticity.k", at_least(3), "exponent k of the Henon-Heiles system of the check")
                      .real("symplecticity.q2", any_finite(), "start q2 of the check (q1 = 0, p1 > 0 from hh.H0)")
                      .real("symplecticity.p2", any_finite(), "start p2 of the check")
                      .real("symplecticity.fd_step", positive(), "step of the central differences of the Jacobian"),
          .reads = {"h", "hh.H0"},
          .run = run_symplecticity,
          .validate =
              [](const Scene& s) {
                MethodsOn<HenonHeiles>::check(s, "symplecticity.methods", symplecticity_system(s));
                check_henon_heiles_starts(s, "symplecticity", symplecticity_system(s), 0.0, true);
              },
          .plan = plan_symplecticity};
}

}  // namespace geomint::ti_drift

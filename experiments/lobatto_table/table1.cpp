// 001 Table 1: one period of the oscillator from q = A, p = 0 at N steps per period (001: 10, 20, 40); the
// largest absolute errors of the Lobatto scheme in p, q, H and the discrete energy H_d of (15), the q
// errors of the compared methods and of eq. (12) as printed (iterated as a scheme of its own), the
// fitted orders, and the comparison with the printed digits.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/analysis/lobatto_oscillator.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

using Z1 = PhaseState<1>;


void check_table1(const Scene& s) {
  check_distinct_methods(s, "table1.methods");
  check_lobatto_bound(s, {"meshes", 1, true});
  check_oscillatory_bounds(s, {"meshes", 1, true}, "table1.methods");
}

// Table 1's errors by N, which 001 prints (published.toml): p, q and H, and H_d (round-off, compared apart).
const std::vector<std::string> kTable1Errors = {"reproduced.p_err", "reproduced.q_err", "reproduced.H_err",
                                                "reproduced.Hd_err"};

void run_table1(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Table 1");
  const auto [osc, A, T, z0] = oscillator_from_rest(s);
  const auto methods = s.texts("table1.methods");
  std::vector<double> hs, Ns, ep, eq, eH, eHd, Hd0s, e12;
  std::vector<std::vector<double>> em(methods.size());
  Value reproduced = Value::record();
  for (double Nd : s.reals("meshes")) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    const Mat<2> Phi = one_step_pq_matrix("lobatto", osc, h);
    double p = 0, q = 0, H = 0, Hd = 0;
    const auto lobatto = trajectory("lobatto", osc, z0, h, N);
    const double H0 = osc.H(z0), Hd0 = discrete_energy(Phi, z0);
    for (std::int64_t j = 1; j <= N; ++j) {
      const Z1& zl = lobatto[static_cast<std::size_t>(j)];
      const Z1 ex = osc.exact(z0, static_cast<double>(j) * h);
      p = std::max(p, std::abs(zl.p[0] - ex.p[0])), q = std::max(q, std::abs(zl.q[0] - ex.q[0]));
      H = std::max(H, std::abs(osc.H(zl) - H0)), Hd = std::max(Hd, std::abs(discrete_energy(Phi, zl) - Hd0));
    }
    for (std::size_t k = 0; k < methods.size(); ++k) em[k].push_back(max_errors(osc, z0, trajectory(methods[k], osc, z0, h, N), h).q);
    const std::string n = std::to_string(N);  // the errors by N
    reproduced["p_err"][n] = p, reproduced["q_err"][n] = q, reproduced["H_err"][n] = H, reproduced["Hd_err"][n] = Hd;
    reproduced["Hd_err_roundoff"][n] = roundoff_floor(std::abs(Hd0));  // (published.toml: H_d is round-off below it)
    hs.push_back(h), Ns.push_back(Nd), ep.push_back(p), eq.push_back(q), eH.push_back(H), eHd.push_back(Hd), Hd0s.push_back(Hd0);
    // 001 eq. (12) as printed, iterated as a scheme of its own (it is not (13)-(14): see the unit tests)
    e12.push_back(max_errors(osc, z0, pq_orbit(lobatto_map_12(h, osc.m, osc.w, Eq12::printed), z0, N), h).q);
  }
  // table1.csv (h, steps N, the errors) and the orders fitted to them over the errors above round-off.
  ConvergenceStudy conv({.csv = "table1.csv", .h = hs, .steps = Ns, .orders_csv = "table1_orders.csv"});
  conv.column("p_err", ep).column("q_err", eq).column("H_err", eH).column("Hd_err", eHd);
  for (std::size_t k = 0; k < methods.size(); ++k) conv.column(label_of(methods[k]) + "_q_err", em[k]);
  conv.column("printed_eq12_q_err", e12);
  const double floor = roundoff_floor();
  conv.fit("lobatto_p", "p_err", floor).fit("lobatto_q", "q_err", floor).fit("lobatto_H", "H_err", floor);
  for (const auto& m : methods) conv.fit(label_of(m), label_of(m) + "_q_err", floor);
  conv.fit("lobatto_printed_eq12_q", "printed_eq12_q_err", floor);
  conv.write(ctx);
  merge(ctx.summary, "reproduced", reproduced);
  ctx.summary["norms"]["table1"] = "max over the steps j = 1..N of one period of the absolute error (p, q, H, H_d)";
  Value relative = Value::list();  // H_d(0) (15) per mesh, the H_d errors relative to it, the q errors, the printed digits
  for (std::size_t i = 0; i < eHd.size(); ++i) relative.push_back(eHd[i] / Hd0s[i]);
  ctx.summary["methods"]["table1"] = labels_of(methods);
  ctx.summary["methods"]["table1_scheme"] = labels_of({"lobatto"});  // (the fits lobatto_*: Table 1's method)
  Value compared = Value::record();  // the q errors of the compared methods per mesh, as table1.csv
  for (std::size_t k = 0; k < methods.size(); ++k) compared[label_of(methods[k])] = em[k];
  ctx.summary["table1"] = {{"Hd0", Hd0s},
                           {"Hd_err_relative", relative},
                           {"Hd_err_range", range_of(eHd)},
                           {"q_err", compared},
                           {"printed", printed_digits_agreement(ctx, kTable1Errors, 3)}};  // (001 prints 3 digits)
}

StudyPlan plan_table1(const Scene& s) {
  double steps = 0, largest = 0;
  const double runs = 2.0 + static_cast<double>(s.texts("table1.methods").size());  // Lobatto, (12), compared
  for (double n : s.reals("meshes")) steps += runs * n, largest = std::max(largest, n);
  const PlanRate& rate = plan_rate("oscillator lobatto");
  return {steps, steps * rate.evals_per_step(), 2 * (largest + 1) * sizeof(Z1), rate.ns_per_step, rate.note};
}

}  // namespace

Study table1_study() {
  return {.name = "table1",
          .makes = {{"001", "Table 1"}},
          .about = "one period at N steps per period: Lobatto's errors of p, q, H and H_d (15), the compared "
                   "methods' q errors, fitted orders",
          .files = {"table1.csv", "table1_orders.csv"},
          .keys = Schema()
                      .reals("meshes", at_least(1), 3, "steps per period N of Table 1 (001: 10, 20, 40)")
                      .texts("table1.methods", MethodsOn<HarmonicOscillator>::names(), 0,
                             "methods compared with Lobatto in Table 1 (max error of q; 001: simpson, "
                             "implicit_midpoint)"),
          .reads = {"oscillator"},
          .run = run_table1,
          .validate = check_table1,
          .plan = plan_table1};
}

}  // namespace geomint::lobatto_table

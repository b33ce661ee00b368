// 000 Fig 9: the error in H against h of symplectic Euler with and without (82) (orders 1 and 2),
// and of explicit Euler on (14) and (17); one task per step size.
#include <algorithm>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/exponential_decay.hpp"
#include "geomint/systems/gompertz.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::euler_compensation {
namespace {


// Max over t_j in [0, N h] of the global error of explicit Euler on a scalar ODE.
template <class Sys>
double euler_max_err(const Sys& sys, double y0, double h, std::int64_t n) {
  ErrorSeries e;
  integrate(one_step_method([&](double y, double dt) { return explicit_euler(sys, y, dt); }), y0, h, n,
            [&](std::int64_t j, double y) { e.add(y - sys.exact(y0, static_cast<double>(j) * h)); });
  return e.max_abs();
}

void run_convergence(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 9: convergence");
  const ExponentialDecay decay{s.real("decay.alpha")};
  const Gompertz gompertz{s.real("gompertz.a"), s.real("gompertz.b")};
  const double gy0 = s.real("gompertz.y0");
  const PhaseState<1> z0 = oscillator_start(s);
  const double H0 = HarmonicOscillator{}.H(z0);
  const auto hs = s.reals("convergence.h");
  const double t_end = s.real("convergence.t_end"), k = s.real("oscillator.k");
  const auto methods = s.texts("convergence.methods");
  struct Row {
    std::vector<OscillatorEnergyErrors> osc;  // one per method
    double ee_decay, ee_gompertz;
    auto fields() { return std::tie(osc, ee_decay, ee_gompertz); }
  };
  const auto rows = distributed_map(hs.size(), [&](std::size_t j) {
    const std::int64_t n = steps_to(t_end, hs[j]);
    return Row{oscillator_energy_errors(methods, k, z0, hs[j], n), euler_max_err(decay, s.real("decay.y0"), hs[j], n),
               euler_max_err(gompertz, gy0, hs[j], n)};
  });
  std::vector<double> steps;
  for (double h : hs) steps.push_back(static_cast<double>(steps_to(t_end, h)));
  // Columns: per method (by label) the max and the eq. (50) errors and the force evaluations, then explicit Euler.
  ConvergenceStudy conv({.csv = "fig9_convergence.csv", .h = hs, .steps = steps});
  const auto per_method = [&](const char* suffix, auto field) {
    for (std::size_t m = 0; m < methods.size(); ++m)
      conv.column(label_of(methods[m]) + suffix, [&](std::size_t, std::size_t j) { return field(rows[j].osc[m]); });
  };
  per_method("_max", [](const OscillatorEnergyErrors& r) { return r.max_err; });
  per_method("_rms", [](const OscillatorEnergyErrors& r) { return r.rms_err; });
  per_method("_evals", [](const OscillatorEnergyErrors& r) { return static_cast<double>(r.force_evals); });
  const std::string ee = label_of("explicit_euler");  // (the right panel's method, on (14) and (17))
  conv.column(ee + "_decay_max", [&](std::size_t, std::size_t j) { return rows[j].ee_decay; })
      .column(ee + "_gompertz_max", [&](std::size_t, std::size_t j) { return rows[j].ee_gompertz; });

  // Orders: least squares on log-log over the points above round-off.
  conv.fit(ee + "_decay", ee + "_decay_max", roundoff_floor(s.real("decay.y0")))
      .fit(ee + "_gompertz", ee + "_gompertz_max", roundoff_floor(gompertz.equilibrium()));
  const double floor = roundoff_floor(std::max(H0, 1.0));
  for (const auto& m : methods) conv.fit(label_of(m) + "_energy", label_of(m) + "_max", floor);
  for (const auto& m : methods) conv.fit(label_of(m) + "_energy_rms", label_of(m) + "_rms", floor);
  conv.write(ctx);
  ctx.summary["norms"] = {
      {"energy", "max over t_j = j h in [0, convergence.t_end] of |H(q_j, p_j) - H(q_0, p_0)|; *_rms: eq. (50)"},
      {"ee", "max over t_j in [0, convergence.t_end] of |y_j - y(t_j)|"},
      {"compensated_max_rel_err", "max over the steps of Figs 2/3 of |Psi^{-1}(ybar_j) - y(t_j)| / |y(t_j)|"},
      {"compensated_max_rel_err_odeint", "the same with y(t_j) from odeint's Bulirsch-Stoer at rtol = atol = 1e-14"},
      {"odeint_max_rel_err", "max over the steps of Figs 2/3 of |y_odeint(t_j) - y(t_j)| / |y(t_j)|"}};
  ctx.summary["h_range"]["convergence"] = h_range(hs);
  ctx.summary["methods"]["convergence"] = labels_of(methods);  // (Fig 9's left panel: its curves, by label)
  ctx.summary["methods"]["convergence_scalar"] = labels_of({"explicit_euler"});  // (its right panel's)
}

StudyPlan plan_convergence(const Scene& s) {
  const double methods = static_cast<double>(s.texts("convergence.methods").size());
  const double steps = (methods + 2) * steps_to_each(s.real("convergence.t_end"), s.reals("convergence.h"));  // and Euler on (14), (17)
  const PlanRate& rate = plan_rate("oscillator compensated symplectic euler");
  return {steps, steps * rate.evals_per_step(), static_cast<double>(s.reals("convergence.h").size()) * (4 + 3 * methods) * kCsvCellBytes,
          rate.ns_per_step, rate.note};
}

}  // namespace

Study convergence_study() {
  return {.name = "convergence",
          .makes = {{"000", "Fig. 9"}},
          .about = "error in H against h: orders 1 and 2",
          .files = {"fig9_convergence.csv", "orders.csv"},
          .keys = Schema()
                      .texts("convergence.methods", compensated_oscillator_choices(), 1,
                             "methods of Fig 9 on the oscillator (registry names or labels); compensated_symplectic_euler "
                             "uses oscillator.k")
                      .reals("convergence.h", positive(), 3, "steps of the convergence study (Fig 9); each divides t_end"),
          .reads = {"convergence.t_end", "oscillator.q0", "oscillator.p0", "oscillator.k", "decay.alpha", "decay.y0",
                    "gompertz.a", "gompertz.b", "gompertz.y0"},
          .run = run_convergence,
          .validate =
              [](const Scene& s) { check_compensated_methods(s, "convergence.h", "convergence.methods", "convergence.t_end"); },
          .plan = plan_convergence};
}

}  // namespace geomint::euler_compensation

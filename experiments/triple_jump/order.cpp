// 005 (Yoshida 1990): the triple jump S(x1 h) S(x0 h) S(x1 h) of a symmetric second-order method S, with
// x1 = 1/(2 - 2^(1/3)) and x0 = 1 - 2 x1, is of fourth order. On the quartic oscillator H = p^2/2 + q^4/4
// (systems/quartic_oscillator.hpp): the largest energy error over [0, t_end] of each method the scene names
// against h, and the order fitted to it (analysis/convergence_study.hpp). The triple jump of Stormer-Verlet
// is the registry's forest_ruth.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/quartic_oscillator.hpp"

namespace geomint::triple_jump {
namespace {

using Methods = MethodsOn<QuarticOscillator>;

// Set-up: the system and its start, from the scene.
PhaseState<1> start(const Scene& s) { return make_state(s.real("order.q0"), s.real("order.p0")); }

// Integrate and measure: max over t_j = j h in [0, t_end] of |H(z_j) - H(z_0)|.
double energy_error(const std::string& method, const PhaseState<1>& z0, double h, std::int64_t n) {
  const QuarticOscillator sys;
  ErrorSeries err;
  Methods::integrate(method, sys, z0, h, n, [&](std::int64_t, const PhaseState<1>& z) { err.add(sys.H(z) - sys.H(z0)); });
  return err.max_abs();
}

void run_order(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto hs = s.reals("order.h");
  const auto methods = s.texts("order.methods");
  const double t_end = s.real("order.t_end");
  const PhaseState<1> z0 = start(s);
  // One task per step size, every method in it (split across threads and MPI ranks).
  const auto errors = distributed_map(hs.size(), [&](std::size_t j) {
    std::vector<double> e;
    for (const auto& m : methods) e.push_back(energy_error(m, z0, hs[j], steps_to(t_end, hs[j])));
    return e;
  });
  // Record: order.csv (h, steps, <label>_energy), the orders <label>_energy fitted over the errors above round-off.
  std::vector<double> steps;
  for (double h : hs) steps.push_back(static_cast<double>(steps_to(t_end, h)));
  ConvergenceStudy conv({.csv = "order.csv", .h = hs, .steps = steps});
  const double floor = roundoff_floor(std::max(QuarticOscillator{}.H(z0), 1.0));
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::string column = label_of(methods[k]) + "_energy";
    conv.column(column, [&](std::size_t, std::size_t j) { return errors[j][k]; }).fit(column, column, floor);
  }
  conv.write(ctx);
  ctx.summary["methods"]["order"] = labels_of(methods);  // (the figure's methods, by the CSV's names)
}

// Each method once, each can step the system, each h below its oscillatory bound at the largest frequency of
// the start's energy level, and each h divides t_end.
void check_order(const Scene& s) {
  Methods::check(s, "order.methods", QuarticOscillator{});
  const double t_end = s.real("order.t_end"), omega = QuarticOscillator::max_frequency(QuarticOscillator{}.H(start(s)));
  for (double h : s.reals("order.h")) {
    for (const auto& m : s.texts("order.methods"))
      check_oscillatory_bound(s, "order.h", "order.methods", m, omega * h, "omega = sqrt(3) q_max, the largest on the energy level");
    const double n = static_cast<double>(steps_to(t_end, h));
    if (!(t_end / h <= max_exact_count) || n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end)
      s.reject("order.h", "each h must divide t_end = " + format_double(t_end) + " into at most 2^53 steps");
  }
}

StudyPlan plan_order(const Scene& s) {
  const double steps = static_cast<double>(s.texts("order.methods").size()) *
                       steps_to_each(s.real("order.t_end"), s.reals("order.h"));
  return {.steps = steps, .memory_bytes = 64.0 * static_cast<double>(s.reals("order.h").size()),
          .note = "force evaluations not counted"};
}

}  // namespace

Study order_study() {
  return {.name = "order",
          .makes = {{"005", "fourth order"}},
          .about = "largest energy error against h on the quartic oscillator: orders 2 and 4",
          .files = {"order.csv", "orders.csv"},
          .keys = Schema()
                      .real("order.q0", any_finite(), "initial q")
                      .real("order.p0", any_finite(), "initial p")
                      .real("order.t_end", positive(), "errors are maxima over t in [0, t_end]")
                      .reals("order.h", positive(), 3, "step sizes; each divides t_end")
                      .texts("order.methods", Methods::choices(), 1, "methods compared (registry names or labels)"),
          .run = run_order,
          .validate = check_order,
          .plan = plan_order};
}
const RegisteredStudy registered{order_study};  // (no main.cpp: the experiment is its registered studies)

}  // namespace geomint::triple_jump

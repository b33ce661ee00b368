// 001 Fig. 1: the trajectories (q, p) of the drawn methods over one period of the oscillator at the
// meshes figure1.meshes (001: N = 3, 10 steps per period), the exact curve, and each method's largest
// errors in q and p.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint::lobatto_table {
namespace {

using Z1 = PhaseState<1>;


void check_figure1(const Scene& s) {
  check_distinct_methods(s, "figure1.methods");
  check_oscillatory_bounds(s, {"figure1.meshes", 1, true}, "figure1.methods");
}

// How close Lobatto's curves are at the smallest mesh of the figure: its largest errors in q and p relative to
// their amplitudes, and, for each other drawn method, the smaller of its two errors' ratios to Lobatto's (above 1:
// Lobatto is the closer in q and in p). Null where the figure does not draw Lobatto.
Value closeness(const Scene& s, const Value& max_error, double q_amplitude, double p_amplitude) {
  const auto methods = s.texts("figure1.methods");
  const auto meshes = s.reals("figure1.meshes");
  const std::size_t smallest = static_cast<std::size_t>(std::min_element(meshes.begin(), meshes.end()) - meshes.begin());
  const Value& errors = max_error.at(smallest);
  const std::string lobatto = label_of("lobatto");
  if (!errors.contains(lobatto)) return {};
  const double q = errors.at(lobatto).at("q").number(), p = errors.at(lobatto).at("p").number();
  Value ratio = Value::record();
  for (const auto& m : methods)
    if (label_of(m) != lobatto && q > 0 && p > 0)
      ratio[label_of(m)] = std::min(errors.at(label_of(m)).at("q").number() / q, errors.at(label_of(m)).at("p").number() / p);
  return {{"mesh", meshes[smallest]}, {"lobatto_rel_error_q", q / q_amplitude}, {"lobatto_rel_error_p", p / p_amplitude},
          {"error_ratio_to_lobatto", ratio}};
}

void run_figure1(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 1");
  const auto [osc, A, T, z0] = oscillator_from_rest(s);
  const auto methods = s.texts("figure1.methods");
  std::vector<std::string> columns = {"j", "t"};
  for (const auto& m : methods) columns.push_back("q_" + label_of(m)), columns.push_back("p_" + label_of(m));
  Value max_error = Value::list();  // per mesh and method: max_j |q_j - q(t_j)| and |p_j - p(t_j)|, j = 0..N
  for (double Nd : s.reals("figure1.meshes")) {
    const auto N = static_cast<std::int64_t>(Nd);
    const double h = T / Nd;
    std::vector<std::vector<Z1>> zs;
    for (const auto& m : methods) zs.push_back(trajectory(m, osc, z0, h, N));
    Csv f(columns);
    for (std::int64_t j = 0; j <= N; ++j) {
      f << j << static_cast<double>(j) * h;
      for (const auto& z : zs) f << z[static_cast<std::size_t>(j)].q[0] << z[static_cast<std::size_t>(j)].p[0];
      f.end_row();
    }
    ctx.write("fig1_N" + std::to_string(N) + ".csv", f);
    Value errors = Value::record();
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const PhaseErrors e = max_errors(osc, z0, zs[k], h);
      errors[label_of(methods[k])] = {{"q", e.q}, {"p", e.p}};
    }
    max_error.push_back(errors);
  }
  Csv fe({"t", "q", "p"});
  for (int i = 0; i <= 400; ++i) {
    const Z1 e = osc.exact(z0, T * i / 400.0);
    fe.row(T * i / 400.0, e.q[0], e.p[0]);
  }
  ctx.write("fig1_exact.csv", fe);
  ctx.summary["methods"]["figure1"] = labels_of(methods);
  // the amplitude of the exact p = -m w A sin(w t), and the largest errors of the drawn methods
  ctx.summary["figure1"] = {{"p_amplitude", osc.m * osc.w * A}, {"max_error", max_error}};
  ctx.summary["figure1"]["closeness"] = closeness(s, max_error, A, osc.m * osc.w * A);
}

StudyPlan plan_figure1(const Scene& s) {
  const double methods = static_cast<double>(s.texts("figure1.methods").size());
  double steps = 0, largest = 0;
  for (double n : s.reals("figure1.meshes")) steps += methods * n, largest = std::max(largest, n);
  const PlanRate& rate = plan_rate("oscillator lobatto");
  return {steps, steps * rate.evals_per_step(), (largest + 1) * (methods * sizeof(Z1) + (2 + 2 * methods) * kCsvCellBytes),
          rate.ns_per_step, rate.note};
}

}  // namespace

Study figure1_study() {
  return {.name = "figure1",
          .makes = {{"001", "Fig. 1"}},
          .about = "trajectories (q, p) over one period of the oscillator at N steps per period, and the exact curve",
          .files = {"fig1_N*.csv", "fig1_exact.csv"},
          .keys = Schema()
                      .reals("figure1.meshes", at_least(1), 1, "steps per period of Fig. 1 (001: 3, 10)")
                      .texts("figure1.methods", MethodsOn<HarmonicOscillator>::names(), 1,
                             "methods drawn in Fig. 1 (001: lobatto, simpson, implicit_midpoint)"),
          .reads = {"oscillator"},
          .run = run_figure1,
          .validate = check_figure1,
          .plan = plan_figure1};
}

}  // namespace geomint::lobatto_table

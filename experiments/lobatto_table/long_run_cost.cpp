// What the accuracy costs over the long run of 001 Fig. 2: each method of long_run_cost.methods at the
// steps long_run_cost.h over long_run.periods periods of the oscillator, against its closed form: the
// phase error at the end and the largest energy error (counting runs in parallel, checkpointed for
// --resume), the wall time (runner/timing.hpp, serial, from a timed segment), the cost per step, the
// errors at equal wall time and the cost of reaching each of long_run_cost.error_targets.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/work_precision.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/systems/counting.hpp"
#include "lobatto_table.hpp"

namespace geomint::lobatto_table {
namespace {

void check_long_run_cost(const Scene& s) {
  check_distinct_methods(s, "long_run_cost.methods");
  for (double h : s.reals("long_run_cost.h")) {
    const double hw = h * s.real("oscillator.omega");
    const std::string what = "h = " + format_double(h);
    for (const auto& m : s.texts("long_run_cost.methods"))
      check_oscillatory_bound(s, "long_run_cost.h", "long_run_cost.methods", m, hw, what);
  }
}

// The steps of a run of `periods` periods T at step h.
std::int64_t steps_of(double periods, double T, double h) { return std::llround(periods * T / h); }

// Errors and force evaluations: one counting run per method and step (in parallel): the largest
// |H(z_j) - H(z_0)| over the run (Fig. 2's quantity) and |z_N - z(t_N)|_2 at its end, both against
// the closed form of the oscillator.
struct Measured {
  std::int64_t evals = 0;
  double energy = 0, phase = 0;
  auto fields() { return std::tie(evals, energy, phase); }
};

// The counting runs: task = method index * (number of steps) + step index.
std::vector<Measured> measure(Context& ctx, const Oscillator& o, const std::vector<std::string>& methods,
                              const std::vector<double>& hs, double periods) {
  const auto& [osc, A, T, z0] = o;
  const std::size_t nh = hs.size();
  const std::vector<std::string> keys = {"oscillator", "long_run.periods", "long_run_cost.methods", "long_run_cost.h"};
  return checkpointed_map<Measured>(ctx, {"long_run_cost", keys}, methods.size() * nh, [&](std::size_t task) {
    Measured r;
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(periods, T, h);
    const double H0 = osc.H(z0);
    const Counting<HarmonicOscillator> counted{osc, &r.evals};
    const Z1 zN = MethodsOn<Counting<HarmonicOscillator>>::integrate(
        methods[task / nh], counted, z0, h, n,
        [&](std::int64_t, const Z1& z) { r.energy = std::max(r.energy, std::abs(osc.H(z) - H0)); });
    r.phase = phase_distance(zN, osc.exact(z0, static_cast<double>(n) * h));
    return r;
  });
}

// The wall times of the runs and the work-precision curves they give, per method label.
struct Timed {
  SpreadTally spreads;
  json ns = json::object(), ns_spread = json::object();
  std::map<std::string, std::vector<CostRun>> phase_runs, energy_runs;
};

// Wall time of the same runs without observation, serial (runner/timing.hpp). Writes timing_long_run.csv.
Timed time_and_write(Context& ctx, const Oscillator& o, const std::vector<std::string>& methods,
                     const std::vector<double>& hs, double periods, int repeats,
                     const std::vector<Measured>& measured) {
  const Scene& s = ctx.scene;
  const auto& [osc, A, T, z0] = o;
  const std::size_t nh = hs.size();
  Csv cost({"method", "h", "steps", "wall_s", "ns_per_step", "force_evals", "phase_err", "energy_err", "wall_spread"});
  Timed timed;
  auto& [spreads, ns, ns_spread, phase_runs, energy_runs] = timed;
  for (std::size_t task = 0; task < measured.size(); ++task) {
    const std::string& m = methods[task / nh];
    const std::string label = label_of(m);
    const double h = hs[task % nh];
    const std::int64_t n = steps_of(periods, T, h);
    // The time per step on the oscillator does not depend on where the step is taken: it is measured
    // on a segment of long_run_cost.timing_steps steps (at most the run), and the run's wall time is
    // its n steps at that rate.
    const std::int64_t n_timed = std::min<std::int64_t>(n, s.integer("long_run_cost.timing_steps"));
    const RunTime t = MethodsOn<HarmonicOscillator>::time(m, osc, std::span(&z0, 1), h, n_timed, repeats);
    spreads.add(t);
    const Measured& r = measured[task];
    const double per_step = t.seconds() / static_cast<double>(n_timed), wall = per_step * static_cast<double>(n);
    cost << label << h << n << wall << 1e9 * per_step << r.evals << r.phase << r.energy << t.spread();
    cost.end_row();
    if (h == *std::min_element(hs.begin(), hs.end()))  // time per step at the smallest step
      ns[label] = 1e9 * per_step, ns_spread[label] = t.spread();
    phase_runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.evals), r.phase});
    energy_runs[label].push_back({h, static_cast<double>(n), wall, static_cast<double>(r.evals), r.energy});
  }
  ctx.write("timing_long_run.csv", cost);
  return timed;
}

// What each method's runs cost: per step at the smallest h, relative to the first method; its errors
// at the wall time `equal_wall`; the wall time and the force evaluations at which it first reaches
// each of long_run_cost.error_targets (null where its measured runs do not reach it).
json cost_by_method(const Scene& s, const std::vector<std::string>& methods, Timed& timed, double equal_wall) {
  auto& [spreads, ns, ns_spread, phase_runs, energy_runs] = timed;
  json c = json::object();
  for (const auto& m : methods) {
    const std::string label = label_of(m);
    const auto phase = by_decreasing_h(phase_runs[label]), energy = by_decreasing_h(energy_runs[label]);
    json cm = {{"ns_per_step", ns[label]}, {"ns_per_step_spread", ns_spread[label]},
               {"relative_cost", ns[label].get<double>() / ns[label_of(methods.front())].get<double>()},
               {"evals_per_step", phase.empty() ? json(nullptr) : json(phase.back().evals / phase.back().steps)},
               {"phase_err_at_equal_wall", or_null(error_at_wall(phase, equal_wall))},
               {"energy_err_at_equal_wall", or_null(error_at_wall(energy, equal_wall))}};
    cm["wall_s_to"] = json::array(), cm["evals_to"] = json::array();  // per target of long_run_cost.error_targets
    for (double target : s.reals("long_run_cost.error_targets")) {
      cm["wall_s_to"].push_back(or_null(cost_to_reach(phase, target, &CostRun::wall_s)));
      cm["evals_to"].push_back(or_null(cost_to_reach(phase, target, &CostRun::evals)));
    }
    c[label] = cm;
  }
  return c;
}

void run_long_run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: long runs on the oscillator");
  const Oscillator o = oscillator(s);
  const auto& [osc, A, T, z0] = o;
  const auto methods = s.texts("long_run_cost.methods");
  const auto hs = s.reals("long_run_cost.h");
  const double periods = s.real("long_run.periods");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto measured = measure(ctx, o, methods, hs, periods);
  Timed timed = time_and_write(ctx, o, methods, hs, periods, repeats, measured);
  auto& [spreads, ns, ns_spread, phase_runs, energy_runs] = timed;
  // The closed form's own error at t_N = periods T: the round-off of cos and sin of omega t_N, about
  // u omega t_N in the phase, i.e. u omega t_N |(A, m omega A)| in z (A and m omega A: the amplitudes
  // of q and p).
  const double t_N = periods * T;
  const double reference_error = std::numeric_limits<double>::epsilon() * osc.w * t_N * std::hypot(A, osc.m * osc.w * A);
  json errors = json::object();
  for (const auto& m : methods) {
    const std::string label = label_of(m);
    double phase_min = std::numeric_limits<double>::infinity(), energy_max = 0, energy_min = phase_min;
    for (const CostRun& r : phase_runs[label]) phase_min = std::min(phase_min, r.err);
    for (const CostRun& r : energy_runs[label]) energy_min = std::min(energy_min, r.err), energy_max = std::max(energy_max, r.err);
    errors[label] = {{"phase_min", phase_min}, {"energy_min", energy_min}, {"energy_max", energy_max}};
  }
  ctx.summary["methods"]["long_run_cost"] = labels_of(methods);
  ctx.summary["long_run_cost"] = {{"t_end", t_N}, {"h_range", range_of(hs)}, {"reference_error", reference_error},
                                  {"errors", errors},
                                  {"norms", "phase: |z_N - z(t_N)|_2 against the closed form; energy: max over the "
                                            "steps of |H(z_j) - H(z_0)|"}};
  // The common budget: the smallest over the methods of their most expensive run (inside every
  // method's measured range when the ranges overlap).
  double equal_wall = std::numeric_limits<double>::infinity();
  for (const auto& m : methods) equal_wall = std::min(equal_wall, largest_wall(by_decreasing_h(phase_runs[label_of(m)])));
  const json c = cost_by_method(s, methods, timed, equal_wall);
  ctx.summary["timing"]["long_run_cost"] = {
      {"cost", c},
      {"equal_wall_s", equal_wall},
      {"spread", spreads.to_json()},
      {"method", "the oscillator of Fig. 2 over long_run.periods periods, every call of a step through integrate; " +
                     timing_method_text(repeats) + "; ns_per_step at the smallest long_run_cost.h; force evaluations "
                     "count U_q and U_qq calls"}};
}

StudyPlan plan_long_run_cost(const Scene& s) {
  const double periods = s.real("long_run.periods"), T = period_of(s);
  const double methods = static_cast<double>(s.texts("long_run_cost.methods").size());
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double timed = static_cast<double>(s.integer("long_run_cost.timing_steps"));
  double counted = 0, steps = 0;
  for (double h : s.reals("long_run_cost.h")) {
    const double n = periods * T / h;
    counted += methods * n, steps += methods * (n + repeats * std::min(n, timed));
  }
  return {steps, counted * kOscillatorEvals,
          methods * static_cast<double>(s.reals("long_run_cost.h").size()) * 9 * kCellBytes, kOscillatorNs,
          "ns per step: Lobatto on the oscillator (paper-scene summary timing.long_run_cost)"};
}

void keys(Schema& s) {
  s.texts("long_run_cost.methods", MethodsOn<HarmonicOscillator>::names(), 1,
          "methods whose cost is measured on the oscillator of Fig. 2 over long_run.periods periods (001: lobatto, "
          "simpson, implicit_midpoint)")
      .reals("long_run_cost.h", positive(), 3, "steps of the long-run work-precision study")
      .reals("long_run_cost.error_targets", positive(), 1,
             "phase errors at the end of the long run whose cost (wall time, force evaluations) each method is asked for")
      .integer("long_run_cost.timing_steps", at_least(1),
               "steps of the timed segment; a long run's wall time is its steps times the time per step measured on it")
      .integer("checkpoint.stop_after", non_negative(),
               "long_run_cost: stop after this many rounds of its runs, leaving a checkpoint for --resume (0: run to the "
               "end)")
      .real("checkpoint.interval", non_negative(), "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work");
}

}  // namespace

Study long_run_cost_study() {
  return {"long_run_cost", "cost over the long run of Fig 2: error against wall time and force evaluations",
          {"timing_long_run.csv"}, {"long_run_cost", "long_run.periods", "oscillator", "timing.repeats", "checkpoint"},
          check_long_run_cost, run_long_run_cost, plan_long_run_cost, keys};
}

}  // namespace geomint::lobatto_table

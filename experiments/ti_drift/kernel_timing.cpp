// Cost (study `kernel_timing`, formerly `timing`; its summary keys stay summary.timing.*): ns per step of
// each named method's kernel (no processing, as Figs 2-6 use them) on Henon-Heiles k, from the ensemble's
// first start (runner/timing.hpp); and the ensembles' lane kernels of Figs 4 and 6 against the scalar method.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/henon_heiles_ensemble.hpp"
#include "geomint/sweep/lanes_timing.hpp"
#include "geomint/sweep/lennard_jones_ensemble.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint::ti_drift {
namespace {

// The index in timing.methods' labels of simplified_takahashi_imada, whose kernel is Fig. 4's scalar method.
std::optional<std::size_t> fig4_scalar(const std::vector<std::string>& labels) {
  const auto at = std::ranges::find(labels, label_of("simplified_takahashi_imada"));
  return at == labels.end() ? std::nullopt : std::optional(static_cast<std::size_t>(at - labels.begin()));
}

template <class HH>
void timing_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: ns per step");
  const double h = s.real("h");
  const std::int64_t n = s.integer("timing.steps"), n_lj = s.integer("timing.lj_steps");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods"), labels = method_labels(methods);
  const auto hh_starts = ensemble_starts(s, kHenonHeilesLanes);
  const auto lj_starts = lennard_jones_starts(s, kLennardJonesLanes);
  // One measurement, a configuration per thread at a time: each method's kernel from the ensemble's first start; the first
  // batch of lanes of Figs 4 and 6 against the scalar method (Fig. 4's: that of simplified_takahashi_imada, if timed).
  InterleavedTiming timing(repeats, kTimingFloorS, ctx.threads);
  for (const auto& m : methods) timing.add(MethodsOn<HH>::timed(m, hhk, {hh_starts.front()}, h, n, Bind::kernel));
  const std::optional<std::size_t> scalar4 = fig4_scalar(labels);
  const LanesConfigs fig4 = add_lanes(timing, hhk, hh_starts, h, n, scalar4);
  const LanesConfigs fig6 = add_lanes(timing, LennardJones<9>{}, lj_starts, s.real("lj.h"), n_lj);
  const std::vector<RunTime> times = timing.run();
  Value ns_per_step, runs, spread;
  std::vector<RunTime> per_step;
  std::vector<double> work;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    per_step.push_back(times[k].scaled(1e9 / static_cast<double>(n)));
    work.push_back(static_cast<double>(evals_per_step(methods[k])));
    ns_per_step[labels[k]] = per_step.back().seconds(), spread[labels[k]] = per_step.back().spread();
    runs[labels[k]] = to_value(times[k]);
  }
  merge(ctx.summary, "timing",
      {{"ns_per_step", ns_per_step},
       {"spread", spread},  // interquartile range / median over the rounds
       {"runs", runs},
       {"method", timing_method_text(repeats) + "; a run is " + std::to_string(n) + " steps of a method's kernel, "
                  "every call inlined; fig4_wall_s, fig6_wall_s: the ensembles on --threads threads, one run"},
       {"lanes", {{"fig4", fig4.of(times).summary(hh_starts.size(), n)},
                  {"fig6", fig6.of(times).summary(lj_starts.size(), n_lj)},
                  {"method", "ns per trajectory-step of the first batch of lanes of Figs 4 and 6, simplified Takahashi-Imada "
                             "unprocessed: scalar, one trajectory after another, inlined" +
                             std::string(scalar4 ? " (Fig. 4's: the run of its kernel above)" : "") +
                             ", against each lane kernel this CPU runs (the same bits)"}}}});
  const auto sv = std::ranges::find(labels, "sv");  // per step, relative to Stormer-Verlet (force evaluations: the work)
  if (sv != labels.end())
    merge(ctx.summary, "timing", {{"relative_to_sv", relative_timings(labels, per_step, work, sv - labels.begin())}});
}

void run_timing(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { timing_with(ctx, hhk); });
}

StudyPlan plan_timing(const Scene& s) {
  // one measurement under the timing protocol: the methods' kernels and the lane kernels this CPU runs for Figs 4
  // and 6 with their scalar method (Fig. 4's the run of simplified_takahashi_imada where timing.methods has it;
  // the Lennard-Jones scalar run planned at the lanes' rate: a lower bound), and the counted lanes' arithmetic alone
  const std::int64_t n = s.integer("timing.steps");
  const PlanRate &hh = plan_rate("henon-heiles splitting"), &lj_lanes = plan_rate("lennard-jones lanes");
  const auto labels = method_labels(s.texts("timing.methods"));
  std::vector<TimedCall> calls(labels.size(), TimedCall{static_cast<double>(n), hh.ns_per_step});
  for (const auto& c : lanes_calls<HenonHeiles>(n, hh.ns_per_step, plan_rate("henon-heiles lanes").ns_per_step,
                                                fig4_scalar(labels).has_value()))
    calls.push_back(c);
  for (const auto& c : lanes_calls<LennardJones<9>>(s.integer("timing.lj_steps"), lj_lanes.ns_per_step, lj_lanes.ns_per_step, false))
    calls.push_back(c);
  StudyPlan p;
  p.memory_bytes = 1e4, p.ns_per_step = hh.ns_per_step, p.note = "the timing protocol; " + hh.note;
  p.time(s, calls);
  return p;
}

}  // namespace

Study kernel_timing_study() {
  return {.name = "kernel_timing",
          .about = "cost: ns per step of each method",
          .keys = Schema()
                      .texts("timing.methods", MethodsOn<HenonHeiles>::choices(), 1, "methods timed (their kernels, on the Fig. 4 system; registry names or labels)")
                      .integer("timing.steps", at_least(1), "steps of each timed run")
                      .integer("timing.lj_steps", at_least(1), "steps of each timed run of the Lennard-Jones lanes (Fig. 6 cluster, lj.h)"),
          .reads = {"timing.repeats", "h", "hh", "hh3.q2", "hh3.p2", "ensemble.seed", "ensemble.perturbation", "lj.h", "lj.seed", "lj.perturbation"},
          .run = run_timing,
          .validate = [](const Scene& s) {
            with_ensemble_system(s, [&](const auto& hh) {
              MethodsOn<std::decay_t<decltype(hh)>>::check(s, "timing.methods", hh);
              check_henon_heiles_starts(s, "hh3", hh, s.real("ensemble.perturbation"), true);
            });
          },
          .plan = plan_timing,
          .aliases = {"timing"}};
}

}  // namespace geomint::ti_drift

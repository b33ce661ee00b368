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

template <class HH>
void timing_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: ns per step");
  const PhaseState<2> z = ensemble_start(s, hhk, 0);
  const double h = s.real("h");
  const std::int64_t n = s.integer("timing.steps");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const auto methods = s.texts("timing.methods");
  // One measurement: each method's kernel from the ensemble's first start, and the ensembles of Figs 4 and 6 in
  // SIMD lanes against the scalar method, from the starts of their first batch of lanes. The scalar method of
  // Fig. 4 is simplified_takahashi_imada's kernel, timed once: where timing.methods has it, its run from the
  // first start (sweep/lanes_timing.hpp).
  InterleavedTiming timing(repeats);
  for (const auto& m : methods) timing.add(MethodsOn<HH>::timed(m, hhk, {z}, h, n, Bind::kernel));
  const std::int64_t n_lj = s.integer("timing.lj_steps");
  std::vector<PhaseState<2>> hh_starts;
  std::vector<PhaseState<18>> lj_starts;
  for (std::size_t i = 0; i < kHenonHeilesLanes; ++i) hh_starts.push_back(ensemble_start(s, hhk, i));
  for (std::size_t i = 0; i < kLennardJonesLanes; ++i) lj_starts.push_back(lennard_jones_start(s, i));
  std::optional<std::size_t> sti;
  for (std::size_t k = 0; k < methods.size(); ++k)
    if (label_of(methods[k]) == label_of("simplified_takahashi_imada")) sti = k;
  const LennardJones<9> lj;
  const LanesConfigs fig4 = add_lanes(timing, hhk, hh_starts, h, n, sti);
  const LanesConfigs fig6 = add_lanes(timing, lj, lj_starts, s.real("lj.h"), n_lj);
  const std::vector<RunTime> times = timing.run();
  Value ns_per_step, runs, spread;
  std::vector<std::string> labels;
  std::vector<RunTime> per_step;
  std::vector<double> work;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::string label = label_of(methods[k]);
    labels.push_back(label), per_step.push_back(times[k].scaled(1e9 / static_cast<double>(n)));
    work.push_back(static_cast<double>(evals_per_step(methods[k])));
    ns_per_step[label] = per_step.back().seconds();
    spread[label] = per_step.back().spread();
    runs[label] = to_value(times[k]);
  }
  merge(ctx.summary, "timing",
      {{"ns_per_step", ns_per_step},
       {"spread", spread},  // interquartile range / median over the rounds
       {"runs", runs},
       {"method", timing_method_text(repeats) + "; a run is " + std::to_string(n) + " steps of a method's kernel, "
                  "every call inlined; fig4_wall_s, fig6_wall_s: the ensembles on --threads threads, one run"}});
  merge(ctx.summary, "timing",
      {{"lanes", {{"fig4", fig4.of(times).summary(hh_starts.size(), n)},
                  {"fig6", fig6.of(times).summary(lj_starts.size(), n_lj)},
                  {"method", "ns per trajectory-step of a batch of lanes (" + std::to_string(kHenonHeilesLanes) + " and " +
                             std::to_string(kLennardJonesLanes) + " trajectories, the first starts of Figs 4 and 6), "
                             "simplified Takahashi-Imada unprocessed: scalar (integrate, every call inlined; Fig. 4: " +
                             (sti ? "the run of its kernel above, from the first start" : "one trajectory after another") +
                             "; Fig. 6: one trajectory after another), against each lane kernel this CPU runs (all lanes "
                             "at once, the same bits); single thread, in the measurement above"}}}});
  const auto sv = std::find(labels.begin(), labels.end(), "sv");
  if (sv != labels.end()) {  // per step, relative to Stormer-Verlet (the force evaluations per step as the work)
    const std::size_t i = static_cast<std::size_t>(sv - labels.begin());
    std::swap(labels[0], labels[i]), std::swap(per_step[0], per_step[i]), std::swap(work[0], work[i]);
    merge(ctx.summary, "timing", {{"relative_to_sv", relative_timings(labels, per_step, work)}});
  }
}

void run_timing(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { timing_with(ctx, hhk); });
}

StudyPlan plan_timing(const Scene& s) {
  // one measurement under the timing protocol: the methods' kernels and the lane kernels this CPU runs for Figs 4
  // and 6 with their scalar method (Fig. 4's the run of simplified_takahashi_imada where timing.methods has it;
  // the Lennard-Jones scalar run planned at the lanes' rate: a lower bound)
  const double n = static_cast<double>(s.integer("timing.steps")), hh_lanes_n = static_cast<double>(kHenonHeilesLanes);
  const double lj_lanes_n = static_cast<double>(kLennardJonesLanes);
  const double lj_n = static_cast<double>(s.integer("timing.lj_steps"));
  const std::size_t kernels = simplified_ti_lanes_kernels<LennardJones<9>>().size();
  const PlanRate &hh = plan_rate("henon-heiles splitting"), &hh_lanes = plan_rate("henon-heiles lanes");
  std::vector<TimedCall> calls(s.texts("timing.methods").size(), TimedCall{n, hh.ns_per_step});
  const auto methods = s.texts("timing.methods");
  if (std::ranges::none_of(methods, [](const std::string& m) { return label_of(m) == label_of("simplified_takahashi_imada"); }))
    calls.push_back(TimedCall{hh_lanes_n * n, hh.ns_per_step});
  calls.insert(calls.end(), kernels, TimedCall{hh_lanes_n * n, hh_lanes.ns_per_step});
  calls.insert(calls.end(), 1 + kernels, TimedCall{lj_lanes_n * lj_n, plan_rate("lennard-jones lanes").ns_per_step});
  StudyPlan p;
  p.memory_bytes = 1e4, p.ns_per_step = hh.ns_per_step;
  p.time(s, calls);
  p.note = "the timing protocol; " + hh.note;
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

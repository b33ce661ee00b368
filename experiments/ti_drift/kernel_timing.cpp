// Cost (study `kernel_timing`, formerly `timing`; its summary keys stay summary.timing.*): ns per step of
// each named method's kernel (no processing, as Figs 2-6 use them) on Henon-Heiles k, from the ensemble's
// first start (runner/timing.hpp); and the ensembles' lane kernels of Figs 4 and 6 against the scalar method.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/lanes_timing.hpp"
#include "henon_heiles_starts.hpp"
#include "ti_drift.hpp"

namespace geomint::ti_drift {
namespace {

// The ensembles' lane kernels against the scalar method (sweep/lanes_timing.hpp): ns per trajectory-step of the
// trajectories from `starts` (one batch), n steps.
template <class Sys>
json lanes_timing(const Sys& sys, const std::vector<typename Sys::State>& starts, double h, std::int64_t n, int repeats) {
  const double steps = static_cast<double>(starts.size()) * static_cast<double>(n);
  const LanesTiming t = time_lanes(sys, starts, h, n, repeats);
  const RunTime& scalar = t.scalar;
  json out = {{"trajectories", starts.size()}, {"steps", n}, {"scalar_ns_per_step", 1e9 * scalar.seconds() / steps},
              {"scalar_spread", scalar.spread()}};
  for (const auto& [name, k] : t.kernels) {
    out["kernels"][name] = {{"ns_per_step", 1e9 * k.seconds() / steps}, {"spread", k.spread()},
                            {"speedup_vs_scalar", scalar.seconds() / k.seconds()}};
    if (!out.contains("isa"))  // the one the ensembles use (the best)
      out["isa"] = name, out["ns_per_step"] = 1e9 * k.seconds() / steps, out["spread"] = k.spread(),
      out["speedup_vs_scalar"] = scalar.seconds() / k.seconds();
  }
  return out;
}

template <class HH>
void timing_with(Context& ctx, const HH& hhk) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: ns per step");
  const Z2 z = ensemble_start(s, hhk, 0);
  const double h = s.real("h");
  const std::int64_t n = s.integer("timing.steps");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  json ns_per_step, runs, spread;
  for (const auto& m : s.texts("timing.methods")) {
    const RunTime t = MethodsOn<HH>::time(m, hhk, std::span(&z, 1), h, n, repeats, Bind::kernel);
    ns_per_step[label_of(m)] = 1e9 * t.seconds() / static_cast<double>(n);
    spread[label_of(m)] = t.spread();
    runs[label_of(m)] = to_json(t);
  }
  merge(ctx.summary, "timing",
      {{"ns_per_step", ns_per_step},
       {"spread", spread},  // (max - min) / min over the timed runs
       {"runs", runs},
       {"method", "minimum of " + std::to_string(repeats) + " timed runs (after a warm-up; each run repeats the " +
                      std::to_string(n) + " steps until it lasts at least 10 ms), single thread, every call inlined; "
                      "spread = (max - min) / min; fig4_wall_s, fig6_wall_s: the ensembles on --threads threads, one run"}});
  // The ensembles of Figs 4 and 6 in SIMD lanes against the scalar method: their first kEnsembleLanes starts.
  std::vector<Z2> hh_starts;
  std::vector<Z18> lj_starts;
  for (std::size_t i = 0; i < kEnsembleLanes; ++i) hh_starts.push_back(ensemble_start(s, hhk, i)), lj_starts.push_back(lj_start_of(s, i));
  merge(ctx.summary, "timing",
      {{"lanes", {{"fig4", lanes_timing(hhk, hh_starts, h, n, repeats)},
                  {"fig6", lanes_timing(LJ{}, lj_starts, s.real("lj.h"), s.integer("timing.lj_steps"), repeats)},
                  {"method", "ns per trajectory-step of " + std::to_string(kEnsembleLanes) + " trajectories (the first starts of "
                             "Figs 4 and 6), simplified Takahashi-Imada unprocessed: scalar, one trajectory after another "
                             "(integrate, every call inlined), against each lane kernel this CPU runs (all lanes at once, the "
                             "same bits); single thread, the timing method above"}}}});
  if (ns_per_step.contains("sv")) {  // per step, relative to Stormer-Verlet
    json relative;
    for (const auto& [label, ns] : ns_per_step.items()) relative[label] = double(ns) / double(ns_per_step["sv"]);
    merge(ctx.summary, "timing", {{"relative_to_sv", relative}});
  }
}

void run_timing(Context& ctx) {
  with_ensemble_system(ctx.scene, [&](const auto& hhk) { timing_with(ctx, hhk); });
}

StudyPlan plan_timing(const Scene& s) {
  const double n = static_cast<double>(s.integer("timing.steps")), r = static_cast<double>(s.integer("timing.repeats"));
  StudyPlan p;
  for (const auto& m : s.texts("timing.methods"))
    p.steps += (r + 1) * n, p.force_evals += (r + 1) * n * static_cast<double>(evals_per_step(m));
  p.memory_bytes = 1e4;
  p.ns_per_step = kNsPerStepHH;
  p.note = "a lower bound (each timed run lasts at least 10 ms); " + std::string(kNsNote);
  return p;
}

void keys(Schema& s) {
  s.texts("timing.methods", MethodsOn<HenonHeiles>::choices(), 1,
          "methods timed (their kernels, on the Fig. 4 system; registry names or labels)")
      .integer("timing.steps", at_least(1), "steps of each timed run")
      .integer("timing.lj_steps", at_least(1), "steps of each timed run of the Lennard-Jones lanes (Fig. 6 cluster, lj.h)");
}

}  // namespace

Study kernel_timing_study() {
  return {"kernel_timing", "cost: ns per step of each method", {},
          {"timing", "h", "hh", "hh3.q2", "hh3.p2", "ensemble.seed", "ensemble.perturbation", "lj.h", "lj.seed",
           "lj.perturbation"},
          [](const Scene& s) {
            with_ensemble_system(s, [&](const auto& hh) {
              MethodsOn<std::decay_t<decltype(hh)>>::check(s, "timing.methods", hh);
              check_hh_starts(s, "hh3", hh, s.real("ensemble.perturbation"), true);
            });
          },
          run_timing, plan_timing, keys, {"timing"}};
}

}  // namespace geomint::ti_drift

// The cost of the map of 000 Fig. 6: the batched kernel (from the map of this run, else on a sample of
// batches) against the straightforward scalar loop, in ns per trajectory-step and core, per coordinate
// system; and each kernel against its target and the hardware ceiling the scene gives (summary timing).
// Study `kernel_timing` (formerly `timing`: Study::aliases).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/runner/clock.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/sweep/energy_map_grid.hpp"
#include "geomint/sweep/parallel_map.hpp"

namespace geomint::energy_map {
namespace {

void check_timing(const Scene& s) {
  check_energy_map(s);
  for (const char* key : {"timing.ceiling.cartesian", "timing.ceiling.polar"})
    if (s.reals(key).size() != 2 || !(s.reals(key)[0] <= s.reals(key)[1])) s.reject(key, "must be [low, high] with low <= high");
}

StudyPlan plan_timing(const Scene& s) {
  const EnergyMapCount n = energy_map_count(s);
  // the timing protocol over both systems: the kernel's sample (an upper bound, as if on one thread) and the
  // scalar loop
  const double kernel = std::min(static_cast<double>(s.integer("timing.kernel_batches")), n.batches) *
                        kEnergyMapBatch * n.steps;
  const double scalar = std::min(static_cast<double>(s.integer("timing.scalar_points")), n.points) *
                        static_cast<double>(s.integer("timing.scalar_steps"));
  const PlanRate &rate = plan_rate("energy map scalar loop"), &kernel_rate = energy_map_kernel_rate();
  StudyPlan p;
  p.memory_bytes = n.batches * kEnergyMapBatch * 2 * sizeof(double), p.ns_per_step = rate.ns_per_step;
  p.note = "the timing protocol; " + rate.note;
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  std::vector<TimedCall> calls(2, TimedCall{kernel, kernel_rate.ns_per_step});
  for (const KernelArithmetic& a : energy_map_kernels().front().arithmetic)  // (alone: at most the kernel's time)
    if (a) calls.push_back({a.trajectory_steps(kArithmeticRepeats), kernel_rate.ns_per_step});
  const TimedPlan sample = timing_plan(calls, repeats);
  const TimedPlan loop = timing_plan({{scalar, rate.ns_per_step}, {scalar, rate.ns_per_step}}, repeats);
  p.timed_seconds = sample.seconds + loop.seconds, p.timed_steps = sample.steps + loop.steps;
  return p;
}

// The batched kernel on the batches batch(0), ..., batch(count - 1) of the grid, in parallel.
template <class BatchIndex>
std::vector<std::vector<EnergyMapPoint>> run_batches(EnergyMapKernel kernel, Coordinates c, const EnergyMapGrid& g,
                                                     std::size_t count, BatchIndex batch) {
  return parallel_map(count, [&](std::size_t b) {
    std::vector<EnergyMapPoint> out(kEnergyMapBatch);
    const std::size_t at = batch(b) * kEnergyMapBatch;
    kernel(c, g.P, &g.x0[at], &g.y0[at], out.data());
    return out;
  });
}

// The scalar loop, one trajectory at a time, single thread: ns per step and the spread, per coordinate system.
void time_scalar_loop(Context& ctx, const EnergyMapGrid& g, int repeats, Value& scalar_ns, Value& scalar_spread, double& drift) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: scalar reference loop");
  const auto nsc = static_cast<std::size_t>(
      std::min<std::int64_t>(s.integer("timing.scalar_points"), static_cast<std::int64_t>(g.npoints)));
  EnergyMapParams Ps = g.P;
  Ps.steps = s.integer("timing.scalar_steps");
  InterleavedTiming timing(repeats, kTimingFloorS, ctx.threads);  // the two coordinate systems together, a core each
  for (const auto c : {Coordinates::cartesian, Coordinates::polar})
    timing.add([&, c] {
      for (std::size_t i = 0; i < nsc; ++i) {
        const std::size_t at = i * (g.npoints / nsc);
        const auto r = energy_map_scalar(c, Ps, g.x0[at], g.y0[at]);
        do_not_optimize(r.eps);
      }
    });
  const std::vector<RunTime> times = timing.run();
  drift = times[0].drift;
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const RunTime& t = times[c == Coordinates::cartesian ? 0 : 1];
    scalar_ns[coordinates_name(c)] = 1e9 * t.seconds() / (static_cast<double>(nsc) * static_cast<double>(Ps.steps));
    scalar_spread[coordinates_name(c)] = t.spread();
  }
}

// The sample: the batched kernel on timing.kernel_batches batches of the grid under the timing protocol (the
// kernel's time where the map did not run in this process and, always, the repeats its target is judged over):
// the wall times of the two systems; their trajectory-steps in `steps`, their ns per step per core in `ns_per_step`,
// the sample in timing.kernel_sample. In the same rounds, the kernel's arithmetic alone on every thread (where
// counted): its ceiling on this core in timing.own_ceiling_ns, ns per trajectory-step and core.
std::vector<RunTime> time_kernel_sample(Context& ctx, const EnergyMapGrid& g, int repeats, Value& timing, double& steps,
                                        std::vector<RunTime>& ns_per_step) {
  ctx.progress("cost: batched kernel on a sample of batches");
  const auto kernels = energy_map_kernels();
  const auto count = std::min<std::size_t>(static_cast<std::size_t>(ctx.scene.integer("timing.kernel_batches")), g.nbatches);
  std::vector<std::size_t> batches(count);
  std::size_t trajectories = 0;
  for (std::size_t i = 0; i < count; ++i) {
    batches[i] = i * g.nbatches / count;
    trajectories += std::min<std::size_t>(kEnergyMapBatch, g.npoints - batches[i] * kEnergyMapBatch);
  }
  InterleavedTiming sample(repeats);  // the two coordinate systems together
  for (const auto c : {Coordinates::cartesian, Coordinates::polar})
    sample.add([&, c] {
      do_not_optimize(run_batches(kernels.front().run, c, g, count, [&](std::size_t b) { return batches[b]; }));
    });
  const auto& arithmetic = kernels.front().arithmetic;  // (counted for both systems, or for neither)
  if (arithmetic[0])
    for (const KernelArithmetic& a : arithmetic)
      sample.add([&] {
        do_not_optimize(parallel_map(static_cast<std::size_t>(ctx.threads), [&](std::size_t) { return a(kArithmeticRepeats); }));
      });
  const std::vector<RunTime> times = sample.run();
  steps = static_cast<double>(trajectories) * static_cast<double>(g.P.steps);
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {  // (configurations 2 and 3; per thread: per core)
    const auto i = static_cast<std::size_t>(c);
    timing["own_ceiling_ns"][coordinates_name(c)] =
        arithmetic[i] ? Value(1e9 * times[2 + i].seconds() / arithmetic[i].trajectory_steps(kArithmeticRepeats)) : Value();
  }
  Value ns;  // per step and core: the median, the quartiles and the drift of the measurement
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const RunTime& t = ns_per_step.emplace_back(times[c == Coordinates::cartesian ? 0 : 1].scaled(1e9 * ctx.threads / steps));
    ns[coordinates_name(c)] = {{"median", t.median_s}, {"q1", t.q1_s}, {"q3", t.q3_s}, {"drift", t.drift}};
  }
  timing["kernel_sample"] = {{"batches", count}, {"trajectories", trajectories},
                             {"wall_s", {{"cartesian", times[0].seconds()}, {"polar", times[1].seconds()}}},
                             {"ns_per_step_per_core", ns}};
  return times;
}

// Each kernel against its target, the AVX-512 ceiling the scene gives, and its own ceiling on this core (its
// arithmetic alone, timing.own_ceiling_ns; in cycles at the clock calibrated in this run; null where not
// counted). The target is judged over the repeats of the sample (ns per step per core of each run, `sample`):
// met where its third quartile, widened by the measurement's drift, is at most the target; missed where its
// first quartile, narrowed by it, is above.
void against_targets(Value& timing, const Scene& s, double ns_cart, double ns_polar, const std::vector<RunTime>& sample) {
  const double ns_cycle = ns_per_cycle(static_cast<int>(s.integer("timing.repeats")));
  timing["clock_ghz"] = 1 / ns_cycle;
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const std::string name = coordinates_name(c);
    const double ns = c == Coordinates::cartesian ? ns_cart : ns_polar;
    const auto ceiling = s.reals("timing.ceiling." + name);
    timing["ceiling_ns"][name] = {{"min", ceiling[0]}, {"max", ceiling[1]}};
    timing["ceiling_fraction"][name] = {{"min", ceiling[0] / ns}, {"max", ceiling[1] / ns}};
    const RunTime& t = sample[c == Coordinates::cartesian ? 0 : 1];
    const double target = s.real("timing.target." + name);
    timing["target_verdict"][name] = t.q3_s * (1 + t.drift) <= target  ? "meets"
                                     : t.q1_s / (1 + t.drift) > target ? "misses"
                                                                        : "is within the spread of";
    const Value& own = timing.at("own_ceiling_ns").at(name);
    timing["cycles_per_step_per_core"][name] = ns / ns_cycle;
    timing["own_ceiling_cycles"][name] = own.is_null() ? Value() : Value(own.number() / ns_cycle);
    timing["own_ceiling_fraction"][name] = own.is_null() ? Value() : Value(own.number() / ns);
  }
}

// The batched kernel (the map study's wall time, or a sample of batches), the scalar loop, and the kernels
// against their targets: summary timing.
void run_timing(Context& ctx, const EnergyMapCost& map) {
  const Scene& s = ctx.scene;
  const EnergyMapGrid g = energy_map_grid(s);
  const auto kernels = energy_map_kernels();
  Value timing;
  timing["kernel_isa"] = kernels.front().isa;
  timing["kernel_max_turn"] = kEnergyMapMaxTurn;  // polar: sin/cos by angle addition up to this turn

  // The kernel: wall time times threads over the trajectory-steps computed.
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  double wall_cart = map.wall_cart, wall_polar = map.wall_polar, steps_cart = map.steps_cart, steps_polar = map.steps_polar;
  Value kernel_spread;  // the sample's spread; the map's wall time is one run, not repeated
  std::string kernel_method = "map: wall time of the batched kernel in the map study of this run, times threads, over "
                              "the trajectory-steps it computed (the map is one long run, not a repeated measurement: "
                              "no median over repeats and no spread)";
  double sample_steps = 0;
  std::vector<RunTime> sample_ns;  // ns per step per core of each run
  const std::vector<RunTime> times = time_kernel_sample(ctx, g, repeats, timing, sample_steps, sample_ns);
  if (!map.ran) {
    wall_cart = times[0].seconds(), wall_polar = times[1].seconds();
    kernel_spread = Value::record();
    kernel_spread["cartesian"] = times[0].spread(), kernel_spread["polar"] = times[1].spread();
    steps_cart = steps_polar = sample_steps;
    kernel_method = "sample: the map study did not run in this process; wall time of the batched kernel on "
                    "timing.kernel_batches batches of the grid (evenly spaced, t_max/dt steps each; runs after "
                    "the timing protocol, the median over timing.repeats rounds), times threads, over their trajectory-steps";
  }
  const double ns_cart = 1e9 * wall_cart * ctx.threads / steps_cart;
  const double ns_polar = 1e9 * wall_polar * ctx.threads / steps_polar;

  Value scalar_ns, scalar_spread;
  double scalar_drift = 0;
  time_scalar_loop(ctx, g, repeats, scalar_ns, scalar_spread, scalar_drift);
  timing["scalar_drift"] = scalar_drift;
  timing["ns_per_step_per_core"] = {{"cartesian", ns_cart}, {"polar", ns_polar}};
  timing["scalar_ns_per_step"] = scalar_ns;
  timing["scalar_ns_per_step_spread"] = scalar_spread;
  timing["kernel_sample_spread"] = kernel_spread;
  timing["speedup_vs_scalar"] = {{"cartesian", scalar_ns.at("cartesian").number() / ns_cart},
                                 {"polar", scalar_ns.at("polar").number() / ns_polar}};
  timing["map_wall_s"] = map.ran ? Value{{"cartesian", wall_cart}, {"polar", wall_polar}} : Value();
  timing["method"] = "kernel timed on the " + kernel_method +
                     "; scalar: the straightforward scalar loop (one trajectory at a time) on timing.scalar_points "
                     "initial conditions of timing.scalar_steps steps, " + timing_method_text(repeats);
  timing["kernel_isa_name"] = kernels.front().name;
  timing["threads"] = ctx.threads;
  if (map.ran) timing["map_wall_total_s"] = wall_cart + wall_polar;
  // 2 n_x n_y J: one run per coordinate system and grid point
  timing["trajectory_steps"] = 2.0 * static_cast<double>(g.npoints) * static_cast<double>(g.P.steps);
  against_targets(timing, s, ns_cart, ns_polar, sample_ns);
  ctx.summary["timing"] = timing;
}


}  // namespace

Study kernel_timing_study(const EnergyMapCost& map) {
  std::vector<std::string> reads = kEnergyMapKeys;
  reads.emplace_back("timing.repeats");
  return {.name = "kernel_timing",
          .about = "cost: batched kernel against the scalar loop, ns per step",
          .keys = Schema()
                      .integer("timing.scalar_points", at_least(1), "initial conditions timed with the scalar reference loop")
                      .integer("timing.scalar_steps", at_least(1), "steps of each scalar timing run")
                      .integer("timing.kernel_batches", at_least(1),
                               "batches of 64 trajectories (evenly spaced over the grid, t_max/dt steps each) on which "
                               "the batched kernel is timed over the repeats: its target verdict, and its time where the "
                               "map study does not run in the same process")
                      .real("timing.target.cartesian", positive(),
                            "the time per trajectory-step and core set as the goal of the Cartesian kernel [ns]")
                      .real("timing.target.polar", positive(), "the same for the polar kernel [ns]")
                      .reals("timing.ceiling.cartesian", positive(), 2,
                             "[low, high] hardware ceiling of the Cartesian kernel [ns per trajectory-step and core]: an "
                             "estimate from performance measurements (bench/README.md), not measured by the run")
                      .reals("timing.ceiling.polar", positive(), 2, "the same for the polar kernel"),
          .reads = reads,
          .run = [&map](Context& ctx) { run_timing(ctx, map); },
          .validate = check_timing,
          .plan = plan_timing,
          .aliases = {"timing"}};
}

}  // namespace geomint::energy_map

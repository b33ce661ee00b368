// The ensemble of 004 Figs 4-5 (sweep/henon_heiles_ensemble.hpp), compiled once.
#include "geomint/sweep/henon_heiles_ensemble.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <utility>

#include "geomint/core/integrate.hpp"
#include "geomint/core/numerical_failure.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {
namespace {

// The error of E along the trajectories of batch b (in lanes, bit for bit the scalar method) at its ns output
// times, every `every` of the n steps.
template <class HH>
std::vector<std::vector<double>> batch_errors(const HH& hhk, const std::vector<PhaseState<2>>& starts, std::size_t b,
                                              double h, std::int64_t n, std::int64_t every) {
  const LaneBatch batch = lane_batch(b, starts.size(), kHenonHeilesLanes);
  std::vector<std::vector<double>> e(batch.count);
  std::vector<double> E0;
  for (std::size_t i = 0; i < batch.count; ++i) E0.push_back(simplified_ti_modified_energy(hhk, starts[batch.first + i], h));
  simplified_ti_lanes(hhk, simplified_ti_lanes_kernels<HH>().front().steps,
                      std::span<const PhaseState<2>>(starts).subspan(batch.first, batch.count), h, n, every,
                      [&](int i, std::int64_t, const PhaseState<2>& z) {
                        e[i].push_back(simplified_ti_modified_energy(hhk, z, h) - E0[i]);
                      });
  return e;
}

}  // namespace

std::vector<PhaseState<2>> ensemble_starts(const Scene& s, std::size_t count) {
  std::vector<PhaseState<2>> starts(count);
  with_ensemble_system(s, [&](const auto& hhk) {
    for (std::size_t i = 0; i < count; ++i) starts[i] = ensemble_start(s, hhk, i);
  });
  return starts;
}

HenonHeilesEnsemble integrate_ensemble(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig. 4: ensemble");
  const double h = s.real("h"), t_end = s.real("t_end");
  const std::int64_t samples = s.integer("samples");
  const auto M = static_cast<std::size_t>(s.integer("ensemble.size"));
  const std::int64_t n4 = steps_to(t_end, h), every4 = std::max<std::int64_t>(1, n4 / samples);
  const auto time_of = [&](std::size_t k) { return static_cast<double>(k) * static_cast<double>(every4) * h; };
  const std::vector<PhaseState<2>> starts = ensemble_starts(s, M);
  const auto t0 = std::chrono::steady_clock::now();  // (on --resume: the part run since)
  auto series = concatenate(checkpointed_map<std::vector<std::vector<double>>>(
      ctx, {"ensemble", kEnsembleKeys}, lane_batches(M, kHenonHeilesLanes), [&](std::size_t b) {
        return with_ensemble_system(s, [&](const auto& hhk) { return batch_errors(hhk, starts, b, h, n4, every4); });
      }));
  const double wall4 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < M; ++i)
    for (std::size_t k = 0; k < series[i].size(); ++k)
      if (!std::isfinite(series[i][k]))
        throw NumericalFailure("simplified_takahashi_imada: E of trajectory " + std::to_string(i) +
                               " is not finite at step " + std::to_string(static_cast<std::int64_t>(k) * every4) +
                               ", t = " + format_double(time_of(k)));
  const std::size_t ns = series[0].size();
  return {h, t_end, M, n4, every4, std::move(starts), std::move(series), ns, wall4};
}

void check_ensemble_run(const Scene& s) {
  with_ensemble_system(s, [&](const auto& hh) { check_henon_heiles_starts(s, "hh3", hh, s.real("ensemble.perturbation"), true); });
  if (s.real("t_end") / s.real("h") < 2) s.reject("t_end", "must be at least two steps h");
}

std::size_t largest_error(const HenonHeilesEnsemble& run) {
  std::size_t worst_i = 0;
  double worst_e = 0;
  for (std::size_t i = 0; i < run.M; ++i)
    if (const double mx = largest_abs(run.series[i]); mx > worst_e) worst_e = mx, worst_i = i;
  return worst_i;
}

}  // namespace geomint

// The ensemble of 004 Fig. 6 (sweep/lennard_jones_ensemble.hpp), compiled once.
#include "geomint/sweep/lennard_jones_ensemble.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "geomint/core/integrate.hpp"
#include "geomint/core/numerical_failure.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint {

PhaseState<18> lennard_jones_start(const Scene& s, std::size_t i) {
  return lennard_jones_grid_start(static_cast<std::uint64_t>(s.integer("lj.seed")), s.real("lj.perturbation"), i);
}

std::vector<PhaseState<18>> lennard_jones_starts(const Scene& s, std::size_t count) {
  std::vector<PhaseState<18>> starts;
  for (std::size_t i = 0; i < count; ++i) starts.push_back(lennard_jones_start(s, i));
  return starts;
}

void check_lennard_jones_step(const Scene& s, const char* key, double h) {
  check_step_bound(s, key, "simplified_takahashi_imada", h * std::sqrt(lennard_jones_grid_stiffness()),
                   "omega^2 = max eig U'' at the 3 x 3 grid of Fig. 6", "2 sqrt(3)");
}

std::vector<std::pair<double, std::int64_t>> lennard_jones_step_scan(const Scene& s) {
  const LennardJones<9> lj;
  const auto hs = s.reals("lj.h_scan");
  const auto scan_size = static_cast<std::size_t>(s.integer("lj.scan_size"));
  return distributed_map(hs.size() * scan_size, [&](std::size_t task) {
    const double hh = hs[task / scan_size];
    const PhaseState<18> start = lennard_jones_start(s, task % scan_size);
    const double Hs = lj.H(start);
    double worst = 0;
    std::int64_t diverged = -1;
    simplified_ti_integrate(lj, start, hh, steps_to(s.real("lj.scan_t"), hh), [&](std::int64_t j, const PhaseState<18>& z) {
      if (diverged >= 0) return;
      const double e = std::abs(lj.H(z) - Hs);
      if (!(e <= s.real("lj.blowup"))) diverged = j;
      else worst = std::max(worst, e);
    });
    return std::pair{worst, diverged};
  });
}

std::vector<double> lennard_jones_stiffness_along(const Scene& s, std::int64_t every) {
  const LennardJones<9> lj;
  const double hl = s.real("lj.h");
  return distributed_map(static_cast<std::size_t>(s.integer("lj.scan_size")), [&](std::size_t i) {
    double largest = 0;
    simplified_ti_integrate(lj, lennard_jones_start(s, i), hl, steps_to(s.real("lj.scan_t"), hl), [&](std::int64_t j, const PhaseState<18>& z) {
      if (j % every == 0) largest = std::max(largest, max_hessian_eigenvalue(lj, z.q));
    });
    return largest;
  });
}

LennardJonesEnsemble integrate_lennard_jones_ensemble(Context& ctx) {
  using LJ = LennardJones<9>;
  using Z18 = PhaseState<18>;
  const LJ lj;
  const Scene& s = ctx.scene;
  const std::int64_t samples = s.integer("samples");
  const double hl = s.real("lj.h");
  const auto Ml = static_cast<std::size_t>(s.integer("lj.size"));
  const std::int64_t nl = steps_to(s.real("lj.t_end"), hl), every_l = std::max<std::int64_t>(1, nl / samples);
  const auto tl0 = std::chrono::steady_clock::now();  // (on --resume: the part run since)
  const std::vector<std::string> series_keys = {"samples", "lj.h", "lj.t_end", "lj.size", "lj.seed", "lj.perturbation"};
  const auto lanes = simplified_ti_lanes_kernels<LJ>().front().steps;  // (bit for bit the scalar method)
  auto lj_series = concatenate(checkpointed_map<std::vector<LennardJonesSeries>>(ctx, {"lj", series_keys}, lane_batches(Ml, kLennardJonesLanes), [&](std::size_t b) {
    const LaneBatch batch = lane_batch(b, Ml, kLennardJonesLanes);
    std::vector<Z18> starts;
    std::vector<double> E0, Hs;
    for (std::size_t i = batch.first; i < batch.first + batch.count; ++i)
      starts.push_back(lennard_jones_start(s, i)), E0.push_back(simplified_ti_modified_energy(lj, starts.back(), hl)), Hs.push_back(lj.H(starts.back()));
    std::vector<LennardJonesSeries> r(batch.count);
    simplified_ti_lanes(lj, lanes, std::span<const Z18>(starts), hl, nl, every_l, [&](int i, std::int64_t, const Z18& z) {
      r[i].E.push_back(simplified_ti_modified_energy(lj, z, hl) - E0[i]);
      r[i].H.push_back(lj.H(z) - Hs[i]);
      r[i].Hhat.push_back(lj.H(ti_process(lj, z, hl, takahashi_imada_alpha)) - Hs[i]);
    });
    return r;
  }));
  const double wall6 = std::chrono::duration<double>(std::chrono::steady_clock::now() - tl0).count();
  for (std::size_t i = 0; i < Ml; ++i)  // diverged as the scan counts it (|H - H0| beyond lj.blowup), or not finite
    for (std::size_t k = 0; k < lj_series[i].E.size(); ++k)
      if (!std::isfinite(lj_series[i].E[k]) || !std::isfinite(lj_series[i].Hhat[k]) ||
          !(std::abs(lj_series[i].H[k]) <= s.real("lj.blowup")))
        throw NumericalFailure("simplified_takahashi_imada at lj.h = " + format_double(hl) + ": trajectory " +
                               std::to_string(i) + " diverged (|H - H0| = " + format_double(std::abs(lj_series[i].H[k])) +
                               " > lj.blowup) by step " + std::to_string(static_cast<std::int64_t>(k) * every_l) +
                               ", t = " + format_double(static_cast<double>(k) * static_cast<double>(every_l) * hl));
  return {hl, Ml, nl, every_l, std::move(lj_series), wall6};
}

}  // namespace geomint

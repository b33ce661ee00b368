#pragma once
// 004 Fig. 6: the scene's ensemble on the Lennard-Jones cluster of 9 particles (systems/lennard_jones.hpp): lj.size
// starts near the 3 x 3 grid (lj.seed, lj.perturbation) along the simplified method (1.6) at lj.h to lj.t_end, and at
// each of its output times the errors of the modified energy E of (3.3) and (4.2), of H, and of H at the processed
// variables (1.5); and the step-size scan of the starts. Compiled once (lennard_jones_ensemble.cpp): the study that reads it compiles only its statistics.
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "geomint/core/state.hpp"

namespace geomint {

class Context;
class Scene;

// The step-size scan of Fig. 6: for each h of lj.h_scan (k) and each of the first lj.scan_size starts (i), at
// [k * lj.scan_size + i], max |H - H_0| over t <= lj.scan_t and the step at which |H - H_0| exceeded lj.blowup or was
// not finite (the run diverged), or -1. (One task each, split across threads and MPI ranks.)
std::vector<std::pair<double, std::int64_t>> lennard_jones_step_scan(const Scene& s);

// The stiffness omega_max^2 (observables/stiffness.hpp) along each of the first lj.scan_size starts integrated at lj.h
// to lj.scan_t: its largest value at every `every`-th step.
std::vector<double> lennard_jones_stiffness_along(const Scene& s, std::int64_t every);

// The step h of `key` below the bound of the simplified method (1.6) at the stiffness of the unperturbed grid
// (omega^2 = 86.8; the perturbed starts and the motion are stiffer: a run that diverges anyway ends with a
// numerical failure, exit 4).
void check_lennard_jones_step(const Scene& s, const char* key, double h);

// Start i of the scene's ensemble: lennard_jones_grid_start from lj.seed and lj.perturbation.
PhaseState<18> lennard_jones_start(const Scene& s, std::size_t i);
// Starts 0 .. count - 1.
std::vector<PhaseState<18>> lennard_jones_starts(const Scene& s, std::size_t count);

// One trajectory's errors at the output times: E - E_0, H - H_0, and H(processed) - H_0.
struct LennardJonesSeries {
  std::vector<double> E, H, Hhat;
  auto fields() { return std::tie(E, H, Hhat); }  // (a record of runner/checkpoint.hpp)
};

// The ensemble as run: lj.size trajectories of nl steps of lj.h, output every every_l steps.
struct LennardJonesEnsemble {
  double hl;
  std::size_t Ml;
  std::int64_t nl, every_l;  // steps, and steps between output times
  std::vector<LennardJonesSeries> lj_series;
  double wall6;  // (on --resume: the part run since)
};

// The ensemble in SIMD lanes (sweep/ensemble_kernels.hpp: bit for bit the scalar method), checkpointed (checkpoint
// "lj"; --resume); a trajectory that diverges as the scan counts it (|H - H0| beyond lj.blowup) or whose errors are
// not finite is a NumericalFailure.
LennardJonesEnsemble integrate_lennard_jones_ensemble(Context& ctx);

}  // namespace geomint

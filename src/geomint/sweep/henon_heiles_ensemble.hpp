#pragma once
// 004 Figs 4-5: the scene's ensemble on Henon-Heiles k (hh.k, coupling hh.coupling) along the simplified method
// (1.6): ensemble.size starts (hh3.q2, hh3.p2) perturbed by ensemble.perturbation on the energy shell hh.H0, and the
// error of the modified energy E of (3.3) and (4.2) of every trajectory at its output times. Fig. 4 (study ensemble)
// reads its statistics; Fig. 5 (study poincare) cuts its trajectory with the largest error, which the ensemble study
// hands over when both run in one process (LargestError), and which the poincare study takes from the ensemble
// integrated again otherwise (integrate_ensemble: the same starts, checkpoint and numbers).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint {

class Context;

// Calls f with the Henon-Heiles system of the ensemble: exponent hh.k, coupling hh.coupling (compiled out if 0).
template <class F>
decltype(auto) with_ensemble_system(const Scene& s, F&& f) {
  return with_henon_heiles(static_cast<int>(s.integer("hh.k")), s.real("hh.coupling"), f);
}

// Start i of the ensemble: (hh3.q2, hh3.p2) perturbed, each trajectory its own stream seeded by (ensemble.seed, i).
template <class HH>
PhaseState<2> ensemble_start(const Scene& s, const HH& hhk, std::size_t i) {
  return hhk.perturbed_start(s.real("hh3.q2"), s.real("hh3.p2"), s.real("hh.H0"), s.real("ensemble.perturbation"),
                             static_cast<std::uint64_t>(s.integer("ensemble.seed")), i);
}

// Starts 0 .. count - 1 of the ensemble (ensemble_start) on the scene's system.
std::vector<PhaseState<2>> ensemble_starts(const Scene& s, std::size_t count);

// The ensemble as run: the error of E of each trajectory at its ns output times, every4 steps apart.
struct HenonHeilesEnsemble {
  double h, t_end;
  std::size_t M;
  std::int64_t n4, every4;
  std::vector<PhaseState<2>> starts;
  std::vector<std::vector<double>> series;  // per trajectory
  std::size_t ns;
  double wall4;  // (on --resume: the part run since)
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

// The scene keys the ensemble depends on (its checkpoint "ensemble"): every study that integrates it reads them.
inline const std::vector<std::string> kEnsembleKeys = {"h", "t_end", "samples", "hh", "ensemble.size", "ensemble.seed",
                                                       "ensemble.perturbation", "hh3.q2", "hh3.p2"};

// The ensemble of the scene in SIMD lanes (sweep/ensemble_kernels.hpp: bit for bit the scalar method), checkpointed
// (checkpoint "ensemble"; --resume), whichever study runs it; a non-finite E is a NumericalFailure.
HenonHeilesEnsemble integrate_ensemble(Context& ctx);

// The checks of the ensemble's scene values before any work: the starts in the bounded well, two steps at least.
void check_ensemble_run(const Scene& s);

// The trajectory with the largest max_k |E_k - E_0| (the first of equal ones).
std::size_t largest_error(const HenonHeilesEnsemble& run);

// One trajectory of the ensemble: its index, its start and recorded error, and the run's steps and output times.
struct EnsembleTrajectory {
  std::size_t index;
  PhaseState<2> start;
  std::vector<double> e;
  double h, t_end;
  std::int64_t n4, every4;
  std::size_t ns;
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

// The trajectory with the largest error, which the ensemble study hands to the poincare study of the same process:
// empty until the ensemble study has run in it.
using LargestError = std::optional<EnsembleTrajectory>;

inline EnsembleTrajectory trajectory_of(const HenonHeilesEnsemble& run, std::size_t i) {
  return {i, run.starts[i], run.series[i], run.h, run.t_end, run.n4, run.every4, run.ns};
}

}  // namespace geomint

#pragma once
// ti_drift: the ensemble of 004 Fig. 4 as run, which Fig. 4 (study ensemble, ensemble.cpp) and Fig. 5 (study
// poincare, poincare.cpp) read: the error of the modified energy E of (3.3) and (4.2) of every trajectory at its
// output times, and the trajectory with the largest error, which Fig. 5 cuts. The poincare study takes that
// trajectory from the ensemble study when both run in one process, and integrates the ensemble itself otherwise
// (integrate_ensemble: the same starts, checkpoint and numbers).
#include <cstdint>
#include <string>
#include <vector>

#include "ti_drift.hpp"

namespace geomint::ti_drift {

// The ensemble as run: the error of E of each trajectory at its ns output times, every4 steps apart.
struct Run {
  double h, t_end;
  std::size_t M;
  std::int64_t n4, every4;
  std::vector<Z2> starts;
  std::vector<std::vector<double>> series;  // per trajectory
  std::size_t ns;
  double wall4;  // (on --resume: the part run since)
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

// The scene keys the ensemble depends on (its checkpoint "ensemble"): both studies read them.
const std::vector<std::string> kEnsembleKeys = {"h", "t_end", "samples", "hh", "ensemble.size", "ensemble.seed",
                                                "ensemble.perturbation", "hh3.q2", "hh3.p2"};

// The ensemble of the scene along the simplified method (1.6), in SIMD lanes (bit for bit the scalar method),
// checkpointed (checkpoint "ensemble"; --resume), whichever study runs it (ensemble.cpp).
Run integrate_ensemble(Context& ctx);

// The checks of the ensemble's scene values before any work: the starts in the bounded well, two steps at least.
void check_ensemble_run(const Scene& s);

// The trajectory with the largest max_k |E_k - E_0| (the first of equal ones).
std::size_t largest_error(const Run& run);

// One trajectory of a run: its index in the ensemble, its start and recorded error, and the run's steps and
// output times (ti_drift.hpp: LargestError, the one the ensemble study hands to the poincare study).
struct Trajectory {
  std::size_t index;
  Z2 start;
  std::vector<double> e;
  double h, t_end;
  std::int64_t n4, every4;
  std::size_t ns;
  double time_of(std::size_t k) const { return static_cast<double>(k) * static_cast<double>(every4) * h; }
};

inline Trajectory trajectory_of(const Run& run, std::size_t i) {
  return {i, run.starts[i], run.series[i], run.h, run.t_end, run.n4, run.every4, run.ns};
}

}  // namespace geomint::ti_drift

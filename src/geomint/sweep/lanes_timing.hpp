#pragma once
// The ensembles' lane kernels (sweep/ensemble_kernels.hpp) timed against the scalar method they
// reproduce bit for bit: the simplified Takahashi-Imada method (004 (1.6)) unprocessed, on the
// trajectories of one batch, single thread (runner/timing.hpp). Compiled once in the library for the
// systems of 004 Figs 4 and 6.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geomint/runner/timing.hpp"

namespace geomint {

struct LanesTiming {
  RunTime scalar;  // integrate(simplified_ti_method(sys, false), ...), one trajectory after another, every call inlined
  struct Kernel {
    std::string name;  // "AVX-512", "AVX2", "SSE2"
    RunTime time;      // all lanes at once
    std::optional<double> own_ceiling_ns;  // its arithmetic alone per trajectory-step (arithmetic_ceiling.hpp), if counted
  };
  std::vector<Kernel> kernels;  // each lane kernel this CPU runs, widest lanes first
  // In ns per trajectory-step of `trajectories` trajectories of n steps: {trajectories, steps, scalar_ns_per_step,
  // scalar, scalar_spread, kernels: {name: {ns_per_step, spread, time, speedup_vs_scalar, speedup_interval,
  // against_scalar, own_ceiling_ns, own_ceiling_fraction (null where not counted)}}}, and the first kernel's (the
  // widest lanes: the one the ensembles use) at the top level, with its name as isa. (Scalar and lanes do the same
  // arithmetic per trajectory-step: the same work.)
  Value summary(std::size_t trajectories, std::int64_t n) const;
};

// The lane kernels of Sys as configurations of a measurement (InterleavedTiming) that may time other things too:
// n steps of h from each of `starts` (at most kLanes<Sys>), every kernel this CPU runs, and the scalar method
// (simplified Takahashi-Imada unprocessed, every call inlined) one trajectory after another; or, given
// `scalar_on_first`, the index of a configuration of the same measurement that already runs the scalar method
// n steps from starts[0], that one, its time taken for every start (the step's arithmetic does not depend on the
// state): one measurement reused, not a second. With each kernel whose arithmetic is counted, that arithmetic
// alone (its own ceiling, arithmetic_ceiling.hpp). For LennardJones<9>, HenonHeilesT<true> and HenonHeilesT<false>.
struct LanesConfigs {
  std::size_t scalar = 0;       // the scalar method's configuration
  double scalar_runs = 1;       // its time times this is that of every start
  struct Kernel {
    std::string name;
    std::size_t config = 0;                 // the kernel's configuration
    std::optional<std::size_t> arithmetic;  // its arithmetic alone's, if counted
    double arithmetic_steps = 0;            // the trajectory-steps of a call of it
  };
  std::vector<Kernel> kernels;
  LanesTiming of(const std::vector<RunTime>& times) const;    // from the measurement's times
};
template <class Sys>
LanesConfigs add_lanes(InterleavedTiming& timing, const Sys& sys, const std::vector<typename Sys::State>& starts,
                       double h, std::int64_t n, std::optional<std::size_t> scalar_on_first = std::nullopt);
// What add_lanes times, to plan (runner/timing.hpp timing_plan): the scalar method's run (without scalar_on_first) at
// scalar_ns per trajectory-step, each kernel's at lanes_ns, and each counted kernel's arithmetic (at most its time).
template <class Sys>
std::vector<TimedCall> lanes_calls(std::int64_t n, double scalar_ns, double lanes_ns, bool scalar_on_first);

}  // namespace geomint

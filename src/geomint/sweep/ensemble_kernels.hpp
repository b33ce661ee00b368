#pragma once
// Ensembles in SIMD lanes: the simplified Takahashi-Imada method (004 (1.6)), unprocessed, as the
// kick-drift-kick kernel of integrators/takahashi_imada.hpp, on a batch of trajectories at once (kLanes)
// (004 Fig. 4 on Henon-Heiles, Fig. 6 on the Lennard-Jones cluster, and the step studies of Fig. 6).
//
// A lane kernel keeps the states of its trajectories in structure-of-arrays form (KickLanes: q, p and
// the cached force F, component-major) and runs n steps with every operation on all lanes at once. The
// force is the system's own gradient(), instantiated for a vector of lanes instead of a double, and the
// step does the operations of kick_drift_kick and simplified_ti_force in their order: the build has no
// FMA contraction (CMakeLists.txt), so each lane is bit for bit the scalar method
// (tests/unit/ensemble_kernels_test.cpp); in AVX-512 a third of a Lennard-Jones gradient's reciprocals come
// correctly rounded from the FMA units instead of the divider (ensemble_kernel.inc). One translation unit per
// instruction set (SSE2, AVX2, AVX-512), chosen at run time by CPU detection, as for the energy map.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/core/state.hpp"
#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/sweep/arithmetic_ceiling.hpp"
#include "geomint/systems/henon_heiles.hpp"
#include "geomint/systems/lennard_jones.hpp"

namespace geomint {

// Trajectories per batch of lanes, per system: enough registers of lanes stepped together to hide the latency
// of a step (kChains, below). A Henon-Heiles step is one chain of about 30 dependent operations, so one register
// of lanes waits on each (8 lanes took as long per trajectory-step in AVX-512 as in SSE2): 32 lanes, 4 AVX-512
// registers (8 AVX2, 16 SSE2). A Lennard-Jones step has hundreds of independent operations (36 pairs, two
// gradients, a reciprocal each): 8 lanes, the fewest a small ensemble fills.
inline constexpr int kHenonHeilesLanes = 32, kLennardJonesLanes = 8;
template <class Sys>
inline constexpr int kLanes = kHenonHeilesLanes;
template <int N>
inline constexpr int kLanes<LennardJones<N>> = kLennardJonesLanes;
// Registers of lanes a kernel steps together, their states kept in registers; a batch of more runs group after
// group. Henon-Heiles: up to 8, whose chains hide each other's latency: AVX-512 steps its 4 registers together
// (0.79 ns per trajectory-step, 1.27 with 2, 2.47 with 1), AVX2 and SSE2 8 of their 8 and 16 despite the spills
// (Fig. 4's lanes with k = 5 on a Sapphire Rapids core: AVX2 1.13-1.19 -> 0.96-1.05 ns, SSE2 2.20-2.32 -> 1.61-1.78,
// three rounds in turn); Lennard-Jones: 1, a step that fills the pipes.
template <class Sys>
inline constexpr int kChains = 8;
template <int N>
inline constexpr int kChains<LennardJones<N>> = 1;

// Kick-drift-kick states of L trajectories: q[k][lane], p[k][lane], F[k][lane].
template <int D, int L>
struct KickLanes {
  alignas(64) double q[D][L], p[D][L], F[D][L];

  void set(int lane, const KickState<D>& s) {
    for (int k = 0; k < D; ++k) q[k][lane] = s.z.q[k], p[k][lane] = s.z.p[k], F[k][lane] = s.F[k];
  }
  KickState<D> get(int lane) const {
    KickState<D> s;
    for (int k = 0; k < D; ++k) s.z.q[k] = q[k][lane], s.z.p[k] = p[k][lane], s.F[k] = F[k][lane];
    return s;
  }
};

// n steps of (1.6) at step h on every lane of s.
template <class Sys>
using LanesOf = KickLanes<Sys::State::dof, kLanes<Sys>>;
template <class Sys>
using LanesSteps = void (*)(const Sys& sys, double h, double alpha, LanesOf<Sys>& s, std::int64_t n);

template <class Sys>
struct LanesKernel {
  std::string isa;   // "avx512", "avx2", "sse2"
  std::string name;  // "AVX-512", "AVX2", "SSE2"
  LanesSteps<Sys> steps;
  // out[i] = 1 / u[i], i < n (a multiple of 8), as the lanes take 1/u where not from the divider (AVX-512: from the
  // FMA units, correctly rounded, ensemble_kernel.inc; the others divide): for the tests.
  void (*reciprocals)(const double* u, double* out, std::size_t n);
  KernelArithmetic arithmetic;  // a step of a register of lanes, its arithmetic alone (arithmetic_ceiling.hpp); empty: not counted
};

// The kernels this CPU can run under GEOMINT_LANES (sweep/lanes_cap.hpp), best first (for LennardJones<9>,
// HenonHeilesT<true> and <false>).
template <class Sys>
std::vector<LanesKernel<Sys>> simplified_ti_lanes_kernels();

// observe(i, j, z): trajectory i (of a batch) is z at step j.
template <class Sys>
using LanesObserver = std::function<void(int i, std::int64_t j, const typename Sys::State& z)>;

// Integrates the trajectories from `starts` (at most kLanes<Sys>; a shorter batch fills its other
// lanes with the first start) by (1.6), unprocessed, at step h for n steps with the kernel `steps`,
// and calls observe(i, j, z) for trajectory i at every step j <= n that is a multiple of `every`
// (j = 0 included), as integrate(simplified_ti_method(sys, false), ...) would for the same z.
// Returns the states at step n. (Compiled once, ensemble_kernels.cpp, for the systems above.)
template <class Sys>
std::vector<typename Sys::State> simplified_ti_lanes(const Sys& sys, LanesSteps<Sys> steps,
                                                    std::span<const typename Sys::State> starts, double h,
                                                    std::int64_t n, std::int64_t every, const LanesObserver<Sys>& observe);

// The trajectories 0..M-1 of an ensemble in batches of `lanes` (kLanes of its system; the tasks of its
// sweep): batch b holds trajectories first..first + count.
struct LaneBatch {
  std::size_t first, count;
};
inline std::size_t lane_batches(std::size_t M, int lanes) { return (M + lanes - 1) / static_cast<std::size_t>(lanes); }
inline LaneBatch lane_batch(std::size_t b, std::size_t M, int lanes) {
  const std::size_t first = b * static_cast<std::size_t>(lanes);
  return {first, std::min<std::size_t>(static_cast<std::size_t>(lanes), M - first)};
}

// The records of the batches, in trajectory order.
template <class R>
std::vector<R> concatenate(std::vector<std::vector<R>>&& batches) {
  std::vector<R> out;
  for (auto& b : batches)
    for (auto& r : b) out.push_back(std::move(r));
  return out;
}

}  // namespace geomint

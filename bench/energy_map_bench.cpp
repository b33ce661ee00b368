// Throughput of the energy-map computation of 000 Fig. 6 (see
// src/geomint/sweep/energy_map.hpp): symplectic Euler, p first (000 eq.
// (42)-(43)), on the elastic pendulum l = m = k = 1, g = 0.02, h = 0.2, from
// initial conditions at rest, accumulating the RMS energy error eq. (50).
// Single-threaded. Every benchmark reports `time_per_step`, CPU time per
// trajectory-step (time / (iterations x trajectories x steps)), so rows are
// comparable whatever the workload.
//
//   BM_EnergyMapKernel/<isa>/<coordinates>  the batch kernels of energy_map_kernels()
//   BM_EnergyMapScalar/<coordinates>        energy_map_scalar (the straightforward scalar loop)
//   BM_EnergyMapOdeint/cartesian            Boost.Odeint symplectic_euler, p-first arrangement
//   BM_KernelArithmetic/<isa>/<coordinates> the kernel's vector arithmetic alone: its ceiling on this core
//   BM_ClockCalibration                      a dependent chain of integer additions: the cycle time
//
// Before any benchmark runs, the odeint loop is checked against
// energy_map_scalar on a regular trajectory (relative difference in eps
// <= 1e-12); the program aborts with a message if they disagree.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <boost/numeric/odeint/integrate/integrate_n_steps.hpp>
#include <boost/numeric/odeint/stepper/symplectic_euler.hpp>

#include "geomint/runner/clock.hpp"
#include "geomint/sweep/energy_map.hpp"

using namespace geomint;

namespace {

// ---- workload: 16 x 16 regular grid, x0 in [-1, 1], y0 in [0.3, 1.4], p = 0 ----------
constexpr int kNx = 16, kNy = 16, kTrajectories = kNx * kNy;  // 8 batches of kEnergyMapBatch
constexpr std::int64_t kSteps = 4000;
static_assert(kTrajectories % kEnergyMapBatch == 0);

EnergyMapParams params(std::int64_t steps = kSteps) {
  return EnergyMapParams{.l = 1.0, .m = 1.0, .k = 1.0, .g = 0.02, .h = 0.2, .steps = steps, .blowup = 1e6};
}

struct Grid {
  std::vector<double> x0, y0;
  Grid() {
    for (int iy = 0; iy < kNy; ++iy) {
      for (int ix = 0; ix < kNx; ++ix) {
        x0.push_back(-1.0 + 2.0 * ix / (kNx - 1));
        y0.push_back(0.3 + 1.1 * iy / (kNy - 1));
      }
    }
  }
};
const Grid& grid() {
  static const Grid g;
  return g;
}

const char* name(Coordinates c) { return c == Coordinates::polar ? "polar" : "cartesian"; }

// Time per trajectory-step: the inverted rate of trajectory-steps per CPU
// second. The console shows it with its unit (e.g. "time_per_step=0.56ns"); in
// --benchmark_format=json it is in seconds.
void set_counters(benchmark::State& state, const std::vector<EnergyMapPoint>& out) {
  const double work = static_cast<double>(kTrajectories) * static_cast<double>(kSteps);
  state.counters["time_per_step"] =
      benchmark::Counter(work, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  int diverged = 0;
  for (const auto& p : out) diverged += std::isnan(p.eps) ? 1 : 0;
  state.counters["diverged"] = diverged;
}

// ---- (c) Boost.Odeint ------------------------------------------------------------------
// Odeint's symplectic_euler updates its first component with the derivative
// taken at the second, then the second at the new first ("coordinate first").
// Passing the state as (p, q) and the system as (dp/dt = -dU/dq, dq/dt = p/m)
// therefore gives p first: p^{j+1} = p^j - h U_q(q^j), q^{j+1} = q^j + h p^{j+1}/m,
// 000 eq. (42)-(43) for the Cartesian pendulum (73).
using Vec2 = std::array<double, 2>;
using OdeintEuler = boost::numeric::odeint::symplectic_euler<Vec2>;

struct MinusUq {  // "coordinate" derivative: dp/dt = -U_q(q), (73)
  double k, l, m, g;
  void operator()(const Vec2& q, Vec2& dpdt) const {
    const double f = k * (1.0 - l / std::sqrt(q[0] * q[0] + q[1] * q[1]));
    dpdt[0] = -(f * q[0]);
    dpdt[1] = -(f * q[1] - m * g);
  }
};
struct Velocity {  // "momentum" derivative: dq/dt = p/m
  double m;
  void operator()(const Vec2& p, Vec2& dqdt) const { dqdt[0] = p[0] / m, dqdt[1] = p[1] / m; }
};

struct EnergyObserver {  // Kahan sum of (H_j - H_0)^2, H of (73); the state is (p, q)
  double k, l, m, g, H0;
  double* sum;
  double* comp;
  double H(const std::pair<Vec2, Vec2>& s) const {
    const auto& [p, q] = s;
    const double r = std::sqrt(q[0] * q[0] + q[1] * q[1]);
    return (p[0] * p[0] + p[1] * p[1]) * (0.5 / m) + 0.5 * k * (r - l) * (r - l) - m * g * q[1];
  }
  void operator()(const std::pair<Vec2, Vec2>& s, double /*t*/) const {
    const double d = H(s) - H0, y = d * d - *comp, t = *sum + y;
    *comp = (t - *sum) - y;
    *sum = t;
  }
};

EnergyMapPoint energy_map_odeint(const EnergyMapParams& P, double x0, double y0) {
  std::pair<Vec2, Vec2> s{Vec2{0.0, 0.0}, Vec2{x0, y0}};  // (p, q)
  double sum = 0.0, comp = 0.0;
  EnergyObserver obs{P.k, P.l, P.m, P.g, 0.0, &sum, &comp};
  obs.H0 = obs.H(s);
  // integrate_n_steps counts steps with an integer (t = t0 + n h) and calls the
  // observer at step 0 (adds (H_0 - H_0)^2 = 0) and after every step.
  boost::numeric::odeint::integrate_n_steps(OdeintEuler{}, std::make_pair(MinusUq{P.k, P.l, P.m, P.g}, Velocity{P.m}),
                                            s, 0.0, P.h, static_cast<std::size_t>(P.steps), obs);
  return {std::sqrt(sum / static_cast<double>(P.steps)), -1};  // (50)
}

// ---- the setup check -------------------------------------------------------------------
// kCheckPoints[0] is a regular point near the hanging equilibrium (0, l + m g / k):
// there odeint must reproduce the reference loop's eps to 1e-12 relative, else
// the program aborts. For all points (the numpy peer prints the same ones) the
// eps of every implementation goes to stderr as lines
//   "eps <coordinates> <implementation> <x0> <y0> <eps>"
// (kernels are not asserted: vector sin/cos are a few ulp from glibc's scalar ones).
constexpr std::int64_t kCheckSteps = 20000;
constexpr std::array<std::pair<double, double>, 3> kCheckPoints{{{0.2, 1.0}, {-0.5, 0.8}, {0.7, 1.3}}};

void check_agreement() {
  const auto P = params(kCheckSteps);
  std::fprintf(stderr, "# eps (000 eq. (50)) after %lld steps, h = %g, p0 = 0\n", static_cast<long long>(P.steps), P.h);
  const auto kernels = energy_map_kernels();
  bool first = true;
  for (const auto& [x0, y0] : kCheckPoints) {
    for (const Coordinates c : {Coordinates::cartesian, Coordinates::polar}) {
      const auto ref = energy_map_scalar(c, P, x0, y0);
      std::fprintf(stderr, "eps %s scalar %g %g %.17g\n", name(c), x0, y0, ref.eps);
      if (c == Coordinates::cartesian) {
        const auto od = energy_map_odeint(P, x0, y0);
        const double rel = std::fabs(od.eps - ref.eps) / std::fabs(ref.eps);
        std::fprintf(stderr, "eps %s odeint %g %g %.17g\n", name(c), x0, y0, od.eps);
        if (first && !(ref.diverge_step < 0 && std::isfinite(ref.eps) && ref.eps > 0 && rel <= 1e-12)) {
          std::fprintf(stderr,
                       "energy_map_bench: Boost.Odeint symplectic_euler (p-first arrangement) disagrees with "
                       "energy_map_scalar at (x0, y0) = (%g, %g): eps %.17g vs %.17g (relative difference %.3g, "
                       "allowed 1e-12); aborting\n",
                       x0, y0, od.eps, ref.eps, rel);
          std::abort();
        }
      }
      for (const auto& k : kernels) {
        std::array<double, kEnergyMapBatch> xs, ys;
        xs.fill(x0), ys.fill(y0);
        std::array<EnergyMapPoint, kEnergyMapBatch> out;
        k.run(c, P, xs.data(), ys.data(), out.data());
        std::fprintf(stderr, "eps %s %s %g %g %.17g\n", name(c), k.isa.c_str(), x0, y0, out[0].eps);
      }
    }
    first = false;
  }
}

// ---- benchmarks ---------------------------------------------------------------------------
void BM_EnergyMapKernel(benchmark::State& state, EnergyMapKernel kernel, Coordinates c) {
  const auto P = params();
  const auto& G = grid();
  std::vector<EnergyMapPoint> out(kTrajectories);
  for (auto _ : state) {
    for (int b = 0; b < kTrajectories; b += kEnergyMapBatch) kernel(c, P, &G.x0[b], &G.y0[b], &out[b]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, out);
}

void BM_EnergyMapScalar(benchmark::State& state, Coordinates c) {
  const auto P = params();
  const auto& G = grid();
  std::vector<EnergyMapPoint> out(kTrajectories);
  for (auto _ : state) {
    for (int i = 0; i < kTrajectories; ++i) out[i] = energy_map_scalar(c, P, G.x0[i], G.y0[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, out);
}

void BM_EnergyMapOdeint(benchmark::State& state) {
  const auto P = params();
  const auto& G = grid();
  std::vector<EnergyMapPoint> out(kTrajectories);
  for (auto _ : state) {
    for (int i = 0; i < kTrajectories; ++i) out[i] = energy_map_odeint(P, G.x0[i], G.y0[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, out);
}

// The kernel's arithmetic alone (arithmetic_ceiling.hpp), per trajectory-step: its ceiling on this core.
void BM_KernelArithmetic(benchmark::State& state, KernelArithmetic arithmetic) {
  for (auto _ : state) benchmark::DoNotOptimize(arithmetic(kArithmeticRepeats));
  state.counters["time_per_step"] = benchmark::Counter(arithmetic.trajectory_steps(kArithmeticRepeats),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The clock, calibrated in the same run: a dependent chain of integer additions (runner/clock.hpp), one cycle
// of latency each on every x86-64 core, timed like the kernels. Its time per addition is the cycle time of the core the benchmarks
// ran on (turbo included), which turns their ns per trajectory-step into cycles (run_energy_map_bench.sh).
void BM_ClockCalibration(benchmark::State& state) {
  constexpr std::int64_t kAdds = 1 << 20;  // per iteration
  for (auto _ : state) dependent_additions(kAdds);
  state.counters["time_per_add"] = benchmark::Counter(static_cast<double>(kAdds),
                                                      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void register_benchmarks() {
  benchmark::RegisterBenchmark("BM_ClockCalibration", BM_ClockCalibration)->Unit(benchmark::kMillisecond);
  for (const auto& k : energy_map_kernels()) {
    for (const Coordinates c : {Coordinates::cartesian, Coordinates::polar}) {
      benchmark::RegisterBenchmark(("BM_EnergyMapKernel/" + k.isa + "/" + name(c)).c_str(), BM_EnergyMapKernel, k.run,
                                   c)
          ->Unit(benchmark::kMillisecond);
      if (const KernelArithmetic a = k.arithmetic[static_cast<int>(c)])
        benchmark::RegisterBenchmark(("BM_KernelArithmetic/" + k.isa + "/" + name(c)).c_str(), BM_KernelArithmetic, a)
            ->Unit(benchmark::kMillisecond);
    }
  }
  for (const Coordinates c : {Coordinates::cartesian, Coordinates::polar}) {
    benchmark::RegisterBenchmark((std::string("BM_EnergyMapScalar/") + name(c)).c_str(), BM_EnergyMapScalar, c)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("BM_EnergyMapOdeint/cartesian", BM_EnergyMapOdeint)->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  check_agreement();
  register_benchmarks();
  benchmark::AddCustomContext("workload", std::to_string(kTrajectories) + " trajectories x " +
                                              std::to_string(kSteps) + " steps, l=m=k=1, g=0.02, h=0.2, p0=0, "
                                              "x0 in [-1,1], y0 in [0.3,1.4] (16x16 grid)");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

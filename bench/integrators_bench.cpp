// Throughput of the steps compared in euler_compensation (one trajectory,
// latency-bound): symplectic Euler with and without the compensating
// transformation (82), RK4, and the pieces of the compensated step.
#include <benchmark/benchmark.h>

#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"
#include "geomint/transforms/point_transform.hpp"

using namespace geomint;

namespace {

constexpr double kH = 0.3;

void BM_SymplecticEuler(benchmark::State& state) {
  const HarmonicOscillator osc;
  auto z = make_state(1.0, 0.0);
  for (auto _ : state) {
    z = symplectic_euler_pq(osc, z, kH);
    benchmark::DoNotOptimize(z);
  }
}
BENCHMARK(BM_SymplecticEuler);

void BM_SymplecticEulerCompensated(benchmark::State& state) {
  const PointTransformed sys{HarmonicOscillator{}, OscillatorCompensation{2.0, kH}};
  auto zb = sys.to_transformed(make_state(1.0, 0.0));
  for (auto _ : state) {
    zb = symplectic_euler_pq(sys, zb, kH);
    benchmark::DoNotOptimize(zb);
  }
}
BENCHMARK(BM_SymplecticEulerCompensated);

void BM_RungeKutta4(benchmark::State& state) {
  const HamiltonianField field{HarmonicOscillator{}};
  auto z = make_state(1.0, 0.0);
  for (auto _ : state) {
    z = runge_kutta4(field, z, kH);
    benchmark::DoNotOptimize(z);
  }
}
BENCHMARK(BM_RungeKutta4);

void BM_CompensationInverse(benchmark::State& state) {
  const OscillatorCompensation map{2.0, kH};
  double qb = 0.0, acc = 0.0;
  for (auto _ : state) {
    acc += map.inverse(qb);
    qb = qb > 0.99 ? -0.99 : qb + 0.0137;
    benchmark::DoNotOptimize(acc);
  }
}
BENCHMARK(BM_CompensationInverse);

}  // namespace

BENCHMARK_MAIN();

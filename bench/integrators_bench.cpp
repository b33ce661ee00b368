// Throughput of the steps compared in euler_compensation (one trajectory,
// latency-bound): symplectic Euler with and without the compensating
// transformation (82), RK4, and the pieces of the compensated step. And what a
// term costs that a scene switches off: a Stormer-Verlet step of the elastic
// pendulum (000 eq. (73)) and of Henon-Heiles (004) with the term compiled out
// (g = 0, c = 0 in the scene) against the same step multiplying it by zero.
#include <benchmark/benchmark.h>

#include "geomint/integrators/stormer_verlet.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/henon_heiles.hpp"

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

template <class Sys>
void stormer_verlet_steps(benchmark::State& state, const Sys& sys, const Vec<2>& q0) {
  KickState<2> s{make_state<2>(q0, Vec<2>(0.1, -0.2)), sys.force(q0)};
  for (auto _ : state) {
    s = stormer_verlet(sys, s, 0.01);
    benchmark::DoNotOptimize(s);
  }
}

void BM_PendulumWithoutGravityTerm(benchmark::State& state) {
  stormer_verlet_steps(state, ElasticPendulumWithoutGravity{1.0, {SpringTerm{1.0, 1.0}}}, Vec<2>(0.5, 1.0));
}
BENCHMARK(BM_PendulumWithoutGravityTerm);

void BM_PendulumGravityTimesZero(benchmark::State& state) {
  stormer_verlet_steps(state, ElasticPendulumWithGravity{1.0, {SpringTerm{1.0, 1.0}, GravityTerm{1.0, 0.0}}},
                       Vec<2>(0.5, 1.0));
}
BENCHMARK(BM_PendulumGravityTimesZero);

void BM_HenonHeilesWithoutCoupling(benchmark::State& state) {
  stormer_verlet_steps(state, HenonHeilesT<false>{{}, 5, 0.0}, Vec<2>(0.1, 0.2));
}
BENCHMARK(BM_HenonHeilesWithoutCoupling);

void BM_HenonHeilesCouplingTimesZero(benchmark::State& state) {
  stormer_verlet_steps(state, HenonHeilesT<true>{{}, 5, 0.0}, Vec<2>(0.1, 0.2));
}
BENCHMARK(BM_HenonHeilesCouplingTimesZero);

}  // namespace

BENCHMARK_MAIN();

// The oscillators' runs by the registered methods (systems/harmonic_oscillator.hpp), compiled once: the
// one-step matrices of 001's methods, and 000's oscillator (74) with and without the compensating
// transformation (82).
#include "geomint/analysis/linear_stability.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {

Mat<2> one_step_pq_matrix(std::string_view method, const HarmonicOscillator& osc, double h) {
  return in_pq_order(one_step_matrix(one_step_by_name(method, osc, Bind::kernel), h));
}

namespace {

// Symplectic Euler in the coordinates of (82) is outside the registry's dispatch by name: it needs the k of (82).
bool compensated(std::string_view method) { return method_info(method).name == CompensatedSymplecticEuler::info.name; }

// One run of a method to t = n h, counting force evaluations.
OscillatorEnergyErrors energy_run(const std::string& method, double k, const PhaseState<1>& z0, double h, std::int64_t n) {
  OscillatorEnergyErrors r;
  const HarmonicOscillator osc;
  const double H0 = osc.H(z0);
  ErrorSeries e;
  const Counting<HarmonicOscillator> counted{osc, &r.force_evals};
  const auto observe = [&](std::int64_t j, const PhaseState<1>& z) {
    check_compensated_state(z, method, j, h);
    e.add(osc.H(z) - H0);
  };
  if (compensated(method)) integrate(CompensatedSymplecticEuler::bind(counted, k), z0, h, n, observe);
  else MethodsOn<Counting<HarmonicOscillator>>::integrate(method, counted, z0, h, n, observe);
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

}  // namespace

std::vector<OscillatorEnergyErrors> oscillator_energy_errors(const std::vector<std::string>& methods, double k,
                                                             const PhaseState<1>& z0, double h, std::int64_t n) {
  std::vector<OscillatorEnergyErrors> runs;
  for (const auto& m : methods) runs.push_back(energy_run(m, k, z0, h, n));
  return runs;
}

std::function<void()> oscillator_timed(std::string_view method, double k, const PhaseState<1>& z0, double h,
                                       std::int64_t n) {
  static const HarmonicOscillator osc;  // (outlives the call it returns)
  if (!compensated(method)) return MethodsOn<HarmonicOscillator>::timed(method, osc, {z0}, h, n);
  return [m = CompensatedSymplecticEuler::bind(osc, k), z0, h, n] { do_not_optimize(integrate_inlined(m, z0, h, n)); };
}

std::vector<std::string> compensated_oscillator_choices() {
  auto names = MethodsOn<Counting<HarmonicOscillator>>::names();
  names.emplace_back(CompensatedSymplecticEuler::info.name);
  return method_choices<Counting<HarmonicOscillator>>(names);
}

}  // namespace geomint

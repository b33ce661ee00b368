// euler_compensation: what its studies share (euler_compensation.hpp).
#include "euler_compensation.hpp"

#include <cmath>

#include "geomint/core/integrate.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/systems/counting.hpp"

namespace geomint::euler_compensation {

State initial_state(const Scene& s) { return make_state(s.real("oscillator.q0"), s.real("oscillator.p0")); }

void check_finite(const State& z, const std::string& method, std::int64_t j, double h) {
  if (!std::isfinite(z.q[0]) || !std::isfinite(z.p[0]))
    throw IntegrationError(method + ": non-finite state at step " + std::to_string(j) + ", t = " +
                           format_double(static_cast<double>(j) * h) +
                           " (for the compensating transformation (82): |qhat| >= 1; increase oscillator.k or decrease h)");
}

namespace {

// Symplectic Euler in the coordinates of (82) is outside the registry's dispatch by name: it needs the k of (82).
bool compensated(const std::string& method) {
  return method_info(method).name == CompensatedSymplecticEuler::info.name;
}

// One convergence run of a method to t = N h, counting force evaluations.
EnergyRun energy_run(const std::string& method, const State& z0, double h, double k, std::int64_t n) {
  EnergyRun r;
  const Oscillator osc;
  const double H0 = osc.H(z0);
  ErrorSeries e;
  const Counting<Oscillator> counted{osc, &r.force_evals};
  const auto observe = [&](std::int64_t j, const State& z) {
    check_finite(z, method, j, h);
    e.add(osc.H(z) - H0);
  };
  if (compensated(method)) integrate(CompensatedSymplecticEuler::bind(counted, k), z0, h, n, observe);
  else MethodsOn<Counting<Oscillator>>::integrate(method, counted, z0, h, n, observe);
  r.max_err = e.max_abs(), r.rms_err = e.rms50();
  return r;
}

}  // namespace

std::vector<EnergyRun> oscillator_runs(const std::vector<std::string>& methods, const State& z0, double h, double k,
                                       std::int64_t n) {
  std::vector<EnergyRun> runs;
  for (const auto& m : methods) runs.push_back(energy_run(m, z0, h, k, n));
  return runs;
}

std::function<void()> oscillator_method_timed(const std::string& method, double k, const State& z0, double h,
                                              std::int64_t n) {
  static const Oscillator osc;  // (outlives the call it returns)
  if (!compensated(method)) return MethodsOn<Oscillator>::timed(method, osc, {z0}, h, n);
  return [m = CompensatedSymplecticEuler::bind(osc, k), z0, h, n] { do_not_optimize(integrate_inlined(m, z0, h, n)); };
}

std::vector<std::string> oscillator_method_choices() {
  auto names = MethodsOn<Counting<Oscillator>>::names();
  names.emplace_back(CompensatedSymplecticEuler::info.name);
  return method_choices<Counting<Oscillator>>(names);
}

void check_oscillator_step(const Scene& s, const char* key, double h) {
  check_oscillatory_bound(s, key, key, "symplectic_euler_pq", h, "omega = 1");
  if (!OscillatorCompensation{s.real("oscillator.k"), h}.defined(s.real("oscillator.q0")))
    s.reject(key, "the transformation (82) needs |q0| < 1 + k h^2 = " +
                      format_double(1 + s.real("oscillator.k") * h * h));
}

void check_steps(const Scene& s, const char* key, const char* methods_key) {
  check_distinct_methods(s, methods_key);
  const double t_end = s.real("convergence.t_end");
  for (double h : s.reals(key)) {
    if (!(t_end / h <= max_exact_count))
      s.reject(key, "at most 2^53 steps to convergence.t_end = " + format_double(t_end) + ", here h = " + format_double(h));
    for (const auto& m : s.texts(methods_key)) {
      if (method_info(m).name == CompensatedSymplecticEuler::info.name) check_oscillator_step(s, key, h);
      else check_oscillatory_bound(s, key, methods_key, m, h, "omega = 1");
    }
    const double n = static_cast<double>(steps_to(t_end, h));
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end)
      s.reject(key, "each h must divide convergence.t_end = " + format_double(t_end));
  }
}


}  // namespace geomint::euler_compensation

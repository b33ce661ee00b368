// The oscillators of a scene (systems/harmonic_oscillator.hpp): 001's released from rest, and 000's (74) with
// the checks of its compensating transformation (82).
#include "geomint/systems/harmonic_oscillator.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include "geomint/integrators/newton.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/transforms/point_transform.hpp"

namespace geomint {

template PhaseState<1> reference_solution<NonlinearPendulum>(const NonlinearPendulum&, const PhaseState<1>&, double, double,
                                                             double);

OscillatorFromRest oscillator_from_rest(const Scene& s) {
  const HarmonicOscillator osc{s.real("oscillator.m"), s.real("oscillator.omega")};
  const double A = s.real("oscillator.amplitude");
  return {osc, A, 2 * std::numbers::pi / osc.w, make_state(A, 0.0)};
}

PhaseErrors max_errors(const HarmonicOscillator& osc, const PhaseState<1>& z0, const std::vector<PhaseState<1>>& zs,
                       double h) {
  PhaseErrors e{0, 0};
  for (std::size_t j = 0; j < zs.size(); ++j) {
    const PhaseState<1> exact = osc.exact(z0, static_cast<double>(j) * h);
    e.q = std::max(e.q, std::abs(zs[j].q[0] - exact.q[0])), e.p = std::max(e.p, std::abs(zs[j].p[0] - exact.p[0]));
  }
  return e;
}

void check_lobatto_bound(const Scene& s, const OscillatorSteps& steps) {
  OscillatorSteps lobatto = steps;
  lobatto.at += "; 001 eq. (10)";
  check_oscillatory_bound(s, lobatto, steps.key, "lobatto", "sqrt(42 - 6 sqrt(29))");
}

PhaseState<1> oscillator_start(const Scene& s) { return make_state(s.real("oscillator.q0"), s.real("oscillator.p0")); }

void check_compensated_state(const PhaseState<1>& z, const std::string& method, std::int64_t j, double h) {
  if (!std::isfinite(z.q[0]) || !std::isfinite(z.p[0]))
    throw IntegrationError(method + ": non-finite state at step " + std::to_string(j) + ", t = " +
                           format_double(static_cast<double>(j) * h) +
                           " (for the compensating transformation (82): |qhat| >= 1; increase oscillator.k or decrease h)");
}

void check_compensated_step(const Scene& s, const char* key, double h) {
  check_oscillatory_bound(s, key, key, "symplectic_euler_pq", h, "omega = 1");
  if (!OscillatorCompensation{s.real("oscillator.k"), h}.defined(s.real("oscillator.q0")))
    s.reject(key, "the transformation (82) needs |q0| < 1 + k h^2 = " +
                      format_double(1 + s.real("oscillator.k") * h * h));
}

void check_compensated_methods(const Scene& s, const char* step_key, const char* methods_key, const char* end_key) {
  check_distinct_methods(s, methods_key);
  check_whole_steps(s, step_key, end_key);
  check_oscillatory_bounds(s, {step_key, 1.0, false, ", omega = 1"}, methods_key);
  for (const auto& m : s.texts(methods_key))
    if (method_info(m).name == CompensatedSymplecticEuler::info.name)
      for (double h : s.reals(step_key)) check_compensated_step(s, step_key, h);
}

}  // namespace geomint

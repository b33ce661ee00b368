// lobatto_table: what its studies share (lobatto_table.hpp).
#include "lobatto_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geomint/analysis/linear_stability.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/timing_report.hpp"

namespace geomint::lobatto_table {

double discrete_energy(const Mat<2>& Phi, const Z1& z) {
  return 0.5 * (Phi(1, 0) * z.p[0] * z.p[0] - Phi(0, 1) * z.q[0] * z.q[0]);
}

Mat<2> pq_matrix(const std::string& method, const HarmonicOscillator& osc, double h) {
  return in_pq_order(one_step_matrix(one_step_by_name(method, osc, Bind::kernel), h));
}

Mat<2> lobatto_matrix(const HarmonicOscillator& osc, double h) { return pq_matrix(kScheme, osc, h); }

void check_lobatto(const Scene& s, const char* key, double hw, const std::string& what) {
  check_oscillatory_bound(s, key, key, kScheme, hw, what + "; 001 eq. (10)", "sqrt(42 - 6 sqrt(29))");
}

void check_lobatto_steps(const Scene& s, const char* key, double omega, const std::string& at) {
  for (double h : s.reals(key)) check_lobatto(s, key, h * omega, "h = " + format_double(h) + at);
}

void check_meshes(const Scene& s, const char* key, const char* methods_key, bool lobatto) {
  for (double n : s.reals(key)) {
    if (n != std::floor(n)) s.reject(key, "every entry must be a whole number of steps per period");
    const double hw = 2 * std::numbers::pi / n;
    const std::string what = "h omega = 2 pi / N at N = " + format_double(n);
    if (lobatto) check_lobatto(s, key, hw, what);
    for (const auto& m : s.texts(methods_key)) check_oscillatory_bound(s, key, methods_key, m, hw, what);
  }
}

void check_pendulum_steps(const Scene& s, const char* methods_key, const std::string& method) {
  for (double h : s.reals("nonlinear.h"))
    check_oscillatory_bound(s, "nonlinear.h", methods_key, method, h * kNonlinearOmega, "h = " + format_double(h) + ", frequency 1");
}

void check_nonlinear_steps(const Scene& s) {
  const double t_end = s.real("nonlinear.t_end");
  for (double h : s.reals("nonlinear.h")) {
    const double n = t_end / h;
    if (!(n <= max_exact_count)) s.reject("nonlinear.h", "at most 2^53 steps to nonlinear.t_end, here h = " + format_double(h));
    if (std::round(n) < 1 || std::abs(std::round(n) * h - t_end) > 1e-9 * t_end)
      s.reject("nonlinear.h", "each h must divide nonlinear.t_end = " + format_double(t_end) + ", here h = " + format_double(h));
  }
}

Oscillator oscillator(const Scene& s) {
  const HarmonicOscillator osc{s.real("oscillator.m"), s.real("oscillator.omega")};
  const double A = s.real("oscillator.amplitude");
  return {osc, A, 2 * std::numbers::pi / osc.w, make_state(A, 0.0)};
}

Pendulum pendulum(const Scene& s) { return {NonlinearPendulum{}, make_state(s.real("nonlinear.pendulum_q0"), 0.0)}; }

double period_of(const Scene& s) { return 2 * std::numbers::pi / s.real("oscillator.omega"); }

std::string cost_method_text(int repeats) {
  return timing_method_text(repeats) + "; ns_per_step at the smallest h of a set; force evaluations count U_q and U_qq "
         "calls; long_run_*: a run's wall time is its steps times the time per step measured on a segment of "
         "long_run_cost.timing_steps steps (at most the run), every call of a step through integrate";
}

}  // namespace geomint::lobatto_table

// ti_drift: what its studies share (ti_drift.hpp, henon_heiles_starts.hpp).
#include "ti_drift.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/systems/counting.hpp"
#include "henon_heiles_starts.hpp"

namespace geomint::ti_drift {

double slope(const std::vector<double>& x, const std::vector<double>& y) { return linear_fit(x, y).slope; }

void put_differences(Context& ctx, const std::string& study) {
  for (const Published& e : ctx.published_entries) {
    const json* r = json_at(ctx.summary, e.summary);
    if (e.study == study && e.value.is_number() && r && r->is_number())
      ctx.summary["difference_from_published"][e.key] = r->get<double>() - e.value.get<double>();
  }
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::int64_t evals_per_step(const std::string& method) {
  std::int64_t n = 0;  // counted from z_0 on: one kernel step (the kernel's processors evaluate no force)
  MethodsOn<Counting<HarmonicOscillator>>::integrate(
      method, {kOscillator, &n}, make_state(1.0, 0.0), 0.1, 1, [&](std::int64_t j, const Z1&) { if (j == 0) n = 0; },
      Bind::kernel);
  if (n < 1) throw std::logic_error(method + " evaluates no force in a step");
  return n;
}

double fit_t_min(const Scene& s, const std::string& section, double t_end) {
  return s.real(section + ".fit_from") * t_end;
}

Vec<2> lj_grid(int k) { return Vec<2>(1 + k % 3, 1 + k / 3); }  // (i, j), i, j in {1, 2, 3}

Z18 lj_start_of(const Scene& s, std::size_t i) {
  std::seed_seq seq{static_cast<std::uint64_t>(s.integer("lj.seed")), static_cast<std::uint64_t>(i)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> u(-s.real("lj.perturbation"), s.real("lj.perturbation"));
  Z18 z;
  for (int k = 0; k < 9; ++k) z.q[2 * k] = lj_grid(k)[0] + u(rng), z.q[2 * k + 1] = lj_grid(k)[1] + u(rng);
  return z;
}

void check_step_bound(const Scene& s, const char* step_key, double h, double omega, const std::string& where) {
  check_oscillatory_bound(s, step_key, step_key, "simplified_takahashi_imada", h * omega, where, "2 sqrt(3)");
}

double kept_samples(double n, double samples) { return std::floor(n / std::max(1.0, std::floor(n / samples))) + 1; }

}  // namespace geomint::ti_drift

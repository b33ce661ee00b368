// ti_drift: what its studies share (ti_drift.hpp).
#include "ti_drift.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "geomint/analysis/episode_cuts.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/systems/counting.hpp"

namespace geomint::ti_drift {

void put_trajectory_method(Context& ctx, const std::string& study) {
  ctx.summary["methods"][study] = labels_of({"simplified_takahashi_imada"});
  ctx.summary["ti_alpha"] = takahashi_imada_alpha;
}

double slope(const std::vector<double>& x, const std::vector<double>& y) { return linear_fit(x, y).slope; }

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

double lj_grid_stiffness() {
  Vec<18> grid_q;
  for (int k = 0; k < 9; ++k) grid_q.segment<2>(2 * k) = lj_grid(k);
  return max_hessian_eigenvalue(LJ{}, grid_q);
}

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

void check_episode_rule(const Scene& s) {
  const double t_end = s.real("t_end");
  for (const char* key : {"ensemble.episode_half_width", "ensemble.episode_min_length"})
    if (s.real(key) > t_end) s.reject(key, "must not exceed t_end = " + format_double(t_end));
}

EpisodeRule episode_rule(const Scene& s, double sample_dt) {
  const auto samples = [&](const char* key) {
    return static_cast<std::size_t>(std::max(1.0, std::round(s.real(key) / sample_dt)));
  };
  return {samples("ensemble.episode_half_width"), s.real("ensemble.episode_threshold"), samples("ensemble.episode_min_length")};
}

double kept_samples(double n, double samples) { return std::floor(n / std::max(1.0, std::floor(n / samples))) + 1; }

namespace {

// %g of v (the numbers of the messages of check_hh_starts).
std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

template <class HH>
void check_hh_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h) {
  const double H0 = s.real("hh.H0"), q2 = s.real(section + ".q2"), p2 = s.real(section + ".p2");
  const double escape = hh.escape_energy();
  if (!(H0 < escape))
    s.reject("hh.H0", "must be below the escape energy " + format_double(escape) + " of U (k = " + std::to_string(hh.k) +
                          ", c = " + format_double(hh.c) + ": its lowest saddle); here " + format_double(H0));
  // the unperturbed start is blamed on its keys, a perturbed one on ensemble.perturbation
  const auto inside = [&](double a) { return a < 1 && (hh.k % 2 == 1 || a > -1); };
  const auto exists = [&](double a, double b) { return 2 * (H0 - hh.U(Vec<2>(0.0, a))) - b * b > 0; };
  if (!inside(q2))
    s.reject(section + ".q2", "the start must lie between the saddles of U on q1 = 0 (q2 < 1" +
                                  std::string(hh.k % 2 ? "" : ", q2 > -1") + "); here q2 = " + format_double(q2));
  if (!exists(q2, p2))
    s.reject(section + ".p2", "the start q1 = 0, q2 = " + short_num(q2) + ", p2 = " + short_num(p2) + " (k = " +
                                  std::to_string(hh.k) + ") needs U(0, q2) + p2^2/2 < hh.H0 = " + short_num(H0));
  for (const double a : {q2 - d, q2 + d})
    for (const double b : {p2 - d, p2 + d})
      if (!inside(a) || !exists(a, b))
        s.reject("ensemble.perturbation", "the perturbed start q1 = 0, q2 = " + short_num(a) + ", p2 = " + short_num(b) +
                                              " must lie between the saddles of U on q1 = 0 with U(0, q2) + p2^2/2 < "
                                              "hh.H0 = " + short_num(H0) + "; here " + format_double(d));
  if (check_h)
    check_step_bound(s, "h", s.real("h"), std::sqrt(max_hessian_eigenvalue(hh, Vec<2>(0.0, q2))),
                     "omega^2 = max eig U''(0, " + section + ".q2), Henon-Heiles k = " + std::to_string(hh.k));
}

template void check_hh_starts(const Scene&, const std::string&, const HenonHeilesT<true>&, double, bool);
template void check_hh_starts(const Scene&, const std::string&, const HenonHeilesT<false>&, double, bool);

}  // namespace geomint::ti_drift

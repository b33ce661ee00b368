#pragma once
// 000 Appendix A: the planar elastic pendulum (mass m, spring stiffness k,
// relaxed length l, gravity g). The y axis points down, as the signs of (72)
// (U = -m g r cos(theta)) and (73) (U = -m g y) imply: the pendulum hangs at
// x = 0, y = l + m g / k.
//
// The Cartesian form (73) is separable, H = |p|^2/(2m) + U(q), and is
// assembled from potential terms, so a scene without gravity compiles a step
// without a gravity term (not one multiplied by zero). Below the systems, what the
// studies of 000 and 001 take of them: the pendulum of a scene, its energies at rest,
// and its runs with or without gravity (ElasticPendulumRuns).
//
// The registered methods run by name on (compiled once each: cmake/geomint_experiment.cmake geomint_methods_on):
// geomint: MethodsOn<ElasticPendulumWithGravity>
// geomint: MethodsOn<ElasticPendulumWithoutGravity>
// geomint: MethodsOn<Counting<ElasticPendulumWithGravity>>
// geomint: MethodsOn<Counting<ElasticPendulumWithoutGravity>>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "geomint/core/state.hpp"
#include "geomint/reference/odeint_reference.hpp"

namespace geomint {

class Scene;

// U = (k/2)(|q| - l)^2: the spring of 000 eq. (73).
struct SpringTerm {
  double k, l;
  double U(const Vec<2>& q) const {
    const double s = q.norm() - l;
    return 0.5 * k * s * s;
  }
  Vec<2> U_q(const Vec<2>& q) const { return k * (1.0 - l / q.norm()) * q; }
  // U_qq v = k [(1 - l/r) v + (l/r^3) q (q.v)]
  Vec<2> U_qq_times(const Vec<2>& q, const Vec<2>& v) const {
    const double r = q.norm();
    return k * ((1.0 - l / r) * v + (l / (r * r * r)) * q.dot(v) * q);
  }
  Mat<2> U_qq(const Vec<2>& q) const {  // k [(1 - l/r) I + (l/r^3) q q^T]
    const double r = q.norm();
    return k * ((1.0 - l / r) * Mat<2>::Identity() + (l / (r * r * r)) * q * q.transpose());
  }
};

// U = -m g y: gravity along +y (downwards), 000 eq. (73).
struct GravityTerm {
  double m, g;
  double U(const Vec<2>& q) const { return -m * g * q[1]; }
  Vec<2> U_q(const Vec<2>&) const { return Vec<2>(0.0, -m * g); }
  Vec<2> U_qq_times(const Vec<2>&, const Vec<2>&) const { return Vec<2>::Zero(); }
  Mat<2> U_qq(const Vec<2>&) const { return Mat<2>::Zero(); }
};

// H = |p|^2/(2m) + sum of the potential terms: 000 eq. (73) with SpringTerm and GravityTerm.
template <class... Terms>
struct ElasticPendulumCartesian {
  using State = PhaseState<2>;
  static constexpr bool separable = true;

  double m;
  std::tuple<Terms...> terms;

  Vec<2> inv_mass(const Vec<2>& p) const { return p / m; }  // M^{-1} p, M = m I
  Vec<2> mass_times(const Vec<2>& v) const { return m * v; }  // M v
  double T(const Vec<2>& p) const { return 0.5 * p.squaredNorm() / m; }
  double U(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (0.0 + ... + t.U(q)); }, terms);
  }
  Vec<2> U_q(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_q(q)).eval(); }, terms);
  }
  Vec<2> U_qq_times(const Vec<2>& q, const Vec<2>& v) const {  // Hessian-vector product
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_qq_times(q, v)).eval(); }, terms);
  }
  Vec<2> force(const Vec<2>& q) const { return -U_q(q); }
  Mat<2> U_qq(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Mat<2>::Zero() + ... + t.U_qq(q)).eval(); }, terms);
  }
  double mass() const { return m; }

  double H(const State& z) const { return T(z.p) + U(z.q); }  // (73)
  Vec<2> H_q(const Vec<2>& q, const Vec<2>&) const { return U_q(q); }
  Vec<2> H_p(const Vec<2>&, const Vec<2>& p) const { return inv_mass(p); }
  Mat<2> H_qp(const Vec<2>&, const Vec<2>&) const { return Mat<2>::Zero(); }
  Mat<2> H_pp(const Vec<2>&, const Vec<2>&) const { return Mat<2>::Identity() / m; }
};

// ---- polar coordinates q = (r, theta), theta measured from +y: x = r sin(theta), y = r cos(theta) ----

// U = (k/2)(r - l)^2: the spring of 000 eq. (72).
struct SpringPolarTerm {
  double k, l;
  double U(const Vec<2>& q) const { return 0.5 * k * (q[0] - l) * (q[0] - l); }
  Vec<2> U_q(const Vec<2>& q) const { return Vec<2>(k * (q[0] - l), 0.0); }
};

// U = -m g r cos(theta): gravity of 000 eq. (72).
struct GravityPolarTerm {
  double m, g;
  double U(const Vec<2>& q) const { return -m * g * q[0] * std::cos(q[1]); }
  Vec<2> U_q(const Vec<2>& q) const { return Vec<2>(-m * g * std::cos(q[1]), m * g * q[0] * std::sin(q[1])); }
};

// 000 eq. (72): H = (p_r^2 + p_theta^2 / r^2)/(2m) + sum of the potential terms. Not
// separable; theta is cyclic without gravity (p_theta is then a first integral).
template <class... Terms>
struct ElasticPendulumPolar {
  using State = PhaseState<2>;
  static constexpr bool separable = false;

  double m;
  std::tuple<Terms...> terms;

  double U(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (0.0 + ... + t.U(q)); }, terms);
  }
  Vec<2> U_q(const Vec<2>& q) const {
    return std::apply([&](const auto&... t) { return (Vec<2>::Zero() + ... + t.U_q(q)).eval(); }, terms);
  }
  double H(const State& z) const {  // (72)
    const double r = z.q[0];
    return (z.p[0] * z.p[0] + z.p[1] * z.p[1] / (r * r)) / (2 * m) + U(z.q);
  }
  Vec<2> H_q(const Vec<2>& q, const Vec<2>& p) const {  // (dH/dr, dH/dtheta)
    const double r = q[0];
    return Vec<2>(-p[1] * p[1] / (m * r * r * r), 0.0) + U_q(q);
  }
  Vec<2> H_p(const Vec<2>& q, const Vec<2>& p) const { return Vec<2>(p[0] / m, p[1] / (m * q[0] * q[0])); }
  Mat<2> H_qp(const Vec<2>& q, const Vec<2>& p) const {
    Mat<2> J = Mat<2>::Zero();
    J(0, 1) = -2 * p[1] / (m * q[0] * q[0] * q[0]);  // d(dH/dr)/dp_theta
    return J;
  }
  Mat<2> H_pp(const Vec<2>& q, const Vec<2>&) const {
    Mat<2> J = Mat<2>::Zero();
    J(0, 0) = 1 / m, J(1, 1) = 1 / (m * q[0] * q[0]);
    return J;
  }
};

struct ElasticPendulumParams {
  double l, m, k, g;
};

// The angular frequency of the spring mode, omega = sqrt(k/m) (000 Appendix A).
inline double spring_frequency(const ElasticPendulumParams& p) { return std::sqrt(p.k / p.m); }

// 000 Sec. 4.1: released from rest at r(0), phi(0) (phi from the downward vertical), with the
// angular motion ignored, m r'' = -k (r - l) + m g cos(phi(0)): a radial oscillation about
// r* = l + (m g / k) cos(phi(0)), between r(0) and 2 r* - r(0).
inline double radial_rest_radius(const ElasticPendulumParams& p, double cos_phi) {
  return p.l + p.m * p.g / p.k * cos_phi;
}

// 000 Sec. 4.1: the boundary of the polar runs, r(0) = 2l + (2mg/k) cos(phi(0)); on and beyond it
// the radial oscillation reaches r = 0.
inline double polar_boundary_radius(const ElasticPendulumParams& p, double cos_phi) {
  return 2 * p.l + 2 * p.m * p.g / p.k * cos_phi;
}

// The energy at the pivot, U(r = 0) = k l^2 / 2 of (72)-(73): for a release from rest the boundary
// above is the isoline H_0 = k l^2 / 2.
inline double pivot_energy(const ElasticPendulumParams& p) { return 0.5 * p.k * (p.l * p.l); }

// The hanging equilibrium x = 0, y = l + m g / k (y pointing down, 000 eq. (73)).
inline double hanging_equilibrium_y(const ElasticPendulumParams& p) { return radial_rest_radius(p, 1.0); }

using ElasticPendulumWithGravity = ElasticPendulumCartesian<SpringTerm, GravityTerm>;
using ElasticPendulumWithoutGravity = ElasticPendulumCartesian<SpringTerm>;
using ElasticPendulumPolarWithGravity = ElasticPendulumPolar<SpringPolarTerm, GravityPolarTerm>;
using FreeParticleCartesian = ElasticPendulumCartesian<>;  // 000 eq. (61)
using FreeParticlePolar = ElasticPendulumPolar<>;          // 000 eq. (62)

// The odeint reference (reference/odeint_reference.hpp) on the pendulum with and without gravity, compiled once
// (elastic_pendulum.cpp).
extern template PhaseState<2> reference_solution<ElasticPendulumWithGravity>(const ElasticPendulumWithGravity&,
                                                                             const PhaseState<2>&, double, double, double);
extern template PhaseState<2> reference_solution<ElasticPendulumWithoutGravity>(const ElasticPendulumWithoutGravity&,
                                                                                const PhaseState<2>&, double, double, double);

// ---- the pendulum of a scene (elastic_pendulum.cpp) ----

// The scene's <section>.l, .m, .k, .g.
ElasticPendulumParams elastic_pendulum_params(const Scene& s, const std::string& section = "pendulum");

// sqrt(<section>.k / <section>.m) of the scene; refuses (<section>.k) one that is not finite and positive.
double spring_frequency(const Scene& s, const std::string& section = "pendulum");

// A state [x, y, px, py], as a scene's rows give it.
inline PhaseState<2> elastic_pendulum_state(const std::vector<double>& row) {
  return make_state<2>(Vec<2>(row[0], row[1]), Vec<2>(row[2], row[3]));
}

// The energies at rest at the Cartesian position (x, y): of (73), and of (72) with (r, theta) from (x, y) by
// 000 eq. (63), or by (63) as printed (`as_printed_63`, transforms/polar.hpp); each with its gravity term.
double cartesian_energy_at_rest(const ElasticPendulumParams& p, double x, double y);
double polar_energy_at_rest(const ElasticPendulumParams& p, double x, double y, bool as_printed_63 = false);

// Rejects a state [x, y, px, py] of the rows `key` at the pivot x = y = 0, where the spring force (73) is singular.
void check_elastic_pendulum_states(const Scene& s, const char* key);

// Calls f with the Cartesian pendulum made of the terms the parameters call for.
template <class F>
decltype(auto) with_elastic_pendulum(const ElasticPendulumParams& p, F&& f) {
  if (p.g == 0.0) return f(ElasticPendulumWithoutGravity{p.m, {SpringTerm{p.k, p.l}}});
  return f(ElasticPendulumWithGravity{p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}});
}

// The Cartesian pendulum (73) of the parameters, with or without its gravity term (with_elastic_pendulum), as a study
// runs it: by the registered methods by name and by the odeint reference, compiled once in the library
// (elastic_pendulum_runs.cpp), so that a study that takes the pendulum from its scene is compiled once, not per system.
class ElasticPendulumRuns {
 public:
  using State = PhaseState<2>;
  using Observer = std::function<void(std::int64_t, const State&)>;
  explicit ElasticPendulumRuns(const ElasticPendulumParams& p);

  double H(const State& z) const;  // (73)
  // z_n after n steps of `method` from z0 (MethodsOn::integrate: pre once, post once), the force evaluations added to
  // *evals; with `observe`, observe(j, z_j) for j = 0..n (each z_j postprocessed).
  State integrate(std::string_view method, const State& z0, double h, std::int64_t n, std::int64_t* evals,
                  const Observer& observe = {}) const;
  // n steps of `method` from z0, every call inlined: a configuration to time (MethodsOn::timed); *this must outlive it.
  std::function<void()> timed(std::string_view method, const State& z0, double h, std::int64_t n) const;
  // The solution at t_end to the tolerances (rtol, atol): odeint's Bulirsch-Stoer (reference_solution).
  State reference(const State& z0, double t_end, double rtol, double atol) const;
  // The solutions at t_end from each state [x, y, px, py] of `starts` (split across threads and ranks:
  // distributed_map), each with its self-check: |z - z'|_2 against z' at 100x tighter tolerances.
  struct Reference {
    State z;
    double self_check;
  };
  std::vector<Reference> references(const std::vector<std::vector<double>>& starts, double t_end, double rtol,
                                    double atol) const;
  // Rejects `key` unless it names each method once, each can step the pendulum (MethodsOn::check) and each is below
  // its oscillatory bound at every step of `step_key` (check_oscillatory_bounds, omega = sqrt(k/m)).
  void check(const Scene& s, const char* key, const char* step_key) const;
  // What a scene may name: the methods that step the pendulum, and their labels (MethodsOn::choices).
  static std::vector<std::string> choices();

 private:
  bool gravity_;
  double omega_;  // sqrt(k/m)
  ElasticPendulumWithGravity with_gravity_;
  ElasticPendulumWithoutGravity without_gravity_;
};

}  // namespace geomint

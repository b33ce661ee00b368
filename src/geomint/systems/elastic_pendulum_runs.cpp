// The elastic pendulum's runs by the registered methods and by odeint (ElasticPendulumRuns,
// systems/elastic_pendulum.hpp), with or without gravity, compiled once.
#include <tuple>

#include "geomint/methods/by_name.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/systems/counting.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint {

ElasticPendulumRuns::ElasticPendulumRuns(const ElasticPendulumParams& p)
    : gravity_(p.g != 0.0),
      omega_(spring_frequency(p)),
      with_gravity_{p.m, {SpringTerm{p.k, p.l}, GravityTerm{p.m, p.g}}},
      without_gravity_{p.m, {SpringTerm{p.k, p.l}}} {}

double ElasticPendulumRuns::H(const State& z) const { return gravity_ ? with_gravity_.H(z) : without_gravity_.H(z); }

namespace {

template <class Sys>
PhaseState<2> counted_run(std::string_view method, const Sys& sys, const PhaseState<2>& z0, double h, std::int64_t n,
                          std::int64_t* evals, const ElasticPendulumRuns::Observer& observe) {
  const Counting<Sys> counted{sys, evals};
  return observe ? MethodsOn<Counting<Sys>>::integrate(method, counted, z0, h, n, observe)
                 : MethodsOn<Counting<Sys>>::integrate(method, counted, z0, h, n);
}

}  // namespace

PhaseState<2> ElasticPendulumRuns::integrate(std::string_view method, const State& z0, double h, std::int64_t n,
                                             std::int64_t* evals, const Observer& observe) const {
  return gravity_ ? counted_run(method, with_gravity_, z0, h, n, evals, observe)
                  : counted_run(method, without_gravity_, z0, h, n, evals, observe);
}

std::function<void()> ElasticPendulumRuns::timed(std::string_view method, const State& z0, double h,
                                                 std::int64_t n) const {
  return gravity_ ? MethodsOn<ElasticPendulumWithGravity>::timed(method, with_gravity_, {z0}, h, n)
                  : MethodsOn<ElasticPendulumWithoutGravity>::timed(method, without_gravity_, {z0}, h, n);
}

PhaseState<2> ElasticPendulumRuns::reference(const State& z0, double t_end, double rtol, double atol) const {
  return gravity_ ? reference_solution(with_gravity_, z0, t_end, rtol, atol)
                  : reference_solution(without_gravity_, z0, t_end, rtol, atol);
}

std::vector<ElasticPendulumRuns::Reference> ElasticPendulumRuns::references(const std::vector<std::vector<double>>& starts,
                                                                          double t_end, double rtol, double atol) const {
  struct Record {  // (a record of runner/distributed_map.hpp)
    State z;
    double self_check;
    auto fields() { return std::tie(z.q[0], z.q[1], z.p[0], z.p[1], self_check); }
  };
  const auto records = distributed_map(starts.size(), [&](std::size_t i) {
    const State z0 = elastic_pendulum_state(starts[i]);
    const State a = reference(z0, t_end, rtol, atol), b = reference(z0, t_end, rtol / 100, atol / 100);
    return Record{a, phase_distance(a, b)};
  });
  std::vector<Reference> refs;
  for (const Record& r : records) refs.push_back({r.z, r.self_check});
  return refs;
}

void ElasticPendulumRuns::check(const Scene& s, const char* key, const char* step_key) const {
  if (gravity_) MethodsOn<ElasticPendulumWithGravity>::check(s, key, with_gravity_);
  else MethodsOn<ElasticPendulumWithoutGravity>::check(s, key, without_gravity_);
  check_oscillatory_bounds(s, {step_key, omega_, false, ", omega = sqrt(k/m)"}, key);
}

std::vector<std::string> ElasticPendulumRuns::choices() { return MethodsOn<Counting<ElasticPendulumWithGravity>>::choices(); }

}  // namespace geomint

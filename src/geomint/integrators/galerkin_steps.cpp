#include "geomint/integrators/galerkin_steps.hpp"

#include "geomint/integrators/galerkin_variational.hpp"

namespace geomint {

namespace {

template <class Sys>
LobattoRun<typename Sys::State> run(const Sys& sys, const typename Sys::State& z0, double h, std::int64_t n) {
  const GalerkinRule<3> lob = lobatto_rule();
  int it = 0;
  double iterations = 0;
  typename Sys::State z = z0;
  for (std::int64_t j = 0; j < n; ++j) z = galerkin_step(lob, sys, z, h, &it), iterations += it;
  return {z, iterations / static_cast<double>(n)};
}

}  // namespace

LobattoRun<PhaseState<1>> lobatto_run(const NonlinearPendulum& sys, const PhaseState<1>& z0, double h, std::int64_t n) {
  return run(sys, z0, h, n);
}

LobattoRun<PhaseState<2>> lobatto_run(const ElasticPendulumWithGravity& sys, const PhaseState<2>& z0, double h,
                                      std::int64_t n) {
  return run(sys, z0, h, n);
}

Mat<2> lobatto_step_jacobian(const NonlinearPendulum& sys, const PhaseState<1>& z, double h) {
  return galerkin_step_jacobian(lobatto_rule(), sys, z, h);
}

Mat<4> lobatto_step_jacobian(const ElasticPendulumWithGravity& sys, const PhaseState<2>& z, double h) {
  return galerkin_step_jacobian(lobatto_rule(), sys, z, h);
}

}  // namespace geomint

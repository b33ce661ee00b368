#pragma once
// Lobatto IIIA-IIIB (galerkin_variational.hpp, lobatto_rule) on the nonlinear pendulum and the elastic pendulum
// (001's nonlinear study): runs of it and the Jacobian of its step, compiled once in the library
// (galerkin_steps.cpp): a file that includes this header neither parses nor instantiates Newton's method on the stage.
#include <cstdint>

#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {

// n steps of Lobatto IIIA-IIIB from z0: the state z_n and the mean number of Newton iterations per step.
template <class State>
struct LobattoRun {
  State z;
  double newton_iterations;
};
LobattoRun<PhaseState<1>> lobatto_run(const NonlinearPendulum& sys, const PhaseState<1>& z0, double h, std::int64_t n);
LobattoRun<PhaseState<2>> lobatto_run(const ElasticPendulumWithGravity& sys, const PhaseState<2>& z0, double h,
                                      std::int64_t n);

// The Jacobian of one step from z (galerkin_step_jacobian).
Mat<2> lobatto_step_jacobian(const NonlinearPendulum& sys, const PhaseState<1>& z, double h);
Mat<4> lobatto_step_jacobian(const ElasticPendulumWithGravity& sys, const PhaseState<2>& z, double h);

}  // namespace geomint

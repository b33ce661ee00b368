#pragma once
// Lobatto IIIA-IIIB's step and its Jacobian (galerkin_variational.hpp, lobatto_rule) on the nonlinear pendulum
// and the elastic pendulum (001's nonlinear study), compiled once in the library (galerkin_steps.cpp): a file
// that includes this header steps them without instantiating Newton's method on the stage again.
#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/systems/harmonic_oscillator.hpp"

namespace geomint {

extern template NonlinearPendulum::State galerkin_step(const GalerkinRule<3>&, const NonlinearPendulum&,
                                                       const NonlinearPendulum::State&, double, int*);
extern template ElasticPendulumWithGravity::State galerkin_step(const GalerkinRule<3>&, const ElasticPendulumWithGravity&,
                                                                const ElasticPendulumWithGravity::State&, double, int*);
extern template Mat<2> galerkin_step_jacobian(const GalerkinRule<3>&, const NonlinearPendulum&,
                                              const NonlinearPendulum::State&, double);
extern template Mat<4> galerkin_step_jacobian(const GalerkinRule<3>&, const ElasticPendulumWithGravity&,
                                              const ElasticPendulumWithGravity::State&, double);

}  // namespace geomint

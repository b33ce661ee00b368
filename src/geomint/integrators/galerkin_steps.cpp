#include "geomint/integrators/galerkin_steps.hpp"

namespace geomint {

template NonlinearPendulum::State galerkin_step(const GalerkinRule<3>&, const NonlinearPendulum&,
                                                const NonlinearPendulum::State&, double, int*);
template ElasticPendulumWithGravity::State galerkin_step(const GalerkinRule<3>&, const ElasticPendulumWithGravity&,
                                                         const ElasticPendulumWithGravity::State&, double, int*);
template Mat<2> galerkin_step_jacobian(const GalerkinRule<3>&, const NonlinearPendulum&, const NonlinearPendulum::State&,
                                       double);
template Mat<4> galerkin_step_jacobian(const GalerkinRule<3>&, const ElasticPendulumWithGravity&,
                                       const ElasticPendulumWithGravity::State&, double);

}  // namespace geomint

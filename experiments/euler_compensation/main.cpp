// euler_compensation: 000 (Takacs & Fulop 2025) Figs 2, 3, 8 and 9.
//   Fig 2  explicit Euler on y' = -alpha y, in y and in ybar = Psi(y) of (15)      decay.cpp
//   Fig 3  explicit Euler on the Gompertz equation (17), in y and in ybar of (18)  gompertz.cpp
//   Fig 8  symplectic Euler (42)-(43) on the oscillator (74), with and without
//          the compensating point transformation (82)                            oscillator.cpp
//   Fig 9  error in H against h for both: fitted orders 1 and 2                  convergence.cpp
// plus what the accuracy costs (study `cost`): error against wall time, ns per step  cost.cpp
// Here: the studies, in the order they run, and the scene keys that several of them read.
#include "geomint/runner/experiment.hpp"

namespace geomint::euler_compensation {
Study decay_study();        // 000 Fig 2      decay.cpp
Study gompertz_study();     // 000 Fig 3      gompertz.cpp
Study oscillator_study();   // 000 Fig 8      oscillator.cpp
Study convergence_study();  // 000 Fig 9      convergence.cpp
Study cost_study();         // cost of Figs 8-9's methods   cost.cpp
}  // namespace geomint::euler_compensation

using namespace geomint;
using namespace geomint::euler_compensation;

namespace {

Schema shared_keys() {
  Schema s;
  s.real("decay.alpha", positive(), "rate alpha of y' = -alpha y (000 eq. (14))")
      .real("decay.y0", positive(), "initial value y(0) > 0")
      .real("gompertz.a", positive(), "growth parameter a of (17)")
      .real("gompertz.b", positive(), "growth parameter b of (17)")
      .real("gompertz.y0", positive(), "initial value, 0 < y0 < e^{a/b} (domain of (18))")
      .real("oscillator.q0", any_finite(), "initial q (the compensation (82) is derived for q0 = 1, p0 = 0)")
      .real("oscillator.p0", any_finite(), "initial p")
      .real("oscillator.h", positive(), "step of symplectic Euler (Fig 8); h < 2 (stability)")
      .real("oscillator.k", positive(), "parameter k of (82), qhat = q / (1 + k h^2)")
      .real("convergence.t_end", positive(), "errors are maxima over t in [0, t_end]");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"euler_compensation",
                      "000 Figs 2, 3, 8, 9: order compensation by a change of variables (explicit Euler) "
                      "and by a change of coordinates (symplectic Euler)",
                      shared_keys(),
                      {decay_study(), gompertz_study(), oscillator_study(), convergence_study(), cost_study()}};
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}

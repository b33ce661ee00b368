#pragma once
// Drive a one-step method for n steps with an integer step counter
// (t_j = j*h is computed by the observer, never accumulated).
#include <cmath>
#include <cstdint>

namespace geomint {

// The number of steps of size h to t_end (scenes check that h divides t_end).
inline std::int64_t steps_to(double t_end, double h) { return std::llround(t_end / h); }

// Calls observe(j, z_j) for j = 0..n and returns z_n.
template <class Step, class State, class Observer>
State integrate_n_steps(const Step& step, State z, std::int64_t n, Observer&& observe) {
  observe(std::int64_t{0}, z);
  for (std::int64_t j = 1; j <= n; ++j) {
    z = step(z);
    observe(j, z);
  }
  return z;
}

// Without an observer: the loop that timing runs measure.
template <class Step, class State>
State integrate_n_steps(const Step& step, State z, std::int64_t n) {
  for (std::int64_t j = 1; j <= n; ++j) z = step(z);
  return z;
}

}  // namespace geomint

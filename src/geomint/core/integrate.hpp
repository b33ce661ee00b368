#pragma once
// The one step interface and the one driver.
//
// A method is a processed method, 000 eq. (22)-(23): Phi^n = post o kernel^n o
// pre. The kernel runs on a state of its own (for kick-drift-kick kernels it
// carries the cached force): `kernel(s, h)` is the step, `pre(z, h)` maps a
// phase-space point into the kernel's state once, and `post` maps back only
// where a result is wanted, either pointwise, `post(s, h)`, or from the kernel
// states at steps j-1, j, j+1, `post(prev, cur, next, h)` (000 eq. (36)-(37)).
// A plain one-step map is the processed method with identity processors
// (one_step_method). `integrate` drives any of them with an integer step
// counter: t_j = j h is computed by the observer, never accumulated.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace geomint {

template <class Kernel, class Pre, class Post>
struct Processed {
  Kernel kernel;  // kernel(s, h) -> s
  Pre pre;        // pre(z, h) -> s
  Post post;      // post(s, h) -> z  or  post(prev, cur, next, h) -> z
};

template <class Kernel, class Pre, class Post>
Processed(Kernel, Pre, Post) -> Processed<Kernel, Pre, Post>;

// A one-step map z -> step(z, h) as a processed method with identity processors.
inline constexpr auto unprocessed = [](const auto& z, double) { return z; };
template <class Step>
auto one_step_method(Step step) {
  return Processed{step, unprocessed, unprocessed};
}

// The step counts, one convention each. steps_to: the steps of size h to t_end, where the scene
// checks that h divides t_end. steps_within: the steps of size h in [0, t], the largest n with
// n h <= t (a quotient t/h within 1e-9 below an integer counts as that integer); step_count_within is
// the same as a real, for --plan's counts before any cast. steps_to_each: the steps of one run to
// t_end for each h of a list, together (--plan).
inline std::int64_t steps_to(double t_end, double h) { return std::llround(t_end / h); }
inline double step_count_within(double t, double h) { return std::floor(t / h + 1e-9); }
inline std::int64_t steps_within(double t, double h) { return std::llround(step_count_within(t, h)); }
inline double steps_to_each(double t_end, const std::vector<double>& hs) {
  double steps = 0;
  for (double h : hs) steps += t_end / h;
  return steps;
}
// The samples a run of n steps keeps when it samples every max(1, floor(n / samples)) steps from step 0 (--plan).
inline double kept_samples(double n, double samples) { return std::floor(n / std::max(1.0, std::floor(n / samples))) + 1; }

namespace detail {
template <class M, class S>
concept StencilPost = requires(const M& m, const S& s, double h) { m.post(s, s, s, h); };
}  // namespace detail

// Calls observe(j, z_j) with z_j = post(...) for j = 0..n; returns z_n. A
// stencil postprocessor needs the kernel state at j-1 for j = 0, taken as
// kernel(s_0, -h) (the inverse step of a symmetric kernel), and at n+1.
template <class M, class Z, class Observer>
Z integrate(const M& m, const Z& z0, double h, std::int64_t n, Observer&& observe) {
  auto cur = m.pre(z0, h);
  using S = decltype(cur);
  if constexpr (detail::StencilPost<M, S>) {
    S prev = m.kernel(cur, -h), next = m.kernel(cur, h);
    Z z = m.post(prev, cur, next, h);
    observe(std::int64_t{0}, z);
    for (std::int64_t j = 1; j <= n; ++j) {
      prev = cur, cur = next, next = m.kernel(cur, h);
      z = m.post(prev, cur, next, h);
      observe(j, z);
    }
    return z;
  } else {
    observe(std::int64_t{0}, m.post(cur, h));
    for (std::int64_t j = 1; j <= n; ++j) {
      cur = m.kernel(cur, h);
      observe(j, m.post(cur, h));
    }
    return m.post(cur, h);
  }
}

// 000 eq. (23) as it is meant to be used: pre once, n kernel steps, post once
// (the loop that timing runs measure).
template <class M, class Z>
Z integrate(const M& m, const Z& z0, double h, std::int64_t n) {
  auto s = m.pre(z0, h);
  using S = decltype(s);
  if constexpr (detail::StencilPost<M, S>) {
    S prev = n > 0 ? s : m.kernel(s, -h);
    for (std::int64_t j = 1; j <= n; ++j) prev = s, s = m.kernel(s, h);
    return m.post(prev, s, m.kernel(s, h), h);
  } else {
    for (std::int64_t j = 1; j <= n; ++j) s = m.kernel(s, h);
    return m.post(s, h);
  }
}

}  // namespace geomint

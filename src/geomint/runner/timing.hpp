#pragma once
// Wall-clock timing for the cost figures and summary.json (never for pass/fail).
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/observables/ensemble_statistics.hpp"

namespace geomint {

// Keeps the compiler from discarding a computation whose result is unused.
template <class T>
inline void do_not_optimize(const T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}

// Median over `repeats` runs of f() (after one untimed warm-up run), in seconds.
template <class F>
double median_seconds(int repeats, const F& f) {
  f();
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(std::move(t));
}

// n steps of eq. (23) (pre once, post once) with every call in the loop inlined: each method is
// timed with its step inlined, however many other methods the executable instantiates.
template <class M, class Z>
[[gnu::flatten, gnu::noinline]] Z integrate_inlined(const M& m, const Z& z0, double h, std::int64_t n) {
  return integrate(m, z0, h, n);
}

}  // namespace geomint

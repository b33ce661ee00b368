#pragma once
// Wall-clock timing for the cost figures and summary.json (never for pass/fail).
//
// The timing method of every cost study: one untimed warm-up call of f, which also calibrates
// `inner`, the number of calls per timed run, so that a timed run lasts at least `min_run_s`
// (10 ms by default: well above the clock's resolution and a scheduler tick's jitter); then
// `repeats` timed runs. A run's time is its wall time over `inner`. The minimum is the estimate
// (the least disturbed run), the spread (max - min) / min says how disturbed the others were.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/core/integrate.hpp"
#include "geomint/observables/ensemble_statistics.hpp"

namespace geomint {

// Keeps the compiler from discarding a computation whose result is unused.
template <class T>
inline void do_not_optimize(const T& value) {
  asm volatile("" : : "r"(&value) : "memory");
}

// The wall time of one call of a timed function, over `repeats` timed runs of `inner` calls.
struct RunTime {
  double min_s = 0, median_s = 0, max_s = 0;  // seconds per call
  int repeats = 0;
  std::int64_t inner = 0;  // calls per timed run
  double seconds() const { return min_s; }  // the estimate
  double spread() const { return min_s > 0 ? (max_s - min_s) / min_s : 0; }
};

inline nlohmann::ordered_json to_json(const RunTime& t) {
  return {{"min_s", t.min_s}, {"median_s", t.median_s}, {"max_s", t.max_s},
          {"spread", t.spread()}, {"repeats", t.repeats}, {"inner", t.inner}};
}

// The timing method of the header comment. repeats >= 1.
template <class F>
RunTime time_runs(int repeats, const F& f, double min_run_s = 0.01) {
  using clock = std::chrono::steady_clock;
  const auto since = [](clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
  };
  const auto warm = clock::now();
  f();
  const double once = since(warm);
  RunTime r;
  r.repeats = std::max(repeats, 1);
  r.inner = once >= min_run_s ? 1 : static_cast<std::int64_t>(std::ceil(min_run_s / std::max(once, 1e-9)));
  std::vector<double> t;
  for (int k = 0; k < r.repeats; ++k) {
    const auto start = clock::now();
    for (std::int64_t i = 0; i < r.inner; ++i) f();
    t.push_back(since(start) / static_cast<double>(r.inner));
  }
  r.min_s = *std::min_element(t.begin(), t.end());
  r.max_s = *std::max_element(t.begin(), t.end());
  r.median_s = median(std::move(t));
  return r;
}

// n steps of eq. (23) (pre once, post once) with every call in the loop inlined: each method is
// timed with its step inlined, however many other methods the executable instantiates.
template <class M, class Z>
[[gnu::flatten, gnu::noinline]] Z integrate_inlined(const M& m, const Z& z0, double h, std::int64_t n) {
  return integrate(m, z0, h, n);
}

}  // namespace geomint

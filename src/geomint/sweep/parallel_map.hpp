#pragma once
// Parallel map with deterministic results: out[i] = f(i) is computed by
// whichever thread, but stored by index, and every reduction over the results
// happens afterwards, serially, in index order. So the numbers do not depend
// on the thread count. An exception thrown by f is rethrown (the one of the
// lowest index) after the loop.
#include <cstddef>
#include <functional>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace geomint {

// task(i) for every i < n, on the threads (OpenMP, one index at a time, dynamic schedule); the exception of
// the lowest index that threw, if any, rethrown after the loop. Compiled once (parallel_map.cpp), so that a
// study's map instantiates no parallel region of its own.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& task);

template <class F>
auto parallel_map(std::size_t n, const F& f) -> std::vector<std::invoke_result_t<const F&, std::size_t>> {
  using R = std::invoke_result_t<const F&, std::size_t>;
  std::vector<std::optional<R>> slots(n);
  parallel_for(n, [&](std::size_t i) { slots[i].emplace(f(i)); });
  std::vector<R> out;
  out.reserve(n);
  for (auto& s : slots) out.push_back(std::move(*s));
  return out;
}

}  // namespace geomint

#pragma once
// Parallel map with deterministic results: out[i] = f(i) is computed by
// whichever thread, but stored by index, and every reduction over the results
// happens afterwards, serially, in index order. So the numbers do not depend
// on the thread count. An exception thrown by f is rethrown (the one of the
// lowest index) after the loop.
#include <cstddef>
#include <exception>
#include <optional>
#include <type_traits>
#include <vector>

namespace geomint {

template <class F>
auto parallel_map(std::size_t n, const F& f) -> std::vector<std::invoke_result_t<const F&, std::size_t>> {
  using R = std::invoke_result_t<const F&, std::size_t>;
  std::vector<std::optional<R>> slots(n);
  std::vector<std::exception_ptr> errors(n);
  const auto count = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic, 1)
  for (long long i = 0; i < count; ++i) {
    try {
      slots[static_cast<std::size_t>(i)].emplace(f(static_cast<std::size_t>(i)));
    } catch (...) {
      errors[static_cast<std::size_t>(i)] = std::current_exception();
    }
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  std::vector<R> out;
  out.reserve(n);
  for (auto& s : slots) out.push_back(std::move(*s));
  return out;
}

}  // namespace geomint

#include "geomint/sweep/parallel_map.hpp"

#include <exception>

namespace geomint {

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& task) {
  std::vector<std::exception_ptr> errors(n);
  const auto count = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic, 1)
  for (long long i = 0; i < count; ++i) {
    try {
      task(static_cast<std::size_t>(i));
    } catch (...) {
      errors[static_cast<std::size_t>(i)] = std::current_exception();
    }
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace geomint

#pragma once
// The definitions of MethodsOn (by_name.hpp), for the files that instantiate it: the generated on_<system>.cpp.
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/dispatch.hpp"
#include "geomint/methods/scene_methods.hpp"

namespace geomint {

namespace detail {
template <class Sys, class F>
decltype(auto) with_bound(Bind bind, std::string_view method, const Sys& sys, F&& f) {
  if (bind == Bind::kernel) return with_kernel(method, sys, f);
  return with_method(method, sys, f);
}
}  // namespace detail

template <class Sys>
std::vector<std::string> MethodsOn<Sys>::names() {
  return methods_for<Sys>();
}

template <class Sys>
std::vector<std::string> MethodsOn<Sys>::choices() {
  return method_choices<Sys>();
}

template <class Sys>
void MethodsOn<Sys>::check(const Scene& s, const char* key, const Sys& sys) {
  check_distinct_methods(s, key);
  for (const auto& m : s.texts(key)) {
    try {
      with_kernel(m, sys, [](const auto&) { return 0; });
    } catch (const std::invalid_argument& e) {
      s.reject(key, e.what());
    }
  }
}

template <class Sys>
auto MethodsOn<Sys>::integrate(std::string_view method, const Sys& sys, const Z& z0, double h, std::int64_t n,
                               Bind bind) -> Z {
  return detail::with_bound(bind, method, sys, [&](const auto& m) { return geomint::integrate(m, z0, h, n); });
}

template <class Sys>
auto MethodsOn<Sys>::integrate(std::string_view method, const Sys& sys, const Z& z0, double h, std::int64_t n,
                               const Observer& observe, Bind bind) -> Z {
  return detail::with_bound(bind, method, sys, [&](const auto& m) { return geomint::integrate(m, z0, h, n, observe); });
}

template <class Sys>
std::function<void()> MethodsOn<Sys>::timed(std::string_view method, const Sys& sys, std::vector<Z> starts, double h,
                                            std::int64_t n, Bind bind) {
  return detail::with_bound(bind, method, sys, [&](const auto& m) -> std::function<void()> {
    return [m, starts = std::move(starts), h, n] {
      for (const Z& z : starts) do_not_optimize(integrate_inlined(m, z, h, n));
    };
  });
}

}  // namespace geomint

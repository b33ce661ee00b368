#pragma once
// The registered methods by scene name, on one system type. Every (method, system) pair a study
// runs is compiled once, in the library: a system header's line "// geomint: MethodsOn<System>" makes
// CMake generate on_<system>.cpp, which instantiates it (by_name_impl.hpp, the registry's dispatch of
// dispatch.hpp; cmake/geomint_experiment.cmake geomint_methods_on). A study includes this header, never
// methods.hpp, so that editing it recompiles the study alone.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/runner/timing.hpp"

namespace geomint {

class Scene;

enum class Bind { method, kernel };  // the method (processed where it is), or its kernel with trivial processors

template <class Sys>
struct MethodsOn {
  using Z = typename Sys::State;
  using Observer = std::function<void(std::int64_t, const Z&)>;

  static std::vector<std::string> names();    // the registry names of the methods that can step Sys
  static std::vector<std::string> choices();  // those and their labels: what a scene may name
  // Rejects `key` unless it names each method once and each can step sys (its kernel, if processed).
  static void check(const Scene& s, const char* key, const Sys& sys);
  // z_n after n steps of eq. (23) from z0 (pre once, post once).
  static Z integrate(std::string_view method, const Sys& sys, const Z& z0, double h, std::int64_t n,
                     Bind bind = Bind::method);
  // The same, calling observe(j, z_j) for j = 0..n (core/integrate.hpp).
  static Z integrate(std::string_view method, const Sys& sys, const Z& z0, double h, std::int64_t n,
                     const Observer& observe, Bind bind = Bind::method);
  // A call that runs n steps from each of `starts`, each step inlined: a configuration to time
  // (runner/timing.hpp, InterleavedTiming). `sys` must outlive it.
  static std::function<void()> timed(std::string_view method, const Sys& sys, std::vector<Z> starts, double h,
                                     std::int64_t n, Bind bind = Bind::method);
};

// The trajectory z_0..z_n of a method by name (pre once, post once), for the studies that draw or tabulate whole
// trajectories (001 Table 1 and Fig. 1).
template <class Sys>
std::vector<typename Sys::State> trajectory(std::string_view method, const Sys& sys, const typename Sys::State& z0,
                                            double h, std::int64_t n) {
  std::vector<typename Sys::State> zs;
  MethodsOn<Sys>::integrate(method, sys, z0, h, n, [&](std::int64_t, const typename Sys::State& z) { zs.push_back(z); });
  return zs;
}

// One step of a method by name as a one-step map (core/integrate.hpp), for the analyses that take a
// method: one_step_matrix (analysis/linear_stability.hpp), step_jacobian_fd (observables/symplecticity.hpp).
// `method` and `sys` must outlive it.
template <class Sys>
auto one_step_by_name(std::string_view method, const Sys& sys, Bind bind = Bind::method) {
  return one_step_method([method, &sys, bind](const typename Sys::State& z, double h) {
    return MethodsOn<Sys>::integrate(method, sys, z, h, 1, bind);
  });
}

}  // namespace geomint

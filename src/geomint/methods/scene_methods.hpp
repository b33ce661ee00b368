#pragma once
// Checks on the methods a scene names (`<study>.methods = [...]`), before any
// work: each named once, able to step the study's system, and every step
// below the stability bound the registry declares for it.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/io/csv.hpp"
#include "geomint/methods/methods.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {

// Rejects `key` if it names a method twice (by its name or its label).
inline void check_distinct_methods(const Scene& s, const char* key) {
  std::vector<std::string> labels;
  for (const auto& m : s.texts(key)) {
    const std::string label = label_of(m);
    if (std::find(labels.begin(), labels.end(), label) != labels.end())
      s.reject(key, "each method once (" + m + " is named twice)");
    labels.push_back(label);
  }
}

// ... and unless each method can step sys (its kernel, for a processed method).
template <class Sys>
void check_methods(const Scene& s, const char* key, const Sys& sys) {
  check_distinct_methods(s, key);
  for (const auto& m : s.texts(key)) {
    try {
      with_kernel(m, sys, [](const auto&) { return 0; });
    } catch (const std::invalid_argument& e) {
      s.reject(key, e.what());
    }
  }
}

// Is omega h at or beyond a method's oscillatory bound (NaN: none declared)?
inline bool beyond_bound(double omega_h, double bound) { return !std::isnan(bound) && !(omega_h < bound); }

// `method` at h omega = hw: below the oscillatory bound the registry declares (none declared: no
// check). Blamed on the step key, or on the methods key if the method is unstable for every h.
// `what` says where hw comes from; `formula`: how the paper writes the bound, if it does.
inline void check_oscillatory_bound(const Scene& s, const char* step_key, const char* methods_key,
                                    const std::string& method, double hw, const std::string& what,
                                    const std::string& formula = {}) {
  const double bound = method_info(method).oscillatory_bound;
  if (beyond_bound(hw, bound))
    s.reject(bound > 0 ? step_key : methods_key,
             method + " is unstable " +
                 (bound > 0 ? "for h omega >= " + (formula.empty() ? "" : formula + " = ") + format_double(bound)
                            : std::string("for every h > 0")) +
                 " on the oscillator (methods/registry.hpp), here h omega = " + format_double(hw) + " (" + what + ")");
}

}  // namespace geomint

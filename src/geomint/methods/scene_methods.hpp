#pragma once
// Checks on the methods a scene names (`<study>.methods = [...]`), before any
// work: each named once and every step below the stability bound the registry
// declares for it (that each can step the study's system: MethodsOn::check, by_name.hpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/io/csv.hpp"
#include "geomint/methods/registry.hpp"
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

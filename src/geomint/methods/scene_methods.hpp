#pragma once
// Checks on the methods a scene names (`<study>.methods = [...]`), before any
// work: each named once and every step below the stability bound the registry
// declares for it (that each can step the study's system: MethodsOn::check, by_name.hpp).
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/io/csv.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {

// Rejects `key` if it names a method twice (by its name or its label).
void check_distinct_methods(const Scene& s, const char* key);

// Is omega h at or beyond a method's oscillatory bound (NaN: none declared)?
inline bool beyond_bound(double omega_h, double bound) { return !std::isnan(bound) && !(omega_h < bound); }

// `method` at h omega = hw: below the oscillatory bound the registry declares (none declared: no
// check). Blamed on the step key, or on the methods key if the method is unstable for every h.
// `what` says where hw comes from; `formula`: how the paper writes the bound, if it does.
void check_oscillatory_bound(const Scene& s, const char* step_key, const char* methods_key, const std::string& method,
                             double hw, const std::string& what, const std::string& formula = {});

// Rejects `key` unless a run to s.real(key) takes at least one step of each length in `steps` (`what` names them).
void check_at_least_one_step(const Scene& s, const char* key, const std::vector<double>& steps, const char* what);

// The same for a study that steps the one method `method` (no methods key): blamed on the step key.
inline void check_step_bound(const Scene& s, const char* step_key, const std::string& method, double hw,
                             const std::string& what, const std::string& formula = {}) {
  check_oscillatory_bound(s, step_key, step_key, method, hw, what, formula);
}

}  // namespace geomint

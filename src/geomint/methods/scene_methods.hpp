#pragma once
// Checks on the methods a scene names (`<study>.methods = [...]`) and on its steps, before any
// work: each method named once and every step below the stability bound the registry declares
// for it (that each can step the study's system: MethodsOn::check, by_name.hpp); every step a
// whole number of times in the run it ends.
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

// A scene's list of steps on an oscillator of frequency `omega`: h omega for each step h of `key`; or, with
// `per_period`, each entry of `key` a whole number N of steps per period (any other is rejected), h omega = 2 pi / N.
// `at` follows the step in a message (e.g. ", frequency 1").
struct OscillatorSteps {
  const char* key;
  double omega = 1;
  bool per_period = false;
  std::string at = {};
};

// check_oscillatory_bound of `method` at every step of `steps`.
void check_oscillatory_bound(const Scene& s, const OscillatorSteps& steps, const char* methods_key,
                             const std::string& method, const std::string& formula = {});

// The same for every method that `methods_key` names.
void check_oscillatory_bounds(const Scene& s, const OscillatorSteps& steps, const char* methods_key);

// Each step h of `step_key` divides t_end (`end_key`) into n = t_end / h steps, a whole number 1 <= n <= 2^53
// (steps are counted in int64, t = j h); else rejects `blame` (default: step_key).
void check_whole_steps(const Scene& s, const char* step_key, const char* end_key, const char* blame = nullptr);

}  // namespace geomint

#include "geomint/methods/scene_methods.hpp"

#include <algorithm>
#include <numbers>
#include <vector>

namespace geomint {

void check_distinct_methods(const Scene& s, const char* key) {
  std::vector<std::string> labels;
  for (const auto& m : s.texts(key)) {
    const std::string label = label_of(m);
    if (std::find(labels.begin(), labels.end(), label) != labels.end())
      s.reject(key, "each method once (" + m + " is named twice)");
    labels.push_back(label);
  }
}

void check_oscillatory_bound(const Scene& s, const char* step_key, const char* methods_key,
                             const std::string& method, double hw, const std::string& what,
                             const std::string& formula) {
  const double bound = method_info(method).oscillatory_bound;
  if (beyond_bound(hw, bound))
    s.reject(bound > 0 ? step_key : methods_key,
             method + " is unstable " +
                 (bound > 0 ? "for h omega >= " + (formula.empty() ? "" : formula + " = ") + format_double(bound)
                            : std::string("for every h > 0")) +
                 " on the oscillator (methods/registry.hpp), here h omega = " + format_double(hw) + " (" + what + ")");
}

void check_at_least_one_step(const Scene& s, const char* key, const std::vector<double>& steps, const char* what) {
  const double longest = *std::max_element(steps.begin(), steps.end());
  if (s.real(key) < longest) s.reject(key, std::string("must be at least one step ") + what + " = " + format_double(longest));
}

void check_oscillatory_bound(const Scene& s, const OscillatorSteps& steps, const char* methods_key,
                             const std::string& method, const std::string& formula) {
  for (double h : s.reals(steps.key)) {
    if (steps.per_period && h != std::floor(h)) s.reject(steps.key, "every entry must be a whole number of steps per period");
    const double hw = steps.per_period ? 2 * std::numbers::pi / h : h * steps.omega;
    const std::string what = (steps.per_period ? "h omega = 2 pi / N at N = " : "h = ") + format_double(h) + steps.at;
    check_oscillatory_bound(s, steps.key, methods_key, method, hw, what, formula);
  }
}

void check_oscillatory_bounds(const Scene& s, const OscillatorSteps& steps, const char* methods_key) {
  for (const auto& m : s.texts(methods_key)) check_oscillatory_bound(s, steps, methods_key, m);
}

void check_whole_steps(const Scene& s, const char* step_key, const char* end_key, const char* blame) {
  const double t_end = s.real(end_key);
  const std::string_view key = blame ? blame : step_key;
  for (double h : s.reals(step_key)) {
    const std::string here = ", here " + std::string(step_key) + " = " + format_double(h);
    if (!(t_end / h <= max_exact_count))
      s.reject(key, "at most 2^53 steps to " + std::string(end_key) + " = " + format_double(t_end) + here);
    const double n = std::round(t_end / h);
    if (n < 1 || std::abs(n * h - t_end) > 1e-9 * t_end)
      s.reject(key, "each of " + std::string(step_key) + " must divide " + std::string(end_key) + " = " +
                        format_double(t_end) + here);
  }
}

}  // namespace geomint

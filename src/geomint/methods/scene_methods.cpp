#include "geomint/methods/scene_methods.hpp"

#include <algorithm>
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

}  // namespace geomint

// The discretizations (5.1) of 003 by name, and the summary over them (methods/discretizations.hpp).
#include "geomint/methods/discretizations.hpp"

#include <algorithm>
#include <cmath>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {
namespace {

const MethodInfo* as_discretization(const MethodInfo& m) {
  return m.family == Family::conformal && parse_discretization(m.label) ? &m : nullptr;
}

// {min, max, abs: {min, max}} of a non-empty list of numbers (abs: of their moduli).
Value signed_range_of(const std::vector<double>& v) {
  Value r = range_of(v);
  double abs_lo = std::abs(v.front()), abs_hi = abs_lo;
  for (double x : v) abs_lo = std::min(abs_lo, std::abs(x)), abs_hi = std::max(abs_hi, std::abs(x));
  r["abs"] = {{"min", abs_lo}, {"max", abs_hi}};
  return r;
}

}  // namespace

std::vector<std::string> discretization_choices() {
  std::vector<std::string> names, labels;
  for (const MethodInfo& m : method_registry())
    if (as_discretization(m)) names.emplace_back(m.name), labels.emplace_back(m.label);
  names.insert(names.end(), labels.begin(), labels.end());
  return names;
}

std::vector<Discretization> scene_discretizations(const Scene& s) {
  std::vector<Discretization> out;
  for (const auto& m : s.texts("methods")) out.push_back(*parse_discretization(method_info(m).label));
  return out;
}

Value method_ranges(const Value& per_method) {
  constexpr const char* groups[] = {"all", "N_midpoint", "N_trapezoidal"};
  Value out = Value::record();
  for (int g = 0; g < 3; ++g) {
    std::vector<double> v;
    bool complete = true;
    for (std::size_t i = 0; i < per_method.size(); ++i) {
      const std::string& label = per_method.keys()[i];
      const Value& x = per_method.at(i);
      if (g > 0 && (g == 1) != n_midpoint(*parse_discretization(label))) continue;
      if (x.is_number() && std::isfinite(x.number()))
        v.push_back(x.number());
      else
        complete = false;
    }
    if (complete && !v.empty()) out[groups[g]] = signed_range_of(v);
  }
  return out;
}

void put_methods(Context& ctx, const std::string& key, Value per_method, const std::string& nest) {
  Value ranges = method_ranges(per_method);
  if (nest.empty()) {
    ctx.summary["reproduced"][key] = std::move(per_method);
    ctx.summary["ranges"][key] = std::move(ranges);
  } else {
    ctx.summary["reproduced"][nest][key] = std::move(per_method);
    ctx.summary["ranges"][nest][key] = std::move(ranges);
  }
}

Value ratio_per_method(const Value& a, const Value& b) {
  Value out;
  for (const std::string& label : a.keys()) out[label] = a.at(label).number() / b.at(label).number();
  return out;
}

void put_run_facts(Context& ctx, const std::vector<Discretization>& methods) {
  ctx.summary["timing"]["threads"] = ctx.threads;
  if (methods.empty()) return;
  Value labels = Value::list();
  for (Discretization d : methods) labels.push_back(discretization_name(d));
  ctx.summary["methods"] = labels;
}

}  // namespace geomint

#include "geomint/runner/plan_rates.hpp"

#include <cstdio>
#include <map>
#include <stdexcept>
#include <toml++/toml.h>

#include "geomint_plan_rates.hpp"  // generated: kPlanRatesToml, experiments/plan_rates.toml

namespace geomint {
namespace {

std::map<std::string, PlanRate, std::less<>> read_table() {
  const toml::table table =
      toml::parse(std::string_view(kPlanRatesToml), std::string_view("experiments/plan_rates.toml"));
  std::map<std::string, PlanRate, std::less<>> rates;
  if (const toml::table* entries = table["rates"].as_table()) {
    for (const auto& [name, node] : *entries) {
      const auto ns = node.at_path("ns_per_step").value<double>();
      const auto what = node.at_path("what").value<std::string>(), cpu = node.at_path("cpu").value<std::string>();
      if (!ns || !(*ns > 0) || !what || !cpu)
        throw std::logic_error("experiments/plan_rates.toml: rate '" + std::string(name.str()) +
                               "' needs ns_per_step > 0, what and cpu");
      char ns_text[32];
      std::snprintf(ns_text, sizeof ns_text, "%.3g", *ns);
      const double evals = node.at_path("force_evals_per_step").value_or(0.0);
      if (!(evals >= 0))
        throw std::logic_error("experiments/plan_rates.toml: rate '" + std::string(name.str()) +
                               "' needs force_evals_per_step >= 0");
      rates.emplace(std::string(name.str()),
                    PlanRate{*ns, "ns per step: " + *what + " (" + ns_text + " ns on " + *cpu + ", plan_rates.toml)",
                             evals});
    }
  }
  return rates;
}

}  // namespace

double PlanRate::evals_per_step() const {
  if (!(force_evals_per_step > 0))
    throw std::logic_error("experiments/plan_rates.toml: the rate of '" + note + "' gives no force_evals_per_step");
  return force_evals_per_step;
}

const PlanRate& plan_rate(std::string_view name) {
  static const std::map<std::string, PlanRate, std::less<>> rates = read_table();
  const auto it = rates.find(name);
  if (it == rates.end()) throw std::logic_error("experiments/plan_rates.toml has no rate '" + std::string(name) + "'");
  return it->second;
}

}  // namespace geomint

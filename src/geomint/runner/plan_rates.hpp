#pragma once
// --plan's rates: the time per step of each kind of step a study takes (experiments/plan_rates.toml, compiled
// into the binary). The table is measured on the paper scenes by `make plan-rates` (scripts/plan_rates.py)
// and names the CPU it was measured on; a plan on another machine is off by the ratio of the two machines.
#include <string>
#include <string_view>

namespace geomint {

struct PlanRate {
  double ns_per_step;  // ns per integration step and thread
  std::string note;    // what the rate is and where it was measured, for the plan's note
  double force_evals_per_step = 0;  // the most in a step of the methods planned with the rate (0: not given)

  // force_evals_per_step; std::logic_error where the table does not give it.
  double evals_per_step() const;
};

// --plan's memory of a CSV: one cell held in memory (its text and separator), in bytes.
inline constexpr double kCsvCellBytes = 24;

// The rate `name` (e.g. "pendulum lobatto"); std::logic_error for a name the table lacks.
const PlanRate& plan_rate(std::string_view name);

}  // namespace geomint

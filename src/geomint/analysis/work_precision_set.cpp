#include "geomint/analysis/work_precision_set.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "geomint/runner/summary.hpp"
#include "geomint/runner/timing_report.hpp"

namespace geomint {

std::vector<std::string> WorkPrecisionSet::methods() const {
  std::vector<std::string> out;
  for (const auto& r : records_)
    if (std::find(out.begin(), out.end(), r.method) == out.end()) out.push_back(r.method);
  return out;
}

std::vector<CostRun> WorkPrecisionSet::runs(const std::string& method) const {
  std::vector<CostRun> out;
  for (const auto& r : records_)
    if (r.method == method) out.push_back({r.h, r.steps, r.wall.seconds(), r.evals, r.err});
  return by_decreasing_h(out);
}

void WorkPrecisionSet::time(int repeats, int workers) {
  InterleavedTiming timing(repeats, kTimingFloorS, workers);
  std::vector<std::size_t> which;
  for (std::size_t k = 0; k < records_.size(); ++k)
    if (timed_[k]) timing.add(timed_[k]), which.push_back(k);
  const std::vector<RunTime> times = timing.run();
  for (std::size_t i = 0; i < which.size(); ++i) records_[which[i]].wall = times[i];
}

Csv WorkPrecisionSet::csv() const {
  Csv out({"method", "h", "steps", "wall_s", "wall_q1_s", "wall_q3_s", "wall_spread", "force_evals", "err"});
  for (const auto& r : records_)
    out.row(r.method, r.h, r.steps, r.wall.seconds(), r.wall.q1_s, r.wall.q3_s, r.wall.spread(), r.evals, r.err);
  return out;
}

nlohmann::ordered_json WorkPrecisionSet::summary(const std::vector<double>& targets) const {
  using json = nlohmann::ordered_json;
  const auto labels = methods();
  std::vector<std::vector<CostRun>> curves;
  for (const auto& m : labels) curves.push_back(runs(m));
  const auto wall = equal_cost(curves, &CostRun::wall_s), evals = equal_cost(curves, &CostRun::evals);
  json by_method = json::object();
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const auto& c = curves[k];
    json m{{"runs", c.size()}};
    if (!c.empty()) {
      const CostRun& finest = c.back();
      m["min_err"] = std::min_element(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.err < b.err; })->err;
      m["ns_per_step"] = 1e9 * finest.wall_s / finest.steps;
      const RunTime per_step = finest_run(labels[k]).wall.scaled(1e9 / finest.steps);
      m["ns_per_step_q1"] = per_step.q1_s, m["ns_per_step_q3"] = per_step.q3_s;
      m["ns_per_step_spread"] = per_step.spread();
      m["evals_per_step"] = finest.evals / finest.steps;
    }
    m["err_at_equal_wall"] = wall ? or_null(error_at_cost(c, *wall, &CostRun::wall_s)) : json(nullptr);
    m["err_at_equal_evals"] = evals ? or_null(error_at_cost(c, *evals, &CostRun::evals)) : json(nullptr);
    m["wall_s_to"] = json::array(), m["evals_to"] = json::array();
    for (double t : targets) {
      m["wall_s_to"].push_back(or_null(cost_to_reach(c, t, &CostRun::wall_s)));
      m["evals_to"].push_back(or_null(cost_to_reach(c, t, &CostRun::evals)));
    }
    by_method[labels[k]] = m;
  }
  SpreadTally spreads;
  for (const auto& r : records_) spreads.add(r.wall);
  return {{"error", error_},         {"methods", labels},      {"targets", targets},
          {"equal_wall_s", or_null(wall)}, {"equal_evals", or_null(evals)}, {"by_method", by_method},
          {"spread", spreads.to_json()}};
}

const WorkPrecisionRecord& WorkPrecisionSet::finest_run(const std::string& method) const {
  const WorkPrecisionRecord* finest = nullptr;
  for (const auto& r : records_)
    if (r.method == method && (!finest || r.h < finest->h)) finest = &r;
  if (!finest) throw std::logic_error("WorkPrecisionSet: no run of " + method);
  return *finest;
}

nlohmann::ordered_json WorkPrecisionSet::relative_ns_per_step() const {
  std::vector<RunTime> per_step;
  std::vector<double> work;
  const auto labels = methods();
  for (const auto& m : labels) {
    const WorkPrecisionRecord& r = finest_run(m);
    per_step.push_back(r.wall.scaled(1 / r.steps)), work.push_back(r.evals / r.steps);
  }
  return relative_timings(labels, per_step, work);
}

}  // namespace geomint

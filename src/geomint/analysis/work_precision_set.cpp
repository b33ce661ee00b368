#include "geomint/analysis/work_precision_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
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

Value WorkPrecisionSet::crossing(const std::string& a, const std::string& b) const {
  const std::vector<CostRun> ra = runs(a), rb = runs(b);
  const auto cross = ra.empty() || rb.empty() ? std::nullopt : crossover(ra, rb);  // (crossover needs runs on both)
  return {{"methods", std::vector<std::string>{a, b}},
          {"wall_s", cross ? Value(cross->wall_s) : Value(nullptr)},
          {"err", cross ? Value(cross->err) : Value(nullptr)}};
}

Value WorkPrecisionSet::cost_ratios(const Value& summary, const std::string& first) {
  Value ratio = Value::record();
  const Value& by = summary.at("by_method");
  for (const std::string& label : by.keys()) {
    const Value& m = by.at(label);
    const Value &a = m.at("wall_s_to").at(0), &b = by.at(first).at("wall_s_to").at(0);
    if (a.is_null() || b.is_null()) continue;  // (evals_to is null exactly where wall_s_to is: the same bracket)
    ratio[label] = {{"wall_s", a.number() / b.number()},
                    {"evals", m.at("evals_to").at(0).number() / by.at(first).at("evals_to").at(0).number()}};
  }
  return ratio;
}

std::vector<CostRun> WorkPrecisionSet::runs(const std::string& method) const {
  std::vector<CostRun> out;
  for (const auto& r : records_)
    if (r.method == method) out.push_back({r.h, r.steps, r.wall.seconds(), r.evals, r.err});
  return by_decreasing_h(out);
}

RunTime affine_in_steps(const RunTime& a, double na, const RunTime& b, double nb, double n) {
  const double w = (n - na) / (nb - na);
  RunTime r;
  for (auto x : {&RunTime::min_s, &RunTime::q1_s, &RunTime::median_s, &RunTime::q3_s, &RunTime::max_s})
    r.*x = a.*x + w * (b.*x - a.*x);
  return r;
}

namespace {

// Whether the force evaluations of the runs are e = a n + c with a > 0 in their steps n, exactly (counts:
// integers, their products below 2^63 for counts below 2^31), on the line through lo and hi.
bool evals_affine_in_steps(std::span<const WorkPrecisionRecord> records, const std::vector<std::size_t>& runs,
                           std::size_t lo, std::size_t hi) {
  const auto n0 = static_cast<std::int64_t>(records[lo].steps), e0 = static_cast<std::int64_t>(records[lo].evals);
  const std::int64_t dn = static_cast<std::int64_t>(records[hi].steps) - n0, de = static_cast<std::int64_t>(records[hi].evals) - e0;
  if (dn <= 0 || de <= 0) return false;
  return std::all_of(runs.begin(), runs.end(), [&](std::size_t k) {
    const double n = records[k].steps, e = records[k].evals;
    return n == std::floor(n) && e == std::floor(e) && n < 2147483648.0 && e < 2147483648.0 &&
           (static_cast<std::int64_t>(e) - e0) * dn == de * (static_cast<std::int64_t>(n) - n0);
  });
}

}  // namespace

void WorkPrecisionSet::time(int repeats, int workers) {
  InterleavedTiming timing(repeats, kTimingFloorS, workers);
  std::vector<std::size_t> which;
  struct Interpolated {
    std::size_t k, lo, hi;  // record k between the timed records lo and hi
  };
  std::vector<Interpolated> between;
  for (const auto& m : methods()) {
    std::vector<std::size_t> mine;
    for (std::size_t k = 0; k < records_.size(); ++k)
      if (timed_[k] && records_[k].method == m) mine.push_back(k);
    const auto [lo, hi] = std::minmax_element(mine.begin(), mine.end(), [&](std::size_t x, std::size_t y) {
      return records_[x].steps < records_[y].steps;
    });
    if (mine.size() > 2 && evals_affine_in_steps(records_, mine, *lo, *hi)) {
      for (std::size_t k : mine)
        if (k != *lo && k != *hi) between.push_back({k, *lo, *hi}), records_[k].wall_timed = false;
      mine = {*lo, *hi};
    }
    for (std::size_t k : mine) timing.add(timed_[k]), which.push_back(k);
  }
  const std::vector<RunTime> times = timing.run();
  for (std::size_t i = 0; i < which.size(); ++i) records_[which[i]].wall = times[i];
  for (const auto& [k, lo, hi] : between)
    records_[k].wall = affine_in_steps(records_[lo].wall, records_[lo].steps, records_[hi].wall, records_[hi].steps, records_[k].steps);
}

void WorkPrecisionSet::times_of(const WorkPrecisionSet& timed) {
  const auto& t = timed.records_;
  for (std::size_t k = 0; k < records_.size(); ++k) {
    WorkPrecisionRecord& r = records_[k];
    if (k >= t.size() || t[k].method != r.method || t[k].h != r.h || t[k].steps != r.steps)
      throw std::logic_error("WorkPrecisionSet::times_of: the sets do not hold the same runs (record " + std::to_string(k) + ")");
    r.wall = t[k].wall, r.wall_timed = t[k].wall_timed;
  }
  if (t.size() != records_.size()) throw std::logic_error("WorkPrecisionSet::times_of: the sets differ in length");
}

Csv WorkPrecisionSet::csv() const {
  Csv out({"method", "h", "steps", "wall_s", "wall_q1_s", "wall_q3_s", "wall_spread", "wall_timed", "force_evals", "err"});
  for (const auto& r : records_)
    out.row(r.method, r.h, r.steps, r.wall.seconds(), r.wall.q1_s, r.wall.q3_s, r.wall.spread(),
            static_cast<std::int64_t>(r.wall_timed), r.evals, r.err);
  return out;
}

Value WorkPrecisionSet::summary(const std::vector<double>& targets) const {
  const auto labels = methods();
  std::vector<std::vector<CostRun>> curves;
  for (const auto& m : labels) curves.push_back(runs(m));
  const auto wall = equal_cost(curves, &CostRun::wall_s), evals = equal_cost(curves, &CostRun::evals);
  Value by_method = Value::record();
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const auto& c = curves[k];
    Value m{{"runs", c.size()}, {"timed_runs", std::count_if(records_.begin(), records_.end(), [&](const auto& r) {
                                  return r.method == labels[k] && r.wall_timed;
                                })}};
    if (!c.empty()) {
      const CostRun& finest = c.back();
      m["min_err"] = std::min_element(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.err < b.err; })->err;
      m["ns_per_step"] = 1e9 * finest.wall_s / finest.steps;
      const RunTime per_step = finest_run(labels[k]).wall.scaled(1e9 / finest.steps);
      m["ns_per_step_q1"] = per_step.q1_s, m["ns_per_step_q3"] = per_step.q3_s;
      m["ns_per_step_spread"] = per_step.spread();
      m["ns_per_step_drift"] = per_step.drift;  // (the measurement's drift, runner/timing.hpp)
      m["evals_per_step"] = finest.evals / finest.steps;
    }
    m["err_at_equal_wall"] = wall ? Value(error_at_cost(c, *wall, &CostRun::wall_s)) : Value();
    m["err_at_equal_evals"] = evals ? Value(error_at_cost(c, *evals, &CostRun::evals)) : Value();
    m["wall_s_to"] = Value::list(), m["evals_to"] = Value::list();
    for (double t : targets) {
      m["wall_s_to"].push_back(cost_to_reach(c, t, &CostRun::wall_s));
      m["evals_to"].push_back(cost_to_reach(c, t, &CostRun::evals));
    }
    by_method[labels[k]] = m;
  }
  SpreadTally spreads;
  for (const auto& r : records_)
    if (r.wall_timed) spreads.add(r.wall);
  return {{"error", error_},         {"methods", labels},      {"targets", targets},
          {"equal_wall_s", wall}, {"equal_evals", evals}, {"by_method", by_method},
          {"spread", spreads.to_value()}, {"ratios_to", ratios_to(by_method, targets)}};
}

Value WorkPrecisionSet::ratios_to(const Value& by_method, const std::vector<double>& targets) const {
  const auto labels = methods();
  const auto per_step = [&](const std::string& m) {
    const WorkPrecisionRecord& r = finest_run(m);
    return r.wall.scaled(1 / r.steps);
  };
  Value out = Value::list();
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const auto reaches = [&](const std::string& m) {
      return by_method.contains(m) && by_method.at(m).at("wall_s_to").at(t).is_number();
    };
    const auto ref = std::find_if(labels.begin(), labels.end(), reaches);
    Value at{{"target", targets[t]}, {"reference", ref == labels.end() ? Value() : Value(*ref)}};
    at["by_method"] = Value::record();
    for (auto m = ref == labels.end() ? ref : std::next(ref); m != labels.end(); ++m) {
      if (!reaches(*m)) continue;
      const auto to = [&](const std::string& label, const char* what) {
        const Value& v = by_method.at(label).at(what).at(t);
        return v.is_number() ? v.number() : std::nan("");
      };
      const TimeRatio w = carried_over(time_ratio(per_step(*m), per_step(*ref)), to(*m, "wall_s_to") / to(*ref, "wall_s_to"));
      at["by_method"][*m] = {{"wall_ratio", w.median}, {"min", w.lo}, {"max", w.hi}, {"drift", w.drift},
                             {"verdict", timing_verdict(w, 1, 1)}};  // (its work per step is judged by relative_ns_per_step)
    }
    out.push_back(at);
  }
  return out;
}

const WorkPrecisionRecord& WorkPrecisionSet::finest_run(const std::string& method) const {
  const WorkPrecisionRecord* finest = nullptr;
  for (const auto& r : records_)
    if (r.method == method && (!finest || r.h < finest->h)) finest = &r;
  if (!finest) throw std::logic_error("WorkPrecisionSet: no run of " + method);
  return *finest;
}

Value WorkPrecisionSet::relative_ns_per_step() const {
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

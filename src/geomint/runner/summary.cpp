#include "geomint/runner/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "geomint/analysis/claim_share.hpp"
#include "geomint/runner/experiment.hpp"

namespace geomint {

Value labels_of(const std::vector<std::string>& methods) {
  Value out = Value::list();
  for (auto& label : method_labels(methods)) out.push_back(std::move(label));
  return out;
}

Value range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {{"min", *lo}, {"max", *hi}};
}

Value spread_of(const std::vector<double>& v) {
  Value r = range_of(v);
  double sum = 0;
  for (double x : v) sum += x;
  r["mean"] = sum / static_cast<double>(v.size());
  return r;
}

Value quartiles(const std::vector<double>& v) {
  const Quartiles q = quartiles_of(v);
  return {{"min", q.min}, {"q1", q.q1}, {"median", q.median}, {"q3", q.q3}, {"max", q.max}};
}

Value claim_share_summary(const std::vector<double>& values, double bound, std::size_t min_samples) {
  const ClaimShare c = claim_share(values, bound);
  Value out = {{"samples", c.samples}, {"holds", c.holds}};
  if (values.empty()) return out;
  out["quartiles"] = quartiles(values), out["coin_flip_stderr"] = c.coin_flip_standard_error;
  if (c.samples < min_samples) return out;
  out["share"] = c.share, out["share_stderr"] = c.standard_error;
  out["share_in_coin_flip_stderr"] = (c.share - 0.5) / c.coin_flip_standard_error;
  return out;
}

Value h_range(const std::vector<double>& hs) {
  Value r = range_of(hs);
  r["count"] = hs.size();
  return r;
}

void record_steps_and_starts(Value& summary, const Scene& s, const char* steps_key, const char* starts_key) {
  summary["h_range"] = h_range(s.reals(steps_key));
  summary["initial_conditions"] = s.real_rows(starts_key).size();
}

namespace {

// Does `reproduced` round to `printed` at `digits` significant digits?
bool rounds_to_printed(double printed, double reproduced, int digits) {
  char a[32], b[32];
  std::snprintf(a, sizeof a, "%.*e", digits - 1, printed);
  std::snprintf(b, sizeof b, "%.*e", digits - 1, reproduced);
  return std::string(a) == b;
}

}  // namespace

Value printed_digits_agreement(const Context& ctx, const std::vector<std::string>& keys, int digits) {
  int compared = 0, rounding = 0;
  double deviation = 0;
  std::vector<std::pair<std::string, std::vector<double>>> roundoff;  // per key: the printed values at round-off
  for (const std::string& key : keys) {
    const auto c = ctx.comparison(ctx.summary, key);
    if (!c) continue;
    const Value &published = c->at("published"), &reproduced = c->at("reproduced");
    const auto at_roundoff = [&](const std::string& at) {  // (an entry the comparison found at round-off)
      const Value* r = c->find("roundoff");
      for (std::size_t i = 0; r && i < r->size(); ++i)
        if (r->at(i).text() == at) return true;
      return false;
    };
    roundoff.push_back({key.substr(key.rfind('.') + 1), {}});
    for (std::size_t i = 0; i < published.size(); ++i) {
      const std::string& at = published.keys()[i];
      const double printed = published.at(i).number();
      if (!reproduced.contains(at)) continue;
      if (at_roundoff(at)) {
        roundoff.back().second.push_back(printed);
      } else {
        ++compared, rounding += rounds_to_printed(printed, reproduced.at(at).number(), digits);
        deviation = std::max(deviation, std::abs(c->at("difference").at(at).number()));  // (relative: compare = rel)
      }
    }
  }
  Value out = {{"compared", compared}, {"round_to_printed_digits", rounding}, {"max_relative_deviation", deviation}};
  for (const auto& [name, printed] : roundoff)
    if (!printed.empty()) out[name + "_range"] = range_of(printed);
  return out;
}

}  // namespace geomint

#pragma once
// How a cost study reports the timing method of runner/timing.hpp (time_runs) in summary.json:
// the method in words, and the spread (max - min) / min of the timed runs it made, so that every
// minimum comes with how disturbed the other repeats were.
#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/runner/timing.hpp"

namespace geomint {

// The timing method of time_runs in words, for summary.json's timing.method.
inline std::string timing_method_text(int repeats) {
  return "minimum over " + std::to_string(repeats) +
         " timed runs (timing.repeats) of at least 10 ms each, the calls per run calibrated by one untimed "
         "warm-up call; steady_clock, single thread; spread = (max - min) / min over the runs";
}

// The spreads of every timed measurement of a study: their largest and median value and how many.
class SpreadTally {
 public:
  void add(const RunTime& t) { spreads_.push_back(t.spread()); }
  nlohmann::ordered_json to_json() const {
    if (spreads_.empty()) return nullptr;
    return {{"max", *std::max_element(spreads_.begin(), spreads_.end())},
            {"median", median(spreads_)},
            {"measurements", spreads_.size()}};
  }

 private:
  std::vector<double> spreads_;
};

}  // namespace geomint

#pragma once
// How a cost study reports the timing protocol of runner/timing.hpp in summary.json: the protocol in
// words, and the spread (interquartile range / median) of the timed runs it made, so that every median
// comes with how disturbed the repeats were.
#include <algorithm>
#include <string>
#include <vector>

#include "geomint/observables/ensemble_statistics.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/runner/timing.hpp"

namespace geomint {

// The timing protocol (runner/timing.hpp) in words, for summary.json's timing.method; `workers` as given
// to InterleavedTiming.
inline std::string timing_method_text(int repeats, int workers = 1) {
  std::string at_a_time = "single thread";
  if (workers > 1) {
    const int used = timing_concurrency(workers, repeats).workers;
    at_a_time = "each run on one thread, " +
                (used > 1 ? std::to_string(used) + " configurations at a time on as many cores (they time alike: "
                                                   "run.json timing_concurrency)"
                          : std::string("one configuration at a time (the cores do not time alike: run.json "
                                        "timing_concurrency)"));
  }
  return "median over " + std::to_string(repeats) + " rounds (timing.repeats) of one timed run of at least " +
         std::to_string(static_cast<int>(kTimingFloorS * 1000)) + " ms per configuration, the configurations "
         "interleaved in an order rotated each round, the calls per run calibrated after an untimed warm-up call; "
         "steady_clock, " + at_a_time + "; spread = interquartile range / median; a ratio of two timings with an "
         "interval from their quartiles";
}

// The spreads of every timed measurement of a study: their largest and median value and how many.
class SpreadTally {
 public:
  void add(const RunTime& t) { spreads_.push_back(t.spread()); }
  Value to_value() const {
    if (spreads_.empty()) return nullptr;
    return {{"max", *std::max_element(spreads_.begin(), spreads_.end())},
            {"median", median(spreads_)},
            {"measurements", spreads_.size()}};
  }

 private:
  std::vector<double> spreads_;
};

}  // namespace geomint

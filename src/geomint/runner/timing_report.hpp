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

// The timing protocol (runner/timing.hpp) in words, for summary.json's timing.method: the same for every
// thread count (how many configurations ran at a time is in run.json, timing_concurrency).
std::string timing_method_text(int repeats);

// The same for work-precision sets (analysis/work_precision_set.hpp) of counted force evaluations, some of them of
// long runs (the sets `long_sets`, e.g. "long_run_*") timed on a segment of `segment_key` steps: the same words
// from every study that adds sets to one summary record, so that each may run alone or after the other.
std::string segmented_timing_method_text(int repeats, const std::string& long_sets, const std::string& segment_key);

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

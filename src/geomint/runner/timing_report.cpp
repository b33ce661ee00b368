#include "geomint/runner/timing_report.hpp"

namespace geomint {

std::string timing_method_text(int repeats, int workers) {
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

}  // namespace geomint

#include "geomint/runner/timing_report.hpp"

namespace geomint {

std::string timing_method_text(int repeats) {  // (the same words for every thread count: how many configurations
                                               // ran at a time is run.json's, not the summary's)
  return "median over " + std::to_string(repeats) + " rounds (timing.repeats) of one timed run of at least " +
         std::to_string(static_cast<int>(kTimingFloorS * 1000)) + " ms per configuration, the configurations "
         "interleaved in an order rotated each round, the calls per run calibrated after an untimed warm-up call; "
         "steady_clock, each run on one thread, with several threads as many configurations at a time on as many cores "
         "where the cores time alike (run.json timing_concurrency); spread = interquartile range / median; a ratio of "
         "two timings with an interval from their quartiles, widened by the measurement's drift (run.json timing_control)";
}

std::string segmented_timing_method_text(int repeats, const std::string& long_sets, const std::string& segment_key) {
  return timing_method_text(repeats) + "; ns_per_step at the smallest h of a set; force evaluations count U_q and U_qq "
         "calls; " + long_sets + ": a run's wall time is its steps times the time per step measured on a segment of " +
         segment_key + " steps (at most the run), every call of a step through integrate";
}

}  // namespace geomint

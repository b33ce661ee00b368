#pragma once
// The core's clock, calibrated in the run that uses it (cycles from measured times, never an assumed clock).

#include <cstdint>

namespace geomint {

// n (a multiple of 8) integer additions, each waiting for the one before: n cycles on every x86-64 core
// (on another architecture, n additions the compiler may fold).
void dependent_additions(std::int64_t n);

// The core's cycle time in ns, calibrated under the timing protocol (runner/timing.hpp): a dependent chain of
// integer additions, one cycle of latency each on every x86-64 core (NaN elsewhere), timed like any
// configuration.
double ns_per_cycle(int repeats);

}  // namespace geomint

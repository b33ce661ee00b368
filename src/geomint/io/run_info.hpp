#pragma once
// Provenance of a run (run.json): commit, compiler and flags, resolved scene,
// machine, threads, command line, start and end time.
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

namespace geomint {

std::string utc_iso8601(std::chrono::system_clock::time_point t);

// The build half of run.json (git commit, compiler, flags), fixed at build time.
nlohmann::ordered_json build_info();

// The machine half: the CPU model (/proc/cpuinfo "model name"; "unknown" elsewhere) and its logical cores.
nlohmann::ordered_json machine_info();
// The machine's load averages over 1, 5 and 15 minutes (getloadavg), or null where unknown.
nlohmann::ordered_json load_average();

}  // namespace geomint

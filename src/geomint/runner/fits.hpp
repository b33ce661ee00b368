#pragma once
// Every fitted number of a summary names what it was fitted to, under summary "fits": the CSV it was
// written to, its columns, the window [from, to] of x, the fit, and the scene key the window comes
// from, so that one test (tests/regression/fits_test.cpp) recomputes it from the CSV with the same fit
// and checks the window against the scene. A fitted number no written CSV holds the data of is listed
// under "fits_not_recomputable" with the reason.
#include <string>

#include <nlohmann/json.hpp>

namespace geomint {

// A fitted number: at `quantity` (a dotted path into the summary), fitted to the columns x and y of
// `csv` (y "c^2": the square of column c) over the rows with from <= x <= to, by `kind`:
// "power_law" (power_law_exponent, observables/ensemble_statistics.hpp: log-log least squares, y > 0)
// or "slope" (slope_from: least squares). The window starts at from = (scene value of from_key) *
// from_factor * to.
struct FitRecord {
  std::string quantity, csv, x, y, kind;
  double from = 0, to = 0;
  std::string from_key;
  double from_factor = 1;
};

inline void record_fit(nlohmann::ordered_json& summary, const FitRecord& f) {
  summary["fits"].push_back({{"quantity", f.quantity}, {"csv", f.csv}, {"x", f.x}, {"y", f.y}, {"kind", f.kind},
                             {"from", f.from}, {"to", f.to}, {"from_key", f.from_key}, {"from_factor", f.from_factor}});
}

inline void record_unfittable(nlohmann::ordered_json& summary, const std::string& quantity, const std::string& why) {
  summary["fits_not_recomputable"].push_back({{"quantity", quantity}, {"why", why}});
}

}  // namespace geomint

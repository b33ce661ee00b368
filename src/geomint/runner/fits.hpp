#pragma once
// Every fitted number of a summary names what it was fitted to, under summary "fit_sources": the CSV
// it was written to, its columns, the rows (by the values of other columns), the window [from, to] of
// x, the fit, and the scene key the window comes from, so that one test (tests/regression/fits_test.cpp)
// recomputes it from the CSV with the same fit and checks the window against the scene. A fitted
// number no written CSV holds the data of is listed under "fits_not_recomputable" with the reason.
#include <string>
#include <utility>
#include <vector>

#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

class Scene;

// The start of a fit window [t_min, t_end] from the scene: <section>.fit_from of t_end.
double fit_window_start(const Scene& s, const std::string& section, double t_end);

// Where a fitted number's data are: columns x and y of `csv` (y "c^2": the square of column c), on the
// rows whose columns `where` hold the given values (as the CSV writes them); for "relative_ptp", less
// the relative change of column `minus` if it is not empty.
struct FitData {
  std::string csv, x, y;
  std::vector<std::pair<std::string, std::string>> where = {};
  std::string minus = {};
};

// A fitted number: at `quantity` (a dotted path into the summary), fitted to `data` over the rows with
// from <= x <= to, by `kind`: "power_law" (power_law_exponent, observables/ensemble_statistics.hpp:
// log-log least squares, y > 0), "slope" (slope_from: least squares) or "order" (fit_order,
// observables/order_fit.hpp: log-log least squares over the errors above `floor`), "relative_ptp"
// (relative_peak_to_peak, geometry/volume_series.hpp: max - min of y_j / y_0 - 1, y_0 at the window's
// first row), "relative_amplitude" (half that), "ptp" (max - min of y), "ptp_about_line" or
// "ptp_about_quadratic" (max - min of y less its least-squares line or quadratic in x,
// observables/ensemble_statistics.hpp). If `from_key` is not
// empty, the window starts at from = (scene value of from_key) * from_factor * to; if `to_key` is not
// empty, it ends at to = (scene value of to_key).
struct FitRecord {
  std::string quantity;
  FitData data;
  std::string kind;
  double from = 0, to = 0;
  std::string from_key = {};
  double from_factor = 1;
  double floor = 0;
  std::string to_key = {};
};

void record_fit(Value& summary, const FitRecord& f);

// An order fitted by fit_order(h, err, floor) to `data`: its window is the range of h it used.
void record_order_fit(Value& summary, const std::string& quantity, const FitData& data, const OrderFit& f,
                      double floor);

void record_unfittable(Value& summary, const std::string& quantity, const std::string& why);

}  // namespace geomint

#pragma once
// A convergence study, the order-plot twin of the work-precision set (analysis/work_precision_set.hpp):
// the errors of runs at steps h_j (per initial condition i where a study has several) in named columns of
// one CSV, and the orders fitted to them, in one shape for every order figure and table:
//   <csv>         [initial,] h, steps, then the columns in the order added: one row per run (i, h_j),
//   <orders_csv>  initial, name, order, log10_c, r2, points, h_min, h_max: one row per order, by initial
//                 condition, then in the order fitted (orders.csv unless a second study of the
//                 experiment writes one too),
//   summary     orders.<name> and fits.<name> of the first initial condition (with several,
//               orders_by_initial[i].<name> too), and for every fitted order its fit source
//               (runner/fits.hpp: the CSV, h, the column, the initial condition, the window, the floor).
// An order is the least-squares slope of log err against log h over the errors above the floor
// (fit_order, observables/order_fit.hpp): below it the errors are round-off (or a reference's
// accuracy, `floor_is`), and a series with fewer than 3 points above it fails the study (exit 4), or,
// where the study says so (OrderFitRule::required false), has "no order": null in the summary, no row.
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geomint/io/csv.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

class Context;

// The runs of a convergence study: at the steps h[j] of steps[j] steps each; `initials` > 0: as many
// initial conditions, each run at every h (an "initial" column, orders per initial condition), 0: one.
struct ConvergenceRuns {
  std::string csv;
  std::vector<double> h, steps;
  std::size_t initials = 0;
  std::string orders_csv = "orders.csv";
};

// How an order is fitted to a column: over the errors above floor(i) (initial condition i; below it the
// errors are `floor_is`) at h <= h_max (larger h: before the asymptotic range). `required`: fewer than 3
// such points fail the study (NumericalFailure); otherwise the order is null ("no order": nothing claimed).
struct OrderFitRule {
  std::function<double(std::size_t i)> floor;
  std::string floor_is = "round-off";
  double h_max = std::numeric_limits<double>::infinity();
  bool required = true;
};

class ConvergenceStudy {
 public:
  explicit ConvergenceStudy(ConvergenceRuns runs);

  // A column: value(i, j) of the run of initial condition i at step h[j] (i = 0 with one condition).
  ConvergenceStudy& column(const std::string& name, const std::function<double(std::size_t i, std::size_t j)>& value);
  // A column of one initial condition: by_h[j] at step h[j] (std::logic_error unless one value per step).
  ConvergenceStudy& column(const std::string& name, const std::vector<double>& by_h);
  // A flag column: 1 where run (i, j) was not made (a method beyond its stability bound, say), else 0. The
  // CSV declares it a flag (io/csv.hpp), so that the other columns may hold NaN ("no run") in its rows; a
  // fit leaves NaN out (fit_order fits finite errors only).
  ConvergenceStudy& flag(const std::string& name, const std::function<bool(std::size_t i, std::size_t j)>& marked);
  // The order `name` of column `column` against h over its errors above `floor` (of initial condition
  // i: floor_of(i)), for every initial condition; throws NumericalFailure naming the series, the
  // initial condition and what errors below the floor are (`floor_is`) where fewer than 3 are above.
  ConvergenceStudy& fit(const std::string& name, const std::string& column, double floor,
                        const std::string& floor_is = "round-off");
  ConvergenceStudy& fit(const std::string& name, const std::string& column,
                        const std::function<double(std::size_t i)>& floor_of, const std::string& floor_is = "round-off");
  ConvergenceStudy& fit(const std::string& name, const std::string& column, const OrderFitRule& rule);

  const std::vector<double>& h() const { return h_; }
  const std::vector<double>& values(const std::string& column, std::size_t i = 0) const;  // by h, of condition i
  const OrderFit& order(const std::string& name, std::size_t i = 0) const;  // (std::logic_error if "no order")
  bool has_order(const std::string& name, std::size_t i = 0) const;
  Value orders(std::size_t i = 0) const;  // {name: order, or null for "no order"} of initial condition i
  Value fits(std::size_t i = 0) const;    // {name: to_value(fit)}, the orders only

  Csv csv() const;         // <csv>
  Csv orders_csv() const;  // <orders_csv>
  // Writes both CSVs and adds the orders, fits and fit sources to the summary.
  void write(Context& ctx) const;

 private:
  struct Column {
    std::string name;
    std::vector<std::vector<double>> by_initial;  // [i][j]
  };
  struct Fit {
    std::size_t initial;
    std::string name, column;
    std::optional<OrderFit> fit;  // none: "no order" (fewer than 3 points, OrderFitRule::required false)
    double floor;
  };
  std::string csv_, orders_csv_;
  std::vector<double> h_, steps_;
  std::size_t initials_;
  bool initial_column_;
  std::vector<Column> columns_;
  std::vector<std::string> flags_;  // the names of the columns that are flags
  std::vector<Fit> fits_;  // in the order fitted
  std::vector<const Fit*> fits_by_initial() const;  // stably sorted by initial condition
  const Column& column_named(const std::string& name) const;
};

}  // namespace geomint

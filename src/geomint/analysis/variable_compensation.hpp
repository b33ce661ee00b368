#pragma once
// 000 Sec. 2, Figs 2 and 3: explicit Euler on a scalar equation y' = f(y), in y and in a compensating variable
// ybar = Psi(y) of transforms/variable_transform.hpp (Euler on the transformed equation (3), mapped back by
// Psi^{-1}); the exact curves; and the errors of both against the closed form and against odeint.
#include <array>
#include <cstdint>
#include <string>

#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/reference/odeint_reference.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/transforms/variable_transform.hpp"

namespace geomint {

constexpr double kCompensatedEulerReferenceTol = 1e-14;  // rtol = atol of the odeint reference of Figs 2-3
constexpr int kCompensatedEulerExactPoints = 400;        // resolution of the exact curves

// The trajectory of Euler in y and in ybar with the exact solution (CSV), the exact curves, and the errors.
struct CompensatedEulerFigure {
  Csv trajectory{{"j", "t", "y_exact", "y_euler", "y_compensated", "ybar_exact", "ybar_euler", "ybar_compensated"}};
  Csv exact{{"t", "y_exact", "ybar_exact"}};
  double euler_max_rel_err = 0;        // Euler in y against the exact solution
  double compensated_max_rel_err = 0;  // Euler in ybar, mapped back by Psi^{-1}
  // Against an independent solution, odeint's Bulirsch-Stoer on y' = f(y) (not the closed form,
  // which is built from the same expression as Psi^{-1}), and that reference's own error.
  double compensated_max_rel_err_odeint = 0, odeint_max_rel_err = 0;
};

// y' = sys.f(y) as the first-order system of reference_solution.
template <class Sys>
struct ScalarFirstOrder {
  const Sys& sys;
  std::array<double, 1> rhs(const std::array<double, 1>& y) const { return {sys.f(y[0])}; }
};

// Explicit Euler in y on sys and in ybar = Psi(y) on `field` (the transformed equation (3), or a
// field to be checked against it), both from y0.
template <class Sys, class Psi, class Field>
CompensatedEulerFigure compensated_euler_figure(const Sys& sys, const Psi& psi, const Field& field, double y0, double h,
                                                std::int64_t steps) {
  CompensatedEulerFigure fig;
  double y = y0, ybar = psi(y0);
  ErrorSeries euler_err, compensated_err, compensated_odeint_err, odeint_err;
  for (std::int64_t j = 0; j <= steps; ++j) {
    const double t = static_cast<double>(j) * h;
    const double exact = sys.exact(y0, t);
    const double y_comp = psi.inverse(ybar);
    const double reference =
        j == 0 ? y0
               : reference_solution(ScalarFirstOrder<Sys>{sys}, std::array<double, 1>{y0}, t, kCompensatedEulerReferenceTol,
                                    kCompensatedEulerReferenceTol)[0];
    euler_err.add(relative_error(y, exact));
    compensated_err.add(relative_error(y_comp, exact));
    compensated_odeint_err.add(relative_error(y_comp, reference));
    odeint_err.add(relative_error(reference, exact));
    fig.trajectory.row(j, t, exact, y, y_comp, psi(exact), psi(y), ybar);
    y = explicit_euler(sys, y, h);
    ybar = explicit_euler(field, ybar, h);
  }
  fig.euler_max_rel_err = euler_err.max_abs();
  fig.compensated_max_rel_err = compensated_err.max_abs();
  fig.compensated_max_rel_err_odeint = compensated_odeint_err.max_abs();
  fig.odeint_max_rel_err = odeint_err.max_abs();
  const double t_end = static_cast<double>(steps) * h;
  for (int i = 0; i <= kCompensatedEulerExactPoints; ++i) {
    const double t = t_end * i / kCompensatedEulerExactPoints;
    const double exact = sys.exact(y0, t);
    fig.exact.row(t, exact, psi(exact));
  }
  return fig;
}

// Writes <figure>.csv and <figure>_exact.csv, the errors of Euler in y and in ybar under <key>_* (the paper
// calls the latter an exact solution: published.toml), and the method of both runs (summary methods.<key>).
template <class Sys, class Psi>
void write_compensated_euler_figure(Context& ctx, const std::string& figure, const std::string& key, const Sys& sys,
                         const Psi& psi, double y0, double h, std::int64_t steps) {
  const CompensatedEulerFigure fig = compensated_euler_figure(sys, psi, TransformedODE{sys, psi}, y0, h, steps);  // 000 eq. (3)
  ctx.write(figure + ".csv", fig.trajectory);
  ctx.write(figure + "_exact.csv", fig.exact);
  ctx.summary["reproduced"][key + "_compensated_max_rel_err"] = fig.compensated_max_rel_err;
  ctx.summary["reproduced"][key + "_euler_max_rel_err"] = fig.euler_max_rel_err;
  ctx.summary["reproduced"][key + "_compensated_max_rel_err_odeint"] = fig.compensated_max_rel_err_odeint;
  ctx.summary["reproduced"][key + "_odeint_max_rel_err"] = fig.odeint_max_rel_err;
  ctx.summary["methods"][key] = labels_of({"explicit_euler"});  // (compensated_euler_figure steps it, in y and in ybar)
}

// --plan of Figs 2, 3: the steps of Euler in y and in ybar, and the trajectory CSV (8 columns) held in memory.
inline StudyPlan compensated_euler_plan(double steps, double figures) {
  const PlanRate& rate = plan_rate("scalar equation with reference");
  return {2 * figures * steps, 2 * figures * steps, (steps + 1) * 8 * kCsvCellBytes, rate.ns_per_step,
          "each step also integrates its odeint reference from t = 0 (not counted); " + rate.note};
}

}  // namespace geomint

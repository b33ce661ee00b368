// Beyond 003: the order of measure preservation (Cor. 4.3 of 003: Phi^(ell) preserves mu^(ell)_mod to
// O(h^(ell + 2))). Phi^(ell) of each discretization, ell in order_study.ells, on a tiny 600-cell cloud
// (radius order_study.radius) at each step of order_study.h: the peak-to-peak volume in its own
// measure mu^(ell)_mod over t <= ptp_window, and the order fitted to it against h above the
// round-off noise, measured by a probe at half the smallest step (analysis/convergence_study.hpp:
// order_study.csv, orders.csv; the probe: order_study_probe.csv); one checkpointed task per run.
#include <algorithm>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/convergence_study.hpp"
#include "geomint/analysis/phi_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/geometry/volume_series.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"

namespace geomint::measure_cloud {
namespace {

// ---- order of measure preservation: Phi^(ell) in its own mu^(ell)_mod on tiny clouds ----

void check_order_study(const Scene& s) {
  check_modified_orders(s, "order_study.ells");
  check_first_conformal_step(s, "order_study.h", s.reals("order_study.h"));
  if (s.real("order_study.t_end") < s.real("ptp_window")) s.reject("order_study.t_end", "must be at least ptp_window");
  check_at_least_one_step(s, "order_study.t_end", s.reals("order_study.h"), "max(order_study.h)");
}

// Task (k, e, i): method k, order es[e], step hs[i]; e == es.size() is the noise probe of
// method k: Phi^(max order) at half the smallest step, whose true volume error
// C (h/2)^(max order + 2) is negligible, so that what it shows is round-off.
struct Task {
  std::size_t k, e, i;
};

// The peak-to-peak volume of a task, and its Newton iterations and steps.
struct Result {
  double ptp;
  std::int64_t iterations, steps;
  auto fields() { return std::tie(ptp, iterations, steps); }
};

// The column (and order) of the peak-to-peak volumes of Phi^(ell) of discretization d: <label>_ell<ell>.
std::string column_name(Discretization d, int ell) { return discretization_name(d) + std::string("_ell") + std::to_string(ell); }

// The per-ell records of the orders the study fitted (column <label>_ell<k>): summary.orders.measure_ell<k>,
// fits.measure_ell<k> and their ranges, and the peak-to-peak at the largest step.
void record_per_ell(Context& ctx, const ConvergenceStudy& conv, const std::vector<Discretization>& methods,
                    const std::vector<int>& es) {
  const auto& hs = conv.h();
  const std::size_t i_max = static_cast<std::size_t>(std::max_element(hs.begin(), hs.end()) - hs.begin());
  const Value orders = conv.orders(), fits = conv.fits();
  for (int ell : es) {
    const std::string key = "measure_ell" + std::to_string(ell);
    Value o, f, points, at_h_max;
    for (const auto& m : methods) {
      const char* name = discretization_name(m);
      const std::string column = column_name(m, ell);
      o[name] = orders.at(column);
      at_h_max[name] = conv.values(column)[i_max];
      points[name] = conv.has_order(column) ? Value(conv.order(column).points) : Value();
      if (fits.contains(column)) f[name] = fits.at(column);
    }
    ctx.summary["orders"][key] = o;
    ctx.summary["ranges"][key] = method_ranges(o);
    ctx.summary["ranges"]["fit_points_" + key] = method_ranges(points);
    put_methods(ctx, "order_study_ptp_phi" + std::to_string(ell) + "_at_h_max", at_h_max);
    if (f.size() > 0) ctx.summary["fits"][key] = f;
  }
}

void run_order_study(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0] = particle_setup(s);
  check_modified_series(ctx, sys);
  const auto methods = scene_discretizations(s);
  put_run_facts(ctx, methods);
  const auto hs = s.reals("order_study.h");
  const auto es = modified_orders(s, "order_study.ells");
  const double t_end = s.real("order_study.t_end");
  const auto cloud = cloud_around(z0, six_hundred_cell_vertices(), s.real("order_study.radius"));
  std::vector<Task> tasks;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    for (std::size_t e = 0; e < es.size(); ++e)
      for (std::size_t i = 0; i < hs.size(); ++i) tasks.push_back({k, e, i});
    tasks.push_back({k, es.size(), 0});
  }
  const double h_probe = 0.5 * *std::min_element(hs.begin(), hs.end());
  const auto step_of = [&](const Task& T) { return T.e == es.size() ? h_probe : hs[T.i]; };
  std::vector<double> work;  // the longest runs first: a run's steps and snapshots both go as 1/h
  for (const Task& T : tasks) work.push_back(static_cast<double>(steps_within(t_end, step_of(T))));
  ctx.progress("order study: " + std::to_string(tasks.size()) + " cloud runs");
  const auto results = checkpointed_map<Result>(ctx, {"order_study", {}, 0, work}, tasks.size(), [&](std::size_t t) {
    const Task& T = tasks[t];
    const bool probe = T.e == es.size();
    const double hh = step_of(T);
    const int ell = probe ? max_modified_order : es[T.e];
    const std::int64_t n = steps_within(t_end, hh);
    const CloudRun run = cloud_phi(methods[T.k], sys, hh, ell, cloud, n);
    const ModifiedSeries ms(methods[T.k], sys, hh);
    std::vector<double> v;
    std::vector<HullFacet> facets;  // those of the previous snapshot, checked before they are taken
    for (const auto& snap : run.snapshots) {
      facets = cloud_hull(snap, facets);
      v.push_back(hull_volumes(snap, facets, ms, {ell})[0]);
    }
    return Result{relative_peak_to_peak(v, static_cast<std::size_t>(steps_within(s.real("ptp_window"), hh)) + 1), run.iterations,
                  run.steps};
  });
  for (const auto& r : results) count_newton(ctx, r.iterations, r.steps);
  const auto ptp = [&](std::size_t k, std::size_t e, std::size_t i) {  // (of task (k, e, i); e == es.size(): the probe)
    return results[k * (es.size() * hs.size() + 1) + e * hs.size() + i].ptp;
  };

  // The round-off probe (order_study_probe.csv: h, steps, <label>_ell<max order>): its largest
  // peak-to-peak is the noise.
  std::vector<std::string> probe_columns{"h", "steps"};
  for (const auto& m : methods) probe_columns.push_back(column_name(m, max_modified_order));
  Csv probe(probe_columns);
  probe << h_probe << steps_within(t_end, h_probe);
  double noise = 0;
  for (std::size_t k = 0; k < methods.size(); ++k) {
    probe << ptp(k, es.size(), 0);
    noise = std::max(noise, ptp(k, es.size(), 0));
  }
  probe.end_row();
  ctx.write("order_study_probe.csv", probe);
  // Points within a factor 2 of the measured round-off noise are left out of the fits.
  const double floor = 2 * noise;
  ctx.summary["reproduced"]["order_study_noise"] = noise;
  ctx.summary["reproduced"]["order_study_noise_floor"] = floor;
  ctx.summary["reproduced"]["order_study_h_probe"] = h_probe;
  ctx.summary["reproduced"]["order_study_h"] = {{"min", *std::min_element(hs.begin(), hs.end())}, {"max", *std::max_element(hs.begin(), hs.end())}};
  ctx.summary["reproduced"]["order_study_h_count"] = hs.size();

  // Record: order_study.csv (h, steps, <label>_ell<k>) and the orders <label>_ell<k> fitted over the
  // peak-to-peak volumes above the floor (fewer than 3 such points: no order, null).
  std::vector<double> steps;
  for (double h : hs) steps.push_back(static_cast<double>(steps_within(t_end, h)));
  ConvergenceStudy conv({.csv = "order_study.csv", .h = hs, .steps = steps});
  const OrderFitRule rule{.floor = [floor](std::size_t) { return floor; },
                          .floor_is = "round-off noise (the probe at half the smallest step)",
                          .required = false};
  for (std::size_t e = 0; e < es.size(); ++e)
    for (std::size_t k = 0; k < methods.size(); ++k) {
      const std::string column = column_name(methods[k], es[e]);
      conv.column(column, [&](std::size_t, std::size_t i) { return ptp(k, e, i); }).fit(column, column, rule);
    }
  conv.write(ctx);
  record_per_ell(ctx, conv, methods, es);
}

StudyPlan plan_order_study(const Scene& s) {
  const auto hs = s.reals("order_study.h");
  const double T = s.real("order_study.t_end"), M = static_cast<double>(s.texts("methods").size());
  const double ells_n = static_cast<double>(s.reals("order_study.ells").size()), h_min = *std::min_element(hs.begin(), hs.end());
  double steps = M * 120 * step_count_within(T, h_min / 2);  // the round-off probes
  for (double h : hs) steps += M * ells_n * 120 * step_count_within(T, h);
  StudyPlan p = phi_plan(steps, 2 * (step_count_within(T, h_min / 2) + 1) * 121 * kPointBytes, plan_rate("cloud order study"), "the snapshots of two runs at once");
  p.tasks = M * (ells_n * static_cast<double>(hs.size()) + 1);  // (a cloud run each)
  return p;
}

}  // namespace

Study order_study_study() {
  return {.name = "order_study",
          .about = "order of measure preservation (003 Cor. 4.3)",
          .files = {"order_study.csv", "orders.csv", "order_study_probe.csv"},
          .keys = Schema()
                      .real("order_study.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxCloudRadius},
                            "radius of its 600-cell clouds (small enough for no hull artefact)")
                      .real("order_study.t_end", positive(), "its end time")
                      .reals("order_study.ells", at_least(0), 1, "its truncation orders ell"),
          .reads = {"potential", "cloud.center", "methods", "order_study.h", "ptp_window", "checkpoint"},
          .run = run_order_study,
          .validate = check_order_study,
          .plan = plan_order_study};
}

}  // namespace geomint::measure_cloud

// 003 Figs 5.2 and 5.4: measure-weighted convex-hull volumes of the 600-cell cloud (circumradius
// cloud.radius around cloud.center) under Phi^(ell), ell in cloud.ells (Fig. 5.2: Phi^(4), Fig. 5.4:
// Phi^(0)), and under the reference flow, in every measure mu^(m)_mod; their peak-to-peak values over
// t <= ptp_window (Cor. 4.3 of 003: Phi^(ell) preserves mu^(ell)_mod to O(h^(ell + 2))). Beside the
// full cloud, the authors' cloud of the published figures (119 vertices), and the reference flow on a
// cloud of a tenth of the radius (the order in r of the hull artefact).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/phi_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/geometry/volume_series.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/fits.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint::measure_cloud {
namespace {

void check_volumes(const Scene& s) {
  check_modified_orders(s, "cloud.ells");
  check_first_conformal_step(s, "h", {s.real("h")});
  check_at_least_one_step(s, "t_end", {s.real("h")}, "h");
  if (s.real("ptp_window") > s.real("t_end")) s.reject("ptp_window", "must not exceed t_end");
}

std::string measure_name(int m) { return m == 0 ? "mu" : "mu" + std::to_string(m); }

// ---- Figs 5.2 and 5.4: hull volumes of the 600-cell cloud under Phi^(ell) and the reference ----

// The scene keys the reference paths of the volumes study depend on (their checkpoints).
const std::vector<std::string> kReferencePathKeys = {"potential", "cloud.center", "cloud.radius", "h",
                                                     "t_end",     "ptp_window",   "reference"};

// The hull volumes of the cloud under Phi^(ell) of each method, in every measure of `measures`
// ([method][measure][step]), written beside the reference's to the CSV `file` (t, reference_mu,
// <method>_<measure>...).
using Volumes = std::vector<std::vector<std::vector<double>>>;
Volumes phi_volumes(Context& ctx, const PhiStudy& p, const std::vector<Point4>& cloud, int ell, std::int64_t n,
                    const std::vector<int>& measures, const std::vector<double>& ref_volumes, const std::string& file) {
  const auto runs = cloud_phi_runs(p, cloud, ell, n);
  std::vector<std::string> cols{"t", "reference_mu"};
  for (Discretization d : p.methods)
    for (int m : measures) cols.push_back(std::string(discretization_name(d)) + "_" + measure_name(m));
  Csv csv(cols);
  Volumes vols(p.methods.size());
  for (std::size_t k = 0; k < p.methods.size(); ++k) {
    const ModifiedSeries ms(p.methods[k], p.sys, p.h);
    const auto per_step = snapshot_volumes(runs[k], ms, measures);
    vols[k].assign(measures.size(), std::vector<double>(per_step.size()));
    for (std::size_t j = 0; j < per_step.size(); ++j)
      for (std::size_t m = 0; m < measures.size(); ++m) vols[k][m][j] = per_step[j][m];
    count_newton(ctx, runs[k].iterations, runs[k].steps);
  }
  for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
    csv << static_cast<double>(j) * p.h << ref_volumes[j];
    for (std::size_t k = 0; k < p.methods.size(); ++k)
      for (std::size_t m = 0; m < measures.size(); ++m) csv << vols[k][m][j];
    csv.end_row();
  }
  ctx.write(file, csv);
  return vols;
}

// Figs 5.2, 5.4 for one cloud: the hull volumes under the reference flow and under Phi^(ell) for each
// ell of cloud.ells, in every measure mu^(m)_mod, m = 0, 2, .., max_modified_order, to t_end; CSV
// <prefix>phi<ell>.csv; summary.reproduced.<nest> (the cloud's own object, or reproduced itself for nest
// ""): the peak-to-peak values over t <= ptp_window, that of each method in its own measure less
// that of the reference, and the reference's relative volume at the window and at t_end.
void cloud_volumes(Context& ctx, const PhiStudy& p, const std::vector<Point4>& cloud, const std::string& prefix,
                   const std::string& nest) {
  const Scene& s = ctx.scene;
  std::vector<int> all_measures;
  for (int m = 0; m <= max_modified_order; m += 2) all_measures.push_back(m);
  const std::int64_t n = steps_within(s.real("t_end"), p.h);
  const std::size_t window = static_cast<std::size_t>(steps_within(s.real("ptp_window"), p.h)) + 1;
  const auto put_here = [&](const std::string& key, Value value) {
    if (nest.empty()) ctx.summary["reproduced"][key] = std::move(value);
    else ctx.summary["reproduced"][nest][key] = std::move(value);
  };
  ctx.progress("Figs 5.2, 5.4: reference, " + std::to_string(cloud.size()) + " points");
  const std::vector<double> ref_volumes = reference_volumes(ctx, nest.empty() ? "volumes.reference" : "volumes.reference_" + nest, kReferencePathKeys, p, cloud, n);
  const std::vector<double> ref_relative = relative_volumes(ref_volumes, ref_volumes.size());
  put_here("cloud_points", cloud.size());
  put_here("ptp_reference_mu", relative_peak_to_peak(ref_volumes, window));
  // Each peak-to-peak over t <= ptp_window of a column of <prefix>phi<ell>.csv (runner/fits.hpp).
  const std::string at = nest.empty() ? "reproduced." : "reproduced." + nest + ".";
  const auto record_ptp = [&](const std::string& quantity, const std::string& csv, const std::string& column,
                              const char* kind, const std::string& minus = "") {
    record_fit(ctx.summary, {.quantity = at + quantity, .data = {csv, "t", column, {}, minus}, .kind = kind, .from = 0,
                             .to = s.real("ptp_window"), .to_key = "ptp_window"});
  };
  put_here("reference_rel_volume_at_window", ref_relative[window - 1]);
  put_here("reference_rel_volume_at_t_end", ref_relative.back());

  for (int ell : modified_orders(s, "cloud.ells")) {
    ctx.progress("Figs 5.2, 5.4: Phi^(" + std::to_string(ell) + "), " + std::to_string(cloud.size()) + " points");
    const std::string file = prefix + "phi" + std::to_string(ell) + ".csv";
    const Volumes vols = phi_volumes(ctx, p, cloud, ell, n, all_measures, ref_volumes, file);
    if (ell == modified_orders(s, "cloud.ells").front()) record_ptp("ptp_reference_mu", file, "reference_mu", "relative_ptp");
    const std::string phi = "ptp_phi" + std::to_string(ell) + "_";
    const auto column = [&](std::size_t k, int m) { return std::string(discretization_name(p.methods[k])) + "_" + measure_name(m); };
    for (std::size_t m = 0; m < all_measures.size(); ++m) {
      Value ptp;
      for (std::size_t k = 0; k < p.methods.size(); ++k) {
        ptp[discretization_name(p.methods[k])] = relative_peak_to_peak(vols[k][m], window);
        record_ptp(phi + measure_name(all_measures[m]) + "." + discretization_name(p.methods[k]), file, column(k, all_measures[m]),
                   "relative_ptp");
      }
      put_methods(ctx, phi + measure_name(all_measures[m]), ptp, nest);
    }
    // the amplitude (half the ptp) in mu^(4)_mod, the quantity 003 reads off Fig. 5.2
    const auto mu4 = std::find(all_measures.begin(), all_measures.end(), 4);
    if (mu4 != all_measures.end()) {
      Value amp;
      for (std::size_t k = 0; k < p.methods.size(); ++k)
        amp[discretization_name(p.methods[k])] =
            relative_amplitude(vols[k][static_cast<std::size_t>(mu4 - all_measures.begin())], window),
        record_ptp("amplitude_phi" + std::to_string(ell) + "_mu4." + discretization_name(p.methods[k]), file, column(k, 4),
                   "relative_amplitude");
      put_methods(ctx, "amplitude_phi" + std::to_string(ell) + "_mu4", amp, nest);
    }
    // in its own measure mu^(ell)_mod, less the reference's relative volume (the hull artefact both share)
    const std::size_t own = static_cast<std::size_t>(std::find(all_measures.begin(), all_measures.end(), ell) - all_measures.begin());
    Value corrected;
    for (std::size_t k = 0; k < p.methods.size(); ++k)
      corrected[discretization_name(p.methods[k])] = relative_peak_to_peak_minus(vols[k][own], ref_volumes, window),
      record_ptp(phi + measure_name(ell) + "_minus_reference." + discretization_name(p.methods[k]), file, column(k, ell),
                 "relative_ptp", "reference_mu");
    put_methods(ctx, phi + measure_name(ell) + "_minus_reference", corrected, nest);
  }
  const Value& r = nest.empty() ? ctx.summary["reproduced"] : ctx.summary["reproduced"][nest];
  if (r.contains("ptp_phi0_mu4") && r.contains("ptp_phi4_mu4"))  // Fig. 5.4 against Fig. 5.2 in mu^(4)_mod
    put_methods(ctx, "ptp_mu4_phi0_over_phi4", ratio_per_method(r.at("ptp_phi0_mu4"), r.at("ptp_phi4_mu4")), nest);
  if (r.contains("ptp_phi0_mu4") && r.contains("ptp_phi0_mu"))  // Fig. 5.4: mu^(4)_mod against mu under Phi^(0)
    put_methods(ctx, "ptp_phi0_mu4_over_mu", ratio_per_method(r.at("ptp_phi0_mu4"), r.at("ptp_phi0_mu")), nest);
}

// The reference flow is run once more on the full cloud of this fraction of cloud.radius: the ratio
// of the two peak-to-peak values shows the order in r of the hull artefact (r^2: a factor 100).
constexpr double artefact_radius_fraction = 0.1;

void run_volumes(Context& ctx) {
  const Scene& s = ctx.scene;
  const PhiStudy p = phi_study(ctx);
  const double r = s.real("cloud.radius");
  const auto cloud = cloud_around(p.z0, six_hundred_cell_vertices(), r);
  cloud_volumes(ctx, p, cloud, "volumes_", "");
  const auto facets0 = hull_facets(cloud);
  ctx.summary["reproduced"]["hull_volume_initial_over_r4"] =
      hull_integral(cloud, facets0, cloud.front(), [](const Point4&) { return 1.0; }) / std::pow(r, 4);
  ctx.summary["reproduced"]["hull_volume_exact_over_r4"] = six_hundred_cell_volume(1.0);
  const auto small = cloud_around(p.z0, six_hundred_cell_vertices(), artefact_radius_fraction * r);
  const std::vector<double> small_volumes = reference_volumes(ctx, "volumes.reference_small", kReferencePathKeys, p, small, steps_within(s.real("ptp_window"), p.h));
  const double ptp_small = relative_peak_to_peak(small_volumes, small_volumes.size());
  ctx.summary["reproduced"]["artefact_radius_fraction"] = artefact_radius_fraction;
  ctx.summary["reproduced"]["ptp_reference_mu_small_radius"] = ptp_small;
  record_unfittable(ctx.summary, "reproduced.ptp_reference_mu_small_radius",
                    "the reference volumes of the small cloud are not written to a CSV (only their peak-to-peak is reported)");
  ctx.summary["reproduced"]["ptp_reference_mu_ratio_to_small_radius"] = ctx.summary.at("reproduced").at("ptp_reference_mu").number() / ptp_small;
  if (s.boolean("cloud.authors_cloud"))  // the cloud of the published figures
    cloud_volumes(ctx, p, cloud_around(p.z0, authors_six_hundred_cell_vertices(), r), "volumes_authors_", "authors_cloud");
}

StudyPlan plan_volumes(const Scene& s) {
  const double n = step_count_within(s.real("t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  const double runs = M * static_cast<double>(s.reals("cloud.ells").size()) + 1;  // + the reference
  const double points = 2 * 121.0;  // the full cloud and the authors' (at most)
  return phi_plan(runs * points * n, runs * (n + 1) * 121 * kPointBytes, plan_rate("cloud volumes"));
}

}  // namespace

Study volumes_study() {
  return {.name = "volumes",
          .makes = {{"003", "Fig. 5.2"}, {"003", "Fig. 5.4"}},
          .about = "measure-weighted convex-hull volumes of the 600-cell cloud under Phi^(ell) and the reference flow",
          .files = {"volumes_phi*.csv", "volumes_authors_phi*.csv"},
          .keys = Schema()
                      .real("t_end", positive(), "end time of the cloud runs (003 Figs 5.2, 5.4: 30)")
                      .real("cloud.radius", {.gt = 0.0, .ge = {}, .lt = {}, .le = kMaxCloudRadius},
                            "circumradius of the 600-cell cloud (003: 0.01)")
                      .boolean("cloud.authors_cloud",
                               "also the cloud of the code of 003 (it drops the vertex (0, 0, r, 0): 119 vertices + "
                               "centre), beside the full one: volumes_authors_phi*.csv, reproduced.authors_cloud")
                      .reals("cloud.ells", at_least(0), 1,
                             "truncation orders ell of the methods Phi^(ell) run on the cloud"),
          .reads = {"potential", "cloud.center", "h", "methods", "ptp_window", "checkpoint", "reference"},
          .run = run_volumes,
          .validate = check_volumes,
          .plan = plan_volumes,
          .makes_under = [](const Scene& s) {
            return s.text("potential") == "harmonic" ? std::vector<Item>{{"003", "Fig. 5.2"}, {"003", "Fig. 5.4"}}
                                                     : std::vector<Item>{};
          }};
}

}  // namespace geomint::measure_cloud

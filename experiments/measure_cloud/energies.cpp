// 003 Figs 5.3, 5.5, 5.6: the energies along Phi^(4) and Phi^(0) of each discretization from the
// centre cloud.center to energies.t_end -- H, K_E, the modified K^(4)_mod (4.2) and E^(4) (4.3) --
// and the distance to the reference flow (checked against one at tolerances 100x tighter); the drift
// of H and the error at the end under Phi^(0) over those under Phi^(4).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/phi_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint::measure_cloud {
namespace {

// ---- Figs 5.3, 5.5, 5.6: energies and errors along Phi^(4) and Phi^(0) from the centre ----

void run_energies(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  const std::string pot = potential_name(sys.potential);
  ctx.progress("Figs 5.3, 5.5, 5.6: energies");
  const std::int64_t n = steps_within(s.real("energies.t_end"), h);
  const auto ref = reference_samples(sys, z0, h, n, rtol, atol);
  const auto ref_tight =
      reference_samples(sys, z0, h, n, reference_check_factor * rtol, reference_check_factor * atol);
  double self_check = 0;
  for (std::size_t j = 0; j < ref.size(); ++j) self_check = std::max(self_check, phase_distance(from_array(ref[j]), from_array(ref_tight[j])));
  ctx.summary["reproduced"]["reference_self_check"] = self_check;
  ctx.summary["reproduced"]["reference_check_factor"] = reference_check_factor;
  ctx.summary["reproduced"]["energy_steps"] = n;
  const double H0 = sys.H(from_array(z0));
  ctx.summary["reproduced"]["H0"] = H0;
  Value H_end, err_end_of;
  for (int ell : {4, 0}) {
    const auto runs = distributed_map(methods.size(), [&](std::size_t k) { return run_phi(methods[k], sys, h, ell, z0, n); });
    std::vector<std::string> cols{"t", "reference_H"};
    for (Discretization d : methods)
      for (const char* q : {"H", "K_E", "K_mod", "E4", "err"}) cols.push_back(std::string(discretization_name(d)) + "_" + q);
    Csv csv(cols);
    const std::size_t M = methods.size();
    std::vector<ModifiedSeries> ms;
    std::vector<double> E_star, max_H(M, 0.0), max_K(M, 0.0), max_Kmod(M, 0.0), err_end(M), H_err_end(M);
    for (Discretization d : methods) ms.emplace_back(d, sys, h), E_star.push_back(ms.back().E(ell, from_array(z0)));
    for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
      csv << static_cast<double>(j) * h << sys.H(from_array(ref[j]));
      for (std::size_t k = 0; k < M; ++k) {
        const PhaseState<2> z = from_array(runs[k].z[j]);
        const double H = sys.H(z), K = sys.K(z, H0), Kmod = ms[k].K4(z, E_star[k]);
        const double err = phase_distance(z, from_array(ref[j]));
        csv << H << K << Kmod << ms[k].E(4, z) << err;
        max_H[k] = std::max(max_H[k], std::abs(H - H0)), max_K[k] = std::max(max_K[k], std::abs(K));
        max_Kmod[k] = std::max(max_Kmod[k], std::abs(Kmod));
        err_end[k] = err, H_err_end[k] = std::abs(H - H0);
      }
      csv.end_row();
    }
    Value Estar, jmax_H, jmax_K, jmax_Kmod, jerr_end, jH_end;
    for (std::size_t k = 0; k < M; ++k) {
      const char* name = discretization_name(methods[k]);
      Estar[name] = E_star[k] - H0, jmax_H[name] = max_H[k], jmax_K[name] = max_K[k], jmax_Kmod[name] = max_Kmod[k];
      jerr_end[name] = err_end[k], jH_end[name] = H_err_end[k];
    }
    for (const auto& r : runs) count_newton(ctx, r.iterations, n);
    ctx.write("energies_phi" + std::to_string(ell) + ".csv", csv);
    const std::string p = "phi" + std::to_string(ell);
    put_methods(ctx, "Estar_minus_H0_" + p, Estar);
    put_methods(ctx, "max_abs_H_err_" + p, jmax_H);
    put_methods(ctx, "max_abs_K_E_" + p, jmax_K);
    put_methods(ctx, "max_abs_K_mod4_" + p, jmax_Kmod);
    put_methods(ctx, "err_at_t_end_" + p, jerr_end);
    put_methods(ctx, "H_err_at_t_end_" + p, jH_end);
    H_end[std::to_string(ell)] = jH_end, err_end_of[std::to_string(ell)] = jerr_end;
  }
  // |H(T) - H0| and the error at T under Phi^(0) over those under Phi^(4)
  put_methods(ctx, pot + "_H_drift_ratio", ratio_per_method(H_end.at("0"), H_end.at("4")));
  put_methods(ctx, pot + "_err_ratio", ratio_per_method(err_end_of.at("0"), err_end_of.at("4")));
}

StudyPlan plan_energies(const Scene& s) {
  const double n = step_count_within(s.real("energies.t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  const double runs = M * (max_modified_order / 2 + 1) + 2;
  return phi_plan(runs * n, runs * (n + 1) * kPointBytes, plan_rate("cloud energies"));
}

}  // namespace

// (energies.t_end is also the end time of the cost runs: a shared key, main.cpp)
Study energies_study() {
  return {.name = "energies",
          .makes = {{"003", "Fig. 5.3"}, {"003", "Fig. 5.5"}, {"003", "Fig. 5.6"}},
          .about = "H, K_E, K^(4)_mod, E^(4) and the error against the reference along Phi^(4), Phi^(0)",
          .files = {"energies_phi*.csv"},
          .reads = {"potential", "cloud.center", "h", "methods", "energies", "reference"},
          .run = run_energies,
          .validate =
              [](const Scene& s) {
                check_at_least_one_step(s, "energies.t_end", {s.real("h")}, "h");
                check_first_conformal_step(s, "h", {s.real("h")});
              },
          .plan = plan_energies,
          // Fig 5.3 is the harmonic particle's, Figs 5.5 (Phi^(4)) and 5.6 (Phi^(0)) the free particle's (003 Sec. 5.3)
          .makes_under = [](const Scene& s) {
            const std::string pot = s.text("potential");
            return pot == "harmonic" ? std::vector<Item>{{"003", "Fig. 5.3"}}
                   : pot == "free"   ? std::vector<Item>{{"003", "Fig. 5.5"}, {"003", "Fig. 5.6"}}
                                     : std::vector<Item>{};
          }};
}

}  // namespace geomint::measure_cloud

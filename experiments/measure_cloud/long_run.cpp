// Beyond 003: the drift of H under Phi^(0) against Phi^(4) of each discretization from the centre
// cloud.center to long_run.t_end, and the distance of both to the reference flow there.
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/phi_study.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/discretizations.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/error_norms.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint::measure_cloud {
namespace {

// ---- long run: drift of H under Phi^(0) against Phi^(4) ----

void run_long_run(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto [sys, z0, rtol, atol, h, methods] = phi_study(ctx);
  ctx.progress("long run");
  const std::int64_t n = steps_within(s.real("long_run.t_end"), h);
  const std::size_t M = methods.size();
  const auto runs = distributed_map(2 * M, [&](std::size_t k) { return run_phi(methods[k % M], sys, h, k < M ? 0 : 4, z0, n); });
  std::vector<std::string> cols{"t"};
  for (int ell : {0, 4})
    for (Discretization d : methods) cols.push_back(std::string(discretization_name(d)) + "_H_phi" + std::to_string(ell));
  Csv csv(cols);
  const double H0 = sys.H(from_array(z0));
  for (std::size_t j = 0; j <= static_cast<std::size_t>(n); ++j) {
    csv << static_cast<double>(j) * h;
    for (const auto& r : runs) csv << sys.H(from_array(r.z[j])) - H0;
    csv.end_row();
  }
  ctx.write("long_run.csv", csv);
  const auto ref = reference_samples(sys, z0, s.real("long_run.t_end"), 1, rtol, atol).back();
  Value H0_end, H4_end, e0, e4;
  for (std::size_t k = 0; k < M; ++k) {
    const char* name = discretization_name(methods[k]);
    H0_end[name] = sys.H(from_array(runs[k].z.back())) - H0, H4_end[name] = sys.H(from_array(runs[M + k].z.back())) - H0;
    e0[name] = phase_distance(from_array(runs[k].z.back()), from_array(ref)),
    e4[name] = phase_distance(from_array(runs[M + k].z.back()), from_array(ref));
    count_newton(ctx, runs[k].iterations + runs[M + k].iterations, 2 * n);
  }
  put_methods(ctx, "long_H_err_phi0", H0_end), put_methods(ctx, "long_H_err_phi4", H4_end);
  put_methods(ctx, "long_err_phi0", e0), put_methods(ctx, "long_err_phi4", e4);
}

StudyPlan plan_long_run(const Scene& s) {
  const double n = step_count_within(s.real("long_run.t_end"), s.real("h")), M = static_cast<double>(s.texts("methods").size());
  return phi_plan(2 * M * n, 2 * M * (n + 1) * kPointBytes, plan_rate("cloud long run"));
}

}  // namespace

Study long_run_study() {
  return {.name = "long_run",
          .about = "H under Phi^(0) and Phi^(4) to long_run.t_end",
          .files = {"long_run.csv"},
          .keys = Schema().real("long_run.t_end", positive(), "end time of the long run of Phi^(0) and Phi^(4)"),
          .reads = {"potential", "cloud.center", "h", "methods", "reference"},
          .run = run_long_run,
          .validate =
              [](const Scene& s) {
                check_at_least_one_step(s, "long_run.t_end", {s.real("h")}, "h");
                check_first_conformal_step(s, "h", {s.real("h")});
              },
          .plan = plan_long_run};
}

}  // namespace geomint::measure_cloud

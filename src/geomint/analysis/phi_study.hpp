#pragma once
// A study of the methods Phi^(ell) of 003 (4.5) on the nonholonomic particle (systems/nonholonomic_particle.hpp,
// systems/nonholonomic_modified_series.hpp): what it reads from the scene (the potential, the centre cloud.center of
// its clouds and start of its trajectories, the reference tolerances, the step, the discretizations), its checks
// before any work, the hull volumes of its clouds in the measures mu^(m)_mod, what it reports besides its results
// (the modified series checked, the Newton iterations per step) and its --plan.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/geometry/hull_volume.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {

// The clouds are neighbourhoods of cloud.center (003: radius 0.01, 1e-5 and 0.3): from radius 3 on, the conformal
// step's Newton iteration fails at h = 0.25 and the reference flow of far points overflows, leaving no hull.
constexpr double kMaxCloudRadius = 1.0;

// The truncation orders ell of the scene's list `key`, and the check that each is even, 0 <= ell <= max_modified_order.
std::vector<int> modified_orders(const Scene& s, const char* key);
void check_modified_orders(const Scene& s, const char* key);

// What every study reads: the particle (potential) and the centre of the clouds (cloud.center).
struct ParticleSetup {
  NonholonomicParticle sys;
  std::array<double, 4> z0;
};
ParticleSetup particle_setup(const Scene& s);

struct ReferenceTolerances {  // of the reference flow: reference.rtol, reference.atol
  double rtol, atol;
};
ReferenceTolerances reference_tolerances(const Scene& s);

// The conformal step's Newton iteration converges at each step of `key` from the centre cloud.center (one step of each
// scene discretization, E = H(z0)): where it does not, every run of the study would fail in its first step.
void check_first_conformal_step(const Scene& s, const char* key, const std::vector<double>& hs);

// Newton iterations per step, over the studies of this run that ran Phi^(ell) (one run per process): adds a study's
// iterations and steps, and reports the mean so far (summary.timing.newton_iterations_mean).
void count_newton(Context& ctx, std::int64_t iterations, std::int64_t steps);

// The generated modified quantities against independent reference values at h = 0.25 for this potential
// (summary.reproduced.golden_max_rel_err, max_modified_order): every study that relies on them says so.
void check_modified_series(Context& ctx, const NonholonomicParticle& sys);

// The inputs of a study that runs Phi^(ell) at the step h and compares them with the reference flow; reading them
// checks the modified series, reports the run facts and h^(ell + 2) of Cor. 4.3 (summary.reproduced.h_pow_ell_plus_2).
struct PhiStudy {
  NonholonomicParticle sys;
  std::array<double, 4> z0;
  double rtol, atol, h;
  std::vector<Discretization> methods;
};
PhiStudy phi_study(Context& ctx);

// The volume of conv(points), bounded by `facets`, in each measure mu^(ell)_mod of density 1/N^(ell)_mod (003 (4.9)),
// ell in `measures` (0: mu itself, density 1/N).
std::vector<double> hull_volumes(const std::vector<Point4>& points, const std::vector<HullFacet>& facets,
                                 const ModifiedSeries& ms, const std::vector<int>& measures);

// The runs of a study, compiled once (phi_study.cpp; each splits its tasks across threads and MPI ranks):
// Phi^(ell) of each of p.methods from each point of `cloud`, n steps of p.h (one task per method);
std::vector<CloudRun> cloud_phi_runs(const PhiStudy& p, const std::vector<Point4>& cloud, int ell, std::int64_t n);
// hull_volumes of each snapshot of a cloud's run (one task per snapshot), each hull checked against the first's;
std::vector<std::vector<double>> snapshot_volumes(const CloudRun& run, const ModifiedSeries& ms, const std::vector<int>& measures);
// the paths of the points of `cloud` under the reference flow at t_j = j dt, j = 0..n (one task per point);
std::vector<std::vector<Point4>> reference_paths(const NonholonomicParticle& sys, const std::vector<Point4>& cloud, double dt,
                                                 std::int64_t n, double rtol, double atol);
// the hull volumes in mu of the images of `cloud` under the reference flow at t_j = j p.h, j = 0..n, the paths kept in
// the checkpoint `name` of the scene keys `keys` (runner/checkpoint.hpp; one task per point);
std::vector<double> reference_volumes(Context& ctx, const std::string& name, const std::vector<std::string>& keys,
                                      const PhiStudy& p, const std::vector<Point4>& cloud, std::int64_t n);
// along Psi_{h,E} of each of `methods` from z0 with E fixed, the symplecticity defect max |J^T Omega J - Omega|
// (observables/symplecticity.hpp) of the Jacobian J of Psi^j (systems/nonholonomic_variational.hpp), j = 0..n.
std::vector<std::vector<double>> psi_symplecticity_defects(const std::vector<Discretization>& methods,
                                                           const NonholonomicParticle& sys, const Point4& z0, double h,
                                                           double E, std::int64_t n);

// --plan of a study: its rate (experiments/plan_rates.toml, measured on its wall time in the paper scenes, hull volumes,
// references and timed repeats included) and force evaluations, Newton iterations, 3.86 per step
// (timing.newton_iterations_mean there); the odeint reference samples count as steps.
constexpr double kPointBytes = 4 * 8;
StudyPlan phi_plan(double steps, double memory, const PlanRate& rate, const std::string& extra = {});

}  // namespace geomint

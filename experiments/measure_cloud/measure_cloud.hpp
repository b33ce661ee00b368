#pragma once
// measure_cloud: 003 (García-Naranjo & Vermeeren) Sec. 5, Figs 5.1-5.6 -- the nonholonomic particle
// as a conformally Hamiltonian system, discretized by the variational integrators Psi_{h,E} of the
// five discrete Lagrangians (5.1) with E = E^(ell)(z_0) per trajectory (the method Phi^(ell), (4.5)).
// One study per file beside this one (main.cpp lists them); here what several of them share: the
// discretizations the scene names, the checks across keys, the reference flow, the method Phi^(ell)
// on single points and on clouds, hull volumes, what the studies report through ctx.summary, and
// the --plan constants.
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/core/integrate.hpp"  // steps_within, step_count_within
#include "geomint/core/state.hpp"
#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/results.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {
class ModifiedSeries;  // systems/nonholonomic_modified_series.hpp
}  // namespace geomint

namespace geomint::measure_cloud {

using Z = PhaseState<2>;

// The studies, in the order they run.
Study shape_study();        // 003 Fig 5.1               shape.cpp
Study volumes_study();      // 003 Figs 5.2, 5.4         volumes.cpp
Study energies_study();     // 003 Figs 5.3, 5.5, 5.6    energies.cpp
Study long_run_study();     // H under Phi^(0) and Phi^(4) to long_run.t_end   long_run.cpp
Study order_study_study();  // order of measure preservation (003 Cor. 4.3)    order_study.cpp
Study cost_study();         // error against wall time; Phi^(4) against Phi^(0) and RK4   cost.cpp

// ---- the discretizations (5.1): the registry's conformal methods whose label names one ----

// What `methods` admits: the registry names (conformal_M, ...) and, as an older spelling, the labels (M, ...).
std::vector<std::string> method_choices();

// The scene's methods; the schema admits only the names and labels above.
std::vector<Discretization> scene_methods(const Scene& s);

// The clouds are neighbourhoods of cloud.center (003: radius 0.01, 1e-5 and 0.3): from radius 3 on, the conformal
// step's Newton iteration fails at h = 0.25 and the reference flow of far points overflows, leaving no hull.
constexpr double kMaxRadius = 1.0;

std::vector<int> ells(const Scene& s, const char* key);

// ---- checks across keys, per study ----

void check_ells(const Scene& s, const char* key);

// A run to s.real(key) takes at least one step of each length in `steps`.
void check_at_least_one_step(const Scene& s, const char* key, const std::vector<double>& steps, const char* what);

// The conformal step's Newton iteration converges at each step of `key` from the centre cloud.center (one step of each
// scene method, E = H(z0)): where it does not, every run of the study would fail in its first step.
void check_first_step(const Scene& s, const char* key, const std::vector<double>& hs);

Z as_state(const Point4& a);

// ---- reference flow: odeint Bulirsch-Stoer on (3.8), sampled at t_j = j dt --------
std::vector<Point4> reference_samples(const NonholonomicParticle& sys, const Point4& z0, double dt, std::int64_t n,
                                      double rtol, double atol);

// The reference is checked against a second one with both tolerances multiplied by this factor.
constexpr double reference_check_factor = 1e-2;

// ---- the method Phi^(ell): Psi_{h,E*} with E* = E^(ell)(z0) (003 eq. (4.5), E fixed at z0) --
struct Trajectory {
  std::vector<Point4> z;        // z_0 .. z_n
  std::int64_t iterations = 0;  // Newton iterations, summed over the steps
  auto fields() { return std::tie(z, iterations); }  // (a record of runner/distributed_map.hpp)
};

Trajectory run_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell, const Point4& z0,
                   std::int64_t n);

// ---- clouds: snapshots[j][i] is point i at step j; point 0 is the image of the centre --
struct CloudRun {
  std::vector<std::vector<Point4>> snapshots;
  std::int64_t iterations = 0, steps = 0;
  auto fields() { return std::tie(snapshots, iterations, steps); }
};

CloudRun transpose(const std::vector<Trajectory>& per_point);

CloudRun cloud_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                   const std::vector<Point4>& cloud, std::int64_t n);

// hull_facets(points, known); a cloud that left the domain of the hull (not finite, degenerate) is a
// NumericalFailure. `known`: the facets of another image of the same cloud, checked and taken
// without Qhull when they bound this one (bounds_hull).
std::vector<HullFacet> cloud_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& known = {});

// Volume of conv(points), bounded by `facets`, for each density 1/N^(ell)_mod, ell in `measures` (0: mu itself, 1/N).
std::vector<double> hull_volumes(const std::vector<Point4>& points, const std::vector<HullFacet>& facets,
                                 const ModifiedSeries& ms, const std::vector<int>& measures);

// The centre z0 and the vertices of a 600-cell of circumradius `radius` around it (the centre
// first: the apex of the hull triangulation).
std::vector<Point4> cloud_around(const Point4& z0, const std::vector<Point4>& vertices, double radius);

// ---- what every study reports through ctx.summary ----

// Sets summary[section][key], indexing ctx.summary afresh (no reference into it outlives an insertion).
void put(Context& ctx, const char* section, const std::string& key, Value value);

// The ranges of a {label: number} object over the methods: "all", and those of each quadrature of N
// (003 (5.1), the first letter of the label): "N_midpoint" (M, MT) and "N_trapezoidal" (TM, TT, T).
// A group is left out if one of its values is not a finite number (an order without a fit).
Value method_ranges(const Value& per_method);

// Sets summary.reproduced.<key> (or summary.reproduced.<nest>.<key>) to a {label: number} object and
// summary.ranges.<key> (summary.ranges.<nest>.<key>) to its method_ranges.
void put_methods(Context& ctx, const std::string& key, Value per_method, const std::string& nest = "");

// {label: a[label] / b[label]} over the labels of a.
Value ratio_per_method(const Value& a, const Value& b);

// What every study reports besides its results: the thread count and the labels of the methods it
// runs (the CSV columns; figure_values.gp: summary_words('methods')).
void put_run_facts(Context& ctx, const std::vector<Discretization>& methods);

// Newton iterations per step, over the studies of this run that ran Phi^(ell) (one run per process):
// adds a study's iterations and steps, and reports the mean so far.
void count_newton(Context& ctx, std::int64_t iterations, std::int64_t steps);

// The generated modified quantities (E^(ell), N^(ell)_mod, K^(4)_mod) against independent
// reference values at h = 0.25, for this potential: every study that relies on them says so.
void check_modified_series(Context& ctx, const NonholonomicParticle& sys);

// What every study reads: the particle and the centre of the clouds (the start of every single trajectory).
struct Setup {
  NonholonomicParticle sys;
  Point4 z0;
};

Setup setup(const Scene& s);

struct Tolerances {  // of the reference flow
  double rtol, atol;
};

Tolerances reference_tolerances(const Scene& s);

// The inputs of a study that runs the methods Phi^(ell) at the step h and compares them with the
// reference flow; reading them checks the modified series the methods rely on.
struct PhiStudy {
  NonholonomicParticle sys;
  Point4 z0;
  double rtol, atol, h;
  std::vector<Discretization> methods;
};

PhiStudy phi_study(Context& ctx);

// ---- what each study costs (--plan), from the scene before any work ----
// ns per step and thread of each study: its rate in experiments/plan_rates.toml, measured on its wall time in
// the paper scenes (the hull volumes, references and timed repeats included); force evaluations: Newton
// iterations, 3.86 per step (timing.newton_iterations_mean there). The odeint reference samples count as steps.
constexpr double kPointBytes = 4 * 8;

StudyPlan make_plan(double steps, double memory, const PlanRate& rate, const std::string& extra = {});

}  // namespace geomint::measure_cloud

// energy_map: 000 (Takacs & Fulop 2025) Fig. 6 -- the RMS energy error (50)
// of symplectic Euler (42)-(43) on the elastic pendulum in Cartesian (73)
// and polar (72) coordinates, over a grid of initial positions at rest; the
// analytic boundary of the polar runs' divergence; and the first integrals of
// Section 5.2 (free particle).
//
// Studies: map (Fig. 6, with a checkpoint for --resume), first_integrals
// (Sec. 5.2), timing (the batched kernel against the straightforward scalar
// loop), cost (work-precision of the two coordinate systems on a few starts).
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "geomint/core/integrate.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/io/atomic_file.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/observables/order_fit.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/distributed_map.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/analysis/work_precision.hpp"
#include "geomint/runner/timing.hpp"
#include "geomint/runner/timing_report.hpp"
#include "geomint/sweep/energy_map.hpp"
#include "geomint/sweep/energy_map_statistics.hpp"
#include "geomint/sweep/parallel_map.hpp"
#include "geomint/systems/elastic_pendulum.hpp"
#include "geomint/transforms/polar.hpp"

using namespace geomint;
using json = nlohmann::ordered_json;

namespace {

// The scene keys the map depends on (the map study adds `checkpoint`, the timing study `timing`).
const std::vector<std::string> kMapKeys = {"dt", "t_max", "grid", "pendulum", "divergence"};

// Inclusive linspace; n = 1 gives the single value lo.
std::vector<double> linspace(double lo, double hi, std::int64_t n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = n == 1 ? lo : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  return v;
}

struct Point {
  EnergyMapPoint cart, polar;
};


// A batch's points as a checkpoint record (runner/checkpoint.hpp): eps and diverge_step per point, eps
// of a diverged point (NaN by contract) stored as 0 and restored from its diverge_step >= 0.
struct BatchCodec {
  void encode(const std::vector<EnergyMapPoint>& batch, std::vector<double>& out) const {
    for (const EnergyMapPoint& p : batch) {
      if (p.diverge_step >= 0 && !std::isnan(p.eps)) throw std::logic_error("energy_map: a diverged point with a finite eps");
      out.push_back(p.diverge_step >= 0 ? 0.0 : p.eps), out.push_back(static_cast<double>(p.diverge_step));
    }
  }
  std::vector<EnergyMapPoint> decode(std::span<const double> v) const {
    if (v.size() != 2 * kEnergyMapBatch)
      throw std::invalid_argument("a record of " + std::to_string(v.size()) + " values, not " + std::to_string(2 * kEnergyMapBatch));
    std::vector<EnergyMapPoint> batch(kEnergyMapBatch);
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const double step = v[2 * i + 1];
      if (!(step >= -1 && step == std::floor(step)))
        throw std::invalid_argument("point " + std::to_string(i) + ": diverge_step " + std::to_string(step) + " is not a step");
      batch[i].diverge_step = static_cast<std::int64_t>(step);
      batch[i].eps = step >= 0 ? std::numeric_limits<double>::quiet_NaN() : v[2 * i];
    }
    return batch;
  }
};

// The map's grid of initial positions at rest, padded to whole batches (x0 = y0 = 0 fills:
// marked dead at once), and its parameters.
struct MapSetup {
  std::vector<double> xs, ys;
  std::size_t npoints, nbatches;
  std::vector<double> x0, y0;  // nbatches * kEnergyMapBatch, x fastest
  EnergyMapParams P;
};

MapSetup map_setup(const Scene& s) {
  MapSetup m;
  m.xs = linspace(s.real("grid.x_min"), s.real("grid.x_max"), s.integer("grid.nx"));
  m.ys = linspace(s.real("grid.y_min"), s.real("grid.y_max"), s.integer("grid.ny"));
  m.npoints = m.xs.size() * m.ys.size();
  m.nbatches = (m.npoints + kEnergyMapBatch - 1) / kEnergyMapBatch;
  m.x0.assign(m.nbatches * kEnergyMapBatch, 0.0), m.y0.assign(m.nbatches * kEnergyMapBatch, 0.0);
  for (std::size_t i = 0; i < m.npoints; ++i) m.x0[i] = m.xs[i % m.xs.size()], m.y0[i] = m.ys[i / m.xs.size()];
  const double dt = s.real("dt");
  m.P = {s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g"), dt,
         steps_to(s.real("t_max"), dt), s.real("divergence.blowup")};
  return m;
}

// The batched kernel on the batches batch(0), ..., batch(count - 1) of the grid, in parallel.
template <class BatchIndex>
std::vector<std::vector<EnergyMapPoint>> run_batches(EnergyMapKernel kernel, Coordinates c, const MapSetup& g,
                                                     std::size_t count, BatchIndex batch) {
  return parallel_map(count, [&](std::size_t b) {
    std::vector<EnergyMapPoint> out(kEnergyMapBatch);
    const std::size_t at = batch(b) * kEnergyMapBatch;
    kernel(c, g.P, &g.x0[at], &g.y0[at], out.data());
    return out;
  });
}

// The grid spacing of an inclusive linspace (0 for a single value).
double spacing(const std::vector<double>& v) { return v.size() > 1 ? (v.back() - v.front()) / static_cast<double>(v.size() - 1) : 0.0; }

// map_grid.csv: x0, y0, H0 of map.csv in grid scans, a blank line between the rows of the grid (the
// form gnuplot contours: figures/energy_map_fig6.gp draws the H_0 isolines from it).
std::string grid_scans(const MapSetup& g, const std::vector<EnergyMapRow>& rows) {
  std::string out = "x0,y0,H0\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out += format_double(rows[i].x0) + "," + format_double(rows[i].y0) + "," + format_double(rows[i].H0) + "\n";
    if ((i + 1) % g.xs.size() == 0 && i + 1 < rows.size()) out += "\n";
  }
  return out;
}

// The largest |H of (72) - H of (73)| at rest over the initial positions of the map (the origin
// aside), with (r, theta) from (x, y) by `to_polar`: 000 eq. (63), either half.
template <class ToPolar>
double polar_mismatch(const ElasticPendulumParams& p, const std::vector<EnergyMapRow>& rows, ToPolar to_polar) {
  const ElasticPendulumPolarWithGravity polar{p.m, {SpringPolarTerm{p.k, p.l}, GravityPolarTerm{p.m, p.g}}};
  double worst = 0;
  for (const EnergyMapRow& row : rows)
    if (std::hypot(row.x0, row.y0) > 0)
      worst = std::max(worst, std::abs(polar.H(to_polar(make_state<2>(Vec<2>(row.x0, row.y0), Vec<2>(0.0, 0.0)))) - row.H0));
  return worst;
}

// The column x0 = 0 above the pivot (theta0 = pi): in Cartesian coordinates the force on x is
// proportional to x (73), so x stays exactly 0 and the run is a radial oscillation on the unstable
// upright line; in polar coordinates theta0 = fl(pi) has sin(theta0) ~ 1.2e-16, and the run falls
// over like its neighbours. Checked at the column point nearest (0, -l): the Cartesian run started
// at x0 = r0 sin(fl(pi)), the polar run's own start, against both runs of the map there.
json upright_column(const MapSetup& g, const std::vector<Point>& points) {
  const auto zero = std::find(g.xs.begin(), g.xs.end(), 0.0);
  if (zero == g.xs.end() || g.ys.front() >= 0) return nullptr;
  const auto nearest = std::min_element(g.ys.begin(), g.ys.end(), [&](double a, double b) {
    return (a < 0 ? std::abs(a + g.P.l) : std::numeric_limits<double>::infinity()) <
           (b < 0 ? std::abs(b + g.P.l) : std::numeric_limits<double>::infinity());
  });
  const double y0 = *nearest;
  const std::size_t i = static_cast<std::size_t>(nearest - g.ys.begin()) * g.xs.size() +
                        static_cast<std::size_t>(zero - g.xs.begin());
  const double x_polar = std::abs(y0) * std::sin(std::atan2(0.0, y0));  // 000 eq. (63): x = r sin(theta)
  const EnergyMapPoint tilted = energy_map_scalar(Coordinates::cartesian, g.P, x_polar, y0);
  const auto value = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  const auto difference = [&](std::size_t at) { return value(points[at].cart.eps - points[at].polar.eps); };
  return {{"y0", y0},
          {"eps_difference", difference(i)},
          {"eps_difference_neighbour", i + 1 < g.npoints && zero + 1 != g.xs.end() ? difference(i + 1) : json(nullptr)},
          {"eps_cartesian", value(points[i].cart.eps)},
          {"eps_polar", value(points[i].polar.eps)},
          {"x0_of_polar_start", x_polar},
          {"eps_cartesian_from_polar_start", value(tilted.eps)}};
}

// What the map study measured, for the timing study of the same run.
struct MapCost {
  bool ran = false;
  double wall_cart = 0, wall_polar = 0;  // wall time of the batched kernel, per coordinate system
  double steps_cart = 0, steps_polar = 0;  // trajectory-steps computed in this run (a resumed run: the rest)
};

const char* coordinates_name(Coordinates c) { return c == Coordinates::cartesian ? "cartesian" : "polar"; }

Schema schema() {
  Schema s;
  s.integer("grid.nx", at_least(1), "initial x0 values (inclusive linspace)")
      .integer("grid.ny", at_least(1), "initial y0 values")
      .real("grid.x_min", any_finite(), "")
      .real("grid.x_max", any_finite(), "")
      .real("grid.y_min", any_finite(), "")
      .real("grid.y_max", any_finite(), "")
      .real("pendulum.l", positive(), "relaxed spring length l (000 eqs. (72)-(73))")
      .real("pendulum.m", positive(), "mass m")
      .real("pendulum.k", positive(), "spring stiffness k")
      .real("pendulum.g", non_negative(), "gravity g (y points down)")
      .real("dt", positive(),
            "step of symplectic Euler (000 Fig. 6: 0.2); dt sqrt(k/m) below its oscillatory bound (geomint-methods)")
      .real("t_max", positive(), "end time (000 Fig. 6: 50 000); a multiple of dt")
      .real("divergence.blowup", positive(), "|H_j - H_0| above this marks a run diverged")
      .real("map_statistics.ring_half_width", positive(),
            "initial radii |r(0) - l| < ring_half_width * l are counted apart for where polar is the more accurate")
      .reals("first_integrals.h", positive(), 3, "steps for the change of p_x per step in polar coordinates")
      .real_rows("first_integrals.initial", 4, any_finite(), 1, "free-particle states [x, y, px, py], x, y not both 0")
      .integer("first_integrals.steps", at_least(1), "steps of the Cartesian angular-momentum run")
      .integer("checkpoint.stop_after", non_negative(),
               "stop after this many rounds (1/32 of the batches of 64 starts, Cartesian then polar), leaving a "
               "checkpoint for --resume (0: run to the end)")
      .real("checkpoint.interval", non_negative(), "seconds between checkpoint saves (0: after every round); a SIGKILL loses at most this much work")
      .integer("timing.repeats", at_least(1),
               "timed runs (>= 10 ms each) per measurement; the minimum is the estimate, the spread is reported")
      .integer("timing.scalar_points", at_least(1), "initial conditions timed with the scalar reference loop")
      .integer("timing.scalar_steps", at_least(1), "steps of each scalar timing run")
      .integer("timing.kernel_batches", at_least(1),
               "batches of 64 trajectories (evenly spaced over the grid, t_max/dt steps each) on which the batched "
               "kernel is timed when the map study does not run in the same process")
      .real("timing.target.cartesian", positive(), "the time per trajectory-step and core set as the goal of the Cartesian kernel [ns]")
      .real("timing.target.polar", positive(), "the same for the polar kernel [ns]")
      .reals("timing.ceiling.cartesian", positive(), 2,
             "[low, high] hardware ceiling of the Cartesian kernel [ns per trajectory-step and core]: an estimate from "
             "performance measurements (bench/README.md), not measured by the run")
      .reals("timing.ceiling.polar", positive(), 2, "the same for the polar kernel")
      .real_rows("cost.starts", 2, any_finite(), 1,
                 "initial positions [x0, y0] (at rest) of the work-precision study, inside the polar runs' "
                 "divergence boundary")
      .reals("cost.dt", positive(), 3, "steps of symplectic Euler in the work-precision study; each divides cost.t_end")
      .real("cost.t_end", positive(), "end time of the work-precision runs (eq. (50) over [0, t_end])")
;
  return s;
}

// ---- checks across keys, per study ----

void check_map(const Scene& s) {
  if (!(s.real("grid.x_max") >= s.real("grid.x_min"))) s.reject("grid.x_max", "must be >= grid.x_min");
  if (!(s.real("grid.y_max") >= s.real("grid.y_min"))) s.reject("grid.y_max", "must be >= grid.y_min");
  const double dt = s.real("dt"), omega = std::sqrt(s.real("pendulum.k") / s.real("pendulum.m"));
  const double bound = method_info("symplectic_euler_pq").oscillatory_bound;
  if (!(dt * omega < bound))
    s.reject("dt", "symplectic Euler is unstable for dt sqrt(k/m) >= " + format_double(bound) +
                       " (methods/registry.hpp): dt < " + format_double(bound / omega));
  const double n = std::round(s.real("t_max") / dt);
  if (n < 1 || std::abs(n * dt - s.real("t_max")) > 1e-9 * s.real("t_max"))
    s.reject("t_max", "must be a positive multiple of dt = " + format_double(dt));
  if (!(n <= max_exact_count))  // steps are counted in int64 and t = j dt
    s.reject("t_max", "t_max / dt must be at most 2^53 steps: t_max <= " + format_double(max_exact_count * dt));
}

void check_timing(const Scene& s) {
  check_map(s);
  for (const char* key : {"timing.ceiling.cartesian", "timing.ceiling.polar"})
    if (s.reals(key).size() != 2 || !(s.reals(key)[0] <= s.reals(key)[1])) s.reject(key, "must be [low, high] with low <= high");
}

void check_first_integrals(const Scene& s) {
  for (const auto& row : s.real_rows("first_integrals.initial"))
    if (row[0] == 0.0 && row[1] == 0.0) s.reject("first_integrals.initial", "polar coordinates are singular at x = y = 0");
}

// ---- plans (--plan, and the counts checked before any work): counts in double from the scene ----

// Measured on the machine of the paper-scene results (summary.json timing, 2 threads): the batched kernel
// 0.47 (Cartesian) and 1.05 (polar) ns per trajectory-step and core; the scalar loop about 20-29 ns per step.
constexpr double kKernelNsPerStep = 0.76;  // mean of the two batched kernels
constexpr double kScalarNsPerStep = 25.0;  // the scalar loop (energy_map_scalar, symplectic Euler step loops)
const char* const kNsNote = "ns per step measured from the paper-scene summary.json timing";

struct GridCount {
  double points, batches, steps;  // grid points, batches of 64 (padded), steps per trajectory (t_max / dt)
};
GridCount grid_count(const Scene& s) {
  const double points = static_cast<double>(s.integer("grid.nx")) * static_cast<double>(s.integer("grid.ny"));
  return {points, std::ceil(points / kEnergyMapBatch), std::round(s.real("t_max") / s.real("dt"))};
}

StudyPlan plan_map(const Scene& s) {
  const GridCount n = grid_count(s);
  const double padded = n.batches * kEnergyMapBatch;
  // x0, y0 (padded) and both runs' points, then per grid point the statistics row and the text of map.csv
  // and map_grid.csv (about 160 and 60 characters)
  const double bytes = padded * (2 * sizeof(double) + sizeof(Point)) + n.points * (sizeof(EnergyMapRow) + 220.0);
  const double steps = 2 * padded * n.steps;  // one run per coordinate system and grid point (padding lanes die at once)
  return {steps, steps, bytes, kKernelNsPerStep, std::string("batched kernel; ") + kNsNote, 2 * n.batches};  // (batches of both maps)
}

StudyPlan plan_first_integrals(const Scene& s) {
  const double polar = static_cast<double>(s.reals("first_integrals.h").size() * s.real_rows("first_integrals.initial").size());
  const double steps = polar + 2 * (static_cast<double>(s.integer("first_integrals.steps")) + 1);  // plain and compensated
  return {steps, steps, 1001 * 100.0, kScalarNsPerStep, kNsNote};  // angular_momentum.csv: at most 1001 rows
}

StudyPlan plan_timing(const Scene& s) {
  const GridCount n = grid_count(s);
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  // the kernel's sample (only when the map study does not run in the same process: an upper bound), both systems
  const double kernel = 2 * repeats * std::min(static_cast<double>(s.integer("timing.kernel_batches")), n.batches) *
                        kEnergyMapBatch * n.steps;
  const double scalar = 2 * repeats * std::min(static_cast<double>(s.integer("timing.scalar_points")), n.points) *
                        static_cast<double>(s.integer("timing.scalar_steps"));
  const double steps = kernel + scalar, bytes = n.batches * kEnergyMapBatch * 2 * sizeof(double);
  const double ns = steps > 0 ? (kernel * kKernelNsPerStep + scalar * kScalarNsPerStep) / steps : 0;
  return {steps, steps, bytes, ns,
          std::string("one call per timed run (runs lengthened to >= 10 ms not counted); the kernel sample only "
                      "without the map study; ") + kNsNote};
}

StudyPlan plan_cost(const Scene& s) {
  double per_start = 0;  // steps of one start at every step size
  for (double dt : s.reals("cost.dt")) per_start += std::round(s.real("cost.t_end") / dt);
  const double repeats = static_cast<double>(s.integer("timing.repeats"));
  const double starts = static_cast<double>(s.real_rows("cost.starts").size());
  const double steps = 2 * starts * per_start * (1 + repeats);  // both systems: the untimed run and the timed ones
  return {steps, steps, starts * static_cast<double>(s.reals("cost.dt").size()) * 2 * 200.0, kScalarNsPerStep,
          std::string("one call per timed run (runs lengthened to >= 10 ms not counted); ") + kNsNote};
}

// ---- Fig. 6: the map, in rounds of batches with a checkpoint after each ----

void run_map(Context& ctx, MapCost& cost) {
  const Scene& s = ctx.scene;
  const MapSetup g = map_setup(s);
  const EnergyMapKernel kernel = energy_map_kernels().front().run;

  // Each coordinate system's batches as a checkpointed map (runner/checkpoint.hpp): a stopped run
  // continues with --resume; the kernel's wall time and the batches computed in this run, for the cost.
  std::vector<Point> points(g.nbatches * kEnergyMapBatch);
  double steps_done[2] = {0, 0}, wall[2] = {0, 0};
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const int ci = c == Coordinates::cartesian ? 0 : 1;
    std::atomic<std::size_t> computed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const auto batches = checkpointed_map<std::vector<EnergyMapPoint>>(
        ctx, {std::string("map.") + coordinates_name(c), kMapKeys}, g.nbatches,
        [&](std::size_t b) {
          std::vector<EnergyMapPoint> out(kEnergyMapBatch);
          kernel(c, g.P, &g.x0[b * kEnergyMapBatch], &g.y0[b * kEnergyMapBatch], out.data());
          ++computed;
          return out;
        },
        BatchCodec{});
    wall[ci] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    steps_done[ci] = static_cast<double>(g.npoints) * static_cast<double>(g.P.steps) *
                     static_cast<double>(computed) / static_cast<double>(g.nbatches);
    for (std::size_t i = 0; i < points.size(); ++i)
      (ci == 0 ? points[i].cart : points[i].polar) = batches[i / kEnergyMapBatch][i % kEnergyMapBatch];
  }
  // (a run resumed after one coordinate system was done has no kernel time for it: the timing study samples)
  cost = {steps_done[0] > 0 && steps_done[1] > 0, wall[0], wall[1], steps_done[0], steps_done[1]};

  // The map, and the analytic boundary of the polar runs r0 >= 2l + (2mg/k) cos(theta0), cos(theta0) = y0/r0.
  Csv map({"x0", "y0", "H0", "eps_cartesian", "eps_polar", "diverged_cartesian", "diverged_polar",
           "diverge_step_polar"});
  std::int64_t agree = 0, counted = 0, both_alive = 0, polar_better = 0, cart_diverged = 0, polar_diverged = 0;
  const auto [l, m, k, gravity, dt, steps, blowup] = g.P;
  const ElasticPendulumParams pendulum{l, m, k, gravity};
  const ElasticPendulumWithGravity cart{m, {SpringTerm{k, l}, GravityTerm{m, gravity}}};
  std::vector<EnergyMapRow> rows;
  for (std::size_t i = 0; i < g.npoints; ++i) {
    const double x = g.x0[i], y = g.y0[i], r = std::hypot(x, y);
    const Point& p = points[i];
    const bool dc = p.cart.diverge_step >= 0, dp = p.polar.diverge_step >= 0;
    const auto at_rest = make_state<2>(Vec<2>(x, y), Vec<2>(0.0, 0.0));
    const double H0 = cart.H(at_rest);
    map.row(x, y, H0, p.cart.eps, p.polar.eps, static_cast<std::int64_t>(dc), static_cast<std::int64_t>(dp),
            p.polar.diverge_step);
    rows.push_back({x, y, H0, p.cart.eps, p.polar.eps, dc, dp, p.polar.diverge_step});
    cart_diverged += dc, polar_diverged += dp;
    if (r > 0.0) {  // the origin is no initial condition of the polar problem
      ++counted;
      agree += dp == (r >= polar_boundary_radius(pendulum, y / r));
    }
    if (!dc && !dp) ++both_alive, polar_better += p.polar.eps < p.cart.eps;
  }
  ctx.write("map.csv", map);
  ctx.out.write("map_grid.csv", grid_scans(g, rows));
  const auto fraction = [](std::int64_t a, std::int64_t b) { return static_cast<double>(a) / static_cast<double>(b); };
  auto& reproduced = ctx.summary["reproduced"];
  reproduced["boundary_agreement"] = fraction(agree, counted);
  reproduced["fraction_polar_better"] = both_alive ? fraction(polar_better, both_alive) : 0.0;
  reproduced["fraction_diverged_polar"] = fraction(polar_diverged, static_cast<std::int64_t>(g.npoints));
  reproduced["fraction_diverged_cartesian"] = fraction(cart_diverged, static_cast<std::int64_t>(g.npoints));
  reproduced["polar_energy_mismatch"] = polar_mismatch(pendulum, rows, polar_from_cartesian);
  reproduced["printed_63_energy_mismatch"] = polar_mismatch(pendulum, rows, [](const PhaseState<2>& z) {
    return make_state<2>(polar_position_as_printed_63(z.q), Vec<2>(0.0, 0.0));  // (at rest: p = 0 in either)
  });
  ctx.summary["grid"] = {{"nx", g.xs.size()}, {"ny", g.ys.size()}, {"points", g.npoints}, {"steps", g.P.steps},
                         {"dx", spacing(g.xs)}, {"dy", spacing(g.ys)}};
  ctx.summary["pendulum"] = {{"dt_omega", dt * spring_frequency(pendulum)},
                             {"dt_omega_bound", method_info("symplectic_euler_pq").oscillatory_bound},  // the registry's
                             {"pivot_energy", pivot_energy(pendulum)}};
  ctx.summary["map_statistics"] = to_json(energy_map_statistics(rows, pendulum, dt, steps, s.real("map_statistics.ring_half_width")));
  ctx.summary["map_statistics"]["upright_column"] = upright_column(g, points);
}

// The local order between the two smallest step sizes: the slope of log(err) against log(h) there.
double local_order(const std::vector<double>& h, const std::vector<double>& err) {
  std::vector<std::pair<double, double>> pts;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] > 0 && err[i] > 0 && std::isfinite(h[i]) && std::isfinite(err[i])) pts.emplace_back(h[i], err[i]);
  std::sort(pts.begin(), pts.end());
  if (pts.size() < 2 || pts[0].first == pts[1].first) return std::nan("");
  return std::log(pts[1].second / pts[0].second) / std::log(pts[1].first / pts[0].first);
}

// ---- Section 5.2, free particle (m = 1): polar symplectic Euler changes p_x by
// O(h^2) per step; Cartesian symplectic Euler keeps x p_y - y p_x ----

void run_first_integrals(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("first integrals");
  const FreeParticleCartesian free_cart{1.0, {}};
  const FreeParticlePolar free_polar{1.0, {}};
  const auto hs = s.reals("first_integrals.h");
  const auto starts = s.real_rows("first_integrals.initial");
  // Per step h: the max over the given states of |p_x^{j+1} - p_x^j| after one polar step.
  const std::vector<double> change = distributed_map(hs.size(), [&](std::size_t k) {
    double worst = 0;
    for (const auto& row : starts) {
      const auto z = make_state<2>(Vec<2>(row[0], row[1]), Vec<2>(row[2], row[3]));
      const auto next = cartesian_from_polar(symplectic_euler_pq(free_polar, polar_from_cartesian(z), hs[k]));
      worst = std::max(worst, std::abs(next.p[0] - z.p[0]));
    }
    return worst;
  });
  Csv fi({"h", "px_change_per_step"});
  for (std::size_t k = 0; k < hs.size(); ++k) fi.row(hs[k], change[k]);
  ctx.write("first_integrals.csv", fi);
  const OrderFit px_fit = fit_order(hs, change, roundoff_floor());

  // The angular momentum is a quadratic invariant of symplectic Euler (a P-series
  // method), preserved exactly in exact arithmetic; in floating point the
  // particle runs off to |q| ~ h |p| n and plain summation random-walks the
  // round-off, so the run is made with and without compensated summation.
  Csv lcsv({"j", "t", "L_rel_drift_plain", "L_rel_drift_compensated"});
  const auto zL = make_state<2>(Vec<2>(starts[0][0], starts[0][1]), Vec<2>(starts[0][2], starts[0][3]));
  const double L0 = angular_momentum(zL), hL = *std::min_element(hs.begin(), hs.end());
  const std::int64_t nL = s.integer("first_integrals.steps"), every = std::max<std::int64_t>(1, nL / 1000);
  double L_drift_plain = 0, L_drift = 0;
  PhaseState<2> zp = zL;
  CompensatedState<2> zc{zL};
  for (std::int64_t j = 0; j <= nL; ++j) {
    if (j > 0) zp = symplectic_euler_pq(free_cart, zp, hL), zc = symplectic_euler_pq(free_cart, zc, hL);
    const double dp = std::abs(angular_momentum(zp) - L0) / std::abs(L0);
    const double dc = std::abs(angular_momentum(zc.z) - L0) / std::abs(L0);
    L_drift_plain = std::max(L_drift_plain, dp), L_drift = std::max(L_drift, dc);
    if (j % every == 0) lcsv.row(j, static_cast<double>(j) * hL, dp, dc);
  }
  ctx.write("angular_momentum.csv", lcsv);

  ctx.summary["reproduced"]["cartesian_L_max_rel_drift"] = L_drift;  // with compensated summation
  ctx.summary["reproduced"]["cartesian_L_max_rel_drift_plain"] = L_drift_plain;
  ctx.summary["orders"] = {{"polar_px_change_per_step", px_fit.order}};
  ctx.summary["fits"] = {{"polar_px_change_per_step", to_json(px_fit)}};
  // |q_J| at the end of the angular-momentum run, and the round-off of evaluating L = x p_y - y p_x
  // there: eps |q_J| |p| / |L_0| (p is constant for the free particle).
  const double q_end = zc.z.q.norm();
  ctx.summary["first_integrals"] = {
      {"h", {{"min", hL}, {"max", *std::max_element(hs.begin(), hs.end())}, {"count", hs.size()}}},
      {"initial_conditions", starts.size()},
      {"px_local_order", local_order(hs, change)},
      {"q_end", q_end},
      {"L_eval_roundoff", std::numeric_limits<double>::epsilon() * q_end * zL.p.norm() / std::abs(L0)}};
}

// ---- Cost: the batched kernel (from the map of this run, else on a sample of
// batches) against the straightforward scalar loop ----

void run_timing(Context& ctx, const MapCost& map) {
  const Scene& s = ctx.scene;
  const MapSetup g = map_setup(s);
  const auto kernels = energy_map_kernels();
  json timing;
  timing["kernel_isa"] = kernels.front().isa;
  timing["kernel_max_turn"] = kEnergyMapMaxTurn;  // polar: sin/cos by angle addition up to this turn

  // The kernel: wall time times threads over the trajectory-steps computed.
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  double wall_cart = map.wall_cart, wall_polar = map.wall_polar, steps_cart = map.steps_cart, steps_polar = map.steps_polar;
  json kernel_spread = nullptr;  // the sample's spread; the map's wall time is one run, not repeated
  std::string kernel_method = "map: wall time of the batched kernel in the map study of this run, times threads, over "
                              "the trajectory-steps it computed (the map is one long run, not a repeated measurement: "
                              "no minimum over repeats and no spread)";
  if (!map.ran) {
    ctx.progress("cost: batched kernel on a sample of batches");
    const auto count = std::min<std::size_t>(static_cast<std::size_t>(s.integer("timing.kernel_batches")), g.nbatches);
    std::vector<std::size_t> batches(count);
    std::size_t trajectories = 0;
    for (std::size_t i = 0; i < count; ++i) {
      batches[i] = i * g.nbatches / count;
      trajectories += std::min<std::size_t>(kEnergyMapBatch, g.npoints - batches[i] * kEnergyMapBatch);
    }
    kernel_spread = json::object();
    for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
      const RunTime t = time_runs(repeats, [&] {
        do_not_optimize(run_batches(kernels.front().run, c, g, count, [&](std::size_t b) { return batches[b]; }));
      });
      (c == Coordinates::cartesian ? wall_cart : wall_polar) = t.seconds();
      kernel_spread[coordinates_name(c)] = t.spread();
    }
    steps_cart = steps_polar = static_cast<double>(trajectories) * static_cast<double>(g.P.steps);
    timing["kernel_sample"] = {{"batches", count}, {"trajectories", trajectories},
                               {"wall_s", {{"cartesian", wall_cart}, {"polar", wall_polar}}}};
    kernel_method = "sample: the map study did not run in this process; wall time of the batched kernel on "
                    "timing.kernel_batches batches of the grid (evenly spaced, t_max/dt steps each; runs after "
                    "an untimed warm-up; the minimum over timing.repeats runs), times threads, over their trajectory-steps";
  }
  const double ns_cart = 1e9 * wall_cart * ctx.threads / steps_cart;
  const double ns_polar = 1e9 * wall_polar * ctx.threads / steps_polar;

  // The scalar loop, one trajectory at a time, single thread.
  ctx.progress("cost: scalar reference loop");
  const auto nsc = static_cast<std::size_t>(
      std::min<std::int64_t>(s.integer("timing.scalar_points"), static_cast<std::int64_t>(g.npoints)));
  EnergyMapParams Ps = g.P;
  Ps.steps = s.integer("timing.scalar_steps");
  json scalar_ns, scalar_spread;
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const RunTime t = time_runs(repeats, [&] {
      for (std::size_t i = 0; i < nsc; ++i) {
        const std::size_t at = i * (g.npoints / nsc);
        const auto r = energy_map_scalar(c, Ps, g.x0[at], g.y0[at]);
        do_not_optimize(r.eps);
      }
    });
    scalar_ns[coordinates_name(c)] = 1e9 * t.seconds() / (static_cast<double>(nsc) * static_cast<double>(Ps.steps));
    scalar_spread[coordinates_name(c)] = t.spread();
  }
  timing["ns_per_step_per_core"] = {{"cartesian", ns_cart}, {"polar", ns_polar}};
  timing["scalar_ns_per_step"] = scalar_ns;
  timing["scalar_ns_per_step_spread"] = scalar_spread;
  timing["kernel_sample_spread"] = kernel_spread;
  timing["speedup_vs_scalar"] = {{"cartesian", scalar_ns["cartesian"].get<double>() / ns_cart},
                                 {"polar", scalar_ns["polar"].get<double>() / ns_polar}};
  timing["map_wall_s"] = map.ran ? json{{"cartesian", wall_cart}, {"polar", wall_polar}} : json(nullptr);
  timing["method"] = "kernel timed on the " + kernel_method +
                     "; scalar: the straightforward scalar loop (one trajectory at a time) on timing.scalar_points "
                     "initial conditions of timing.scalar_steps steps, " + timing_method_text(repeats);
  timing["kernel_isa_name"] = kernels.front().name;
  timing["threads"] = ctx.threads;
  if (map.ran) timing["map_wall_total_s"] = wall_cart + wall_polar;
  // 2 n_x n_y J: one run per coordinate system and grid point
  timing["trajectory_steps"] = 2.0 * static_cast<double>(g.npoints) * static_cast<double>(g.P.steps);
  // each kernel against its target and the hardware ceiling (the scene's estimates)
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const std::string name = coordinates_name(c);
    const double ns = c == Coordinates::cartesian ? ns_cart : ns_polar;
    const auto ceiling = s.reals("timing.ceiling." + name);
    timing["ceiling_ns"][name] = {{"min", ceiling[0]}, {"max", ceiling[1]}};
    timing["ceiling_fraction"][name] = {{"min", ceiling[0] / ns}, {"max", ceiling[1] / ns}};
    timing["target_verdict"][name] = ns <= s.real("timing.target." + name) ? "meets" : "misses";
  }
  ctx.summary["timing"] = timing;
}

// ---- What an energy error costs in either coordinate system (work-precision): symplectic Euler from a
// few starts of the map at several steps, the scalar loop (energy_map_scalar) in both systems ----

void check_cost(const Scene& s) {
  const ElasticPendulumParams p{s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
  const double bound = method_info("symplectic_euler_pq").oscillatory_bound, omega = std::sqrt(p.k / p.m);
  const double t_end = s.real("cost.t_end");
  for (double dt : s.reals("cost.dt")) {
    if (!(dt * omega < bound))
      s.reject("cost.dt", "symplectic Euler is unstable for dt sqrt(k/m) >= " + format_double(bound) +
                              " (methods/registry.hpp): dt < " + format_double(bound / omega));
    const double n = std::round(t_end / dt);
    if (n < 1 || std::abs(n * dt - t_end) > 1e-9 * t_end)
      s.reject("cost.t_end", "must be a positive multiple of every cost.dt, here " + format_double(dt));
    if (!(n <= max_exact_count))  // steps are counted in int64 and t = j dt
      s.reject("cost.t_end", "cost.t_end / cost.dt must be at most 2^53 steps, here cost.dt = " + format_double(dt));
  }
  for (const auto& x : s.real_rows("cost.starts")) {
    const double r = std::hypot(x[0], x[1]);
    if (!(r > 0) || !(r < polar_boundary_radius(p, x[1] / r)))
      s.reject("cost.starts", "every start must lie inside the polar runs' divergence boundary r0 < 2l + (2mg/k) "
                              "cos(theta0), and not at the origin");
  }
}

void run_cost(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("cost: work-precision of the two coordinate systems");
  const auto starts = s.real_rows("cost.starts");
  const auto dts = s.reals("cost.dt");
  const double t_end = s.real("cost.t_end");
  const int repeats = static_cast<int>(s.integer("timing.repeats"));
  const ElasticPendulumParams pendulum{s.real("pendulum.l"), s.real("pendulum.m"), s.real("pendulum.k"), s.real("pendulum.g")};
  const auto params = [&](double dt) {
    return EnergyMapParams{pendulum.l, pendulum.m, pendulum.k, pendulum.g, dt, steps_to(t_end, dt), s.real("divergence.blowup")};
  };
  const Coordinates systems[] = {Coordinates::cartesian, Coordinates::polar};
  const std::size_t ns = starts.size(), nd = dts.size();
  // The energy errors (50): one untimed run per system, step and start (split across threads and ranks).
  const auto eps = distributed_map(2 * nd * ns, [&](std::size_t task) {
    const std::size_t c = task / (nd * ns), d = task / ns % nd, i = task % ns;
    return energy_map_scalar(systems[c], params(dts[d]), starts[i][0], starts[i][1]);
  });
  // The wall time: per system and step one timed function integrates every start in turn (serial, one
  // thread); a start's share is the minimum over the repeats divided by the number of starts (the loop's
  // time per step does not depend on the start: its only branch is the divergence test).
  Csv csv({"coordinates", "start", "x0", "y0", "h", "steps", "wall_s", "force_evals", "eps", "wall_spread"});
  std::vector<std::vector<std::vector<CostRun>>> curves(2, std::vector<std::vector<CostRun>>(ns));
  SpreadTally spreads;
  json ns_per_step, ns_spread;
  for (std::size_t d = 0; d < nd; ++d) {  // (both systems at one step back to back: a busy spell hits both alike)
    for (std::size_t c = 0; c < 2; ++c) {
      const EnergyMapParams P = params(dts[d]);
      const RunTime t = time_runs(repeats, [&] {
        for (const auto& x : starts) do_not_optimize(energy_map_scalar(systems[c], P, x[0], x[1]).eps);
      });
      spreads.add(t);
      const double wall = t.seconds() / static_cast<double>(ns);
      const double evals = static_cast<double>(P.steps);  // symplectic Euler (42): one gradient of U per step
      for (std::size_t i = 0; i < ns; ++i) {
        const EnergyMapPoint& e = eps[(c * nd + d) * ns + i];
        csv.row(coordinates_name(systems[c]), static_cast<std::int64_t>(i), starts[i][0], starts[i][1], dts[d], P.steps,
                wall, P.steps, e.eps, t.spread());
        curves[c][i].push_back({dts[d], static_cast<double>(P.steps), wall, evals, e.eps});
      }
      if (dts[d] == *std::min_element(dts.begin(), dts.end())) {  // time per step at the smallest step
        ns_per_step[coordinates_name(systems[c])] = 1e9 * wall / static_cast<double>(P.steps);
        ns_spread[coordinates_name(systems[c])] = t.spread();
      }
    }
  }
  ctx.write("timing_cost.csv", csv);

  // Per start: where it lies, the reference's own error, the fitted orders; what each target costs.
  const auto or_null = [](std::optional<double> v) { return v ? json(*v) : json(nullptr); };
  const double u = std::numeric_limits<double>::epsilon();
  json start_list = json::array(), cost_list = json::array();
  int polar_faster = 0, cartesian_faster = 0, compared = 0;
  double evals_ratio_min = std::numeric_limits<double>::infinity(), evals_ratio_max = 0;
  for (std::size_t i = 0; i < ns; ++i) {
    const double x = starts[i][0], y = starts[i][1], r = std::hypot(x, y);
    const double spring = 0.5 * pendulum.k * (r - pendulum.l) * (r - pendulum.l), gravity = pendulum.m * pendulum.g * y;
    json st = {{"x0", x}, {"y0", y}, {"r0", r}, {"H0", spring - gravity},
               {"r0_over_boundary", r / polar_boundary_radius(pendulum, y / r)},
               // H_0 is conserved by the flow: the reference is exact, its own error the round-off of
               // evaluating H, u (|k (r - l)^2 / 2| + |m g y|) at the start
               {"reference_error", u * (std::abs(spring) + std::abs(gravity))}};
    for (std::size_t c = 0; c < 2; ++c) {
      std::vector<double> h, e;
      for (const CostRun& run : curves[c][i]) h.push_back(run.h), e.push_back(run.err);
      st["order"][coordinates_name(systems[c])] = fit_order(h, e, roundoff_floor(), "cost").order;
      st["eps_range"][coordinates_name(systems[c])] = {{"min", *std::min_element(e.begin(), e.end())},
                                                       {"max", *std::max_element(e.begin(), e.end())}};
    }
    // The target: the geometric middle of the error range both systems cover at this start.
    const auto range = [&](std::size_t c) {
      double lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (const CostRun& run : curves[c][i]) lo = std::min(lo, run.err), hi = std::max(hi, run.err);
      return std::pair{lo, hi};
    };
    const double lo = std::max(range(0).first, range(1).first), hi = std::min(range(0).second, range(1).second);
    json cost_i = {{"start", i}};
    if (lo < hi) {
      const double target = std::sqrt(lo * hi);
      st["error_target"] = target;
      const auto cart = by_decreasing_h(curves[0][i]), polar = by_decreasing_h(curves[1][i]);
      const auto wc = cost_to_reach(cart, target, &CostRun::wall_s), wp = cost_to_reach(polar, target, &CostRun::wall_s);
      const auto ec = cost_to_reach(cart, target, &CostRun::evals), ep = cost_to_reach(polar, target, &CostRun::evals);
      json t = {{"target", target},
                {"wall_s", {{"cartesian", or_null(wc)}, {"polar", or_null(wp)}}},
                {"evals", {{"cartesian", or_null(ec)}, {"polar", or_null(ep)}}},
                {"wall_ratio_polar_over_cartesian", wc && wp ? json(*wp / *wc) : json(nullptr)},
                {"evals_ratio_polar_over_cartesian", ec && ep ? json(*ep / *ec) : json(nullptr)},
                {"faster", wc && wp ? json(*wp < *wc ? "polar" : "cartesian") : json(nullptr)}};
      if (wc && wp) ++compared, (*wp < *wc ? polar_faster : cartesian_faster) += 1;
      if (ec && ep) evals_ratio_min = std::min(evals_ratio_min, *ep / *ec), evals_ratio_max = std::max(evals_ratio_max, *ep / *ec);
      cost_i.update(t);
    }
    start_list.push_back(st);
    cost_list.push_back(cost_i);
  }
  double reference_error = 0;
  for (const auto& st : start_list) reference_error = std::max(reference_error, st["reference_error"].get<double>());
  ctx.summary["work_precision"] = {{"starts", start_list}, {"start_count", ns}, {"t_end", t_end},
                                   {"reference_error_max", reference_error},
                                   {"dt_range", {{"min", *std::min_element(dts.begin(), dts.end())},
                                                 {"max", *std::max_element(dts.begin(), dts.end())}}},
                                   {"error", "eq. (50) over [0, cost.t_end] against H_0 = H(z_0), per start"}};
  json& timing = ctx.summary["timing"]["work_precision"];
  timing = {{"ns_per_step", ns_per_step},
            {"ns_per_step_spread", ns_spread},
            {"ns_per_step_ratio_polar_over_cartesian",
             ns_per_step["polar"].get<double>() / ns_per_step["cartesian"].get<double>()},
            {"spread", spreads.to_json()},
            {"per_start", cost_list},
            {"compared", compared},
            {"evals_ratio_range", evals_ratio_max > 0 ? json{{"min", evals_ratio_min}, {"max", evals_ratio_max}} : json(nullptr)},
            {"polar_faster", polar_faster},
            {"cartesian_faster", cartesian_faster},
            {"method", "the scalar loop energy_map_scalar in both systems (not the batched kernels); per system and "
                       "step one timed function runs every start of cost.starts in turn, a start's wall time is its "
                       "share; " + timing_method_text(repeats) + "; force evaluations: one gradient of U per step"}};
}

}  // namespace

int main(int argc, char** argv) {
  ExperimentSpec spec{"energy_map",
                      "000 Fig. 6: RMS energy error of symplectic Euler in Cartesian and polar coordinates "
                      "over initial conditions; first integrals of Sec. 5.2",
                      schema(),
                      {}};
  MapCost map_cost;  // the map study's kernel wall time, for the timing study of the same run
  std::vector<std::string> map_uses = kMapKeys, timing_uses = kMapKeys;
  map_uses.insert(map_uses.end(), {"checkpoint", "map_statistics"});
  timing_uses.push_back("timing");
  spec.studies = {
      {"map", "000 Fig 6", {"map.csv", "map_grid.csv"}, map_uses, check_map, [&](Context& ctx) { run_map(ctx, map_cost); }, plan_map},
      {"first_integrals", "000 Sec 5.2", {"first_integrals.csv", "angular_momentum.csv"}, {"first_integrals"},
       check_first_integrals, run_first_integrals, plan_first_integrals},
      {"timing", "cost: batched kernel against the scalar loop, ns per step", {}, timing_uses, check_timing,
       [&](Context& ctx) { run_timing(ctx, map_cost); }, plan_timing},
      {"cost", "cost: energy error against wall time and force evaluations, Cartesian and polar",
       {"timing_cost.csv"}, {"cost", "pendulum", "divergence", "timing.repeats"}, check_cost, run_cost, plan_cost},
  };
  return run_experiment(argc, argv, std::move(spec), GEOMINT_EXPERIMENT_DIR);
}

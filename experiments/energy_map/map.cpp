// 000 Fig. 6: the RMS energy error (50) of symplectic Euler (42)-(43) on the elastic pendulum in
// Cartesian (73) and polar (72) coordinates, over a grid of initial positions at rest (the batched
// kernel, in rounds of batches with a checkpoint after each: a stopped run continues with --resume);
// the analytic boundary of the polar runs' divergence, r0 >= 2l + (2mg/k) cos(theta0); the energy of
// (72) against (73) at the map's starts (000 eq. (63)); and the statistics the report gives about the map.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/sweep/energy_map_grid.hpp"
#include "geomint/sweep/energy_map_statistics.hpp"
#include "geomint/systems/elastic_pendulum.hpp"

namespace geomint::energy_map {
namespace {

// A grid point's runs, one per coordinate system.
struct Point {
  EnergyMapPoint cart, polar;
};

// The grid spacing of an inclusive linspace (0 for a single value).
double spacing(const std::vector<double>& v) { return v.size() > 1 ? (v.back() - v.front()) / static_cast<double>(v.size() - 1) : 0.0; }

// map_grid.csv: x0, y0, H0 of map.csv in grid scans, a blank line between the rows of the grid (the
// form gnuplot contours: figures/energy_map_fig6.gp draws the H_0 isolines from it).
std::string grid_scans(const EnergyMapGrid& g, const std::vector<EnergyMapRow>& rows) {
  std::string out = "x0,y0,H0\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out += format_double(rows[i].x0) + "," + format_double(rows[i].y0) + "," + format_double(rows[i].H0) + "\n";
    if ((i + 1) % g.xs.size() == 0 && i + 1 < rows.size()) out += "\n";
  }
  return out;
}

// The largest |H of (72) - H of (73)| at rest over the initial positions of the map (the origin
// aside), with (r, theta) from (x, y) by 000 eq. (63), or by (63) as printed.
double polar_mismatch(const ElasticPendulumParams& p, const std::vector<EnergyMapRow>& rows, bool as_printed_63) {
  double worst = 0;
  for (const EnergyMapRow& row : rows)
    if (std::hypot(row.x0, row.y0) > 0)
      worst = std::max(worst, std::abs(polar_energy_at_rest(p, row.x0, row.y0, as_printed_63) - row.H0));
  return worst;
}

// The column x0 = 0 above the pivot (theta0 = pi): in Cartesian coordinates the force on x is
// proportional to x (73), so x stays exactly 0 and the run is a radial oscillation on the unstable
// upright line; in polar coordinates theta0 = fl(pi) has sin(theta0) ~ 1.2e-16, and the run falls
// over like its neighbours. Checked at the column point nearest (0, -l): the Cartesian run started
// at x0 = r0 sin(fl(pi)), the polar run's own start, against both runs of the map there.
Value upright_column(const EnergyMapGrid& g, const std::vector<Point>& points) {
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
  const auto value = [](double v) { return std::isfinite(v) ? Value(v) : Value(); };
  const auto difference = [&](std::size_t at) { return value(points[at].cart.eps - points[at].polar.eps); };
  return {{"y0", y0},
          {"eps_difference", difference(i)},
          {"eps_difference_neighbour", i + 1 < g.npoints && zero + 1 != g.xs.end() ? difference(i + 1) : Value()},
          {"eps_cartesian", value(points[i].cart.eps)},
          {"eps_polar", value(points[i].polar.eps)},
          {"x0_of_polar_start", x_polar},
          {"eps_cartesian_from_polar_start", value(tilted.eps)}};
}

StudyPlan plan_map(const Scene& s) {
  const EnergyMapCount n = energy_map_count(s);
  const double padded = n.batches * kEnergyMapBatch;
  // x0, y0 (padded) and both runs' points, then per grid point the statistics row and the text of map.csv
  // and map_grid.csv (about 160 and 60 characters)
  const double bytes = padded * (2 * sizeof(double) + sizeof(Point)) + n.points * (sizeof(EnergyMapRow) + 220.0);
  const double steps = 2 * padded * n.steps;  // one run per coordinate system and grid point (padding lanes die at once)
  return {steps, steps, bytes, energy_map_kernel_rate().ns_per_step, energy_map_kernel_rate().note, 2 * n.batches};  // (batches of both maps)
}

// ---- Fig. 6: the map, in rounds of batches with a checkpoint after each ----

// Each coordinate system's batches as a checkpointed map (runner/checkpoint.hpp): a stopped run
// continues with --resume; the kernel's wall time and the batches computed in this run, for the cost.
std::vector<Point> integrate_map(Context& ctx, const EnergyMapGrid& g, EnergyMapCost& cost) {
  std::vector<Point> points(g.nbatches * kEnergyMapBatch);
  double steps_done[2] = {0, 0}, wall[2] = {0, 0};
  for (const auto c : {Coordinates::cartesian, Coordinates::polar}) {
    const int ci = c == Coordinates::cartesian ? 0 : 1;
    std::size_t computed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const auto map = energy_map_points(ctx, std::string("map.") + coordinates_name(c), g, c, computed);
    wall[ci] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    steps_done[ci] = static_cast<double>(g.npoints) * static_cast<double>(g.P.steps) *
                     static_cast<double>(computed) / static_cast<double>(g.nbatches);
    for (std::size_t i = 0; i < points.size(); ++i) (ci == 0 ? points[i].cart : points[i].polar) = map[i];
  }
  // (a run resumed after one coordinate system was done has no kernel time for it: the timing study samples)
  cost = {steps_done[0] > 0 && steps_done[1] > 0, wall[0], wall[1], steps_done[0], steps_done[1]};
  return points;
}

// The map, and the analytic boundary of the polar runs r0 >= 2l + (2mg/k) cos(theta0), cos(theta0) = y0/r0:
// map.csv, map_grid.csv and the summary.
void write_map(Context& ctx, const EnergyMapGrid& g, const std::vector<Point>& points) {
  const Scene& s = ctx.scene;
  Csv map({"x0", "y0", "H0", "eps_cartesian", "eps_polar", "diverged_cartesian", "diverged_polar",
           "diverge_step_polar"});
  map.flags({"diverged_cartesian", "diverged_polar"});  // (eps of a diverged run is NaN)
  std::int64_t agree = 0, counted = 0, both_alive = 0, polar_better = 0, cart_diverged = 0, polar_diverged = 0;
  const auto [l, m, k, gravity, dt, steps, blowup] = g.P;
  const ElasticPendulumParams pendulum{l, m, k, gravity};
  std::vector<EnergyMapRow> rows;
  for (std::size_t i = 0; i < g.npoints; ++i) {
    const double x = g.x0[i], y = g.y0[i], r = std::hypot(x, y);
    const Point& p = points[i];
    const bool dc = p.cart.diverge_step >= 0, dp = p.polar.diverge_step >= 0;
    const double H0 = cartesian_energy_at_rest(pendulum, x, y);
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
  reproduced["polar_energy_mismatch"] = polar_mismatch(pendulum, rows, false);
  reproduced["printed_63_energy_mismatch"] = polar_mismatch(pendulum, rows, true);
  merge(ctx.summary, "timing", {{"kernel_isa", energy_map_kernels().front().isa}});  // (the kernel the map ran)
  ctx.summary["grid"] = {{"nx", g.xs.size()}, {"ny", g.ys.size()}, {"points", g.npoints}, {"steps", g.P.steps},
                         {"dx", spacing(g.xs)}, {"dy", spacing(g.ys)}};
  ctx.summary["pendulum"] = {{"dt_omega", dt * spring_frequency(pendulum)},
                             {"dt_omega_bound", method_info("symplectic_euler_pq").oscillatory_bound},  // the registry's
                             {"pivot_energy", pivot_energy(pendulum)}};
  const EnergyMapStatistics statistics = energy_map_statistics(rows, pendulum, dt, steps, s.real("map_statistics.ring_half_width"));
  ctx.summary["map_statistics"] = to_value(statistics);
  ctx.summary["map_statistics"]["same_energy"] = to_value(same_energy_wins(rows, g.xs.size(), statistics.roundoff_tie_tolerance));
  ctx.summary["map_statistics"]["upright_column"] = upright_column(g, points);
}

void run_map(Context& ctx, EnergyMapCost& cost) {
  const Scene& s = ctx.scene;
  const EnergyMapGrid g = energy_map_grid(s);
  const std::vector<Point> points = integrate_map(ctx, g, cost);
  write_map(ctx, g, points);
}


}  // namespace

Study map_study(EnergyMapCost& cost) {
  std::vector<std::string> reads = kEnergyMapKeys;
  reads.emplace_back("checkpoint");
  return {.name = "map",
          .makes = {{"000", "Fig. 6"}},
          .about = "epsilon of symplectic Euler, Cartesian - polar, over initial positions; the divergence boundary",
          .files = {"map.csv", "map_grid.csv"},
          .keys = Schema().real("map_statistics.ring_half_width", positive(),
                                "initial radii |r(0) - l| < ring_half_width * l are counted apart for where polar is "
                                "the more accurate"),
          .reads = reads,
          .run = [&cost](Context& ctx) { run_map(ctx, cost); },
          .validate = check_energy_map,
          .plan = plan_map};
}

}  // namespace geomint::energy_map

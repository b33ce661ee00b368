// 004 Fig. 5: Poincare cuts (q1 = 0 upwards, p1 > 0) of the trajectory of the Fig. 4 ensemble with the largest
// error, in the window where its error grows fastest and in the flattest, and the growth episodes of its error
// against (4.3). The trajectory: the ensemble study's, when it ran in the same process (LargestError, main.cpp);
// else this study integrates the ensemble itself (sweep/henon_heiles_ensemble.hpp: the same starts, checkpoint
// and numbers) and takes its trajectory with the largest error. The printed side of the cuts over many starts is the
// study episode_sides (episode_sides.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geomint/analysis/episode_cuts.hpp"
#include "geomint/analysis/growth_episodes.hpp"
#include "geomint/analysis/poincare.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/observables/linear_fit.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/henon_heiles_ensemble.hpp"

namespace geomint::ti_drift {
namespace {

using Z2 = PhaseState<2>;
using Trajectory = EnsembleTrajectory;

constexpr std::size_t kPoincareWindows = 20;  // Fig. 5: the run of the trajectory is cut into this many windows

// The windows of the trajectory's run: the one where its error grows fastest and the flattest.
struct Windows {
  std::size_t windows, per, steep, flat, compared;
  double tw;  // their length in time
};

Windows choose_windows(const Trajectory& run, const std::vector<double>& e) {
  const double h = run.h;
  const std::int64_t every4 = run.every4;
  const std::size_t ns = run.ns;
  const std::size_t windows = kPoincareWindows, per = std::max<std::size_t>(2, ns / windows);
  std::size_t steep = 0, flat = 0, compared = 0;
  double smax = -1, smin = std::numeric_limits<double>::infinity();
  for (std::size_t w = 0; w < windows && (w + 1) * per <= ns; ++w, ++compared) {
    std::vector<double> x, y;
    for (std::size_t k = w * per; k < (w + 1) * per; ++k) x.push_back(static_cast<double>(k)), y.push_back(e[k]);
    const double sl_w = std::abs(linear_fit(x, y).slope);
    if (sl_w > smax) smax = sl_w, steep = w;
    if (sl_w < smin) smin = sl_w, flat = w;
  }
  const double tw = static_cast<double>(per) * static_cast<double>(every4) * h;
  return {windows, per, steep, flat, compared, tw};
}

// The cuts of a window or an episode: their number, those with p2 < 0, and the sum of their p2.
struct Cuts {
  std::size_t count = 0, negative = 0;
  double p2_sum = 0;
};

// The growth episodes found, the times of the recorded error, and the rule's parameters.
struct Episodes {
  double sample_dt;
  std::size_t half, min_samples;
  std::vector<double> t_rec;
  SlopeNoise slope_sn;
  std::vector<Episode> episodes;
  std::vector<int> episode_of;  // the episode of the interval [t_k, t_{k+1}), or -1 (the complement)
};

// The growth episodes of its recorded error (analysis/growth_episodes.hpp; the scene's ensemble.episode_*).
// fig5_episodes.csv: at each output time the error, its running slope and its episode.
Episodes find_episodes(Context& ctx, const Trajectory& run, const std::vector<double>& e) {
  const Scene& s = ctx.scene;
  const std::size_t ns = run.ns;
  const auto time_of = [&](std::size_t k) { return run.time_of(k); };
  const double sample_dt = time_of(1);
  const EpisodeRule rule = episode_rule(s, "ensemble", sample_dt);
  const std::size_t half = rule.half, min_samples = rule.min_samples;
  std::vector<double> t_rec(ns);
  for (std::size_t k = 0; k < ns; ++k) t_rec[k] = time_of(k);
  const std::vector<double> run_slope = running_slope(t_rec, e, half);
  const SlopeNoise slope_sn = slope_noise(run_slope);
  const std::vector<Episode> episodes = growth_episodes(run_slope, rule.threshold, min_samples);
  std::vector<int> episode_of(ns, -1);  // the episode of the interval [t_k, t_{k+1}), or -1 (the complement)
  for (std::size_t i = 0; i < episodes.size(); ++i)
    for (std::size_t k = episodes[i].begin; k < episodes[i].end; ++k) episode_of[k] = static_cast<int>(i);
  Csv f5e({"t", "E_err", "running_slope", "episode", "sign"});
  for (std::size_t k = 0; k < ns; ++k)
    f5e.row(t_rec[k], e[k], run_slope[k], static_cast<std::int64_t>(episode_of[k]),
            static_cast<std::int64_t>(episode_of[k] >= 0 ? episodes[static_cast<std::size_t>(episode_of[k])].sign : 0));
  ctx.write("fig5_episodes.csv", f5e);
  return {sample_dt, half, min_samples, std::move(t_rec), slope_sn, episodes, std::move(episode_of)};
}

// The crossings of q1 = 0 upwards along the trajectory: in each window (fig5_poincare.csv) and in each
// episode (fig5_episode_cuts.csv, written last).
// Per episode (the last entry: the complement): its cuts, and (4.3) integrated along the steps, h sum dE/dt.
struct Crossings {
  std::map<std::string, Cuts> cuts;
  std::vector<Cuts> ep_cuts;
  std::vector<double> ep_predicted;
  std::vector<std::int64_t> ep_steps, ep_steps_negative;
  Csv f5c;
};

template <class HH>
Crossings cut_trajectory(Context& ctx, const HH& hhk, const Trajectory& run, const Windows& win, const Episodes& found) {
  const double h = run.h, tw = win.tw;
  const std::int64_t every4 = run.every4, n4 = run.n4;
  const std::size_t ns = run.ns, steep = win.steep, flat = win.flat;
  const std::vector<Episode>& episodes = found.episodes;
  const std::vector<int>& episode_of = found.episode_of;
  Csv f5({"window", "t", "q2", "p2"});
  std::map<std::string, Cuts> cuts;
  std::vector<Cuts> ep_cuts(episodes.size() + 1);
  std::vector<double> ep_predicted(episodes.size() + 1, 0.0);
  std::vector<std::int64_t> ep_steps(episodes.size() + 1, 0), ep_steps_negative(episodes.size() + 1, 0);
  Csv f5c({"episode", "sign", "t", "q2", "p2"});
  Z2 prev = run.start;
  simplified_ti_integrate(hhk, run.start, h, n4, [&](std::int64_t j, const Z2& z) {
    const double t = static_cast<double>(j) * h;
    const std::size_t k_prev = j > 0 ? static_cast<std::size_t>((j - 1) / every4) : 0;
    const int ep = k_prev < ns ? episode_of[k_prev] : -1;
    const std::size_t slot = ep >= 0 ? static_cast<std::size_t>(ep) : episodes.size();
    if (j > 0 && k_prev + 1 < ns) {
      ep_predicted[slot] += h * simplified_ti_drift_rate(hhk, prev, h);
      ++ep_steps[slot], ep_steps_negative[slot] += prev.p[1] < 0;
    }
    const std::optional<SectionCut> cut = j > 0 ? upward_cut(prev, z) : std::nullopt;  // q1 = 0 upwards, p1 > 0
    if (cut && k_prev + 1 < ns) {
      Cuts& c = ep_cuts[slot];
      ++c.count, c.negative += cut->p2 < 0, c.p2_sum += cut->p2;
      if (ep >= 0)
        f5c.row(static_cast<std::int64_t>(ep), static_cast<std::int64_t>(episodes[static_cast<std::size_t>(ep)].sign),
                t - (1 - cut->a) * h, cut->q2, cut->p2);
    }
    for (const auto& [label, w] : {std::pair{"growth", steep}, std::pair{"no_growth", flat}}) {
      if (cut && t >= static_cast<double>(w) * tw && t < static_cast<double>(w + 1) * tw) {
        f5.row(label, t - (1 - cut->a) * h, cut->q2, cut->p2);
        Cuts& c = cuts[label];
        ++c.count, c.negative += cut->p2 < 0, c.p2_sum += cut->p2;
      }
    }
    prev = z;
  });
  ctx.write("fig5_poincare.csv", f5);
  return {std::move(cuts), std::move(ep_cuts), std::move(ep_predicted), std::move(ep_steps), std::move(ep_steps_negative),
          std::move(f5c)};
}

// Each window: its cuts, and the error of E of the trajectory at its ends (output times).
Value window_summary(const Context& ctx, const Trajectory& run, const std::vector<double>& e, const Windows& win,
                     Crossings& x) {
  const std::size_t ns = run.ns, windows = win.windows, compared = win.compared, per = win.per;
  const std::size_t steep = win.steep, flat = win.flat;
  const double tw = win.tw;
  auto& cuts = x.cuts;
  Value poincare = {{"windows", windows}, {"windows_compared", compared}};
  for (const auto& [label, w] : {std::pair{"growth", steep}, std::pair{"no_growth", flat}}) {
    const Cuts& c = cuts[label];
    const double E_lo = e[w * per], E_hi = e[(w + 1) * per < ns ? (w + 1) * per : ns - 1];
    poincare[label] = {{"t_start", static_cast<double>(w) * tw},
                       {"t_end", static_cast<double>(w + 1) * tw},
                       {"length", tw},
                       {"cuts", c.count},
                       {"cuts_per_time", static_cast<double>(c.count) / tw},
                       {"share_p2_negative", c.count ? static_cast<double>(c.negative) / static_cast<double>(c.count) : 0.0},
                       {"mean_p2", c.count ? c.p2_sum / static_cast<double>(c.count) : 0.0},
                       {"E_err_start", E_lo},
                       {"E_err_end", E_hi},
                       {"E_err_change", E_hi - E_lo},
                       {"E_err_slope", (E_hi - E_lo) / tw}};
    // The printed window (published.toml: poincare_<label>): its length and cuts per unit time.
    const Value printed_window = ctx.published_values("poincare_" + std::string(label));
    const double length = printed_window.at("t_end").number() - printed_window.at("t_start").number();
    poincare["printed"][label] = {{"length", length}, {"cuts_per_time", printed_window.at("cuts").number() / length}};
  }
  return poincare;
}

// The episodes against (4.3): dE/dt = -h^4/2880 U^(5)(p^5) = h^4/120 p2^5 for k = 5 (U_22222 = -24): E rises where
// the time average of p2^5 over the episode is positive. The change (4.3) predicts, h sum_n dE/dt(p_n, q_n) over the
// episode's steps, against the recorded change; and the share of the cuts, and of the steps, with p2 < 0.
Value episode_summary(const Scene& s, const Trajectory& run, const std::vector<double>& e, const Episodes& found,
                      const Crossings& x) {
  const std::size_t ns = run.ns;
  const double sample_dt = found.sample_dt;
  const std::size_t half = found.half, min_samples = found.min_samples;
  const std::vector<double>& t_rec = found.t_rec;
  const SlopeNoise& slope_sn = found.slope_sn;
  const std::vector<Episode>& episodes = found.episodes;
  const std::vector<Cuts>& ep_cuts = x.ep_cuts;
  const std::vector<double>& ep_predicted = x.ep_predicted;
  const std::vector<std::int64_t>& ep_steps = x.ep_steps;
  const std::vector<std::int64_t>& ep_steps_negative = x.ep_steps_negative;
  const auto share = [](const Cuts& c) { return c.count ? static_cast<double>(c.negative) / static_cast<double>(c.count) : 0.0; };
  const auto time_share = [&](std::size_t slot) {
    return ep_steps[slot] ? static_cast<double>(ep_steps_negative[slot]) / static_cast<double>(ep_steps[slot]) : 0.0;
  };
  double worst_rel = 0;
  int cut_sign_positive = 0;  // growths with a majority of cuts at p2 > 0 and declines with a majority at p2 < 0
  Value eps = Value::list();
  Cuts growth_all, decline_all;
  int agree = 0;
  double growth_time = 0;
  std::size_t longest = episodes.size();
  for (std::size_t i = 0; i < episodes.size(); ++i) {
    const Episode& ep = episodes[i];
    const std::size_t last = std::min(ep.end, ns - 1);
    const double ta = t_rec[ep.begin], tb = t_rec[last], change = e[last] - e[ep.begin];
    const Cuts& c = ep_cuts[i];
    (ep.sign > 0 ? growth_all : decline_all).count += c.count;
    (ep.sign > 0 ? growth_all : decline_all).negative += c.negative;
    const bool agrees = (ep_predicted[i] > 0) == (change > 0);
    agree += agrees;
    cut_sign_positive += c.count > 0 && (ep.sign > 0) == (share(c) < 0.5);
    worst_rel = std::max(worst_rel, std::abs(ep_predicted[i] / change - 1));
    if (ep.sign > 0) growth_time += tb - ta;
    if (ep.sign > 0 && (longest == episodes.size() || tb - ta > t_rec[std::min(episodes[longest].end, ns - 1)] -
                                                                    t_rec[episodes[longest].begin]))
      longest = i;
    eps.push_back({{"t_start", ta},
                   {"t_end", tb},
                   {"sign", ep.sign},
                   {"cuts", c.count},
                   {"share_p2_negative", share(c)},
                   {"share_one_side", c.count ? std::max(share(c), 1 - share(c)) : 0.0},  // the side holding most cuts
                   {"mean_p2", c.count ? c.p2_sum / static_cast<double>(c.count) : 0.0},
                   {"share_time_p2_negative", time_share(i)},
                   {"E_err_change", change},
                   {"E_change_predicted", ep_predicted[i]},  // h sum of (4.3) over the episode's steps
                   {"predicted_over_recorded", ep_predicted[i] / change},
                   {"E_err_slope", change / (tb - ta)},
                   {"sign_agrees_with_43", agrees}});
  }
  const Cuts& rest = ep_cuts[episodes.size()];
  Value ep_summary = {{"rule", {{"half_width", static_cast<double>(half) * sample_dt},
                                {"half_width_samples", half},
                                {"threshold", s.real("ensemble.episode_threshold")},
                                {"min_length", static_cast<double>(min_samples) * sample_dt},
                                {"slope_median", slope_sn.centre},
                                {"slope_noise", slope_sn.noise}}},
                      {"count", episodes.size()},
                      {"sign_agrees_with_43", agree},                 // episodes whose recorded change has the sign of (4.3)
                      {"max_rel_difference_from_43", worst_rel},       // max |predicted / recorded - 1| over the episodes
                      {"cut_majority_on_side_of_change", cut_sign_positive},
                      {"growth_time", growth_time},
                      {"list", eps},
                      {"growth", {{"cuts", growth_all.count}, {"share_p2_negative", share(growth_all)}}},
                      {"decline", {{"cuts", decline_all.count}, {"share_p2_negative", share(decline_all)}}},
                      {"complement", {{"cuts", rest.count}, {"share_p2_negative", share(rest)},
                                      {"share_time_p2_negative", time_share(episodes.size())},
                                      {"mean_p2", rest.count ? rest.p2_sum / static_cast<double>(rest.count) : 0.0},
                                      {"E_change_predicted", ep_predicted[episodes.size()]}}}};
  if (longest < episodes.size()) ep_summary["longest_growth"] = eps.at(longest);
  return ep_summary;
}

// Fig. 5 of the trajectory (fig5_episodes.csv, fig5_poincare.csv, fig5_episode_cuts.csv, summary.reproduced);
// returns summary.poincare.
template <class HH>
Value write_fig5(Context& ctx, const HH& hhk, const Trajectory& run) {
  ctx.progress("Fig. 5: Poincare cuts");
  const auto& e = run.e;
  const Windows win = choose_windows(run, e);
  const std::size_t steep = win.steep, flat = win.flat;
  const double tw = win.tw;
  const Episodes found = find_episodes(ctx, run, e);
  Crossings x = cut_trajectory(ctx, hhk, run, win, found);
  Value reproduced;
  reproduced["poincare_trajectory"] = run.index;
  reproduced["poincare_windows"] = {
      {"growth", std::vector<double>{static_cast<double>(steep) * tw, static_cast<double>(steep + 1) * tw}},
      {"no_growth", std::vector<double>{static_cast<double>(flat) * tw, static_cast<double>(flat + 1) * tw}}};
  merge(ctx.summary, "reproduced", reproduced);
  Value poincare = window_summary(ctx, run, e, win, x);
  poincare["episodes"] = episode_summary(ctx.scene, run, e, found, x);
  ctx.write("fig5_episode_cuts.csv", x.f5c);
  return poincare;
}

// The trajectory with the largest error: the ensemble study's of this process, or that of the ensemble integrated
// here when that study did not run (the same function, starts and checkpoint: the same trajectory).
void run_poincare(Context& ctx, const LargestError& largest) {
  put_simplified_ti_method(ctx.summary, "poincare");
  LargestError own;
  if (!largest) {
    const HenonHeilesEnsemble run = integrate_ensemble(ctx);
    own = trajectory_of(run, largest_error(run));
  }
  const Trajectory& worst = largest ? *largest : *own;
  with_ensemble_system(ctx.scene, [&](const auto& hhk) {
    ctx.summary["poincare"] = write_fig5(ctx, hhk, worst);
  });
}

void check_poincare(const Scene& s) {
  check_ensemble_run(s);
  check_episode_rule(s, "ensemble", "t_end");
}

// With the ensemble study in the same process: the rerun of one trajectory (scalar, (4.3) and a cut test every step),
// its series and CSVs. Alone: the ensemble too, in lanes, as the ensemble study plans it. One rate: the time of the
// parts over their steps.
StudyPlan plan_poincare(const Scene& s) {
  const double n = s.real("t_end") / s.real("h"), M = static_cast<double>(s.integer("ensemble.size"));
  const double evals = static_cast<double>(evals_per_step("simplified_takahashi_imada"));
  const double rows = kept_samples(n, static_cast<double>(s.integer("samples")));
  const PlanRate &lanes = plan_rate("henon-heiles lanes"), &scalar = plan_rate("henon-heiles splitting");
  const StudyPlan taken{n, n * evals, rows * 208 + kHenonHeilesLanes * rows * 40, scalar.ns_per_step,
                        "the trajectory of the ensemble study of this run; " + scalar.note, 1};
  StudyPlan alone{(M + 1) * n, (M + 1) * n * evals, M * rows * 8 + rows * 200,
                  (scalar.ns_per_step + M * lanes.ns_per_step) / (M + 1),
                  "the ensemble integrated again (without the ensemble study); " + lanes.note,
                  static_cast<double>(lane_batches(static_cast<std::size_t>(M), kHenonHeilesLanes))};  // (tasks: batches of lanes)
  alone.reuses = "ensemble", alone.when_reusing = std::make_shared<const StudyPlan>(taken);
  return alone;
}

}  // namespace

Study poincare_study(const LargestError& largest) {
  std::vector<std::string> reads = kEnsembleKeys;  // (main.cpp's shared keys: the ensemble study reads them too)
  reads.emplace_back("checkpoint");
  return {.name = "poincare",
          .makes = {{"004", "Fig. 5"}},
          .about = "Poincare cuts of the Fig 4 ensemble's trajectory with the largest error (from the ensemble study "
                   "of the same run; without it, the ensemble integrated again, the same numbers)",
          .files = {"fig5_poincare.csv", "fig5_episodes.csv", "fig5_episode_cuts.csv"},
          .keys = Schema()
                      .real("ensemble.episode_half_width", positive(),
                            "Fig. 5 episodes: the running slope of the error of E of the trajectory is fitted over +- "
                            "this time")
                      .real("ensemble.episode_threshold", positive(),
                            "Fig. 5 episodes: a sample belongs to an episode where its running slope differs from "
                            "their median by more than this many robust standard deviations (1.4826 MAD) of the "
                            "running slopes")
                      .real("ensemble.episode_min_length", positive(),
                            "Fig. 5 episodes: the shortest episode (time units)"),
          .reads = reads,
          .run = [&largest](Context& ctx) { run_poincare(ctx, largest); },
          .validate = check_poincare,
          .plan = plan_poincare};
}

}  // namespace geomint::ti_drift

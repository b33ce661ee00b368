// 004 Fig. 5 over many starts (study episode_sides): the printed side of the Poincare cuts (p2 < 0) during a growth
// episode of the error of E, judged over independent samples, since 004 prints one trajectory of random starts: the
// first growth episode of each of episode_sides.starts starts of the Fig. 4 ensemble's streams, by the rule of Fig. 5
// (ensemble.episode_*), and the cuts along it (analysis/episode_cuts.hpp).
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geomint/analysis/episode_cuts.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/methods/force_evals.hpp"
#include "geomint/runner/checkpoint.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/runner/plan_rates.hpp"
#include "geomint/runner/summary.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"
#include "geomint/sweep/henon_heiles_ensemble.hpp"

namespace geomint::ti_drift {
namespace {

using Z2 = PhaseState<2>;

constexpr std::size_t kMinClaimSamples = 20;  // the share of a claim from at least this many samples

// The printed claim over many starts: the first growth episode of each start 0 .. episode_sides.starts - 1 of the Fig. 4
// ensemble's streams (its own first, integrated again; analysis/episode_cuts.hpp), one independent sample each. The
// claim holds for a sample where most of its cuts lie in p2 < 0; its share over the samples (from kMinClaimSamples on)
// with the binomial standard error, against a coin flip (fig5_starts.csv, summary episode_sides: runner/summary.hpp).
Value write_starts(Context& ctx) {
  const Scene& s = ctx.scene;
  const auto N = static_cast<std::size_t>(s.integer("episode_sides.starts"));
  ctx.progress("Fig. 5: growth episodes of " + std::to_string(N) + " starts");
  const double h = s.real("h");
  const std::int64_t n = steps_to(s.real("t_end"), h), every = std::max<std::int64_t>(1, n / s.integer("samples"));
  const EpisodeRule rule = episode_rule(s, "ensemble", static_cast<double>(every) * h);
  const std::vector<Z2> starts = ensemble_starts(s, N);
  const std::vector<EpisodeSample> found = concatenate(checkpointed_map<std::vector<EpisodeSample>>(
      ctx, {"episode_sides.starts"}, lane_batches(N, kHenonHeilesLanes), [&](std::size_t b) {  // (the keys: all the study reads)
        const LaneBatch batch = lane_batch(b, N, kHenonHeilesLanes);
        return with_ensemble_system(s, [&](const auto& hhk) {
          return first_growth_episode_cuts(hhk, std::span<const Z2>(starts).subspan(batch.first, batch.count), h, n, every, rule);
        });
      }));
  Csv f5s({"start", "t_start", "t_end", "cuts", "share_p2_negative", "mean_p2"});
  std::vector<double> share, one_side;
  for (std::size_t i = 0; i < N; ++i) {
    const EpisodeSample& e = found[i];
    if (!e.found || e.count == 0) continue;
    const double c = static_cast<double>(e.count), sh = static_cast<double>(e.negative) / c;
    share.push_back(sh), one_side.push_back(std::max(sh, 1 - sh));
    const auto time_of = [&](std::int64_t k) { return static_cast<double>(k) * static_cast<double>(every) * h; };
    f5s.row(static_cast<std::int64_t>(i), time_of(e.begin), time_of(std::min<std::int64_t>(e.end, n / every)), e.count, sh,
            e.p2_sum / c);
  }
  ctx.write("fig5_starts.csv", f5s);
  Value out = {{"starts", N}, {"p2_negative", claim_share_summary(share, 0.5, kMinClaimSamples)}};
  if (!one_side.empty()) out["one_side"] = quartiles(one_side);  // the share of the cuts on the side holding most
  return out;
}

void run_episode_sides(Context& ctx) { ctx.summary["episode_sides"] = write_starts(ctx); }

// The episode_sides.starts starts in lanes (their episodes' few steps cut again by the scalar method left out).
StudyPlan plan_episode_sides(const Scene& s) {
  const double n = s.real("t_end") / s.real("h"), N = static_cast<double>(s.integer("episode_sides.starts"));
  const double evals = static_cast<double>(evals_per_step("simplified_takahashi_imada"));
  const PlanRate& lanes = plan_rate("henon-heiles lanes");
  return {N * n, N * n * evals, N * 64, lanes.ns_per_step, "the starts in lanes; " + lanes.note,
          static_cast<double>(lane_batches(static_cast<std::size_t>(N), kHenonHeilesLanes))};
}

}  // namespace

Study episode_sides_study() {
  std::vector<std::string> reads = kEnsembleKeys;  // (the ensemble's streams and the rule of Fig. 5)
  for (const char* key : {"ensemble.episode_half_width", "ensemble.episode_threshold", "ensemble.episode_min_length",
                          "checkpoint"})
    reads.emplace_back(key);
  return {.name = "episode_sides",
          .makes = {{"004", "Fig. 5"}},
          .about = "the side of p2 = 0 of the Poincare cuts of the first growth episode of each of many starts of "
                   "the Fig 4 ensemble's streams: 004 Fig 5's printed side judged over independent samples",
          .files = {"fig5_starts.csv"},
          .keys = Schema().integer("episode_sides.starts", at_least(1),
                                   "Fig. 5 over many starts: the first growth episode of each of this many starts of "
                                   "the Fig. 4 ensemble's streams (its own first), the side of p2 = 0 its cuts lie on"),
          .reads = reads,
          .run = run_episode_sides,
          .validate = [](const Scene& s) { check_ensemble_run(s), check_episode_rule(s, "ensemble", "t_end"); },
          .plan = plan_episode_sides};
}

}  // namespace geomint::ti_drift

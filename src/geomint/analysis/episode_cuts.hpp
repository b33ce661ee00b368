#pragma once
// 004 Fig. 5 over many starts: the first growth episode of each trajectory of an ensemble (the rule of
// growth_episodes.hpp on its recorded error of the modified energy E) and the Poincare cuts (q1 = 0
// upwards, p1 > 0: poincare.hpp) along that episode, with the side of p2 = 0 they lie on. The trajectories
// run in SIMD lanes (sweep/ensemble_kernels.hpp, bit for bit the scalar method) with their states kept at the
// output times; an episode is then cut by the scalar method from its first output time, the same steps as a
// run from the start would take.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "geomint/analysis/growth_episodes.hpp"
#include "geomint/core/state.hpp"
#include "geomint/systems/henon_heiles.hpp"

namespace geomint {

class Scene;

// The episode rule in samples: the running slope over +- half samples, the threshold in robust standard
// deviations, the shortest episode.
struct EpisodeRule {
  std::size_t half = 1;
  double threshold = 0;
  std::size_t min_samples = 1;
};

// The scene's rule: the running slope over +- <section>.episode_half_width, the threshold
// <section>.episode_threshold, the shortest episode <section>.episode_min_length (times), in samples of sample_dt.
EpisodeRule episode_rule(const Scene& s, const std::string& section, double sample_dt);
// Rejects a width of the rule above (episode_half_width, episode_min_length) that exceeds the scene's value t_end_key.
void check_episode_rule(const Scene& s, const std::string& section, const std::string& t_end_key);

// The first growth episode (sign +1) of y(t) by the rule, if any.
inline std::optional<Episode> first_growth_episode(std::span<const double> t, std::span<const double> y,
                                                   const EpisodeRule& rule) {
  for (const Episode& e : growth_episodes(running_slope(t, y, rule.half), rule.threshold, rule.min_samples))
    if (e.sign > 0) return e;
  return std::nullopt;
}

// The steps of an episode [begin, end) of a record of ns output times, `every` steps apart: those of the
// intervals [t_k, t_k+1) with k in [begin, end) and k + 1 < ns (the last output time closes the record),
// from step begin every.
inline std::int64_t episode_steps(const Episode& e, std::size_t ns, std::int64_t every) {
  const std::size_t last = std::min(e.end, ns - 1);
  return last > e.begin ? static_cast<std::int64_t>(last - e.begin) * every : 0;
}

// The cuts of q1 = 0 upwards along n steps of (1.6) from z: their number, those with p2 < 0, the sum of p2.
struct SectionCuts {
  std::int64_t count = 0, negative = 0;
  double p2_sum = 0;
};

// One start: whether its record shows a growth episode, the first one's samples [begin, end), and its cuts.
struct EpisodeSample {
  std::int64_t found = 0, begin = 0, end = 0, count = 0, negative = 0;
  double p2_sum = 0;
  auto fields() { return std::tie(found, begin, end, count, negative, p2_sum); }
};

// The starts (at most kHenonHeilesLanes) along (1.6) at step h for n steps, the error of E of each at the output times
// every `every` steps (as 004 Fig. 4 records it: E(z_j) - E(z_0)); per start its first growth episode by `rule`
// and the cuts along it. Compiled once, in episode_cuts.cpp, for the Henon-Heiles systems of 004.
template <class Sys>
std::vector<EpisodeSample> first_growth_episode_cuts(const Sys& sys, std::span<const PhaseState<2>> starts, double h,
                                                     std::int64_t n, std::int64_t every, const EpisodeRule& rule);

extern template std::vector<EpisodeSample> first_growth_episode_cuts(const HenonHeilesT<true>&, std::span<const PhaseState<2>>,
                                                                     double, std::int64_t, std::int64_t, const EpisodeRule&);
extern template std::vector<EpisodeSample> first_growth_episode_cuts(const HenonHeilesT<false>&, std::span<const PhaseState<2>>,
                                                                     double, std::int64_t, std::int64_t, const EpisodeRule&);

}  // namespace geomint

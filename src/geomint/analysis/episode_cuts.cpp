// 004 Fig. 5 over many starts (analysis/episode_cuts.hpp), compiled once for the Henon-Heiles systems of 004.
#include "geomint/analysis/episode_cuts.hpp"

#include <algorithm>
#include <cmath>

#include "geomint/analysis/poincare.hpp"
#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/scene/scene.hpp"
#include "geomint/sweep/ensemble_kernels.hpp"

namespace geomint {

EpisodeRule episode_rule(const Scene& s, const std::string& section, double sample_dt) {
  const auto samples = [&](const char* key) {
    return static_cast<std::size_t>(std::max(1.0, std::round(s.real(section + key) / sample_dt)));
  };
  return {samples(".episode_half_width"), s.real(section + ".episode_threshold"), samples(".episode_min_length")};
}

void check_episode_rule(const Scene& s, const std::string& section, const std::string& t_end_key) {
  const double t_end = s.real(t_end_key);
  for (const char* key : {".episode_half_width", ".episode_min_length"})
    if (s.real(section + key) > t_end) s.reject(section + key, "must not exceed " + t_end_key + " = " + format_double(t_end));
}

namespace {

// The cuts of q1 = 0 upwards along n steps of (1.6) from z.
template <class Sys>
SectionCuts cuts_along(const Sys& sys, const PhaseState<2>& z, double h, std::int64_t n) {
  SectionCuts c;
  PhaseState<2> prev = z;
  simplified_ti_integrate(sys, z, h, n, [&](std::int64_t j, const PhaseState<2>& zj) {
    if (j > 0)
      if (const std::optional<SectionCut> cut = upward_cut(prev, zj)) ++c.count, c.negative += cut->p2 < 0, c.p2_sum += cut->p2;
    prev = zj;
  });
  return c;
}

}  // namespace

template <class Sys>
std::vector<EpisodeSample> first_growth_episode_cuts(const Sys& sys, std::span<const PhaseState<2>> starts, double h,
                                                     std::int64_t n, std::int64_t every, const EpisodeRule& rule) {
  const std::size_t m = starts.size();
  std::vector<std::vector<double>> e(m);
  std::vector<std::vector<PhaseState<2>>> z(m);
  std::vector<double> E0;
  for (const PhaseState<2>& s : starts) E0.push_back(simplified_ti_modified_energy(sys, s, h));
  simplified_ti_lanes(sys, simplified_ti_lanes_kernels<Sys>().front().steps, starts, h, n, every,
                      [&](int i, std::int64_t, const PhaseState<2>& zj) {
                        e[i].push_back(simplified_ti_modified_energy(sys, zj, h) - E0[i]);
                        z[i].push_back(zj);
                      });
  std::vector<EpisodeSample> out(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t ns = e[i].size();
    std::vector<double> t(ns);
    for (std::size_t k = 0; k < ns; ++k) t[k] = static_cast<double>(k) * static_cast<double>(every) * h;
    const std::optional<Episode> ep = first_growth_episode(t, e[i], rule);
    if (!ep) continue;
    const SectionCuts c = cuts_along(sys, z[i][ep->begin], h, episode_steps(*ep, ns, every));
    out[i] = {1, static_cast<std::int64_t>(ep->begin), static_cast<std::int64_t>(ep->end), c.count, c.negative, c.p2_sum};
  }
  return out;
}

template std::vector<EpisodeSample> first_growth_episode_cuts(const HenonHeilesT<true>&, std::span<const PhaseState<2>>,
                                                              double, std::int64_t, std::int64_t, const EpisodeRule&);
template std::vector<EpisodeSample> first_growth_episode_cuts(const HenonHeilesT<false>&, std::span<const PhaseState<2>>,
                                                              double, std::int64_t, std::int64_t, const EpisodeRule&);

}  // namespace geomint

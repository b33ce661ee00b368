#pragma once
// Poincare sections of a two-degree-of-freedom trajectory (004 Fig. 5: Henon-Heiles, the section
// q1 = 0 crossed upwards, p1 > 0), from its steps: the crossing of one step, by linear interpolation.
#include <optional>

#include "geomint/core/state.hpp"

namespace geomint {

// Where the step prev -> z crosses q1 = 0 upwards with p1 > 0: the fraction `a` of the step at which
// q1 = 0 (the cut lies at t - (1 - a) h, t the time of z) and (q2, p2) there, interpolated linearly.
struct SectionCut {
  double a, q2, p2;
};

inline std::optional<SectionCut> upward_cut(const PhaseState<2>& prev, const PhaseState<2>& z) {
  if (!(prev.q[0] < 0 && z.q[0] >= 0 && z.p[0] > 0)) return std::nullopt;
  const double a = -prev.q[0] / (z.q[0] - prev.q[0]);
  return SectionCut{a, prev.q[1] + a * (z.q[1] - prev.q[1]), prev.p[1] + a * (z.p[1] - prev.p[1])};
}

}  // namespace geomint

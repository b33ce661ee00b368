#pragma once
// The point transformation between Cartesian (x, y) and polar (r, theta)
// coordinates of the plane and the momentum map it induces (000 eq. (41)).
// Convention: theta is measured from +y towards +x, x = r sin(theta),
// y = r cos(theta), so that (72) and (73) describe the same pendulum (gravity
// along +y, U = -m g y = -m g r cos(theta)); then theta = atan2(x, y) (C's
// order of arguments), as in the first half of (63). (The second half of (63),
// written for the free mass, prints x = r cos(theta), the other convention.)
#include <cmath>

#include "geomint/core/state.hpp"

namespace geomint {

// (x, y, px, py) -> (r, theta, p_r, p_theta): p_r = (x px + y py)/r, p_theta = y px - x py (41).
inline PhaseState<2> polar_from_cartesian(const PhaseState<2>& z) {
  const double x = z.q[0], y = z.q[1], r = std::hypot(x, y);
  return make_state<2>(Vec<2>(r, std::atan2(x, y)), Vec<2>((x * z.p[0] + y * z.p[1]) / r, y * z.p[0] - x * z.p[1]));
}

// (r, theta, p_r, p_theta) -> (x, y, px, py): px = p_r sin + p_theta cos / r, py = p_r cos - p_theta sin / r.
inline PhaseState<2> cartesian_from_polar(const PhaseState<2>& z) {
  const double r = z.q[0], s = std::sin(z.q[1]), c = std::cos(z.q[1]);
  return make_state<2>(Vec<2>(r * s, r * c), Vec<2>(z.p[0] * s + z.p[1] * c / r, z.p[0] * c - z.p[1] * s / r));
}

// (r, theta) of (x, y) as the second half of 000 eq. (63) prints it, x = r cos(theta), y = r sin(theta):
// theta = atan2(y, x), measured from +x. It is not the inverse of the first half (atan2(x, y)), and
// with it -m g y of (73) becomes -m g r sin(theta), not the -m g r cos(theta) of (72).
inline Vec<2> polar_position_as_printed_63(const Vec<2>& q) {
  return Vec<2>(std::hypot(q[0], q[1]), std::atan2(q[1], q[0]));
}

// The angular momentum about the origin in Cartesian coordinates, x p_y - y p_x (000 eq. (69));
// with theta measured from +y it equals -p_theta.
inline double angular_momentum(const PhaseState<2>& z) { return z.q[0] * z.p[1] - z.q[1] * z.p[0]; }

}  // namespace geomint

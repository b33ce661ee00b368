#pragma once
// The area of the convex hull of points in the plane: Andrew's monotone chain, then the shoelace
// formula. (003 Fig. 5.1 draws the shadows of a cloud on the (x, p_x) and (y, p_y) planes.)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace geomint {

// 0 for fewer than three points or points on one line; repeated and interior points do not count.
inline double convex_area(std::vector<std::array<double, 2>> p) {
  std::sort(p.begin(), p.end());
  const auto cross = [](const auto& o, const auto& a, const auto& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<std::array<double, 2>> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); hull[k++] = p[i++])  // lower hull, left to right
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0; hull[k++] = p[i])  // upper hull, right to left
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
  double a = 0;
  for (std::size_t i = 0; i + 1 < k; ++i) a += hull[i][0] * hull[i + 1][1] - hull[i + 1][0] * hull[i][1];
  return 0.5 * std::abs(a);
}

}  // namespace geomint

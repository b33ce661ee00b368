#pragma once
// Initial point clouds of 003 Sec. 5: the vertices of the 600-cell (Figs 5.2,
// 5.4) and random points on a 3-sphere (Fig. 5.1), generated in code.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace geomint {

using Point4 = std::array<double, 4>;

// The 120 vertices of the 600-cell of circumradius 1 (Coxeter, Regular Polytopes, Sec. 8.7):
// the 8 permutations of (+-1, 0, 0, 0), the 16 points (+-1/2, +-1/2, +-1/2, +-1/2) and the 96
// even permutations of (+-phi, +-1, +-1/phi, 0)/2, phi the golden ratio.
inline std::vector<Point4> six_hundred_cell_vertices() {
  std::vector<Point4> v;
  for (int i = 0; i < 4; ++i)
    for (double s : {1.0, -1.0}) {
      Point4 p{};
      p[i] = s;
      v.push_back(p);
    }
  for (int m = 0; m < 16; ++m) v.push_back({m & 1 ? -0.5 : 0.5, m & 2 ? -0.5 : 0.5, m & 4 ? -0.5 : 0.5, m & 8 ? -0.5 : 0.5});
  constexpr double phi = std::numbers::phi;
  const std::array<double, 4> base{phi / 2, 0.5, 0.5 / phi, 0.0};
  std::array<int, 4> perm{0, 1, 2, 3};
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    if (inversions % 2) continue;  // even permutations only
    for (int m = 0; m < 8; ++m) {
      Point4 p;
      for (int i = 0; i < 4; ++i) {
        const int k = perm[i];  // coordinate i takes base entry k; the three nonzero entries get signs
        p[i] = k < 3 && (m >> k & 1) ? -base[k] : base[k];
      }
      v.push_back(p);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return v;
}

// The 4-content of the 600-cell of circumradius r: (25/4)(2 + sqrt 5) a^4 with the edge a = r/phi
// (Coxeter, Regular Polytopes, Table I(iv)).
inline double six_hundred_cell_volume(double r) {
  const double a = r / std::numbers::phi;
  return 25.0 / 4 * (2 + std::sqrt(5.0)) * a * a * a * a;
}

// The 600-cell as the code of 003 (github.com/mvermeeren/conf-ham-sys-2020) loads it: its loader
// skips the first line of the vertex file, the vertex (0, 0, 1, 0), and keeps the other 119.
inline std::vector<Point4> authors_six_hundred_cell_vertices() {
  std::vector<Point4> v = six_hundred_cell_vertices();
  std::erase(v, Point4{0, 0, 1, 0});
  return v;
}

// A uniform point on the unit 3-sphere per call: g / |g| for g ~ N(0, I_4), with a
// Box-Muller transform written out so that the stream depends only on the seed.
class SpherePoints {
 public:
  explicit SpherePoints(std::uint64_t seed) : gen_(seed) {}
  Point4 next() {
    Point4 g;
    for (int i = 0; i < 4; i += 2) {
      const double u1 = uniform(), u2 = uniform(), r = std::sqrt(-2.0 * std::log(u1));
      g[i] = r * std::cos(2 * std::numbers::pi * u2), g[i + 1] = r * std::sin(2 * std::numbers::pi * u2);
    }
    const double n = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g[3] * g[3]);
    for (double& c : g) c /= n;
    return g;
  }

 private:
  double uniform() { return (static_cast<double>(gen_() >> 11) + 0.5) * 0x1p-53; }  // in (0, 1)
  std::mt19937_64 gen_;
};

// center + radius * u for each unit vector u.
inline std::vector<Point4> scaled_cloud(const std::vector<Point4>& unit, const Point4& center, double radius) {
  std::vector<Point4> out;
  out.reserve(unit.size());
  for (const Point4& u : unit) out.push_back({center[0] + radius * u[0], center[1] + radius * u[1], center[2] + radius * u[2], center[3] + radius * u[3]});
  return out;
}

// The centre z0 and the vertices of a polytope of circumradius `radius` around it (the unit `vertices` scaled), the
// centre first: the apex of the hull triangulation (003 Figs 5.2, 5.4).
inline std::vector<Point4> cloud_around(const Point4& z0, const std::vector<Point4>& vertices, double radius) {
  std::vector<Point4> unit{{0, 0, 0, 0}};
  unit.insert(unit.end(), vertices.begin(), vertices.end());
  return scaled_cloud(unit, z0, radius);
}

}  // namespace geomint

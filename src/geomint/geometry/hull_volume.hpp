#pragma once
// Measure-weighted volume of the convex hull of a 4-D point cloud (003 Figs
// 5.2, 5.4): Qhull triangulates the hull boundary into tetrahedra, each is
// coned from an interior apex into a 4-simplex, and the density is integrated
// over each simplex by a 5-point rule exact for polynomials of degree 2.
#include <array>
#include <cmath>
#include <vector>

#include "geomint/geometry/clouds.hpp"

namespace geomint {

using HullFacet = std::array<int, 4>;  // indices into the point list

// The boundary of conv(points) as tetrahedra (Qhull, reentrant API, option Qt), in a canonical
// order: each facet's indices increasing, the facets in lexicographic order, so that a sum over
// them does not depend on the order in which Qhull built the hull.
// Throws std::domain_error for a cloud Qhull cannot take (a coordinate not finite or beyond 1e100 from the centroid,
// fewer than 5 points, all equal) or on which it fails (with the first line of its message).
std::vector<HullFacet> hull_facets(const std::vector<Point4>& points);

// True when `facets`, the hull_facets of a cloud of as many points (e.g. an earlier image of this
// one under a flow), are the boundary of conv(points): the centroid and every point not on a
// facet lie inside the facet's hyperplane by more than 1e-9 of the cloud's width. Then each facet
// is a facet of conv(points), and a closed triangulated 3-sphere made of facets of a simplicial
// hull is all of its boundary, so hull_facets(points) == facets. False for a cloud with a
// coordinate that is not finite and for any near-degenerate one (coplanar points, a flat facet).
bool bounds_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& facets);

// hull_facets(points), without Qhull when bounds_hull(points, known) (same value either way).
std::vector<HullFacet> hull_facets(const std::vector<Point4>& points, const std::vector<HullFacet>& known);

// hull_facets(points, known) of a cloud under a flow, where a cloud that left the domain of the hull (not finite,
// degenerate) is a NumericalFailure (core/numerical_failure.hpp), not a programming error.
std::vector<HullFacet> cloud_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& known = {});

// int_{conv(points)} rho over the simplices conv(apex, facet), apex inside the hull: the
// degree-2 rule |T|/5 sum_i rho(xi_i), xi_i with barycentric weight alpha on vertex i and
// beta on the other four, alpha = (6 + 4 sqrt 6)/30, beta = (6 - sqrt 6)/30
// (Stroud, Approximate Calculation of Multiple Integrals, rule T_n:2-1).
template <class Density>
double hull_integral(const std::vector<Point4>& points, const std::vector<HullFacet>& facets, const Point4& apex,
                     const Density& rho) {
  const double alpha = (6 + 4 * std::sqrt(6.0)) / 30, beta = (6 - std::sqrt(6.0)) / 30;
  double total = 0;
  for (const HullFacet& f : facets) {
    std::array<Point4, 5> v{apex, points[f[0]], points[f[1]], points[f[2]], points[f[3]]};
    double m[4][4];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = v[r + 1][c] - apex[c];
    // 4x4 determinant by Laplace expansion in 2x2 minors of the first two rows.
    const auto d2 = [&](int r0, int r1, int c0, int c1) { return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]; };
    const double det = d2(0, 1, 0, 1) * d2(2, 3, 2, 3) - d2(0, 1, 0, 2) * d2(2, 3, 1, 3) +
                       d2(0, 1, 0, 3) * d2(2, 3, 1, 2) + d2(0, 1, 1, 2) * d2(2, 3, 0, 3) -
                       d2(0, 1, 1, 3) * d2(2, 3, 0, 2) + d2(0, 1, 2, 3) * d2(2, 3, 0, 1);
    double sum = 0;
    for (int i = 0; i < 5; ++i) {
      Point4 xi{};
      for (int k = 0; k < 5; ++k)
        for (int c = 0; c < 4; ++c) xi[c] += (k == i ? alpha : beta) * v[k][c];
      sum += rho(xi);
    }
    total += std::abs(det) / 24 * sum / 5;
  }
  return total;
}

}  // namespace geomint

#include "geomint/geometry/hull_volume.hpp"

#include "geomint/core/numerical_failure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace geomint {

namespace {

// The cloud relative to its centroid, the coordinates the hull is computed and checked in (the
// clouds are tiny, radius down to 1e-5, and far from the origin); width: the largest |coordinate|.
struct Centred {
  std::vector<Point4> z;
  double width = 0;
  bool finite = true;
};

Centred centred(const std::vector<Point4>& points) {
  const int n = static_cast<int>(points.size());
  Point4 c{};
  for (const Point4& p : points)
    for (int k = 0; k < 4; ++k) c[k] += p[k] / n;
  Centred out{std::vector<Point4>(points.size())};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      out.z[i][k] = points[i][k] - c[k];
      out.finite = out.finite && std::isfinite(out.z[i][k]);
      out.width = std::max(out.width, std::abs(out.z[i][k]));
    }
  return out;
}

}  // namespace

std::vector<HullFacet> hull_facets(const std::vector<Point4>& points) {
  const int n = static_cast<int>(points.size());
  const auto [z, width, finite] = centred(points);
  std::vector<coordT> coords(4 * points.size());
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) coords[4 * i + k] = z[i][k];
  // Qhull squares coordinates and has no defence against NaN or Inf: refuse what it cannot take.
  if (!finite || width > 1e100)
    throw std::domain_error("convex hull of " + std::to_string(n) + " points: a coordinate is not finite or beyond 1e100");
  if (n < 5 || width == 0) throw std::domain_error("convex hull of " + std::to_string(n) + " points: the cloud is degenerate");

  auto qh_storage = std::make_unique<qhT>();
  qhT* qh = qh_storage.get();
  // Qhull's messages go to a temporary file: its first line becomes the exception's text
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> errfile(std::tmpfile(), &std::fclose);
  std::FILE* err = errfile ? errfile.get() : stderr;
  qh_zero(qh, err);
  char options[] = "qhull Qt";  // Qt: triangulated output, every facet a tetrahedron
  const int exitcode = qh_new_qhull(qh, 4, n, coords.data(), False, options, nullptr, err);
  std::vector<HullFacet> facets;
  if (exitcode == 0) {
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      HullFacet f{};
      int k = 0;
      FOREACHvertex_(facet->vertices) {
        if (k < 4) f[k] = qh_pointid(qh, vertex->point);
        ++k;
      }
      if (k != 4) {
        facets.clear();
        break;
      }
      facets.push_back(f);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (exitcode != 0) {
    std::string first = "no message";
    if (errfile) {
      char line[512] = {};
      std::rewind(err);
      if (std::fgets(line, sizeof line, err)) first = line;
      if (!first.empty() && first.back() == '\n') first.pop_back();
    }
    throw std::domain_error("Qhull failed on a cloud of " + std::to_string(n) + " points (exit code " +
                            std::to_string(exitcode) + ": " + first + ")");
  }
  if (facets.empty()) throw std::runtime_error("Qhull returned a facet that is not a tetrahedron");
  for (HullFacet& f : facets) std::sort(f.begin(), f.end());
  std::sort(facets.begin(), facets.end());
  return facets;
}

bool bounds_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& facets) {
  const std::size_t n = points.size();
  if (facets.empty()) return false;
  const auto [z, width, finite] = centred(points);  // the centroid is the origin from here on
  if (!finite) return false;
  const double margin = 1e-9 * width;
  std::array<std::vector<double>, 4> columns;  // z by coordinate: the count over the points below vectorises
  for (int k = 0; k < 4; ++k)
    for (const Point4& p : z) columns[k].push_back(p[k]);
  const double *z0 = columns[0].data(), *z1 = columns[1].data(), *z2 = columns[2].data(), *z3 = columns[3].data();
  for (const HullFacet& f : facets) {
    for (int v : f)
      if (v < 0 || static_cast<std::size_t>(v) >= n) return false;
    // the hyperplane {x : u.x = w} through the facet: u from the cofactors of the edges from vertex f[0]
    double e[3][4];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) e[r][k] = z[f[r + 1]][k] - z[f[0]][k];
    const auto det3 = [&](int a, int b, int d) {
      return e[0][a] * (e[1][b] * e[2][d] - e[1][d] * e[2][b]) - e[0][b] * (e[1][a] * e[2][d] - e[1][d] * e[2][a]) +
             e[0][d] * (e[1][a] * e[2][b] - e[1][b] * e[2][a]);
    };
    std::array<double, 4> u{det3(1, 2, 3), -det3(0, 2, 3), det3(0, 1, 3), -det3(0, 1, 2)};
    double w = 0, norm = 0;
    for (int k = 0; k < 4; ++k) w += u[k] * z[f[0]][k], norm += u[k] * u[k];
    norm = std::sqrt(norm);
    if (!(norm > 0)) return false;
    const double s = (w > 0 ? 1 : -1) / norm;  // |u| = 1, the centroid on the side u.x < w
    for (int k = 0; k < 4; ++k) u[k] *= s;
    w *= s;
    if (!(w > margin)) return false;
    // the distance inside the hyperplane, w - u.z_i: round-off for the facet's own four vertices,
    // more than the margin for every other point
    const double u0 = u[0], u1 = u[1], u2 = u[2], u3 = u[3];
    const auto inside = [=](std::size_t i) { return w - (u0 * z0[i] + u1 * z1[i] + u2 * z2[i] + u3 * z3[i]); };
    for (int v : f)
      if (!(std::abs(inside(static_cast<std::size_t>(v))) <= margin)) return false;
    double near = 0;  // (a double count: the comparisons and the sum in one vector width)
#pragma omp simd reduction(+ : near)
    for (std::size_t i = 0; i < n; ++i) near += inside(i) > margin ? 0.0 : 1.0;
    if (near != 4) return false;
  }
  return true;
}

std::vector<HullFacet> hull_facets(const std::vector<Point4>& points, const std::vector<HullFacet>& known) {
  return bounds_hull(points, known) ? known : hull_facets(points);
}

std::vector<HullFacet> cloud_hull(const std::vector<Point4>& points, const std::vector<HullFacet>& known) {
  try {
    return hull_facets(points, known);
  } catch (const std::domain_error& e) {
    throw NumericalFailure(std::string("hull volume: ") + e.what());
  }
}

}  // namespace geomint

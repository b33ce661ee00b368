#include "geomint/geometry/hull_volume.hpp"

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

std::vector<HullFacet> hull_facets(const std::vector<Point4>& points) {
  // Qhull works on coordinates relative to the centroid: the clouds are tiny
  // (radius down to 1e-5) and far from the origin.
  const int n = static_cast<int>(points.size());
  Point4 c{};
  for (const Point4& p : points)
    for (int k = 0; k < 4; ++k) c[k] += p[k] / n;
  std::vector<coordT> coords(4 * points.size());
  double width = 0;
  bool finite = true;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 4; ++k) {
      coords[4 * i + k] = points[i][k] - c[k];
      finite = finite && std::isfinite(coords[4 * i + k]);
      width = std::max(width, std::abs(coords[4 * i + k]));
    }
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
  return facets;
}

}  // namespace geomint

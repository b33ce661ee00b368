// The nonholonomic particle of 003: discrete Lagrangians (5.1), their momenta,
// the Newton step, the generated modified quantities, clouds and hull volumes.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../hard_case.hpp"

#include "geomint/geometry/clouds.hpp"
#include "geomint/geometry/hull_volume.hpp"
#include "geomint/geometry/volume_series.hpp"
#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/observables/symplecticity.hpp"
#include "geomint/systems/nonholonomic_golden.hpp"
#include "geomint/systems/nonholonomic_modified_series.hpp"
#include "geomint/systems/nonholonomic_variational.hpp"

using namespace geomint;

namespace measure_cloud_test {  // the file's scope (the tests build as one translation unit)

namespace {

using Z = PhaseState<2>;
Z state(double x, double y, double px, double py) { return make_state<2>(Vec<2>(x, y), Vec<2>(px, py)); }
double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }
const NonholonomicParticle harmonic{Potential::harmonic}, free_particle{Potential::free};

TEST(MeasureCloud, GeneratedModifiedQuantitiesMatchGoldenValues) {
  for (const auto& g : nonholonomic::golden_cases) {
    const NonholonomicParticle sys{parse_potential(g.potential)};
    const ModifiedSeries ms(*parse_discretization(g.discretization), sys, nonholonomic::golden_h);
    const std::string where = std::string(g.discretization) + " " + g.potential;
    for (const auto* p : {&g.a, &g.b}) {
      const Z z = from_array(p->z);
      EXPECT_LT(rel(sys.H(z), p->H), 1e-15) << where;
      EXPECT_LT(rel(ms.E(2, z), p->E2), 1e-13) << where << " E^(2)";
      EXPECT_LT(rel(ms.E(4, z), p->E4), 1e-13) << where << " E^(4)";
      EXPECT_LT(rel(ms.N(2, z), p->N2), 1e-13) << where << " N^(2)";
      EXPECT_LT(rel(ms.N(4, z), p->N4), 1e-13) << where << " N^(4)";
      EXPECT_LT(rel(ms.K4(z, 1.0), p->K4_at_E1), 1e-13) << where << " K^(4)";
      EXPECT_EQ(ms.E(0, z), sys.H(z));
      EXPECT_EQ(ms.N(0, z), NonholonomicParticle::N(z.q[1]));
    }
  }
}

TEST(MeasureCloud, OneStepMatchesGoldenValues) {
  for (const auto& g : nonholonomic::golden_cases) {
    const NonholonomicParticle sys{parse_potential(g.potential)};
    const Discretization d = *parse_discretization(g.discretization);
    const Z za = from_array(g.a.z);
    const double E4 = ModifiedSeries(d, sys, nonholonomic::golden_h).E(4, za);
    const auto a = to_array(conformal_variational_step(d, sys, za, nonholonomic::golden_h, E4).z);
    const auto b = to_array(conformal_variational_step(d, sys, za, nonholonomic::golden_h, sys.H(za)).z);
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(rel(a[k], g.step_with_E4[k]), 1e-13) << g.discretization << " " << g.potential << " k=" << k;
      EXPECT_LT(rel(b[k], g.step_with_H[k]), 1e-13) << g.discretization << " " << g.potential << " k=" << k;
    }
  }
}

// p_0 = -h d Lambda_d / d q_0 and p_1 = h d Lambda_d / d q_1: the closed forms against AD of (5.1).
TEST(MeasureCloud, DiscreteMomentaAreDerivativesOfTheDiscreteLagrangian) {
  using AD = Eigen::AutoDiffScalar<Eigen::Vector4d>;
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto* sys : {&harmonic, &free_particle})
    for (Discretization d : all_discretizations)
      for (int trial = 0; trial < 5; ++trial) {
        const Vec<2> q0(u(gen), u(gen)), q1(u(gen), u(gen));
        const double h = 0.3, E = 0.7 + u(gen);
        Eigen::Matrix<AD, 2, 1> a0, a1;
        for (int i = 0; i < 2; ++i) a0[i] = AD(q0[i], 4, i), a1[i] = AD(q1[i], 4, 2 + i);
        const Eigen::Vector4d g = discrete_lagrangian(d, *sys, a0, a1, h, E).derivatives();
        const Vec<2> p0 = discrete_momentum<double>(d, *sys, q0, q1, h, E, -1);
        const Vec<2> p1 = discrete_momentum<double>(d, *sys, q0, q1, h, E, +1);
        for (int i = 0; i < 2; ++i) {
          EXPECT_NEAR(p0[i], -h * g[i], 1e-14) << discretization_name(d);
          EXPECT_NEAR(p1[i], h * g[2 + i], 1e-14) << discretization_name(d);
        }
      }
}

TEST(MeasureCloud, NewtonConvergesQuadratically) {
  const Z z = state(0.3, -0.4, 0.7, 1.1);
  const double h = 0.25, E = harmonic.H(z);
  for (Discretization d : all_discretizations) {
    Vec<2> q1 = z.q + h * harmonic.altered_velocity(z);
    std::vector<double> err;  // distance of the iterates to the converged solution
    const Vec<2> solution = conformal_variational_step(d, harmonic, z, h, E).z.q;
    for (int it = 0; it < 6; ++it) {
      err.push_back((q1 - solution).norm());
      const auto [r, J] = momentum_residual(d, harmonic, z, q1, h, E);
      q1 -= J.partialPivLu().solve(r);
    }
    int quadratic_steps = 0;
    double c = 0;  // the largest e_{k+1} / e_k^2 while e_k > 1e-7
    for (std::size_t k = 0; k + 1 < err.size(); ++k)
      if (err[k] > 1e-7) c = std::max(c, err[k + 1] / (err[k] * err[k])), ++quadratic_steps;
    const std::string name = discretization_name(d);
    EXPECT_CASE(name + ", h = 0.25: largest e_{k+1} / e_k^2 over the iterates above 1e-7", c, "<", 10);
    EXPECT_CASE(name + ": iterates above 1e-7", quadratic_steps, ">=", 2);
    EXPECT_CASE(name + ": error after 6 iterations", err.back(), "<", 1e-15);
    EXPECT_CASE(name + ": Newton iterations of the step", conformal_variational_step(d, harmonic, z, h, E).newton_iterations,
                "<=", 6);
  }
}

// For fixed E the step is the map of the type-I generating function h Lambda_d: symplectic.
TEST(MeasureCloud, StepIsSymplecticForFixedE) {
  const Z z = state(0.3, -0.4, 0.7, 1.1);
  const double h = 0.25, E = 1.2, dz = 1e-6;
  for (Discretization d : all_discretizations) {
    Mat<4> J;
    for (int c = 0; c < 4; ++c) {
      Z a = z, b = z;
      (c < 2 ? a.q[c] : a.p[c - 2]) += dz;
      (c < 2 ? b.q[c] : b.p[c - 2]) -= dz;
      const Z za = conformal_variational_step(d, harmonic, a, h, E).z, zb = conformal_variational_step(d, harmonic, b, h, E).z;
      J.col(c) << (za.q - zb.q) / (2 * dz), (za.p - zb.p) / (2 * dz);
    }
    EXPECT_LT(symplecticity_defect<4>(J), 1e-8) << discretization_name(d);
  }
}

// With U = 0 the discrete Lagrangians are invariant under x-translations: p_x is conserved (to round-off).
TEST(MeasureCloud, FreeParticleConservesPx) {
  Z z = state(0.1, 0.2, 0.9, 1.3);
  for (Discretization d : all_discretizations) {
    Z w = z;
    for (int j = 0; j < 40; ++j) w = conformal_variational_step(d, free_particle, w, 0.25, 1.0).z;
    EXPECT_NEAR(w.p[0], z.p[0], 1e-13) << discretization_name(d);  // 40 steps, a few ulp each
  }
}

// The reference right-hand side (3.8) conserves H and is N J grad H.
TEST(MeasureCloud, ReferenceFieldIsConformallyHamiltonian) {
  const std::array<double, 4> z{0.3, -0.4, 0.7, 1.1};
  const auto f = harmonic.rhs(z);
  const double N = NonholonomicParticle::N(z[1]), y = z[1];
  EXPECT_NEAR(f[0], N * z[2], 1e-15);                     // N H_px
  EXPECT_NEAR(f[1], N * (1 + y * y) * z[3], 1e-15);        // N H_py
  EXPECT_NEAR(f[2], -N * z[0], 1e-15);                     // -N H_x
  EXPECT_NEAR(f[3], -N * (y * z[3] * z[3] + y), 1e-15);    // -N H_y
}

TEST(MeasureCloud, SixHundredCellVertices) {
  const auto v = six_hundred_cell_vertices();
  ASSERT_EQ(v.size(), 120u);
  const double edge = 1 / std::numbers::phi;
  for (std::size_t i = 0; i < v.size(); ++i) {
    double n2 = 0;
    for (double c : v[i]) n2 += c * c;
    EXPECT_NEAR(n2, 1.0, 1e-15);
    int neighbours = 0;
    double closest = 10;
    for (std::size_t j = 0; j < v.size(); ++j) {
      if (i == j) continue;
      double d2 = 0;
      for (int k = 0; k < 4; ++k) d2 += (v[i][k] - v[j][k]) * (v[i][k] - v[j][k]);
      closest = std::min(closest, std::sqrt(d2));
      neighbours += std::abs(std::sqrt(d2) - edge) < 1e-12;
    }
    EXPECT_NEAR(closest, edge, 1e-12);
    EXPECT_EQ(neighbours, 12);  // the vertex figure of the 600-cell is an icosahedron
  }
}

TEST(MeasureCloud, HullVolumeOfTheSixHundredCell) {
  const double r = 0.01;
  std::vector<Point4> unit{{0, 0, 0, 0}};
  for (const auto& p : six_hundred_cell_vertices()) unit.push_back(p);
  const auto cloud = scaled_cloud(unit, {0, 0, 1, 1}, r);
  const auto facets = hull_facets(cloud);
  EXPECT_EQ(facets.size(), 600u);
  // the closed form (25/4)(2 + sqrt 5) (r/phi)^4 against the hull's 600 cells coned from the centre
  EXPECT_LT(rel(hull_integral(cloud, facets, cloud.front(), [](const Point4&) { return 1.0; }), six_hundred_cell_volume(r)),
            1e-12);
}

// The hulls of a run are taken from the previous snapshot when bounds_hull says they still bound
// the cloud: it must say so exactly when Qhull would return the same facets.
TEST(MeasureCloud, KnownFacetsAreTakenOnlyWhenTheyBoundTheHull) {
  const double r = 1e-5;
  std::vector<Point4> unit{{0, 0, 0, 0}};
  for (const auto& p : six_hundred_cell_vertices()) unit.push_back(p);
  const auto cloud = scaled_cloud(unit, {0, 0, 1, 1}, r);
  const auto known = hull_facets(cloud);
  int judged = 0, cases = 0;  // the clouds whose known facets are judged as they should be
  const auto judge = [&](bool right, const char* which) { EXPECT_TRUE(right) << which, judged += right, ++cases; };
  EXPECT_TRUE(std::is_sorted(known.begin(), known.end()));
  for (const HullFacet& f : known) EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
  judge(bounds_hull(cloud, known), "the cloud itself");
  // a sheared and slightly bent image of the cloud (as a step of a flow makes it): the same hull
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(-1, 1);
  double A[4][4];
  for (auto& row : A)
    for (double& a : row) a = uni(rng);
  for (int k = 0; k < 4; ++k) A[k][k] += 3;
  auto image = cloud;
  for (Point4& p : image) {
    Point4 d{};
    for (int k = 0; k < 4; ++k) d[k] = p[k] - cloud.front()[k];
    for (int k = 0; k < 4; ++k) {
      p[k] = cloud.front()[k] + 1e-2 * d[k] * d[0] / r;  // bent: a term of second order in the offset
      for (int c = 0; c < 4; ++c) p[k] += A[k][c] * d[c];
    }
  }
  judge(bounds_hull(image, known), "its sheared image");
  EXPECT_EQ(hull_facets(image), known);
  EXPECT_EQ(hull_facets(image, known), known);
  // a vertex pulled halfway to the centre is no hull vertex any more: Qhull is asked, and its
  // answer is a different set of facets
  auto dented = image;
  for (int k = 0; k < 4; ++k) dented[7][k] = 0.5 * (dented[7][k] + dented[0][k]);
  judge(!bounds_hull(dented, known), "a vertex pulled in");
  EXPECT_EQ(hull_facets(dented, known), hull_facets(dented));
  EXPECT_NE(hull_facets(dented), known);
  // pushed out: the facets around it no longer bound the cloud
  auto bumped = image;
  for (int k = 0; k < 4; ++k) bumped[7][k] += 0.5 * (bumped[7][k] - bumped[0][k]);
  judge(!bounds_hull(bumped, known), "a vertex pushed out");
  EXPECT_EQ(hull_facets(bumped, known), hull_facets(bumped));
  // a coordinate that is not finite, and facets of another number of points
  auto broken = image;
  broken[3][2] = std::nan("");
  judge(!bounds_hull(broken, known), "a NaN coordinate");
  judge(!bounds_hull(std::vector<Point4>(image.begin(), image.begin() + 60), known), "60 points");
  judge(!bounds_hull(image, {}), "no facets");
  // the authors' cloud lacks a vertex: the hull has a facet with the 12 co-hyperplanar vertices of an
  // icosahedron, triangulated by Qhull in one of many ways, and is never taken without Qhull
  std::vector<Point4> authors_unit{{0, 0, 0, 0}};
  for (const auto& p : authors_six_hundred_cell_vertices()) authors_unit.push_back(p);
  const auto authors = scaled_cloud(authors_unit, {0, 0, 1, 1}, r);
  judge(!bounds_hull(authors, hull_facets(authors)), "the authors' cloud");
  EXPECT_CASE("clouds near r = 1e-5 whose known facets are taken, or refused, as they should be", judged, "==", cases);
}

// The loader of the code of 003 skips the first vertex of its file, (0, 0, 1, 0): 119 vertices, the
// others in the same order, and a cloud that is no longer centrally symmetric.
TEST(MeasureCloud, AuthorsCloudLacksOneVertex) {
  const auto all = six_hundred_cell_vertices(), authors = authors_six_hundred_cell_vertices();
  ASSERT_EQ(authors.size(), 119u);
  std::vector<Point4> expected;
  for (const auto& v : all)
    if (v != Point4{0, 0, 1, 0}) expected.push_back(v);
  EXPECT_EQ(authors, expected);
  EXPECT_NE(std::find(authors.begin(), authors.end(), Point4{0, 0, -1, 0}), authors.end());  // its opposite stays
}

// V_j/V_0 - 1 over the first samples, its peak-to-peak, and that of its difference from a reference.
TEST(MeasureCloud, VolumeSeriesPeakToPeak) {
  const std::vector<double> v{2.0, 2.5, 1.5, 3.0, 10.0}, r{4.0, 4.4, 3.8, 4.0, 4.0};
  EXPECT_EQ(relative_volumes(v, 4), (std::vector<double>{0.0, 0.25, -0.25, 0.5}));
  EXPECT_EQ(relative_volumes(v, 9).size(), 5u);
  EXPECT_DOUBLE_EQ(relative_peak_to_peak(v, 4), 0.75);   // 0.5 - (-0.25); the sample 10 is outside
  EXPECT_DOUBLE_EQ(relative_peak_to_peak(v, 2), 0.25);
  // differences 0, 0.25 - 0.1, -0.25 + 0.05, 0.5 - 0
  EXPECT_DOUBLE_EQ(relative_peak_to_peak_minus(v, r, 4), 0.5 - (-0.2));
  EXPECT_EQ(peak_to_peak(std::vector<double>{}), 0.0);
  EXPECT_EQ(peak_to_peak(std::vector<double>{-1.0, 3.0, 2.0}), 4.0);
}

// The window decides: a peak outside the first `count` samples does not count, and the amplitude
// is half the peak-to-peak.
TEST(MeasureCloud, PeakToPeakOverAWindowIgnoresLaterSamples) {
  const std::vector<double> v{1.0, 1.1, 0.95, 1.05, 0.5, 2.0};
  EXPECT_NEAR(peak_to_peak(relative_volumes(v, 4)), 0.15, 1e-15);
  EXPECT_NEAR(relative_peak_to_peak(v, 4), 0.15, 1e-15);
  EXPECT_NEAR(relative_peak_to_peak(v, 6), 1.5, 1e-15);  // the whole series
  EXPECT_NEAR(relative_amplitude(v, 4), 0.075, 1e-15);
  EXPECT_DOUBLE_EQ(peak_to_peak(std::vector<double>{0.2}), 0.0);
}

// N(y) g(z) is the field (3.8), and the AD Jacobians of both flows match central differences.
TEST(MeasureCloud, FieldJacobiansMatchFiniteDifferences) {
  const Vec<4> z(0.3, -0.4, 0.7, 1.1);
  for (const auto* sys : {&harmonic, &free_particle}) {
    const auto f = sys->rhs({z[0], z[1], z[2], z[3]});
    const Vec<4> g = canonical_field<double>(*sys, z), nf = NonholonomicParticle::N(z[1]) * g;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(nf[i], f[i], 1e-15);
    for (ParticleFlow flow : {ParticleFlow::conformal, ParticleFlow::hamiltonian}) {
      const auto [v, J] = field_and_jacobian(*sys, z, flow);
      const double d = 1e-6;
      for (int c = 0; c < 4; ++c) {
        Vec<4> a = z, b = z;
        a[c] += d, b[c] -= d;
        const Vec<4> fd = (field_and_jacobian(*sys, a, flow).first - field_and_jacobian(*sys, b, flow).first) / (2 * d);
        EXPECT_LT((fd - J.col(c)).cwiseAbs().maxCoeff(), 1e-9) << c;
      }
    }
  }
}

// The exact Jacobian of one step of Psi_{h,E} (implicit function theorem) against central differences
// of the step, and its symplecticity defect at round-off.
TEST(MeasureCloud, StepJacobianMatchesFiniteDifferencesAndIsSymplectic) {
  const Z z = state(0.3, -0.4, 0.7, 1.1);
  const double h = 0.25, E = 1.2, dz = 1e-6;
  for (Discretization d : all_discretizations) {
    const Z z1 = conformal_variational_step(d, harmonic, z, h, E).z;
    const Mat<4> J = psi_step_jacobian(d, harmonic, z, z1, h, E);
    Mat<4> fd;
    for (int c = 0; c < 4; ++c) {
      Z a = z, b = z;
      (c < 2 ? a.q[c] : a.p[c - 2]) += dz;
      (c < 2 ? b.q[c] : b.p[c - 2]) -= dz;
      const Z za = conformal_variational_step(d, harmonic, a, h, E).z, zb = conformal_variational_step(d, harmonic, b, h, E).z;
      fd.col(c) << (za.q - zb.q) / (2 * dz), (za.p - zb.p) / (2 * dz);
    }
    EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-8) << discretization_name(d);
    EXPECT_LT(symplecticity_defect<4>(J), 1e-14) << discretization_name(d);
  }
}

// Over a few periods, the variational equations of the flow of H (N = 1) keep Phi symplectic to the
// integration tolerance, those of (3.8) do not, and both agree with finite differences of the flow.
TEST(MeasureCloud, VariationalFlowJacobians) {
  const Vec<4> z0(0.0, 0.0, 1.0, 1.0);
  const auto c = variational_flow(harmonic, z0, ParticleFlow::conformal, 1.0, 5, 1e-12, 1e-12);
  const auto ham = variational_flow(harmonic, z0, ParticleFlow::hamiltonian, 1.0, 5, 1e-12, 1e-12);
  EXPECT_LT(symplecticity_defect<4>(ham.back().Phi), 1e-10);
  EXPECT_GT(symplecticity_defect<4>(c.back().Phi), 0.1);
  const double d = 1e-6;
  for (int k = 0; k < 4; ++k) {
    Vec<4> a = z0, b = z0;
    a[k] += d, b[k] -= d;
    const Vec<4> za = variational_flow(harmonic, a, ParticleFlow::conformal, 1.0, 5, 1e-13, 1e-13).back().z;
    const Vec<4> zb = variational_flow(harmonic, b, ParticleFlow::conformal, 1.0, 5, 1e-13, 1e-13).back().z;
    EXPECT_LT(((za - zb) / (2 * d) - c.back().Phi.col(k)).cwiseAbs().maxCoeff(), 1e-6) << k;
  }
}

// The 5-point rule is exact for quadratic densities: the standard 4-simplex, int x^a = a!/(4 + |a|)!.
TEST(MeasureCloud, SimplexRuleIsExactForQuadratics) {
  const std::vector<Point4> simplex{{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const Point4 apex{0.2, 0.2, 0.2, 0.2};
  const auto facets = hull_facets(simplex);
  ASSERT_EQ(facets.size(), 5u);
  const double got = hull_integral(simplex, facets, apex, [](const Point4& z) { return 1 + z[0] * z[0] + 3 * z[0] * z[1] - z[3]; });
  EXPECT_NEAR(got, 1.0 / 24 + 2.0 / 720 + 3.0 / 720 - 1.0 / 120, 1e-15);
}

TEST(MeasureCloud, SpherePointsAreSeededAndOnTheSphere) {
  SpherePoints a(5), b(5);
  for (int i = 0; i < 100; ++i) {
    const auto p = a.next(), q = b.next();
    EXPECT_EQ(p, q);
    EXPECT_NEAR(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3], 1.0, 1e-15);
  }
}

}  // namespace

}  // namespace measure_cloud_test

#pragma once
// The closed forms of 001 (Dubois & Rojas-Quintero 2025) for the Lobatto scheme on the harmonic
// oscillator H = p^2/(2m) + m w^2 q^2/2: the one-step map (13)-(14) and the system (12) it is
// derived from, the exact orbit of the map from (q, p) = (A, 0), the growth rate of Fig. 2 in exact
// arithmetic, and the exact stable set in h w. The executable builds the scheme from its definition
// (integrators/galerkin_variational.hpp); these closed forms are checked against it (unit tests)
// and give what a run in floating point cannot: the behaviour in exact arithmetic.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include <Eigen/LU>

#include "geomint/core/state.hpp"
#include "geomint/observables/linear_fit.hpp"

namespace geomint {

// 001 eq. (14), x = h^2 w^2: Phi = [[a, b], [c, a]] / delta~ acting on (p, q).
struct LobattoCoefficients {
  double delta_tilde, a, b, c;
};

inline LobattoCoefficients lobatto_coefficients(double h, double m, double w) {
  const double x = (h * w) * (h * w);
  return {1 + x / 30 + x * x / 1800,                                          // (14) delta~
          1 - 7 * x / 15 + 23 * x * x / 900 - std::pow(x, 3) / 3600,         // (14) a
          m * h * w * w / 43200 * (x - 60) * (x * x - 84 * x + 720),          // (14) b
          h / m * (1 - 2 * x / 15 + x * x / 300)};                            // (14) c
}

// 001 eq. (13): the one-step matrix on (p, q).
inline Mat<2> lobatto_map_13(double h, double m, double w) {
  const LobattoCoefficients k = lobatto_coefficients(h, m, w);
  Mat<2> Phi;
  Phi << k.a, k.b, k.c, k.a;
  return Phi / k.delta_tilde;
}

// 001 eq. (12), second equation: (q_{j+1} - q_j)/h = beta (p_j + p_{j+1})/m with beta as printed,
// -(12 x - 30)/(x^2 - 84 x + 720), or corrected, -12 (x - 30)/(x^2 - 84 x + 720) (x = h^2 w^2).
enum class Eq12 { printed, corrected };

// The one-step matrix on (p, q) defined by 001 eq. (12):
//   (p_{j+1} - p_j)/h = -m w^2 alpha (q_j + q_{j+1}), alpha = (x - 60)/(12 (x - 10)),
//   (q_{j+1} - q_j)/h = beta (p_j + p_{j+1})/m, solved for (p_{j+1}, q_{j+1}).
inline Mat<2> lobatto_map_12(double h, double m, double w, Eq12 form) {
  const double x = (h * w) * (h * w);
  const double alpha = (x - 60) / (12 * (x - 10));                                       // (12), first equation
  const double beta = (form == Eq12::printed ? -(12 * x - 30) : -12 * (x - 30)) / (x * x - 84 * x + 720);  // (12), second
  const double f = h * m * w * w * alpha, g = h * beta / m;
  Mat<2> lhs, rhs;
  lhs << 1, f, -g, 1;
  rhs << 1, -f, g, 1;
  return lhs.inverse() * rhs;
}

// z_0..z_N of a one-step matrix Phi on (p, q), 001's order of eq. (13) (in floating point: (12) as printed,
// iterated as a scheme of its own).
inline std::vector<PhaseState<1>> pq_orbit(const Mat<2>& Phi, const PhaseState<1>& z0, std::int64_t N) {
  std::vector<PhaseState<1>> zs = {z0};
  Vec<2> x(z0.p[0], z0.q[0]);
  for (std::int64_t j = 1; j <= N; ++j) x = Phi * x, zs.push_back(make_state(x[1], x[0]));
  return zs;
}

// The orbit of (13)-(14) from q = A, p = 0 in exact arithmetic where b < 0 < c (the first and the
// third stability interval): with cos theta = a/delta~, sin theta = sqrt(-bc)/delta~ (det Phi = 1),
// q_j = A cos(j theta), p_j = -sqrt(-b/c) A sin(j theta), so H_j - H_0 = K sin^2(j theta).
struct LobattoOrbit {
  double theta;  // rotation per step
  double K;      // H_j - H_0 = K sin^2(j theta)
  double H0;     // H(p_0, q_0)
  double Hd0;    // 001 eq. (15) at (p_0, q_0)
};

inline std::optional<LobattoOrbit> lobatto_exact_orbit(double h, double m, double w, double A) {
  const LobattoCoefficients k = lobatto_coefficients(h, m, w);
  if (!(k.b < 0 && 0 < k.c && k.delta_tilde > 0)) return std::nullopt;
  return LobattoOrbit{std::atan2(std::sqrt(-k.b * k.c), k.a),
                      0.5 * A * A * (-k.b / (m * k.c) - m * w * w),  // K = (A^2/2) (-b/(m c) - m w^2)
                      0.5 * m * w * w * A * A,                       // H_0 = m w^2 A^2 / 2
                      -k.b * A * A / (2 * k.delta_tilde)};           // (15) at p = 0: -b q^2 / (2 delta~)
}

// Fig. 2's growth rate in exact arithmetic: the window maxima of |H_j - H_0| = |K| sin^2(j theta)
// over the steps j = 1..n, n = periods T/h, in windows of n/windows steps (complete windows only,
// as the executable's runs), and their least-squares slope per period.
struct LobattoGrowth {
  std::vector<double> maxima;     // per window
  double slope_per_period;        // least-squares slope of the maxima against time, per period
  double bound;                   // |K|: |H_j - H_0| <= |K| for every j
  std::optional<double> periods_to_peak;  // periods until a sample first reaches |K| (0: one starts on it)
  double eps;                     // theta - 2 pi / N, N = T/h steps per period
};

// The largest sin^2 over the samples j = j0, j0 + N, ..., j1 of the residue class k (mod N):
// their phases are 2 pi k/N + j eps, which move monotonically, so the maximum is 1 if a peak
// pi/2 + l pi lies between the ends, else at an end.
inline double class_maximum(std::int64_t k, std::int64_t N, std::int64_t j0, std::int64_t j1, double eps) {
  const double half = std::numbers::pi / 2;
  const double phi = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(N);
  const double a0 = phi + static_cast<double>(j0) * eps, a1 = phi + static_cast<double>(j1) * eps;
  const double lo = std::min(a0, a1), hi = std::max(a0, a1);
  const double peak = half + std::numbers::pi * std::ceil((lo - half) / std::numbers::pi);
  return peak <= hi ? 1.0 : std::max(std::pow(std::sin(a0), 2), std::pow(std::sin(a1), 2));
}

// Periods until the first sample reaches the peak of sin^2: the residue class whose phase is
// nearest a peak, in the direction in which eps moves it (0 if one starts on it).
inline std::optional<double> periods_to_peak(std::int64_t N, double eps, double h, double T) {
  if (eps == 0) return std::nullopt;
  const double half = std::numbers::pi / 2;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::int64_t k = 0; k < N; ++k) {
    const double phi = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(N);
    double d = std::fmod(eps > 0 ? half - phi : phi - half, std::numbers::pi);  // distance to the next peak
    if (d < 0) d += std::numbers::pi;
    nearest = std::min(nearest, std::min(d, std::numbers::pi - d) < 1e-12 ? 0.0 : d);
  }
  return nearest / std::abs(eps) * h / T;
}

// nullopt where the orbit does not exist or h is not T/N for a whole N (|N eps| > 1e-3).
inline std::optional<LobattoGrowth> lobatto_exact_growth(double h, double m, double w, double A, double periods,
                                                         std::int64_t windows) {
  const auto orbit = lobatto_exact_orbit(h, m, w, A);
  const double T = 2 * std::numbers::pi / w;
  const auto N = static_cast<std::int64_t>(std::llround(T / h));
  if (!orbit || N < 1) return std::nullopt;
  const double eps = orbit->theta - 2 * std::numbers::pi / static_cast<double>(N);
  if (std::abs(static_cast<double>(N) * eps) > 1e-3) return std::nullopt;
  const std::int64_t n = std::llround(periods * T / h);
  const std::int64_t W = std::max<std::int64_t>(1, n / windows);
  const auto mod = [](std::int64_t a, std::int64_t b) { return ((a % b) + b) % b; };
  LobattoGrowth g{{}, 0, std::abs(orbit->K), periods_to_peak(N, eps, h, T), eps};
  for (std::int64_t i = 0; i < n / W; ++i) {
    const std::int64_t s = i * W + 1, e = (i + 1) * W;  // the steps of window i
    double best = 0;
    for (std::int64_t k = 0; k < N; ++k) {
      const std::int64_t j0 = s + mod(k - s, N), j1 = e - mod(e - k, N);  // first and last step of class k
      if (j0 <= e) best = std::max(best, class_maximum(k, N, j0, j1, eps));
    }
    g.maxima.push_back(g.bound * best);
  }
  std::vector<double> index(g.maxima.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<double>(i);
  g.slope_per_period = linear_fit(index, g.maxima).slope / (static_cast<double>(W) * h / T);
  return g;
}

// With x = h^2 w^2, (14) gives a - delta~ = -x (x - 30)(x - 60)/3600 and
// a + delta~ = -(x - 10)(x^2 - 84 x + 720)/3600: the map is stable (eigenvalues on the unit circle,
// det Phi = 1) where |a/delta~| < 1, and these are its boundaries, the roots in x >= 0, ascending.
inline std::vector<double> lobatto_stability_boundaries_x() {
  const double r = std::sqrt(42.0 * 42.0 - 720.0);  // x^2 - 84 x + 720 = 0 at x = 42 -+ r
  std::vector<double> x = {0.0, 30.0, 60.0, 10.0, 42.0 - r, 42.0 + r};
  std::sort(x.begin(), x.end());
  return x;
}

// The exact stable set of (13)-(14) in h w: the intervals between consecutive boundaries on which
// |a/delta~| < 1 (tested at their midpoints; beyond the last boundary |a/delta~| grows like x/2).
inline std::vector<std::array<double, 2>> lobatto_stable_set() {
  const auto x = lobatto_stability_boundaries_x();
  std::vector<std::array<double, 2>> set;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const LobattoCoefficients k = lobatto_coefficients(std::sqrt(0.5 * (x[i] + x[i + 1])), 1.0, 1.0);
    if (std::abs(k.a / k.delta_tilde) < 1) set.push_back({std::sqrt(x[i]), std::sqrt(x[i + 1])});
  }
  return set;
}

}  // namespace geomint

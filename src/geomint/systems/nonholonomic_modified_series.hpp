#pragma once
// The modified quantities of 003 Sec. 4 for the five discretizations (5.1),
// truncated at h^ell: the modified conformal Hamiltonian E^(ell) (4.3), the
// modified conformal factor N^(ell)_mod (4.9) and the modified altered
// Hamiltonian K^(4)_mod (4.2). Their coefficients are derived symbolically
// by scripts/derive_nonholonomic.py into nonholonomic_modified.hpp, which only
// nonholonomic_modified_series.cpp compiles (the series of every method and potential
// are compiled once, not in each file that evaluates one).
#include <array>
#include <cstdint>
#include <tuple>
#include <vector>

#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {

inline constexpr int max_modified_order = 6;  // (nonholonomic::generated::max_order: checked where compiled)

class ModifiedSeries {
 public:
  ModifiedSeries(Discretization d, const NonholonomicParticle& sys, double h) : d_(d), sys_(sys), h_(h) {}

  // E^(ell) = H + h^2 E_2 + ... + h^ell E_ell (003 eq. (4.3), truncated).
  double E(int ell, const PhaseState<2>& z) const;
  // N^(ell)_mod = N + h^2 N_2 + ... + h^ell N_ell (003 eq. (4.9), truncated); mu^(ell)_mod has density 1/N^(ell)_mod.
  double N(int ell, const PhaseState<2>& z) const;
  // K^(4)_mod(z; E) = N (H - E) + h^2 K_2 + h^4 K_4 (003 eq. (4.2), truncated).
  double K4(const PhaseState<2>& z, double E) const;

  // std::invalid_argument unless ell is even and 0 <= ell <= max_modified_order.
  static void check_order(int ell);

 private:
  Discretization d_;
  NonholonomicParticle sys_;
  double h_;
};

// ---- The method Phi^(ell) of 003 (4.5): Psi_{h,E*} with E* = E^(ell)(z_0), E fixed at the start
// (nonholonomic_phi.cpp) ----

// One point's run: z_0 .. z_n as (x, y, px, py), and the Newton iterations summed over its steps.
struct PointTrajectory {
  std::vector<std::array<double, 4>> z;
  std::int64_t iterations = 0;
  auto fields() { return std::tie(z, iterations); }  // (a record of runner/distributed_map.hpp)
};

// n steps of Phi^(ell) of discretization d at the step h from z0.
PointTrajectory run_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                        const std::array<double, 4>& z0, std::int64_t n);

// A cloud's run: snapshots[j][i] is point i at step j (point 0: the image of the centre), and the Newton iterations
// and steps over all its points.
struct CloudRun {
  std::vector<std::vector<std::array<double, 4>>> snapshots;
  std::int64_t iterations = 0, steps = 0;
  auto fields() { return std::tie(snapshots, iterations, steps); }
};

// The runs of the points of a cloud as a CloudRun.
CloudRun transpose(const std::vector<PointTrajectory>& per_point);

// n steps of Phi^(ell) of d at the step h from each point of `cloud`, each point its own E*.
CloudRun cloud_phi(Discretization d, const NonholonomicParticle& sys, double h, int ell,
                   const std::vector<std::array<double, 4>>& cloud, std::int64_t n);

// The largest relative difference of the generated E^(2), E^(4), N^(2), N^(4) and K^(4)_mod from independent
// reference values at h = 0.25 (systems/nonholonomic_golden.hpp) for the potential of sys.
double modified_series_golden_error(const NonholonomicParticle& sys);

}  // namespace geomint

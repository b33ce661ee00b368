#pragma once
// The modified quantities of 003 Sec. 4 for the five discretizations (5.1),
// truncated at h^ell: the modified conformal Hamiltonian E^(ell) (4.3), the
// modified conformal factor N^(ell)_mod (4.9) and the modified altered
// Hamiltonian K^(4)_mod (4.2). Their coefficients are derived symbolically
// by scripts/derive_nonholonomic.py into nonholonomic_modified.hpp, which only
// nonholonomic_modified_series.cpp compiles (the series of every method and potential
// are compiled once, not in each file that evaluates one).
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

}  // namespace geomint

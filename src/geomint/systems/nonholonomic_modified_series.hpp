#pragma once
// The modified quantities of 003 Sec. 4 for the five discretizations (5.1),
// truncated at h^ell: the modified conformal Hamiltonian E^(ell) (4.3), the
// modified conformal factor N^(ell)_mod (4.9) and the modified altered
// Hamiltonian K^(4)_mod (4.2). Their coefficients are derived symbolically
// by scripts/derive_nonholonomic.py into nonholonomic_modified.hpp.
#include <stdexcept>
#include <string>

#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/systems/nonholonomic_modified.hpp"
#include "geomint/systems/nonholonomic_particle.hpp"

namespace geomint {

inline constexpr int max_modified_order = nonholonomic::generated::max_order;

class ModifiedSeries {
 public:
  ModifiedSeries(Discretization d, const NonholonomicParticle& sys, double h)
      : s_(nonholonomic::generated::series[static_cast<int>(d)][sys.potential == Potential::free ? 1 : 0]),
        sys_(sys), h_(h) {}

  // E^(ell) = H + h^2 E_2 + ... + h^ell E_ell (003 eq. (4.3), truncated).
  double E(int ell, const PhaseState<2>& z) const { return sum(ell, sys_.H(z), s_.E, z); }
  // N^(ell)_mod = N + h^2 N_2 + ... + h^ell N_ell (003 eq. (4.9), truncated); mu^(ell)_mod has density 1/N^(ell)_mod.
  double N(int ell, const PhaseState<2>& z) const { return sum(ell, NonholonomicParticle::N(z.q[1]), s_.N, z); }
  // K^(4)_mod(z; E) = N (H - E) + h^2 K_2 + h^4 K_4 (003 eq. (4.2), truncated).
  double K4(const PhaseState<2>& z, double E) const {
    const double x = z.q[0], y = z.q[1], px = z.p[0], py = z.p[1], h2 = h_ * h_;
    return sys_.K(z, E) + h2 * (s_.K[0](x, y, px, py, E) + h2 * s_.K[1](x, y, px, py, E));
  }

  static void check_order(int ell) {
    if (ell < 0 || ell % 2 || ell > max_modified_order)
      throw std::invalid_argument("modified quantities exist for even orders 0.." + std::to_string(max_modified_order) + ", not " + std::to_string(ell));
  }

 private:
  template <class Coefficients>
  double sum(int ell, double leading, const Coefficients& c, const PhaseState<2>& z) const {
    check_order(ell);
    const double x = z.q[0], y = z.q[1], px = z.p[0], py = z.p[1];
    double acc = 0, hk = 1;
    for (int k = 0; 2 * (k + 1) <= ell; ++k) hk *= h_ * h_, acc += hk * c[k](x, y, px, py);
    return leading + acc;
  }

  const nonholonomic::generated::ModifiedSeries& s_;
  NonholonomicParticle sys_;
  double h_;
};

}  // namespace geomint

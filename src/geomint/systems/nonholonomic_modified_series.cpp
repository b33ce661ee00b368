#include "geomint/systems/nonholonomic_modified_series.hpp"

#include <stdexcept>
#include <string>

#include "geomint/systems/nonholonomic_modified.hpp"

namespace geomint {
namespace {

static_assert(max_modified_order == nonholonomic::generated::max_order);

const nonholonomic::generated::ModifiedSeries& coefficients(Discretization d, const NonholonomicParticle& sys) {
  return nonholonomic::generated::series[static_cast<int>(d)][sys.potential == Potential::free ? 1 : 0];
}

// leading + h^2 c_0(z) + h^4 c_1(z) + ... up to h^ell.
template <class Coefficients>
double sum(int ell, double h, double leading, const Coefficients& c, const PhaseState<2>& z) {
  ModifiedSeries::check_order(ell);
  const double x = z.q[0], y = z.q[1], px = z.p[0], py = z.p[1];
  double acc = 0, hk = 1;
  for (int k = 0; 2 * (k + 1) <= ell; ++k) hk *= h * h, acc += hk * c[k](x, y, px, py);
  return leading + acc;
}

}  // namespace

double ModifiedSeries::E(int ell, const PhaseState<2>& z) const {
  return sum(ell, h_, sys_.H(z), coefficients(d_, sys_).E, z);
}

double ModifiedSeries::N(int ell, const PhaseState<2>& z) const {
  return sum(ell, h_, NonholonomicParticle::N(z.q[1]), coefficients(d_, sys_).N, z);
}

double ModifiedSeries::K4(const PhaseState<2>& z, double E) const {
  const auto& s = coefficients(d_, sys_);
  const double x = z.q[0], y = z.q[1], px = z.p[0], py = z.p[1], h2 = h_ * h_;
  return sys_.K(z, E) + h2 * (s.K[0](x, y, px, py, E) + h2 * s.K[1](x, y, px, py, E));
}

void ModifiedSeries::check_order(int ell) {
  if (ell < 0 || ell % 2 || ell > max_modified_order)
    throw std::invalid_argument("modified quantities exist for even orders 0.." + std::to_string(max_modified_order) +
                                ", not " + std::to_string(ell));
}

}  // namespace geomint

// The reference integrator of reference/odeint_reference.hpp: Boost.Odeint's Bulirsch-Stoer stepper
// on std::vector<double>, parsed and compiled here only.
#include "geomint/reference/odeint_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>

namespace geomint {

namespace odeint = boost::numeric::odeint;

struct ReferenceIntegrator::Impl {
  ReferenceField f;
  odeint::bulirsch_stoer<std::vector<double>> stepper;
  std::vector<double> x;
};

ReferenceIntegrator::ReferenceIntegrator(std::size_t n, ReferenceField f, double rtol, double atol)
    : impl_(std::make_unique<Impl>(Impl{std::move(f), odeint::bulirsch_stoer<std::vector<double>>(atol, rtol),
                                        std::vector<double>(n)})) {}

ReferenceIntegrator::~ReferenceIntegrator() = default;

void ReferenceIntegrator::integrate(std::span<double> x, double t0, double t1, double dt0) {
  if (x.size() != impl_->x.size())
    throw std::invalid_argument("ReferenceIntegrator: a state of " + std::to_string(x.size()) + " values, not " +
                                std::to_string(impl_->x.size()));
  const auto where = [&] { return "odeint reference from t = " + std::to_string(t0) + " to " + std::to_string(t1); };
  std::vector<double>& y = impl_->x;
  std::copy(x.begin(), x.end(), y.begin());
  const ReferenceField& f = impl_->f;
  try {
    odeint::integrate_adaptive(impl_->stepper, [&f](const std::vector<double>& s, std::vector<double>& dsdt, double) {
      f(s.data(), dsdt.data());
    }, y, t0, t1, dt0);
  } catch (const odeint::odeint_error& e) {
    throw NumericalFailure(where() + ": " + e.what());
  }
  if (!std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); }))
    throw NumericalFailure(where() + ": the state is not finite");
  std::copy(y.begin(), y.end(), x.begin());
}

}  // namespace geomint

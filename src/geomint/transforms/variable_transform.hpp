#pragma once
// Order-compensating variable transformations ybar = Psi(y) of 000 Section 2.
// Each solves (12) via (13), so the transformed field (3) is the constant C1
// and explicit Euler integrates it exactly.
#include <cmath>

namespace geomint {

// 000 eq. (15): Psi(y) = ln(y)/alpha for y' = -alpha*y (C1 = -1, C2 = ln(y0)/alpha).
// By (3) the transformed equation is ybar' = Psi'(y) f(y) = -1; the paper's
// (16) prints -alpha, which is the field for Psi = ln y instead (see paper/).
struct DecayCompensation {
  double alpha;
  double operator()(double y) const { return std::log(y) / alpha; }
  double derivative(double y) const { return 1.0 / (alpha * y); }
  double inverse(double ybar) const { return std::exp(alpha * ybar); }
};

// 000 eq. (16) as printed, ybar' = -alpha: the transformed field of Psi = ln y, not of (15). With (15)
// it gives the exact solution only for alpha = 1 (kept to show the misprint, published.toml).
struct DecayFieldAsPrinted16 {
  double alpha;
  double f(double) const { return -alpha; }
};

// 000 eq. (18): Psi(y) = (ln(1 - (b/a) ln y0) - ln(1 - (b/a) ln y)) / b for the
// Gompertz equation (17) (C1 = 1, C2 = 0); defined for y < e^{a/b}.
struct GompertzCompensation {
  double a, b, y0;
  double operator()(double y) const {
    return (std::log(1.0 - b / a * std::log(y0)) - std::log(1.0 - b / a * std::log(y))) / b;
  }
  double derivative(double y) const { return 1.0 / (y * (a - b * std::log(y))); }  // = 1/f(y), (13)
  // ln y = (a/b) (1 - (1 - (b/a) ln y0) e^{-b ybar}).
  double inverse(double ybar) const {
    return std::exp(a / b * (1.0 - (1.0 - b / a * std::log(y0)) * std::exp(-b * ybar)));
  }
};

// 000 eq. (3), scalar case: ybar' = fbar(ybar) = Psi'(y) f(y) with y = Psi^{-1}(ybar).
template <class Sys, class Psi>
struct TransformedODE {
  Sys sys;
  Psi psi;
  double f(double ybar) const {
    const double y = psi.inverse(ybar);
    return psi.derivative(y) * sys.f(y);
  }
};

template <class Sys, class Psi>
TransformedODE(Sys, Psi) -> TransformedODE<Sys, Psi>;

}  // namespace geomint

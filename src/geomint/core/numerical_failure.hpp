#pragma once
// A computation whose result would be meaningless: a NaN or Inf, Newton's method not converged, a
// trajectory outside its chart, a reference integrator that gives up, an order fit with too few
// points above round-off. The runner reports it on one line, naming the study, and exits with 4
// (runner/experiment.hpp); no results are written.
#include <stdexcept>

namespace geomint {

struct NumericalFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace geomint

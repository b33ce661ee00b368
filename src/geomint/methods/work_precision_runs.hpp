#pragma once
// The runs of a method by name (methods/by_name.hpp) for a work-precision set (analysis/work_precision_set.hpp):
// at each step h, to t_end from z0, its force evaluations by a counting run (systems/counting.hpp), the error
// of its end state (processed where the method has processing) by a run of its own, and a run to time with the
// set's other runs (WorkPrecisionSet::time). MethodsOn<Sys> and MethodsOn<Counting<Sys>> are compiled in the
// library; a study that includes this header compiles only the loop.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/analysis/work_precision_set.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/core/numerical_failure.hpp"
#include "geomint/io/csv.hpp"
#include "geomint/methods/by_name.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/systems/counting.hpp"

namespace geomint {

// error(z_N) of each run; NumericalFailure where it is not finite.
template <class Sys, class Err>
void add_method_runs(WorkPrecisionSet& set, const std::string& method, const Sys& sys, const typename Sys::State& z0,
                     const std::vector<double>& hs, double t_end, const Err& error) {
  for (double h : hs) {
    const std::int64_t n = steps_to(t_end, h);
    std::int64_t evals = 0;
    MethodsOn<Counting<Sys>>::integrate(method, Counting<Sys>{sys, &evals}, z0, h, n);
    const double err = error(MethodsOn<Sys>::integrate(method, sys, z0, h, n));
    if (!std::isfinite(err))
      throw NumericalFailure(method + " at h = " + format_double(h) + ": the error at t = " + format_double(t_end) +
                             " is not finite");
    set.add({label_of(method), h, static_cast<double>(n), {}, static_cast<double>(evals), err},
            MethodsOn<Sys>::timed(method, sys, {z0}, h, n));
  }
}

}  // namespace geomint

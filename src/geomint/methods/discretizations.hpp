#pragma once
// The registry's conformal methods whose label names a discrete Lagrangian (5.1) of 003 (M, MT, TM, TT, T): what a
// scene may name, the scene's, and the summary of a study that runs them: values by label, and their ranges over each
// quadrature of N.
#include <string>
#include <vector>

#include "geomint/integrators/conformal_variational.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

class Context;
class Scene;

// What a scene's `methods` admits: the registry names (conformal_M, ...) and, as an older spelling, the labels (M, ...).
std::vector<std::string> discretization_choices();

// The discretizations of the scene's `methods` (names or labels of discretization_choices).
std::vector<Discretization> scene_discretizations(const Scene& s);

// The ranges of a {label: number} object over the discretizations: "all", and those of each quadrature of N
// (003 (5.1), the first letter of the label): "N_midpoint" (M, MT) and "N_trapezoidal" (TM, TT, T), each
// {min, max, abs: {min, max}}. A group is left out if one of its values is not a finite number (an order without a fit).
Value method_ranges(const Value& per_method);

// Sets summary.reproduced.<key> (or summary.reproduced.<nest>.<key>) to a {label: number} object and
// summary.ranges.<key> (summary.ranges.<nest>.<key>) to its method_ranges.
void put_methods(Context& ctx, const std::string& key, Value per_method, const std::string& nest = "");

// {label: a[label] / b[label]} over the labels of a.
Value ratio_per_method(const Value& a, const Value& b);

// What a study reports besides its results: the thread count (summary.timing.threads) and the labels of the
// discretizations it runs (summary.methods; its CSV columns).
void put_run_facts(Context& ctx, const std::vector<Discretization>& methods);

}  // namespace geomint

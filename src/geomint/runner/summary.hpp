#pragma once
// What summary.json reports, in one shape in every experiment (runner/results.hpp): the labels of a
// figure's methods, the range of a list, its spread, the range of a scene's list of steps, and how reproduced
// values meet the printed digits.
#include <algorithm>
#include <string>
#include <vector>

#include "geomint/methods/registry.hpp"
#include "geomint/runner/results.hpp"

namespace geomint {

// The labels of registered methods (their CSV columns and summary keys), for summary.methods.<study>.
Value labels_of(const std::vector<std::string>& methods);

// {min, max} of a non-empty list.
Value range_of(const std::vector<double>& v);

// {min, max, mean} of a non-empty list.
Value spread_of(const std::vector<double>& v);

// {min, max, count} of a scene's non-empty list of steps.
Value h_range(const std::vector<double>& hs);

class Context;
// How the values at `keys` of the summary (each a record by a parameter, e.g. a mesh) meet the paper's values
// printed with `digits` significant digits, through the comparisons the runner will make (Context::comparison).
// Those compared (relatively): "compared", how many "round_to_printed_digits", and the largest relative difference,
// "max_relative_deviation". Those at round-off (not comparable): the range of the printed values, "<name>_range"
// (name: the key's last part). Keys without a comparison in this scene are left out.
Value printed_digits_agreement(const Context& ctx, const std::vector<std::string>& keys, int digits);

}  // namespace geomint

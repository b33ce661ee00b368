#pragma once
// What summary.json reports, in one shape in every experiment (runner/results.hpp): the labels of a
// figure's methods, the range of a list, its spread, and the range of a scene's list of steps.
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

}  // namespace geomint

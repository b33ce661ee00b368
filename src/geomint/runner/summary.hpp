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

class Scene;
// What a study of steps from several starts reports of its scene: "h_range" (h_range of the steps `steps_key`) and
// "initial_conditions" (the number of rows of `starts_key`).
void record_steps_and_starts(Value& summary, const Scene& s, const char* steps_key, const char* starts_key);

// {min, q1, median, q3, max} of a non-empty list (analysis/claim_share.hpp).
Value quartiles(const std::vector<double>& v);

// A yes/no claim "value > bound" over independent samples, one value each (analysis/claim_share.hpp): "samples",
// "holds"; with a sample, the "quartiles" of the values and the standard error of the share if the claim held by a
// coin flip, "coin_flip_stderr"; with at least min_samples, the "share" where it holds, its binomial standard error
// "share_stderr", and "share_in_coin_flip_stderr", (share - 1/2) / coin_flip_stderr.
Value claim_share_summary(const std::vector<double>& values, double bound, std::size_t min_samples);

class Context;
// How the values at `keys` of the summary (each a record by a parameter, e.g. a mesh) meet the paper's values
// printed with `digits` significant digits, through the comparisons the runner will make (Context::comparison).
// Those compared (relatively): "compared", how many "round_to_printed_digits", and the largest relative difference,
// "max_relative_deviation". Those at round-off (not comparable): the range of the printed values, "<name>_range"
// (name: the key's last part). Keys without a comparison in this scene are left out.
Value printed_digits_agreement(const Context& ctx, const std::vector<std::string>& keys, int digits);

}  // namespace geomint

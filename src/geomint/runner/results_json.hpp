#pragma once
// The runner's side of runner/results.hpp: a summary Value as JSON (summary.json) and back. Only the
// runner and the library's .cpp files include this; a study never does.
#include <nlohmann/json.hpp>

#include "geomint/runner/results.hpp"

namespace geomint {

nlohmann::ordered_json to_json(const Value& v);
Value value_of(const nlohmann::ordered_json& j);

}  // namespace geomint

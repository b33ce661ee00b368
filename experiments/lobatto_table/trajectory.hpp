#pragma once
// The trajectory of a registered method by name (methods/by_name.hpp), for the studies that draw or
// tabulate whole trajectories: Table 1 and Fig. 1.
#include <cstdint>
#include <string>
#include <vector>

#include "geomint/methods/by_name.hpp"
#include "lobatto_table.hpp"

namespace geomint::lobatto_table {

// The trajectory z_0..z_n of a registered method.
template <class Sys>
std::vector<Z1> trajectory(const std::string& method, const Sys& sys, const Z1& z0, double h, std::int64_t n) {
  std::vector<Z1> zs;
  MethodsOn<Sys>::integrate(method, sys, z0, h, n, [&](std::int64_t, const Z1& z) { zs.push_back(z); });
  return zs;
}

}  // namespace geomint::lobatto_table

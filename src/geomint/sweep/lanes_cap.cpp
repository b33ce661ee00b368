#include "geomint/sweep/lanes_cap.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>

namespace geomint {
namespace {
constexpr std::array<std::string_view, 3> kWidestFirst{"avx512", "avx2", "sse2"};
}  // namespace

std::string lanes_cap() {
  const char* v = std::getenv("GEOMINT_LANES");
  const std::string cap = v ? v : "";
  if (!cap.empty() && std::find(kWidestFirst.begin(), kWidestFirst.end(), cap) == kWidestFirst.end())
    throw std::invalid_argument("GEOMINT_LANES=" + cap + ": the lanes' widest instruction set is avx512, avx2 or sse2");
  return cap;
}

bool lanes_allowed(std::string_view isa) {
  const std::string cap = lanes_cap();
  const auto rank = [](std::string_view s) {
    return std::find(kWidestFirst.begin(), kWidestFirst.end(), s) - kWidestFirst.begin();
  };
  return cap.empty() || rank(isa) >= rank(cap);
}

}  // namespace geomint

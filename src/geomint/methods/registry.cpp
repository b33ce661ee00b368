#include "geomint/methods/registry.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "geomint/methods/methods.hpp"

namespace geomint {

namespace {

template <class... Ms>
constexpr std::array<MethodInfo, sizeof...(Ms)> entries(MethodList<Ms...>) {
  return {Ms::info...};
}

constexpr auto registry = entries(registered_methods{});

// A name or label finds one entry: no name or label is used twice.
constexpr bool lookups_are_unique() {
  for (std::size_t i = 0; i < registry.size(); ++i)
    for (std::size_t j = 0; j < registry.size(); ++j) {
      const MethodInfo &a = registry[i], &b = registry[j];
      if (a.name == b.label && i != j) return false;
      if (i < j && (a.name == b.name || a.label == b.label || a.label == b.name)) return false;
    }
  return true;
}
static_assert(lookups_are_unique(), "two registered methods share a name or a label");

}  // namespace

std::span<const MethodInfo> method_registry() { return registry; }

const MethodInfo* find_method(std::string_view name_or_label) {
  for (const MethodInfo& m : registry)
    if (m.name == name_or_label || m.label == name_or_label) return &m;
  return nullptr;
}

const MethodInfo& method_info(std::string_view name_or_label) {
  if (const MethodInfo* m = find_method(name_or_label)) return *m;
  std::string valid;
  for (const MethodInfo& m : registry) valid += (valid.empty() ? "" : ", ") + std::string(m.name);
  throw std::invalid_argument("unknown method '" + std::string(name_or_label) + "'; the registered methods are " + valid);
}

std::string_view family_name(Family f) {
  switch (f) {
    case Family::explicit_method: return "explicit";
    case Family::symplectic: return "symplectic";
    case Family::variational: return "variational";
    case Family::processed: return "processed";
    case Family::conformal: return "conformal";
    case Family::reference: return "reference";
  }
  return "?";
}

}  // namespace geomint

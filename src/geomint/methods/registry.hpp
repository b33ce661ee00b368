#pragma once
// The method registry: name, family, orders, linear-stability bounds,
// properties and citation of every method, the one place a method is
// described. The entries are the `info` of the method types listed in
// methods/methods.hpp, in that order; experiments look methods up here (by
// scene name or by label), `geomint-methods` prints the table, and
// tests/verification checks every entry.
#include <span>
#include <string>
#include <string_view>

namespace geomint {

enum class Family { explicit_method, symplectic, variational, processed, conformal, reference };

namespace property {
inline constexpr unsigned symplectic = 1, time_reversible = 2, volume_preserving = 4, modified_measure = 8;
}

// For a processed method (000 eq. (22)-(23)) the stability bounds and the
// properties are those of its kernel, the map that is iterated.
struct MethodInfo {
  std::string_view name;        // scene name (canonical)
  std::string_view label;       // short prefix of CSV columns and summary keys
  Family family;
  int order;                    // declared order; for processed methods the effective order
  int kernel_order;             // order of the kernel alone (== order unless processed)
  double real_bound;            // stable on y' = lambda y (lambda < 0) for h|lambda| <= bound; inf: every h; NaN: not applicable
  double oscillatory_bound;     // stable on q'' = -w^2 q for w h < bound; 0: unstable for every h > 0; inf: every h; NaN: not declared
  unsigned properties = 0;      // property:: flags
  int measure_order = 0;        // Phi^(ell): mu^(ell)_mod preserved to O(h^measure_order), = ell + 2; else 0
  std::string_view applies_to;  // the systems it can step, in words
  std::string_view citation;    // the paper and equation(s) that define it
  // How figures show it (figures/methods.gpi, generated from these by geomint-methods --gnuplot):
  std::string_view title;       // its name in a figure's key (gnuplot enhanced text)
  std::string_view equations;   // the equations that define it in each paper that prints them: "000 (26)–(28); 004 (1.3)"
  std::string_view colour;      // its colour in every figure ("#rrggbb": Okabe-Ito, and Paul Tol's bright for 003's five)
  int marker;                   // its marker in every figure (a gnuplot point type, 1-15); (colour, marker) is one
                                // method's alone (ctest MethodRegistry.ColourAndMarkerNameOneMethod): methods drawn
                                // together are told apart, whichever of them a scene names

  bool has(unsigned p) const { return (properties & p) == p; }
};

std::span<const MethodInfo> method_registry();  // all entries, in a fixed order
const MethodInfo* find_method(std::string_view name_or_label);
// Throws std::invalid_argument naming the valid names.
const MethodInfo& method_info(std::string_view name_or_label);
// The label (CSV column and summary-key prefix) of a method named by its name or label.
inline std::string label_of(std::string_view name_or_label) { return std::string(method_info(name_or_label).label); }
inline std::vector<std::string> method_labels(const std::vector<std::string>& names_or_labels) {
  std::vector<std::string> labels;
  for (const auto& m : names_or_labels) labels.push_back(label_of(m));
  return labels;
}
std::string_view family_name(Family);

}  // namespace geomint

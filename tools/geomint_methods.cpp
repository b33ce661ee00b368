// geomint-methods: the method registry (src/geomint/methods/registry.hpp) as a
// table, as JSON (--json) or as one name per line (--names).
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "geomint/methods/registry.hpp"

using namespace geomint;

namespace {

std::vector<std::string> property_names(unsigned p) {
  std::vector<std::string> names;
  for (const auto& [flag, name] : {std::pair{property::symplectic, "symplectic"}, {property::time_reversible, "time_reversible"},
                                   {property::volume_preserving, "volume_preserving"}, {property::modified_measure, "modified_measure"}})
    if (p & flag) names.emplace_back(name);
  return names;
}

std::string properties_text(unsigned p) {
  std::string s;
  for (const auto& name : property_names(p)) s += (s.empty() ? "" : "|") + name;
  return s.empty() ? "-" : s;
}

std::string bound_text(double b) {
  if (std::isnan(b)) return "-";
  if (std::isinf(b)) return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", b);
  return buf;
}

nlohmann::ordered_json bound_json(double b) {
  if (std::isnan(b)) return nullptr;
  if (std::isinf(b)) return "inf";
  return b;
}

void print_table() {
  std::printf("%-29s %-22s %-10s %5s %6s %11s %11s %-33s %7s %-46s %s\n", "name", "label", "family", "order", "kernel",
              "real_bound", "osc_bound", "properties", "measure", "applies_to", "citation");
  for (const MethodInfo& m : method_registry())
    std::printf("%-29s %-22s %-10s %5d %6d %11s %11s %-33s %7d %-46s %s\n", std::string(m.name).c_str(),
                std::string(m.label).c_str(), std::string(family_name(m.family)).c_str(), m.order, m.kernel_order,
                bound_text(m.real_bound).c_str(), bound_text(m.oscillatory_bound).c_str(),
                properties_text(m.properties).c_str(), m.measure_order, std::string(m.applies_to).c_str(),
                std::string(m.citation).c_str());
}

void print_json() {
  auto all = nlohmann::ordered_json::array();
  for (const MethodInfo& m : method_registry())
    all.push_back({{"name", m.name}, {"label", m.label}, {"family", family_name(m.family)}, {"order", m.order},
                   {"kernel_order", m.kernel_order}, {"real_bound", bound_json(m.real_bound)},
                   {"oscillatory_bound", bound_json(m.oscillatory_bound)}, {"properties", property_names(m.properties)},
                   {"measure_order", m.measure_order}, {"applies_to", m.applies_to}, {"citation", m.citation}});
  std::printf("%s\n", all.dump(2).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const std::string_view option = argc > 1 ? argv[1] : "";
  if (argc > 2 || !(option.empty() || option == "--json" || option == "--names" || option == "--help")) {
    std::fprintf(stderr, "geomint-methods: unknown option '%s' (use --json, --names or --help)\n", argv[argc > 2 ? 2 : 1]);
    return 2;
  }
  if (option == "--help") {
    std::printf("usage: geomint-methods [--json | --names]\n  the method registry as a table, as JSON (bounds: a number, "
                "\"inf\", or null where not applicable), or one scene name per line\n");
  } else if (option == "--json") {
    print_json();
  } else if (option == "--names") {
    for (const MethodInfo& m : method_registry()) std::printf("%s\n", std::string(m.name).c_str());
  } else {
    print_table();
  }
  return 0;
}

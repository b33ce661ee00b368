// Verification of every registered method (verification.hpp): one test per method, the checks of its
// generic binding or its case.
#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "geomint/methods/methods.hpp"
#include "verification.hpp"

using namespace geomint;
using namespace geomint::verification;

namespace {

void verify_bound_method(const MethodInfo& m) {
  check_orders(m);
  check_bounds(m);
  check_properties(m);
}

using Case = void (*)(const MethodInfo&);
const std::map<std::string_view, Case> cases = {
    {"compensated_symplectic_euler", verify_compensated_symplectic_euler},
    {"conformal_M", verify_conformal}, {"conformal_MT", verify_conformal}, {"conformal_TM", verify_conformal},
    {"conformal_TT", verify_conformal}, {"conformal_T", verify_conformal},
    {"phi0", verify_phi}, {"phi2", verify_phi}, {"phi4", verify_phi}, {"phi6", verify_phi},
    {"odeint_bulirsch_stoer", verify_bulirsch_stoer}};

std::vector<std::string> registered_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : method_registry()) names.emplace_back(m.name);
  return names;
}

}  // namespace

class Verification : public testing::TestWithParam<std::string> {};

TEST_P(Verification, DeclaredOrdersBoundsAndProperties) {
  const MethodInfo& m = method_info(GetParam());
  const auto bound = methods_for<UnsymmetricPendulum>();
  if (std::find(bound.begin(), bound.end(), m.name) != bound.end()) {
    verify_bound_method(m);
  } else if (const auto c = cases.find(m.name); c != cases.end()) {
    c->second(m);
  } else {
    FAIL() << "registered method " << m.name << " has no verification case: give it a generic binding "
           << "(src/geomint/methods/methods.hpp) or a case in tests/verification/special_cases.cpp";
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, Verification, testing::ValuesIn(registered_names()),
                         [](const testing::TestParamInfo<std::string>& p) { return p.param; });

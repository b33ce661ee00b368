// The checks of the scene's Henon-Heiles starts (henon_heiles.hpp), compiled once for both systems.
#include "geomint/systems/henon_heiles.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "geomint/integrators/takahashi_imada_systems.hpp"
#include "geomint/methods/scene_methods.hpp"
#include "geomint/observables/stiffness.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {
namespace {

// %g of v (the numbers of the messages of check_henon_heiles_starts).
std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

template <class HH>
void check_henon_heiles_starts(const Scene& s, const std::string& section, const HH& hh, double d, bool check_h) {
  const double H0 = s.real("hh.H0"), q2 = s.real(section + ".q2"), p2 = s.real(section + ".p2");
  const double escape = hh.escape_energy();
  if (!(H0 < escape))
    s.reject("hh.H0", "must be below the escape energy " + format_double(escape) + " of U (k = " + std::to_string(hh.k) +
                          ", c = " + format_double(hh.c) + ": its lowest saddle); here " + format_double(H0));
  // the unperturbed start is blamed on its keys, a perturbed one on ensemble.perturbation
  const auto inside = [&](double a) { return a < 1 && (hh.k % 2 == 1 || a > -1); };
  const auto exists = [&](double a, double b) { return 2 * (H0 - hh.U(Vec<2>(0.0, a))) - b * b > 0; };
  if (!inside(q2))
    s.reject(section + ".q2", "the start must lie between the saddles of U on q1 = 0 (q2 < 1" +
                                  std::string(hh.k % 2 ? "" : ", q2 > -1") + "); here q2 = " + format_double(q2));
  if (!exists(q2, p2))
    s.reject(section + ".p2", "the start q1 = 0, q2 = " + short_num(q2) + ", p2 = " + short_num(p2) + " (k = " +
                                  std::to_string(hh.k) + ") needs U(0, q2) + p2^2/2 < hh.H0 = " + short_num(H0));
  for (const double a : {q2 - d, q2 + d})
    for (const double b : {p2 - d, p2 + d})
      if (!inside(a) || !exists(a, b))
        s.reject("ensemble.perturbation", "the perturbed start q1 = 0, q2 = " + short_num(a) + ", p2 = " + short_num(b) +
                                              " must lie between the saddles of U on q1 = 0 with U(0, q2) + p2^2/2 < "
                                              "hh.H0 = " + short_num(H0) + "; here " + format_double(d));
  if (check_h)
    check_step_bound(s, "h", "simplified_takahashi_imada", s.real("h") * std::sqrt(max_hessian_eigenvalue(hh, Vec<2>(0.0, q2))),
                     "omega^2 = max eig U''(0, " + section + ".q2), Henon-Heiles k = " + std::to_string(hh.k), "2 sqrt(3)");
}

template void check_henon_heiles_starts(const Scene&, const std::string&, const HenonHeilesT<true>&, double, bool);
template void check_henon_heiles_starts(const Scene&, const std::string&, const HenonHeilesT<false>&, double, bool);

}  // namespace geomint

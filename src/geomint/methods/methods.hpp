#pragma once
// The registered methods: one type per method with its registry entry `info`
// (registry.hpp) and, where it steps a system generically, `applies<Sys>` and
// `bind(sys)`, a processed method (core/integrate.hpp) for
// integrate; a processed method also has `bind_kernel(sys)`, its
// kernel with trivial processors. The list `registered_methods` is the source
// of both method_registry() and with_method(). Adding a method: its stepper
// header, its type here, one line in the list.
#include <concepts>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "geomint/integrators/explicit_euler.hpp"
#include "geomint/integrators/forest_ruth.hpp"
#include "geomint/integrators/galerkin_variational.hpp"
#include "geomint/integrators/runge_kutta4.hpp"
#include "geomint/integrators/symplectic_euler.hpp"
#include "geomint/integrators/takahashi_imada.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/systems/hamiltonian_field.hpp"
#include "geomint/core/integrate.hpp"
#include "geomint/transforms/point_transform.hpp"
#include "geomint/transforms/rowlands_processors.hpp"

namespace geomint {

// ---- what a system offers; the `applies` of the methods ----

template <class Sys>  // y' = f(y)
concept FirstOrderSystem = requires(const Sys& s, const typename Sys::State& y) { s.f(y); };

template <class Sys>  // z' = J grad H(z) (000 eq. (20))
concept HamiltonianSystem = requires(const Sys& s, const typename Sys::State& z) {
  { Sys::separable } -> std::convertible_to<bool>;
  s.H_q(z.q, z.p);
  s.H_p(z.q, z.p);
  s.H_qp(z.q, z.p);
};

template <class Sys>  // L = m |qdot|^2 / 2 - U(q)
concept MechanicalSystem = requires(const Sys& s, const typename Sys::State& z) {
  { s.mass() } -> std::convertible_to<double>;
  s.U_q(z.q);
  s.U_qq(z.q);
};

template <class Sys>  // H = p^T M^{-1} p / 2 + U(q), with the force and the Hessian-vector product
concept SeparableSystem = HamiltonianSystem<Sys> && MechanicalSystem<Sys> && Sys::separable &&
                          requires(const Sys& s, const typename Sys::State& z) {
                            s.force(z.q);
                            s.inv_mass(z.p);
                            s.U_qq_times(z.q, z.p);
                          };

inline constexpr double every_h = std::numeric_limits<double>::infinity();  // stable for every step
inline constexpr double no_bound = std::numeric_limits<double>::quiet_NaN();  // not applicable or not declared

// The system as a first-order ODE: itself, or z' = J grad H (000 eq. (20)).
template <class Sys>
auto first_order_form(const Sys& sys) {
  if constexpr (FirstOrderSystem<Sys>) return sys;
  else return HamiltonianField<Sys>{sys};
}

// ---- the methods ----

struct ExplicitEuler {
  static constexpr MethodInfo info{
      .name = "explicit_euler", .label = "ee", .family = Family::explicit_method, .order = 1, .kernel_order = 1,
      .real_bound = 2.0, .oscillatory_bound = 0.0,  // |1 + h lambda| <= 1; |1 + i w h| > 1
      .applies_to = "first-order ODE; Hamiltonian as z' = J grad H", .citation = "000 eq. (9)",
      .title = "explicit Euler", .equations = "000 (9)", .colour = "#D55E00", .marker = 11};
  template <class Sys>
  static constexpr bool applies = FirstOrderSystem<Sys> || HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([f = first_order_form(sys)](const auto& y, double h) { return explicit_euler(f, y, h); });
  }
};

struct RungeKutta4 {
  static constexpr MethodInfo info{
      .name = "rk4", .label = "rk4", .family = Family::explicit_method, .order = 4, .kernel_order = 4,
      .real_bound = 2.785293563405282, .oscillatory_bound = 2 * std::sqrt(2.0),  // |R(z)| = 1, R the degree-4 Taylor polynomial of e^z
      .applies_to = "first-order ODE; Hamiltonian as z' = J grad H",
      .citation = "classical RK4 (Hairer, Norsett, Wanner I, Table 1.2)",
      .title = "classical RK4", .equations = "", .colour = "#009E73", .marker = 8};
  template <class Sys>
  static constexpr bool applies = FirstOrderSystem<Sys> || HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([f = first_order_form(sys)](const auto& y, double h) { return runge_kutta4(f, y, h); });
  }
};

struct SymplecticEulerPQ {
  static constexpr MethodInfo info{
      .name = "symplectic_euler_pq", .label = "se", .family = Family::symplectic, .order = 1, .kernel_order = 1,
      .real_bound = no_bound, .oscillatory_bound = 2.0,  // trace of the one-step matrix 2 - (w h)^2
      .properties = property::symplectic, .applies_to = "Hamiltonian", .citation = "000 eq. (42)-(43)",
      .title = "symplectic Euler", .equations = "000 (42)–(43)", .colour = "#D55E00", .marker = 7};
  template <class Sys>
  static constexpr bool applies = HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([&sys](const auto& z, double h) { return symplectic_euler_pq(sys, z, h); });
  }
};

struct SymplecticEulerQP {
  static constexpr MethodInfo info{
      .name = "symplectic_euler_qp", .label = "se_qp", .family = Family::symplectic, .order = 1, .kernel_order = 1,
      .real_bound = no_bound, .oscillatory_bound = 2.0, .properties = property::symplectic,
      .applies_to = "Hamiltonian", .citation = "adjoint of 000 eq. (42)-(43) (000 footnote 3)",
      .title = "symplectic Euler, adjoint", .equations = "", .colour = "#D55E00", .marker = 6};
  template <class Sys>
  static constexpr bool applies = HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([&sys](const auto& z, double h) { return symplectic_euler_qp(sys, z, h); });
  }
};

// Symplectic Euler in the coordinates of (82): its order 2 is that of the energy error (000 Fig. 9).
struct CompensatedSymplecticEuler {
  static constexpr MethodInfo info{
      .name = "compensated_symplectic_euler", .label = "se_compensated", .family = Family::processed, .order = 2,
      .kernel_order = 1, .real_bound = no_bound, .oscillatory_bound = no_bound, .properties = property::symplectic,
      .applies_to = "harmonic oscillator (74), amplitude 1",
      .citation = "000 eq. (82), App. B: symplectic Euler (42)-(43) after the point transformation (82), (41)",
      .title = "symplectic Euler with transformation", .equations = "000 (82)", .colour = "#0072B2", .marker = 13};
  // Not in the dispatch by name: (82) has a parameter k of its own. Pre: (41) with Q of (82); kernel:
  // symplectic Euler in (qbar, pbar); post: the inverse of (41) (NaN where |qhat| >= 1).
  template <class Sys>
  static auto bind(const Sys& osc, double k) {
    const auto in = [osc, k](double h) { return PointTransformed{osc, OscillatorCompensation{k, h}}; };
    return Processed{[in](const PhaseState<1>& zb, double h) { return symplectic_euler_pq(in(h), zb, h); },
                     [in](const PhaseState<1>& z, double h) { return in(h).to_transformed(z); },
                     [in](const PhaseState<1>& zb, double h) { return in(h).to_original(zb); }};
  }
};

struct StormerVerlet {
  static constexpr MethodInfo info{
      .name = "stormer_verlet", .label = "sv", .family = Family::symplectic, .order = 2, .kernel_order = 2,
      .real_bound = no_bound, .oscillatory_bound = 2.0,  // 004 Sect. 1.4
      .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
      .citation = "000 eq. (26)-(28)",
      .title = "Störmer–Verlet", .equations = "000 (26)–(28); 004 (1.3)", .colour = "#D55E00", .marker = 5};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return stormer_verlet_method(sys);
  }
};

// On the oscillator the force of (30) is -w^2 (1 - (w h)^2/12) q, as for Takahashi-Imada: w h < 2 sqrt(3) (004 Sect. 1.4).
inline constexpr double rowlands_kernel_bound = 2 * std::sqrt(3.0);

struct RowlandsKernel {
  static constexpr MethodInfo info{
      .name = "rowlands_kernel", .label = "kernel", .family = Family::symplectic, .order = 2, .kernel_order = 2,
      .real_bound = no_bound, .oscillatory_bound = rowlands_kernel_bound,
      .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
      .citation = "000 eq. (30)-(31)",
      .title = "Rowlands kernel", .equations = "000 (30)–(31)", .colour = "#E69F00", .marker = 12};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return rowlands_kernel_method(sys);
  }
};

// The processed Rowlands methods: the kernel (30)-(31) with the processors of 000.
struct RowlandsProcessed {
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind_kernel(const Sys& sys) {
    return rowlands_kernel_method(sys);
  }
};

constexpr MethodInfo rowlands_info(std::string_view name, int order, std::string_view citation, std::string_view title,
                                   std::string_view equations, std::string_view colour, int marker) {
  return {.name = name, .label = name, .family = Family::processed, .order = order, .kernel_order = 2,
          .real_bound = no_bound, .oscillatory_bound = rowlands_kernel_bound,
          .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
          .citation = citation, .title = title, .equations = equations, .colour = colour, .marker = marker};
}

struct Rowlands : RowlandsProcessed {
  static constexpr MethodInfo info =
      rowlands_info("rowlands", 4, "000 eq. (30)-(33) with the derived coefficient h^2/12 (transforms/rowlands_processors.hpp)",
                    "Rowlands, processors h²/12", "000 (32)–(33)", "#0072B2", 14);
  template <class Sys>
  static auto bind(const Sys& sys) {
    return rowlands_method(sys);
  }
};

struct RowlandsCheap : RowlandsProcessed {
  static constexpr MethodInfo info = rowlands_info("rowlands_cheap", 4, "000 eq. (30)-(31), (34)-(37)",
                                                     "Rowlands, cheap processors", "000 (34)–(37)", "#56B4E9", 9);
  template <class Sys>
  static auto bind(const Sys& sys) {
    return rowlands_cheap_method(sys);
  }
};

struct RowlandsPrinted : RowlandsProcessed {
  static constexpr MethodInfo info = rowlands_info("rowlands_printed", 2, "000 eq. (30)-(33) as printed (h^2/24)",
                                                   "Rowlands, printed processors h²/24", "000 (32)–(33)", "#CC79A7", 6);
  template <class Sys>
  static auto bind(const Sys& sys) {
    return rowlands_method(sys, rowlands_processor_coefficient_printed);
  }
};

// The Takahashi-Imada methods are written for unit mass (004 (1.1)).
template <class Sys>
const Sys& unit_mass(const Sys& sys, std::string_view method) {
  if (sys.mass() != 1.0) throw std::invalid_argument(std::string(method) + " is implemented for unit mass (004 (1.1))");
  return sys;
}

struct TakahashiImada {
  static constexpr MethodInfo info{
      .name = "takahashi_imada", .label = "ti", .family = Family::processed, .order = 4, .kernel_order = 2,
      .real_bound = no_bound, .oscillatory_bound = 2 * std::sqrt(3.0),  // 004 Sect. 1.4
      .properties = property::symplectic | property::time_reversible,
      .applies_to = "separable Hamiltonian, unit mass", .citation = "004 (1.4)-(1.5)",
      .title = "Takahashi–Imada", .equations = "004 (1.4)", .colour = "#0072B2", .marker = 10};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return takahashi_imada_method(unit_mass(sys, info.name), true);
  }
  template <class Sys>
  static auto bind_kernel(const Sys& sys) {
    return takahashi_imada_method(unit_mass(sys, info.name), false);
  }
};

// Not symplectic for more than one degree of freedom (004 Sect. 1.3).
struct SimplifiedTakahashiImada {
  static constexpr MethodInfo info{
      .name = "simplified_takahashi_imada", .label = "sti", .family = Family::processed, .order = 4, .kernel_order = 2,
      .real_bound = no_bound, .oscillatory_bound = 2 * std::sqrt(3.0),  // 004 Sect. 1.4
      .properties = property::volume_preserving | property::time_reversible,
      .applies_to = "separable Hamiltonian, unit mass", .citation = "004 (1.6), (1.5)",
      .title = "simplified Takahashi–Imada", .equations = "004 (1.6)", .colour = "#009E73", .marker = 1};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return simplified_ti_method(unit_mass(sys, info.name), true);
  }
  template <class Sys>
  static auto bind_kernel(const Sys& sys) {
    return simplified_ti_method(unit_mass(sys, info.name), false);
  }
};

struct ForestRuth {
  static constexpr MethodInfo info{
      .name = "forest_ruth", .label = "forest_ruth", .family = Family::symplectic, .order = 4, .kernel_order = 4,
      .real_bound = no_bound, .oscillatory_bound = 1.5734019474345401,  // the trace of the one-step matrix reaches +2
      .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
      .citation = "Forest & Ruth (1990), Yoshida (1990): SV(g1 h) SV(g2 h) SV(g1 h), g1 = 1/(2 - 2^(1/3))",
      .title = "Forest–Ruth", .equations = "", .colour = "#000000", .marker = 2};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return forest_ruth_method(sys);
  }
};

struct ImplicitMidpoint {
  static constexpr MethodInfo info{
      .name = "implicit_midpoint", .label = "midpoint", .family = Family::symplectic, .order = 2, .kernel_order = 2,
      .real_bound = every_h, .oscillatory_bound = every_h,  // R(z) = (1 + z/2)/(1 - z/2)
      .properties = property::symplectic | property::time_reversible, .applies_to = "mechanical Lagrangian",
      .citation = "implicit midpoint rule (001 ref. [10])",
      .title = "implicit midpoint", .equations = "", .colour = "#D55E00", .marker = 8};
  template <class Sys>
  static constexpr bool applies = MechanicalSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([&sys](const auto& z, double h) { return implicit_midpoint(sys, z, h); });
  }
};

struct Lobatto {
  static constexpr MethodInfo info{
      .name = "lobatto", .label = "lobatto", .family = Family::variational, .order = 6, .kernel_order = 6,
      .real_bound = no_bound, .oscillatory_bound = std::sqrt(42.0 - 6.0 * std::sqrt(29.0)),  // 001 eq. (10)
      .properties = property::symplectic | property::time_reversible, .applies_to = "mechanical Lagrangian",
      .citation = "001 eq. (2)-(11), bound (10)",
      .title = "Lobatto", .equations = "001 (13)–(14)", .colour = "#0072B2", .marker = 4};
  template <class Sys>
  static constexpr bool applies = MechanicalSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([&sys, rule = lobatto_rule()](const auto& z, double h) { return galerkin_step(rule, sys, z, h); });
  }
};

struct Simpson {
  static constexpr MethodInfo info{
      .name = "simpson", .label = "simpson", .family = Family::variational, .order = 4, .kernel_order = 4,
      .real_bound = no_bound, .oscillatory_bound = std::sqrt(8.0),  // spectral radius of the one-step matrix
      .properties = property::symplectic | property::time_reversible, .applies_to = "mechanical Lagrangian",
      .citation = "001 ref. [2] (P2 elements, Simpson's rule)",
      .title = "Simpson", .equations = "001 [2]", .colour = "#E69F00", .marker = 13};
  template <class Sys>
  static constexpr bool applies = MechanicalSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return one_step_method([&sys, rule = simpson_rule()](const auto& z, double h) { return galerkin_step(rule, sys, z, h); });
  }
};

// Psi_{h,E} of 003 Sec. 4.2 with one of the discrete Lagrangians (5.1)
// (integrators/conformal_variational.hpp); symplectic and symmetric for the
// altered Hamiltonian K_E at fixed E, in the fictitious time.
constexpr MethodInfo conformal_info(std::string_view name, std::string_view discretization, std::string_view title,
                                    std::string_view colour, int marker) {
  return {.name = name, .label = discretization, .family = Family::conformal, .order = 2, .kernel_order = 2,
          .real_bound = no_bound, .oscillatory_bound = no_bound,
          .properties = property::symplectic | property::time_reversible, .applies_to = "nonholonomic particle (003)",
          .citation = "003 eq. (5.1), Sec. 4.2", .title = title, .equations = "003 (5.1)", .colour = colour,
          .marker = marker};
}
struct ConformalM { static constexpr MethodInfo info = conformal_info("conformal_M", "M", "Ψ_{h,E}, M", "#4477AA", 7); };
struct ConformalMT { static constexpr MethodInfo info = conformal_info("conformal_MT", "MT", "Ψ_{h,E}, MT", "#228833", 5); };
struct ConformalTM { static constexpr MethodInfo info = conformal_info("conformal_TM", "TM", "Ψ_{h,E}, TM", "#EE6677", 9); };
struct ConformalTT { static constexpr MethodInfo info = conformal_info("conformal_TT", "TT", "Ψ_{h,E}, TT", "#AA3377", 13); };
struct ConformalT { static constexpr MethodInfo info = conformal_info("conformal_T", "T", "Ψ_{h,E}, T", "#CCBB44", 11); };

// Phi^(ell) of 003 eq. (4.5): Psi_{h,E} with E = E^(ell)(z_0), any of (5.1); keeps mu^(ell)_mod to O(h^(ell+2)) (Cor. 4.3).
constexpr MethodInfo phi_info(std::string_view name, int ell, std::string_view title, std::string_view colour,
                              int marker) {
  return {.name = name, .label = name, .family = Family::conformal, .order = 2, .kernel_order = 2,
          .real_bound = no_bound, .oscillatory_bound = no_bound, .properties = property::modified_measure,
          .measure_order = ell + 2, .applies_to = "nonholonomic particle (003)",
          .citation = "003 eq. (4.5), Cor. 4.3: Psi_{h,E} with E = E^(ell)(z_0)", .title = title,
          .equations = "003 (4.5)", .colour = colour, .marker = marker};
}
struct Phi0 { static constexpr MethodInfo info = phi_info("phi0", 0, "Φ^{(0)}_h", "#D55E00", 10); };
struct Phi2 { static constexpr MethodInfo info = phi_info("phi2", 2, "Φ^{(2)}_h", "#E69F00", 9); };
struct Phi4 { static constexpr MethodInfo info = phi_info("phi4", 4, "Φ^{(4)}_h", "#0072B2", 15); };
struct Phi6 { static constexpr MethodInfo info = phi_info("phi6", 6, "Φ^{(6)}_h", "#009E73", 3); };

// The odeint methods' steppers, declared here and defined in reference/odeint_steppers.hpp, which a file that
// binds one includes (methods/dispatch.hpp does): a file that binds another method of this header does not
// parse Boost.Odeint.
template <class Sys>
auto odeint_rk4_method(const Sys& sys);
template <class Sys>
auto odeint_rkf78_method(const Sys& sys);
template <class Sys>
auto odeint_rkn_sb3a_method(const Sys& sys);
template <class Sys>
auto odeint_velocity_verlet_method(const Sys& sys);

struct OdeintRK4 {
  static constexpr MethodInfo info{
      .name = "odeint_rk4", .label = "odeint_rk4", .family = Family::explicit_method, .order = 4, .kernel_order = 4,
      .real_bound = RungeKutta4::info.real_bound, .oscillatory_bound = RungeKutta4::info.oscillatory_bound,
      .applies_to = "Hamiltonian", .citation = "Boost.Odeint runge_kutta4",
      .title = "odeint: classical RK4", .equations = "", .colour = "#009E73", .marker = 10};
  template <class Sys>
  static constexpr bool applies = HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return odeint_rk4_method(sys);
  }
};

struct OdeintRknSb3a {
  static constexpr MethodInfo info{
      .name = "odeint_rkn_sb3a", .label = "odeint_rkn_sb3a", .family = Family::symplectic, .order = 4,
      .kernel_order = 4, .real_bound = no_bound,
      .oscillatory_bound = 2.9218392391961706,  // the trace of the one-step matrix reaches -2 (stable again on (3.297, 4.647))
      .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
      .citation = "Boost.Odeint symplectic_rkn_sb3a_mclachlan (McLachlan 1995)",
      .title = "odeint: symplectic RKN SB3a, order 4", .equations = "", .colour = "#882255", .marker = 10};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return odeint_rkn_sb3a_method(sys);
  }
};

struct OdeintVelocityVerlet {
  static constexpr MethodInfo info{
      .name = "odeint_velocity_verlet", .label = "odeint_velocity_verlet", .family = Family::symplectic, .order = 2,
      .kernel_order = 2, .real_bound = no_bound, .oscillatory_bound = 2.0,  // Stormer-Verlet
      .properties = property::symplectic | property::time_reversible, .applies_to = "separable Hamiltonian",
      .citation = "Boost.Odeint velocity_verlet",
      .title = "odeint: velocity Verlet", .equations = "", .colour = "#8C3B00", .marker = 6};
  template <class Sys>
  static constexpr bool applies = SeparableSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return odeint_velocity_verlet_method(sys);
  }
};

struct OdeintRKF78 {
  static constexpr MethodInfo info{
      .name = "odeint_rkf78", .label = "odeint_rkf78", .family = Family::explicit_method, .order = 8,
      .kernel_order = 8, .real_bound = no_bound, .oscillatory_bound = no_bound, .applies_to = "Hamiltonian",
      .citation = "Boost.Odeint runge_kutta_fehlberg78, fixed step",
      .title = "odeint: Runge–Kutta–Fehlberg 7(8), fixed step", .equations = "", .colour = "#CC79A7", .marker = 10};
  template <class Sys>
  static constexpr bool applies = HamiltonianSystem<Sys>;
  template <class Sys>
  static auto bind(const Sys& sys) {
    return odeint_rkf78_method(sys);
  }
};

// The reference solution of every experiment (reference/odeint_reference.hpp).
struct OdeintBulirschStoer {
  static constexpr MethodInfo info{
      .name = "odeint_bulirsch_stoer", .label = "reference", .family = Family::reference, .order = 0,
      .kernel_order = 0, .real_bound = no_bound, .oscillatory_bound = no_bound,
      .applies_to = "Hamiltonian; first-order ODE (003 (3.8))",
      .citation = "Boost.Odeint bulirsch_stoer, adaptive, to the stated tolerances",
      .title = "odeint: Bulirsch–Stoer", .equations = "", .colour = "#000000", .marker = 3};
};

template <class... Ms>
struct MethodList {};

using registered_methods =
    MethodList<ExplicitEuler, RungeKutta4, SymplecticEulerPQ, SymplecticEulerQP, CompensatedSymplecticEuler,
               StormerVerlet, RowlandsKernel, Rowlands, RowlandsCheap, RowlandsPrinted, TakahashiImada,
               SimplifiedTakahashiImada, ForestRuth, ImplicitMidpoint, Lobatto, Simpson, ConformalM, ConformalMT,
               ConformalTM, ConformalTT, ConformalT, Phi0, Phi2, Phi4, Phi6, OdeintRK4, OdeintRknSb3a,
               OdeintVelocityVerlet, OdeintRKF78, OdeintBulirschStoer>;

// ---- dispatch by name ----

template <class M, class Sys>
concept Binds = requires { requires M::template applies<Sys>; };

namespace detail {
template <class Sys, class... Ms>
std::vector<std::string> names_for(MethodList<Ms...>) {
  std::vector<std::string> names;
  (..., [&] {
    if constexpr (Binds<Ms, Sys>) names.emplace_back(Ms::info.name);
  }());
  return names;
}
}  // namespace detail

// The scene names of the methods that can step Sys.
template <class Sys>
std::vector<std::string> methods_for() {
  return detail::names_for<Sys>(registered_methods{});
}

// What a scene may name for a study on Sys: the registry names of the methods that can step it and,
// as shorter spellings, their labels.
template <class Sys>
std::vector<std::string> method_choices(std::vector<std::string> names = methods_for<Sys>()) {
  std::vector<std::string> out = names;
  for (const auto& name : names)
    if (method_info(name).label != name) out.emplace_back(method_info(name).label);
  return out;
}

}  // namespace geomint

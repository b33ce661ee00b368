# Beyond the paper: what accuracy costs on the nonholonomic particle (harmonic potential U = (x² + y²)/2),
# one trajectory from z_0 = cloud.center with N = ⌊t_end/h⌋ steps per run: Φ^(4)_h (E* = ℰ^(4)(z_0)) of
# each discretization (5.1) and Φ^(0)_h (E = H(z_0)) of cost.discretization, for each step h of the order
# study, and the classical RK4 on (3.8), which preserves neither the energy nor a measure, over cost.rk4_h.
# Two rows, one per error (the work-precision sets of the cost study, figures/cost.gpi): the trajectory
# error ‖z_N − z_ref(t_N)‖_2 at the last step t_N = N h (≤ t_end; the reference is taken there), and
# the energy error max_j |H(z_j) − H_0| over the run; each against the wall time of the run (left) and
# against the evaluations (right): Newton iterations of Ψ_{h,E} (each the discrete momentum with its
# 2×2 Jacobian), 4 evaluations of (3.8) per RK4 step.
# Input: cost_trajectory.csv, cost_energy.csv (the work-precision sets of the cost study,
# figures/cost.gpi), scene values (energies.t_end, timing.repeats, cloud.center, cost.discretization),
# summary values (cost.trajectory.methods: phi4_<label> of each discretization, phi0_<label>, rk4).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('harmonic')
CSV_METHODS = summary_words('cost.trajectory.methods')
PREFERRED = "phi4_M phi4_MT phi4_TM phi4_TT phi4_T"   # Φ^(4) in the order of the discretizations; then Φ^(0), RK4
eval ORDER_METHODS
# a label phi<ell>_<discretization>: its ell and its discretization ("" for rk4)
ELL(m) = m[1:3] eq "phi" ? m[4:strstrt(m, "_") - 1] : ""
DISC(m) = m[1:3] eq "phi" ? m[strstrt(m, "_") + 1:] : ""
COST_OWN_STYLES = 1   # (its curves are Phi^(ell) of a discretization: 003's styles, measure_cloud_style.gpi)
LABEL(m) = ELL(m) eq "4" ? sprintf("Φ^{(4)}_h, %s", MC_DESC(DISC(m))) \
         : ELL(m) ne "" ? sprintf("Φ^{(%s)}_h, %s", ELL(m), DISC(m)) : m eq "rk4" ? "classical RK4 on (3.8)" : nosub(m)
# Φ^(4): the colour, marker and dashes of its discretization (figures/measure_cloud_style.gpi); Φ^(0):
# vermillion, open circles; RK4: green, open triangles, as method_colour has them
set style line 361 lc rgb method_colour('phi0') lw 1.2 dt (5,3) pt 6 ps 0.6
set style line 362 lc rgb method_colour('rk4') lw 1.2 dt 1 pt 8 ps 0.6
STYLE(m) = ELL(m) eq "4" ? MC_LS(DISC(m)) : ELL(m) ne "" ? 361 : m eq "rk4" ? 362 : LS_OTHER

eval need_num('TEND', scene_real('energies.t_end'))
eval need_num('REPEATS', scene_real('timing.repeats'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
# the discretization of Φ^(0) by its label (the scene may name it conformal_M or M)
CMP = mc_scene_str('cost.discretization')
CMP = CMP[1:10] eq "conformal_" ? CMP[11:] : CMP
COST_NAME = 'measure_cloud_cost'
COST_TITLE = sprintf("{/:Bold Cost:} Φ^{(4)}_h, Φ^{(0)}_h and RK4, harmonic potential U = (x^2 + y^2)/2, one run from z_0 = %s to t_N = N h ≤ %g\n" \
                     . "wall time: %s; Φ^{(0)}_h with the discretization %s", \
                     Z0, TEND, REPEATS > 1 ? sprintf("median of %d interleaved runs of ≥ 20 ms", REPEATS) : "one run of ≥ 20 ms", \
                     CMP)
COST_SETS = "trajectory energy"
COST_YLABEL(cs) = cs eq "trajectory" ? "‖z_N − z_{ref}(t_N)‖_2" : "max_j |H(z_j) − H_0|"
COST_EVALS = "evaluations: Newton iterations (Φ), 4 per step (RK4)"
load 'figures/cost.gpi'

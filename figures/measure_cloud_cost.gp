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
# figures/cost.gpi), scene values (energies.t_end, timing.repeats, cloud.center),
# summary values (cost.trajectory.methods: phi4_<label> of each discretization, phi0_<label>, rk4).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('harmonic')
METHODS = summary_words('cost.trajectory.methods')   # in the run's order: Φ^(4) of each discretization, Φ^(0), RK4
# a label phi<ell>_<discretization>: its Φ^(ℓ) ("phi4") and its discretization ("M"), both registry labels ("" for rk4)
PHI(m) = m[1:3] eq "phi" ? m[1:strstrt(m, "_") - 1] : ""
DISC(m) = m[1:3] eq "phi" ? m[strstrt(m, "_") + 1:] : ""
# colour and marker from the registry: a Φ^(ℓ) drawn for several discretizations (Φ^(4)) those of each
# discretization, one drawn for one (Φ^(0): cost.discretization) its own, as RK4
NPHI(p) = sum [i = 1:words(METHODS)] (PHI(word(METHODS, i)) eq p ? 1 : 0)
AS(m) = PHI(m) eq "" ? m : NPHI(PHI(m)) > 1 ? DISC(m) : PHI(m)
COST_OWN_STYLES = 1   # (its curves Φ^(ℓ) of a discretization are named by two registry labels)
STYLED = ""; do for [m in METHODS] { STYLED = STYLED . AS(m) . " " }
eval method_styles(STYLED)   # (the i-th of METHODS drawn with the style of the i-th of STYLED)
STYLE(m) = method_ls(m)
LABEL(m) = PHI(m) ne "" ? method_key(PHI(m), '003') . ", " . method_key(DISC(m), '003') : method_key(m, '003')

eval need_num('TEND', scene_real('energies.t_end'))
eval need_num('REPEATS', scene_real('timing.repeats'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
# the title names the methods compared: each Φ^(ℓ) and RK4 (registry titles)
NAMES = ""; do for [m in METHODS] { NAMES = NAMES . (PHI(m) eq "" ? m : PHI(m)) . " " }
NAMES = unique_words(NAMES)
COMPARED = method_title(word(NAMES, 1))
do for [i = 2:words(NAMES)] { COMPARED = COMPARED . (i < words(NAMES) ? ", " : " and ") . method_title(word(NAMES, i)) }
COST_NAME = 'measure_cloud_cost'
COST_TITLE = sprintf("{/:Bold Cost:} %s, harmonic potential U = (x^2 + y^2)/2, one run from z_0 = %s to t_N = N h ≤ %g\n" \
                     . "wall time: %s", \
                     COMPARED, Z0, TEND, REPEATS > 1 ? sprintf("median of %d interleaved runs of ≥ 20 ms", REPEATS) : "one run of ≥ 20 ms")
COST_SETS = "trajectory energy"
COST_YLABEL(cs) = cs eq "trajectory" ? "‖z_N − z_{ref}(t_N)‖_2" : "max_j |H(z_j) − H_0|"
COST_EVALS = "evaluations: Newton iterations (Φ), 4 per step (RK4)"
load 'figures/cost.gpi'

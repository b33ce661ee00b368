# What the accuracy of Störmer–Verlet (1.3), Takahashi–Imada (1.4) and the simplified method (1.6)
# costs (work-precision, not in 004): the global error at t = work_precision.t_end against the wall
# time of one run (left; the median of timing.repeats interleaved timed runs of at least 20 ms each) and against
# the force evaluations of one run (right; gradients and Hessian–vector products, counted, processing
# included), log-log, one colour per method. TI and the simplified method are processed by (1.5) as in
# ti_drift_fig1.gp. Top row: Hénon–Heiles k = 3 from the start of ti_drift_fig3.gp, against an odeint Bulirsch–Stoer
# reference at tolerances work_precision.reference_tol / 100; bottom row: the harmonic oscillator of
# ti_drift_fig1.gp (ω = 1, start q = 0, p = 1; there TI and the simplified method are the same map, so their
# points coincide in the right panel), against the exact solution.
# Input: cost_henon_heiles.csv and cost_oscillator.csv (the work-precision sets of the cost study,
# figures/cost.gpi), scene values (work_precision.t_end, work_precision.reference_tol, timing.repeats),
# summary values (cost.henon_heiles.methods: the methods of the sets, by registry label).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
eval need_num('T', scene_real('work_precision.t_end'))
eval need_num('REF_TOL', scene_real('work_precision.reference_tol'))
CSV_METHODS = summary_words('cost.henon_heiles.methods')
PREFERRED = "sv ti sti"
eval ORDER_METHODS
COST_PAPER = "004"   # (TI and the simplified method coincide on the oscillator: their markers, an open triangle
                     # and a plus, keep both visible)
COST_NAME = 'ti_drift_cost'
COST_TITLE = sprintf("{/:Bold Cost:} global error at t = %g against computing effort; top: Hénon–Heiles k = 3 (reference: odeint " \
                     . "Bulirsch–Stoer at tolerances %s),\nbottom: harmonic oscillator (exact solution); wall time: median of %s interleaved runs of ≥ 20 ms", \
                     T, sci(REF_TOL / 100), scene_num('timing.repeats'))
COST_SETS = "henon_heiles oscillator"
COST_EVALS = "force evaluations in one run (U_q, or U_{qq}v)"
COST_YLABEL(cs) = (cs eq "henon_heiles" ? "Hénon–Heiles: " : "oscillator: ") . "global error at t = " . gprintf("%g", T)
load 'figures/cost.gpi'

# What the accuracy of the schemes of Dubois & Rojas-Quintero (2025) costs over the long run of the
# long_run study (lobatto_table_fig2.gp; its item in the title: made_by('long_run')) (work-precision), beyond the paper: the oscillator (m = 1, ω = 2π, q(0) = π/2,
# p(0) = 0) over long_run.periods periods with the steps long_run_cost.h, for the methods of the
# scene key long_run_cost.methods (by label: summary value cost.long_run_phase.methods). Top: the
# phase-space error |z_N − z(t_N)|_2 at the end against the closed form (set long_run_phase);
# bottom: the largest energy error |H(z_j) − H(z_0)| over the run (lobatto_table_fig2.gp's quantity; set
# long_run_energy). Left: against the wall time of one run; right: against the force evaluations
# of one run (U_q and U_qq calls, so Newton's Jacobians count). The closed form's own error at t_N
# (round-off of cos ωt_N) is stated (summary value long_run_cost.reference_error).
# Input: cost_long_run_phase.csv, cost_long_run_energy.csv (the work-precision sets of the study
# long_run_cost, figures/cost.gpi); scene values (periods, repetitions); summary values (methods,
# reference error).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
eval need_num('PERIODS', scene_num('long_run.periods'))
eval need_num('REF_ERR', summary_real('long_run_cost.reference_error'))
METHODS = summary_words('cost.long_run_phase.methods')
if (words(METHODS) == 0) { exit error sprintf("%s/figure_values.gp: no cost.long_run_phase.methods", results) }
COST_PAPER = "001"
COST_NAME = 'lobatto_table_long_run_cost'
COST_TITLE = sprintf("{/:Bold Cost over the long run of " . item_name(made_by('long_run')) . ":} oscillator m = 1, ω = 2π, q(0) = π/2, p(0) = 0, %g periods per run\n" \
                     . "wall time: median of %s interleaved runs of ≥ 20 ms, single thread; reference: the closed form, its own error at t_N ≤ %s", \
                     PERIODS, scene_num('timing.repeats'), sci(REF_ERR))
COST_SETS = "long_run_phase long_run_energy"
COST_EVALS = "force evaluations in one run (U_q and U_{qq} calls)"
COST_YLABEL(cs) = cs eq "long_run_phase" ? "|z_N − z(t_N)|_2,  z = (q, p)" : "max_j |H(z_j) − H(z_0)|"
load 'figures/cost.gpi'

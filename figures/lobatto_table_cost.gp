# What the accuracy of the Lobatto scheme of Dubois & Rojas-Quintero (2025) costs
# (work-precision), beyond the paper: phase-space error at t_end on the nonlinear pendulum
# L = q̇²/2 + cos q of the Lobatto scheme (Newton on the internal nodes), the Simpson scheme, the
# implicit midpoint rule, and two fixed-step Boost.Odeint steppers (classical RK4 and
# Runge–Kutta–Fehlberg 7(8)), against the wall time of one run (left) and the number of force
# evaluations in one run (right; U_q and U_qq calls, so Newton's Jacobians count). The methods are
# those of the scene key timing.methods (the rows of cost_pendulum.csv, by label: summary value
# cost.pendulum.methods).
# Input: cost_pendulum.csv (the work-precision set "pendulum" of the cost study, figures/cost.gpi);
# scene values (t_end, q(0), repetitions); summary values (the methods).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
eval need_num('T', scene_full('nonlinear.t_end'))
# the methods of the scene key timing.methods, by label, in the order of cost_pendulum.csv
METHODS = summary_words('cost.pendulum.methods')
if (words(METHODS) == 0) { exit error sprintf("%s/figure_values.gp: no cost.pendulum.methods", results) }
COST_PAPER = "001"
COST_NAME = 'lobatto_table_cost'
COST_TITLE = sprintf("{/:Bold Cost:} phase-space error against computing effort, nonlinear pendulum L = q̇²/2 + cos q, q(0) = %s, p(0) = 0\n" \
                     . "one run to t_{end} = %g per step size h; wall time: median of %s interleaved runs of ≥ 20 ms, single thread", \
                     scene_num('nonlinear.pendulum_q0'), T, scene_num('timing.repeats'))
COST_SETS = "pendulum"
COST_EVALS = "force evaluations in one run (U_q and U_{qq} calls)"
COST_YLABEL(cs) = "|z_N − z(t_{end})|_2,  z = (q, p)"
load 'figures/cost.gpi'

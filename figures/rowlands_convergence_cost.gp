# What the accuracy of the convergence study (rowlands_convergence_fig4.gp, after Takács & Fülöp (2025)) costs
# (work-precision):
# phase-space error at t_max of Störmer–Verlet, of the Rowlands method with either processors, and
# of three Boost.Odeint steppers (classical RK4, McLachlan's fourth-order symplectic RKN SB3a,
# velocity Verlet = Störmer–Verlet), and of Forest–Ruth (the standard fourth-order composition,
# 3 force evaluations per step), against the wall time of one run (left) and against the number
# of force evaluations in one run (right), on the planar elastic pendulum. The methods are those
# of cost_phase.csv (the scene's timing.methods, by registry label): ours, then odeint's, any others after.
# Input: cost_phase.csv (the work-precision set of the cost study, figures/cost.gpi), scene values
# (pendulum parameters, initial condition and repetitions, for the title), summary values
# (cost.phase.methods: the methods of cost_phase.csv, by registry label).
if (!exists("results")) results = 'results/rowlands_convergence'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
stats csv('cost_phase.csv') using (column("h") * column("steps")) nooutput
T = STATS_max
# the methods of cost_phase.csv (registry labels), in the key's order: ours | odeint | others
CSV_METHODS = summary_words('cost.phase.methods')
PREFERRED = "sv rowlands rowlands_cheap forest_ruth odeint_velocity_verlet odeint_rkn_sb3a odeint_rk4"
eval ORDER_METHODS
COST_PAPER = "000"
PARAMS = sprintf("l = %s, m = %s, k = %s, g = %s, t_{max} = %g", \
                 scene_num('pendulum.l'), scene_num('pendulum.m'), scene_num('pendulum.k'), scene_num('pendulum.g'), T)
Z0 = sprintf("(x, y, p_x, p_y) = (%s, %s, %s, %s)", scene_num('initial.0.0'), scene_num('initial.0.1'), \
             scene_num('initial.0.2'), scene_num('initial.0.3'))
COST_NAME = 'rowlands_convergence_cost'
COST_TITLE = sprintf("{/:Bold Cost:} phase-space error against computing effort, planar elastic pendulum, %s\none run from %s with h = t_{max}/N; wall time: median of %s interleaved runs of ≥ 20 ms", \
                     PARAMS, Z0, scene_num('timing.repeats'))
COST_SETS = "phase"
COST_EVALS = "force evaluations in one run (U_q, or U_{qq}v)"
COST_YLABEL(cs) = "|z^N − z(t_{max})|_2,  z = (x, y, p_x, p_y)"
load 'figures/cost.gpi'

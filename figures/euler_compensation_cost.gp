# What the accuracy of the methods of the convergence study (euler_compensation_fig9.gp) costs
# (work-precision): energy error of symplectic
# Euler without and with the compensating transformation (82), and of RK4, against wall time
# (left) and against force evaluations (right), on the harmonic oscillator.
# Input: cost_energy.csv (the work-precision set "energy" of the cost study, figures/cost.gpi;
# one row per method and step size h), scene values (repetitions, for the title).
load 'figures/common.gp'
stats csv('cost_energy.csv') using (column("h") * column("steps")) nooutput
T = STATS_max
METHODS = summary_words('cost.energy.methods')
COST_PAPER = "000"
COST_NAME = 'euler_compensation_cost'
COST_TITLE = sprintf("{/:Bold Cost:} energy error against computing effort, harmonic oscillator, one run to T = %g per step size h\nwall time: median of %s interleaved runs of at least 20 ms, single thread", T, scene_num('timing.repeats'))
COST_SETS = "energy"
COST_XTICS = "1"       # (decades only: the runs span four decades of wall time)
COST_YLABEL(cs) = "max_{t_j ∈ [0,T]} |H(q_j, p_j) − H_0|"
load 'figures/cost.gpi'

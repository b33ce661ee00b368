# What the accuracy of the methods of Fig. 9 costs (work-precision): energy error of symplectic
# Euler without and with the compensating transformation (82), and of RK4, against wall time
# (left) and against force evaluations (right), on the harmonic oscillator.
# Input: timing.csv (one row per method and step size h).
load 'figures/common.gp'
TIMING = csv('timing.csv')
stats TIMING using (column("h") * column("steps")) nooutput
T = STATS_max
METHODS = "se se_compensated rk4"
LABEL(m) = m eq "se" ? "symplectic Euler" : m eq "se_compensated" ? "with transformation (82)" : "RK4 (reference)"
STYLE(m) = m eq "se" ? LS_SE : m eq "se_compensated" ? LS_COMP : LS_RK4
# the rows of each method in a datablock $T_<method>, columns: wall_s, force_evals, energy_err_max
do for [m in METHODS] {
    eval sprintf("set table $T_%s separator comma", m)
    plot TIMING using "wall_s":"force_evals":"energy_err_max" with table if (strcol("method") eq m)
    unset table
}

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_cost', 17, 9)
    set multiplot layout 1,2 title sprintf("{/:Bold Cost:} energy error against computing effort, harmonic oscillator, one run to T = %g per step size h\nwall time: minimum of %s runs of at least 10 ms, single thread", T, scene_num('timing.repeats'))
    set logscale xy
    set format x LOGFMT
    set format y LOGFMT
    set ylabel "max_{t_j ∈ [0,T]} |H(q_j, p_j) − H_0|"
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, 0, 0

    set xlabel "wall time of one run [s]"
    unset key        # one key, in the right panel
    plot for [m in METHODS] '$T_'.m using 1:3 with linespoints ls STYLE(m) title LABEL(m)
    set xlabel "force evaluations in one run"
    set key bottom left width -2
    plot for [m in METHODS] '$T_'.m using 2:3 with linespoints ls STYLE(m) title LABEL(m)
    unset multiplot
    unset output
}

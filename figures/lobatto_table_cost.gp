# What the accuracy of the Lobatto scheme of Dubois & Rojas-Quintero (2025) costs
# (work-precision), beyond the paper: phase-space error at t_end on the nonlinear pendulum
# L = q̇²/2 + cos q of the Lobatto scheme (Newton on the internal nodes), the Simpson scheme, the
# implicit midpoint rule, and two fixed-step Boost.Odeint steppers (classical RK4 and
# Runge–Kutta–Fehlberg 7(8)), against the wall time of one run (left) and the number of force
# evaluations in one run (right; U_q and U_qq calls, so Newton's Jacobians count). The methods are
# those of the scene key timing.methods (the rows of timing.csv, by label: summary value methods.timing).
# Input: timing.csv (one row per method and step size h); scene values (t_end, q(0), repetitions);
# summary values (the methods).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
TIMING = csv('timing.csv')
eval need_num('T', scene_full('nonlinear.t_end'))
# the methods of the scene key timing.methods, by label, in the order of timing.csv
METHODS = summary_words('methods.timing')
if (words(METHODS) == 0) { exit error sprintf("%s/figure_values.gp: no methods.timing", results) }
do for [i = 1:words(METHODS)] {   # styles for methods other than these five
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 pt %d ps 0.7", 60 + i, word("#882255 #56B4E9 #999999 #000000 #E69F00 #0072B2 #D55E00 #009E73 #CC79A7", (i - 1) % 9 + 1), (2 * i) % 14 + 1)
}
LABEL(m) = m eq "lobatto"  ? "Lobatto (13)–(14), Newton" \
         : m eq "simpson"  ? "Simpson [2], Newton" \
         : m eq "midpoint" ? "implicit midpoint, Newton" \
         : m eq "odeint_rk4" ? "odeint: classical RK4" \
         : m eq "odeint_rkf78" ? "odeint: Runge–Kutta–Fehlberg 7(8), fixed step" : nosub(m)
STYLE(m) = m eq "lobatto" ? LS_LOB : m eq "simpson" ? LS_SIMP : m eq "midpoint" ? LS_MID \
         : m eq "odeint_rk4" ? LS_RK4 : m eq "odeint_rkf78" ? LS_RKF78 : 60 + word_index(METHODS, m)
# the rows of each method in a datablock $T_<method>, columns: wall_s, force_evals, error
do for [m in METHODS] {
    eval sprintf("set table $T_%s separator comma", m)
    plot TIMING using "wall_s":"force_evals":"error" with table if (strcol("method") eq m)
    unset table
}

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_cost', 17, 11)
    # two panels side by side and, below them, one key for both (a third, empty plot)
    set multiplot title sprintf("{/:Bold Cost:} phase-space error against computing effort, nonlinear pendulum L = q̇²/2 + cos q, q(0) = %s, p(0) = 0\n" \
                                . "one run to t_{end} = %g per step size h; wall time: minimum of %s runs of ≥ 10 ms, single thread", \
                                scene_num('nonlinear.pendulum_q0'), T, scene_num('timing.repeats'))
    set tmargin at screen 0.88; set bmargin at screen 0.27
    set border 31; set xtics autofreq; set ytics autofreq; set mxtics; set mytics; set autoscale xy  # (after the key plot)
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set ylabel "|z_N − z(t_{end})|_2,  z = (q, p)"
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04
    unset key

    set lmargin at screen 0.10; set rmargin at screen 0.47
    set xlabel "wall time of one run [µs]"
    eval LOGTICS("1 2 5")
    plot for [m in METHODS] '$T_'.m using ($1 * 1e6):3 with linespoints ls STYLE(m)
    set lmargin at screen 0.61; set rmargin at screen 0.98
    set xlabel "force evaluations in one run (U_q and U_{qq} calls)"
    eval LOGTICS("1 2 5")
    plot for [m in METHODS] '$T_'.m using 2:3 with linespoints ls STYLE(m)

    set lmargin at screen 0.02; set rmargin at screen 0.98
    set tmargin at screen 0.16; set bmargin at screen 0.01
    unset logscale; unset xlabel; unset ylabel; unset offsets
    set border 0; set xtics ("" 5); set ytics ("" 5); unset mxtics; unset mytics; set xrange [0:1]; set yrange [0:1]
    set key center center horizontal Left reverse maxrows 3 samplen 3 width -4
    plot 2 with lines notitle, \
         for [m in METHODS] keyentry with linespoints ls STYLE(m) title LABEL(m)   # (2: off the yrange; a plot of keyentries only fails)
    unset multiplot
    unset output
}

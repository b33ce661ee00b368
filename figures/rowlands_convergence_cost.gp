# What the accuracy of Fig. 4 (Takács & Fülöp (2025), Sec. 3.3) costs (work-precision):
# phase-space error at t_max of Störmer–Verlet, of the Rowlands method with either processors, and
# of three Boost.Odeint steppers (classical RK4, McLachlan's fourth-order symplectic RKN SB3a,
# velocity Verlet = Störmer–Verlet), and of Forest–Ruth (the standard fourth-order composition,
# 3 force evaluations per step), against the wall time of one run (left) and against the number
# of force evaluations in one run (right), on the planar elastic pendulum. The methods are those
# of timing.csv (the scene's timing.methods, by registry label): ours, then odeint's, any others after.
# Input: timing.csv (one row per method and step size h; one run = pre- and postprocessing once),
# scene values (pendulum parameters, initial condition and repetitions, for the title), summary
# values (methods.timing: the methods of timing.csv, by registry label).
if (!exists("results")) results = 'results/rowlands_convergence'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
TIMING = csv('timing.csv')
stats TIMING using (column("h") * column("steps")) nooutput
T = STATS_max
# the methods of timing.csv (column "method", registry labels), in the key's order: ours | odeint | others
CSV_METHODS = summary_words('methods.timing')
PREFERRED = "sv rowlands rowlands_cheap forest_ruth odeint_velocity_verlet odeint_rkn_sb3a odeint_rk4"
eval ORDER_METHODS
LABEL(m) = m eq "sv"             ? "Störmer–Verlet (26)–(28)" \
         : m eq "rowlands"       ? "Rowlands, processors (32)–(33), h²/12" \
         : m eq "rowlands_cheap" ? "Rowlands, cheap processors (34)–(37)" \
         : m eq "forest_ruth"    ? "Forest–Ruth, order 4 (3 forces per step)" \
         : m eq "odeint_rk4"     ? "odeint: classical RK4" \
         : m eq "odeint_rkn_sb3a" ? "odeint: symplectic RKN SB3a, order 4" \
         : m eq "odeint_velocity_verlet" ? "odeint: velocity Verlet (= Störmer–Verlet)" : nosub(m)
STYLE(m) = m eq "sv" ? LS_SV : m eq "rowlands" ? LS_ROW : m eq "rowlands_cheap" ? LS_ROWCH \
         : m eq "forest_ruth" ? LS_FR : m eq "odeint_rk4" ? LS_RK4 : m eq "odeint_rkn_sb3a" ? LS_RKN \
         : m eq "odeint_velocity_verlet" ? LS_VV : LS_OTHER
# the rows of each method in a datablock $T_<method>, columns: wall_s, force_evals, phase_err
do for [m in METHODS] {
    eval sprintf("set table $T_%s separator comma", m)
    plot TIMING using "wall_s":"force_evals":"phase_err" with table if (strcol("method") eq m)
    unset table
}
PARAMS = sprintf("l = %s, m = %s, k = %s, g = %s, t_{max} = %g", \
                 scene_num('pendulum.l'), scene_num('pendulum.m'), scene_num('pendulum.k'), scene_num('pendulum.g'), T)
Z0 = sprintf("(x, y, p_x, p_y) = (%s, %s, %s, %s)", scene_num('initial.0.0'), scene_num('initial.0.1'), \
             scene_num('initial.0.2'), scene_num('initial.0.3'))

do for [fmt in FORMATS] {
    eval term(fmt, 'rowlands_convergence_cost', 17, 11)
    # two panels side by side and, below them, one key for both (a third, empty plot)
    set multiplot title sprintf("{/:Bold Cost:} phase-space error against computing effort, planar elastic pendulum, %s\none run from %s with h = t_{max}/N; wall time: minimum of %s runs of ≥ 10 ms", \
                                PARAMS, Z0, scene_num('timing.repeats'))
    set tmargin at screen 0.88; set bmargin at screen 0.27
    set border 31; set xtics autofreq; set ytics autofreq; set mxtics; set mytics; set autoscale xy  # (after the key plot)
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set ylabel "|z^N − z(t_{max})|_2,  z = (x, y, p_x, p_y)"
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, 0, 0
    unset key

    set lmargin at screen 0.10; set rmargin at screen 0.47
    set xlabel "wall time of one run [µs]"
    eval LOGTICS("1 2 5")
    plot for [m in METHODS] '$T_'.m using ($1 * 1e6):3 with linespoints ls STYLE(m)
    set lmargin at screen 0.61; set rmargin at screen 0.98
    set xlabel "force evaluations in one run (U_q, or U_{qq}v)"
    eval LOGTICS("1 3")
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

# Beyond the paper: accuracy against cost of Φ^(4)_h (E* = ℰ^(4)(z_0)) for the five discretizations (5.1),
# harmonic potential U = (x² + y²)/2, one trajectory from z_0 = (0, 0, 1, 1) with N = ⌊t_end/h⌋ steps for each
# step size h of the order study: the error ‖z_N − z_ref(t_N)‖_2 at the last step t_N = N h (≤ t_end; the
# reference is taken there) against (a) the wall time of the run (the minimum over timing.repeats) and (b) the
# number of Newton iterations, N × (mean iterations per step): the force evaluations of the implicit step.
# Log–log, one line per method.
# Panels (c), (d): Φ^(4) against Φ^(0) (same discretization) and the classical RK4 on (3.8): trajectory error
# (filled, solid) and energy error max|H − H_0| (open, dashed) against wall time and evaluations
# (Newton iterations; 4 evaluations of (3.8) per RK4 step).
# Input: timing_cost.csv (method, h, steps, t_end, err, wall_s, ns_per_step, newton_iterations_per_step),
# timing_work_precision.csv (method, h, steps, t_end, err, energy_err, evals, wall_s, wall_spread),
# summary values (methods), scene values (energies.t_end, timing.repeats, cloud.center).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('harmonic')
eval MC_NEED_METHODS
TC = csv('timing_cost.csv')
WP = csv('timing_work_precision.csv')
WPM = "phi4 phi0 rk4"
WPDESC(m) = m eq "phi4" ? "Φ^{(4)}_h" : m eq "phi0" ? "Φ^{(0)}_h" : "RK4 on (3.8)"
do for [i = 1:3] {
    m = word(WPM, i)
    eval sprintf("set style line %d lc rgb '%s' lw 1.2 dt 1 pt 7 ps 0.5", 360 + i, method_colour(m))
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 dt (5,3) pt 6 ps 0.6", 370 + i, method_colour(m))
}

eval need_num('TEND', scene_real('energies.t_end'))
eval need_num('REPEATS', scene_real('timing.repeats'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
iters = 'column("steps") * column("newton_iterations_per_step")'
stats TC using "h" nooutput
HMIN = STATS_min; HMAX = STATS_max
stats TC using "newton_iterations_per_step" nooutput
ITMIN = STATS_min; ITMAX = STATS_max
# the data, one block per method (wall_s, err, iterations)
undefine $FULLB
do for [m in MC_METHODS] {
    set table $FULLB append separator comma
    plot TC using (column("wall_s")):(column("err")):(@iters) with table if (strcol("method") eq m)
    unset table
    set print $FULLB append; print ""; print ""; unset print
}

stats $FULLB using 1:2 nooutput
WMIN = STATS_min_x; WMAX = STATS_max_x; EMAX = STATS_max_y
stats $FULLB using 3 nooutput
IMIN = STATS_min; IMAX = STATS_max
# x tics at these multiples of the powers of ten, fewer the more decades the axis spans (from lo to hi)
TICSET(lo, hi) = log10(hi / lo) > 3 ? "1" : log10(hi / lo) > 1.2 ? "1 2 5" : "1 1.5 2 3 5 7"
# guide: error ∝ h² ∝ (cost)^(−2), above the data
GUIDE(x, x0) = 2.5 * EMAX * (x / x0)**(-2)

do for [fmt in FORMATS] {
    eval term(fmt, 'measure_cloud_cost', 17, 17)
    set multiplot title sprintf("{/:Bold Cost:} Φ^{(4)}_h, harmonic potential U = (x^2 + y^2)/2, z_0 = %s, h = %g … %g: " \
        . "error at t_N = N h ≤ %g against cost\n(wall time: %s; Newton iterations per step %.2f – %.2f)", \
        Z0, HMIN, HMAX, TEND, REPEATS > 1 ? sprintf("minimum of %d runs of ≥ 10 ms", REPEATS) : "one run", ITMIN, ITMAX)
    unset key
    set logscale xy
    set format y LOGFMT
    set mxtics 10; set mytics 10
    set tmargin at screen 0.90; set bmargin at screen 0.62
    set autoscale fix
    set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08
    set ylabel "‖z_N − z_{ref}(t_N)‖_2" offset 1, 0

    # ---- (a) wall time ----
    set lmargin at screen 0.10; set rmargin at screen 0.48
    set title "(a) against wall time" offset 0, -0.4
    set xlabel "wall time of the run [μs]" offset 0, 0.4
    set format x "%g"
    eval LOGTICS(TICSET(WMIN, WMAX))
    plot for [i = 0:words(MC_METHODS) - 1] $FULLB index i using ($1 * 1e6):2 with linespoints ls MC_LS(word(MC_METHODS, i + 1)) ps 0.6 notitle, \
         [t=0:1:1] '+' using (x = 1e6 * WMIN * (WMAX / WMIN)**t, x):(GUIDE(x, 1e6 * WMIN)) with lines ls MC_LS_GUIDE notitle

    # ---- (b) Newton iterations ----
    set lmargin at screen 0.60; set rmargin at screen 0.98
    set title "(b) against Newton iterations (force evaluations)"
    set xlabel "Newton iterations, N × (mean per step)"
    set format x "%g"
    eval LOGTICS(TICSET(IMIN, IMAX))
    plot for [i = 0:words(MC_METHODS) - 1] $FULLB index i using 3:2 with linespoints ls MC_LS(word(MC_METHODS, i + 1)) ps 0.6 notitle, \
         [t=0:1:1] '+' using (x = IMIN * (IMAX / IMIN)**t, x):(GUIDE(x, IMIN)) with lines ls MC_LS_GUIDE notitle

    # ---- (c), (d): Φ^(4), Φ^(0), RK4 ----
    set tmargin at screen 0.47; set bmargin at screen 0.19
    set autoscale xy
    set ylabel "error" offset 1, 0
    set lmargin at screen 0.10; set rmargin at screen 0.48
    set title sprintf("(c) Φ^{(4)}, Φ^{(0)} (%s) and RK4 against wall time", mc_scene_str('cost.discretization'))
    set xlabel "wall time of the run [μs]"
    set format x "%g"
    eval LOGTICS("1 2 5")
    plot for [i = 1:3] WP using (strcol("method") eq word(WPM, i) ? 1e6 * column("wall_s") : NaN):"err" with linespoints ls 360 + i notitle, \
         for [i = 1:3] WP using (strcol("method") eq word(WPM, i) ? 1e6 * column("wall_s") : NaN):"energy_err" with linespoints ls 370 + i notitle
    set lmargin at screen 0.60; set rmargin at screen 0.98
    set title "(d) against evaluations"
    set xlabel "Newton iterations (Φ); 4 × steps (RK4)"
    plot for [i = 1:3] WP using (strcol("method") eq word(WPM, i) ? column("evals") : NaN):"err" with linespoints ls 360 + i notitle, \
         for [i = 1:3] WP using (strcol("method") eq word(WPM, i) ? column("evals") : NaN):"energy_err" with linespoints ls 370 + i notitle

    # ---- shared key ----
    unset logscale xy
    set lmargin at screen 0.10; set rmargin at screen 0.98
    set tmargin at screen 0.08; set bmargin at screen 0.0
    unset title; unset xlabel; unset ylabel; unset border; unset tics; unset grid
    set xrange [0:1]; set yrange [0:1]
    set key at screen 0.06, screen 0.12 left top vertical Left reverse maxrows 4 samplen 2.5 width -2 spacing 1.05 font ",8" nobox
    plot NaN notitle, \
         for [m in MC_METHODS] keyentry with linespoints ls MC_LS(m) ps 0.6 title MC_DESC(m), \
         keyentry with lines ls MC_LS_GUIDE title "slope −2: error ∝ h^2 ∝ cost^{−2}", \
         for [i = 1:3] keyentry with linespoints ls 360 + i title "(c, d) " . WPDESC(word(WPM, i)) . ": trajectory error", \
         for [i = 1:3] keyentry with linespoints ls 370 + i title "(c, d) " . WPDESC(word(WPM, i)) . ": energy error max|H − H_0|"
    set border; set tics; set grid
    set autoscale xy
    unset multiplot
    unset output
}

# What an energy error of Fig. 6 of Takács & Fülöp (2025) costs in either coordinate system
# (work-precision), beyond the paper: the energy error ε of eq. (50) over [0, t_end] of symplectic
# Euler (42)–(43) on the elastic pendulum, from a few starts (x0, y0) at rest of the map (scene key
# cost.starts), at the steps cost.dt, in Cartesian (73) and polar (72) coordinates, against the wall
# time of one run (left; the scalar loop energy_map_scalar in both systems, single thread) and the
# number of force evaluations of one run (right; one gradient of U per step in either system).
# Colours as in Fig. 6 (blue Cartesian, red polar: the method, symplectic Euler, is the same); one
# marker per start. The reference is H_0 = H(z_0), conserved by the flow; its own error is the
# round-off of evaluating H (summary value work_precision.reference_error_max).
# Input: timing_cost.csv (one row per coordinate system, start and step); scene values (t_end,
# starts, pendulum); summary values (the reference's round-off).
if (!exists("results")) results = 'results/energy_map'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
COST = csv('timing_cost.csv')
eval need_num('T_END', scene_num('cost.t_end'))
eval need_num('REF_ERR', summary_real('work_precision.reference_error_max'))
eval need_num('NSTARTS', summary_num('work_precision.start_count'))
eval need_num('H_MAX', summary_num('work_precision.dt_range.max'))
eval need_num('H_MIN', summary_num('work_precision.dt_range.min'))
C_CART  = '#2166ac'   # Fig. 6's blue (Cartesian better there)
C_POLAR = '#b2182b'   # Fig. 6's red (polar better there)
MARKERS = "7 5 9 13 11 15"   # filled: circle, square, triangle, diamond, inverted triangle, pentagon
do for [i = 1:NSTARTS] {
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 pt %s ps 0.6", 200 + i, C_CART, word(MARKERS, (i - 1) % 6 + 1))
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 dt (5,3) pt %d ps 0.7", 220 + i, C_POLAR, int(word(MARKERS, (i - 1) % 6 + 1)) - 1)
}
start_x(i) = scene_num(sprintf('cost.starts.%d.0', i - 1))
start_y(i) = scene_num(sprintf('cost.starts.%d.1', i - 1))
# the rows of each system and start in a datablock $C_<system>_<start>, columns: wall_s, force_evals, eps
do for [c in "cartesian polar"] {
    do for [i = 1:NSTARTS] {
        eval sprintf("set table $C_%s_%d separator comma", c, i)
        plot COST using "wall_s":"force_evals":"eps" with table if (strcol("coordinates") eq c && column("start") == i - 1)
        unset table
    }
}

do for [fmt in FORMATS] {
    eval term(fmt, 'energy_map_cost', 17, 11)
    set multiplot title sprintf("{/:Bold Cost:} energy error (50) of symplectic Euler against computing effort, elastic pendulum, g = %s, Cartesian (73) and polar (72)\n" \
                                . "one run to t_{end} = %g per start and step h = %g … %g; wall time: scalar loop, minimum of %s runs of ≥ 10 ms, single thread\n" \
                                . "reference: H_0 = H(z_0), conserved by the flow; its own error (round-off of H) ≤ %s", \
                                scene_num('pendulum.g'), T_END, H_MAX, H_MIN, scene_num('timing.repeats'), sci(REF_ERR))
    set tmargin at screen 0.84; set bmargin at screen 0.27
    set border 31; set xtics autofreq; set ytics autofreq; set mxtics; set mytics; set autoscale xy
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set ylabel "ε = (Σ_j (H_j − H_0)^2 / J)^{1/2}"
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04
    unset key

    set lmargin at screen 0.10; set rmargin at screen 0.47
    set xlabel "wall time of one run [µs]"
    eval LOGTICS("1 2 5")
    plot for [i = 1:NSTARTS] sprintf('$C_cartesian_%d', i) using ($1 * 1e6):3 with linespoints ls 200 + i, \
         for [i = 1:NSTARTS] sprintf('$C_polar_%d', i) using ($1 * 1e6):3 with linespoints ls 220 + i
    set lmargin at screen 0.61; set rmargin at screen 0.98
    set xlabel "force evaluations in one run (one gradient of U per step)"
    eval LOGTICS("1 2 5")
    plot for [i = 1:NSTARTS] sprintf('$C_cartesian_%d', i) using 2:3 with linespoints ls 200 + i, \
         for [i = 1:NSTARTS] sprintf('$C_polar_%d', i) using 2:3 with linespoints ls 220 + i

    set lmargin at screen 0.02; set rmargin at screen 0.98
    set tmargin at screen 0.16; set bmargin at screen 0.01
    unset logscale; unset xlabel; unset ylabel; unset offsets
    set border 0; set xtics ("" 5); set ytics ("" 5); unset mxtics; unset mytics; set xrange [0:1]; set yrange [0:1]
    set key center center horizontal Left reverse maxrows 2 samplen 3 width -2
    plot 2 with lines notitle, \
         for [i = 1:NSTARTS] keyentry with linespoints ls 200 + i title sprintf("Cartesian, (x_0, y_0) = (%s, %s)", start_x(i), start_y(i)), \
         for [i = 1:NSTARTS] keyentry with linespoints ls 220 + i title sprintf("polar, (x_0, y_0) = (%s, %s)", start_x(i), start_y(i))
    unset multiplot
    unset output
}

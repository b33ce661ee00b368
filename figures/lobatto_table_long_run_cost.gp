# What the accuracy of the schemes of Dubois & Rojas-Quintero (2025) costs over the long run of
# their Fig. 2 (work-precision), beyond the paper: the oscillator (m = 1, ω = 2π, q(0) = π/2,
# p(0) = 0) over long_run.periods periods with the steps long_run_cost.h, for the methods of the
# scene key long_run_cost.methods (the rows of timing_long_run.csv, by label: summary value
# methods.long_run_cost). Top: the phase-space error |z_N − z(t_N)|_2 at the end against the closed
# form; bottom: the largest energy error |H(z_j) − H(z_0)| over the run (Fig. 2's quantity). Left:
# against the wall time of one run; right: against the force evaluations of one run (U_q and U_qq
# calls, so Newton's Jacobians count). The closed form's own error at t_N (round-off of cos ωt_N) is
# stated (summary value long_run_cost.reference_error).
# Input: timing_long_run.csv; scene values (periods, repetitions); summary values (methods, reference error).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
COST = csv('timing_long_run.csv')
eval need_num('PERIODS', scene_num('long_run.periods'))
eval need_num('REF_ERR', summary_real('long_run_cost.reference_error'))
METHODS = summary_words('methods.long_run_cost')
if (words(METHODS) == 0) { exit error sprintf("%s/figure_values.gp: no methods.long_run_cost", results) }
do for [i = 1:words(METHODS)] {   # styles for methods other than these three
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 pt %d ps 0.7", 60 + i, method_colour(word(METHODS, i)), (2 * i) % 14 + 1)
}
LABEL(m) = m eq "lobatto"  ? "Lobatto (13)–(14)" \
         : m eq "simpson"  ? "Simpson [2]" \
         : m eq "midpoint" ? "implicit midpoint" : nosub(m)
STYLE(m) = m eq "lobatto" ? LS_LOB : m eq "simpson" ? LS_SIMP : m eq "midpoint" ? LS_MID : 60 + word_index(METHODS, m)
# the rows of each method in a datablock $L_<method>, columns: wall_s, force_evals, phase_err, energy_err
do for [m in METHODS] {
    eval sprintf("set table $L_%s separator comma", m)
    plot COST using "wall_s":"force_evals":"phase_err":"energy_err" with table if (strcol("method") eq m)
    unset table
}

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_long_run_cost', 17, 16)
    set multiplot title sprintf("{/:Bold Cost over the long run of Fig. 2:} oscillator m = 1, ω = 2π, q(0) = π/2, p(0) = 0, %g periods per run\n" \
                                . "wall time: minimum of %s runs of ≥ 10 ms, single thread; reference: the closed form, its own error at t_N ≤ %s", \
                                PERIODS, scene_num('timing.repeats'), sci(REF_ERR))
    set border 31; set xtics autofreq; set ytics autofreq; set mxtics; set mytics; set autoscale xy
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, graph 0.1, graph 0.1
    unset key
    do for [row = 1:2] {
        col = row == 1 ? 3 : 4
        set tmargin at screen (row == 1 ? 0.88 : 0.50); set bmargin at screen (row == 1 ? 0.60 : 0.22)
        set ylabel (row == 1 ? "|z_N − z(t_N)|_2,  z = (q, p)" : "max_j |H(z_j) − H(z_0)|")
        set lmargin at screen 0.10; set rmargin at screen 0.47
        set xlabel "wall time of one run [s]"
        eval LOGTICS("1 2 5")
        plot for [m in METHODS] '$L_'.m using 1:col with linespoints ls STYLE(m)
        set lmargin at screen 0.61; set rmargin at screen 0.98
        set xlabel "force evaluations in one run (U_q and U_{qq} calls)"
        eval LOGTICS("1 2 5")
        plot for [m in METHODS] '$L_'.m using 2:col with linespoints ls STYLE(m)
    }

    set lmargin at screen 0.02; set rmargin at screen 0.98
    set tmargin at screen 0.08; set bmargin at screen 0.01
    unset logscale; unset xlabel; unset ylabel; unset offsets
    set border 0; set xtics ("" 5); set ytics ("" 5); unset mxtics; unset mytics; set xrange [0:1]; set yrange [0:1]
    set key center center horizontal Left reverse maxrows 1 samplen 3 width -2
    plot 2 with lines notitle, \
         for [m in METHODS] keyentry with linespoints ls STYLE(m) title LABEL(m)
    unset multiplot
    unset output
}

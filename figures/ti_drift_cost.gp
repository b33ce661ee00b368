# What the accuracy of Störmer–Verlet (1.3), Takahashi–Imada (1.4) and the simplified method (1.6)
# costs (work-precision, not in 004): the global error at t = work_precision.t_end against the wall
# time of one run (left; the minimum of timing.repeats timed runs of at least 10 ms each) and against
# the force evaluations of one run (right; gradients and Hessian–vector products, counted, processing
# included), log-log, one colour per method. TI and the simplified method are processed by (1.5) as in
# Fig. 1. Filled points: the harmonic oscillator of Fig. 1 (ω = 1, start q = 0, p = 1; there TI and the
# simplified method are the same map, so their points coincide in the right panel), against the
# exact solution; open points: Hénon–Heiles k = 3 from the start of Fig. 3, against an odeint
# Bulirsch–Stoer reference whose error estimate is summary values's work_precision.reference.henon_heiles_error.
# Input: timing_work_precision.csv; summary values (reference error); scene values (work_precision.t_end).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8
WP = csv('timing_work_precision.csv')
eval need_num('T', scene_real('work_precision.t_end'))
eval need_num('REF_ERR', summary_real('work_precision.reference.henon_heiles_error'))
METHODS = "sv ti sti"
NAME(m) = m eq "sv" ? "stormer_verlet" : m eq "ti" ? "takahashi_imada" : "simplified_takahashi_imada"
LABEL(m) = m eq "sv" ? "Störmer–Verlet (1.3)" : m eq "ti" ? "Takahashi–Imada (1.4)" : "simplified TI (1.6)"
PROBLEMS = "oscillator henon_heiles"
# the rows of each problem and method in a datablock $W_<problem>_<method>: wall_s, force_evals, error
do for [p in PROBLEMS] {
    do for [m in METHODS] {
        eval sprintf("set table $W_%s_%s separator comma", p, m)
        plot WP using "wall_s":"force_evals":"error" with table if (strcol("problem") eq p && strcol("method") eq m)
        unset table
    }
}
do for [i = 1:3] {
    m = word(METHODS, i)
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 pt 7 ps 0.6", 700 + i, method_colour(NAME(m)))
    eval sprintf("set style line %d lc rgb '%s' lw 1.0 dt (6,3) pt 6 ps 0.7", 710 + i, method_colour(NAME(m)))
}

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_cost', 17, 9)
    set multiplot layout 1,2 title sprintf("{/:Bold Cost:} global error at t = %g against computing effort; filled: oscillator (exact solution), " \
        . "open: Hénon–Heiles k = 3\n(reference: odeint Bulirsch–Stoer, estimated error %s)", T, sci(REF_ERR)) font ",9"
    set logscale xy
    set format x LOGFMT
    set format y LOGFMT
    set ylabel "global error at t = ".gprintf("%g", T)
    set offsets graph 0.04, graph 0.04, 0, 0
    set xlabel "wall time of one run [s] (minimum of the timed runs)"
    unset key
    plot for [i = 1:3] '$W_oscillator_'.word(METHODS, i) using 1:3 with linespoints ls 700 + i, \
         for [i = 1:3] '$W_henon_heiles_'.word(METHODS, i) using 1:3 with linespoints ls 710 + i
    set xlabel "force evaluations in one run"
    set key bottom left Left reverse width -2 font ",8"
    plot for [i = 1:3] '$W_oscillator_'.word(METHODS, i) using 2:3 with linespoints ls 700 + i title LABEL(word(METHODS, i)), \
         for [i = 1:3] '$W_henon_heiles_'.word(METHODS, i) using 2:3 with linespoints ls 710 + i notitle
    unset multiplot
    unset output
}

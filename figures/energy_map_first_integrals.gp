# Takács & Fülöp (2025), Sec. 5.2: first integrals of a free point mass (61)–(62) under symplectic
# Euler in the "wrong" coordinates. Left (5.2.1): in polar coordinates the linear momentum is not
# preserved: |Δp_x| after one step, p_x from (66), against h, with the least-squares slope in
# log-log (expected 2: p_x^{j+1} = p_x^j + O(h²)). Right (5.2.2): in Cartesian coordinates the
# angular momentum (69), L = x p_y − y p_x, is a quadratic invariant, preserved up to round-off:
# its relative drift |L_j − L_0| / |L_0| along one run, with plain and with compensated (Kahan)
# summation of the updates. Zeros (exact preservation) cannot be drawn on the log axis and are left out.
# (As the experiment computes them: |Δp_x| is the largest over the scene's first_integrals.initial
# states; the angular-momentum run starts from the first of them, at the smallest h.)
# Input: first_integrals.csv, angular_momentum.csv, summary values (the fitted order and line,
# maximal drifts), scene values (the initial state of the angular-momentum run).
if (!exists("results")) results = 'results/energy_map'
load 'figures/common.gp'
set encoding utf8
FI  = csv('first_integrals.csv')
ANG = csv('angular_momentum.csv')
pos(c) = (column(c) > 0) ? column(c) : NaN            # log axes: zeros and "nan" are skipped

# ---- left: the least-squares fit of the run, |Δp_x| = 10^c h^order over [h_min, h_max] (summary values)
eval need_num('ORDER', summary_num('fits.polar_px_change_per_step.order'))
eval need_num('LOG10C', summary_num('fits.polar_px_change_per_step.log10_c'))
eval need_num('HMIN', summary_num('fits.polar_px_change_per_step.h_min'))
eval need_num('HMAX', summary_num('fits.polar_px_change_per_step.h_max'))
stats FI using "h":"px_change_per_step" nooutput
H_SMALLEST = STATS_min_x
DPX_AT_HMIN = STATS_index_min_y == STATS_index_min_x ? STATS_min_y : NaN   # (the smallest change is at the smallest h)
eval need_num('ORDER_PAPER', summary_num('comparisons.polar_px_change_per_step.published'))
# reference line of the paper's order through the point at the smallest h
ref(h) = DPX_AT_HMIN * (h / H_SMALLEST)**ORDER_PAPER

# ---- right: the angular-momentum run ----------------------------------------------
stats ANG using "j" nooutput
JMAX = STATS_max
stats ANG using "t" nooutput
TMAX = STATS_max
H_ANG = TMAX / JMAX
stats ANG using (column("t") > 0 ? 1 : 0) nooutput     # (t = 0 is left out of the log t axis)
N_ANG = STATS_sum
stats ANG using (column("t") > 0 && column("L_rel_drift_plain") > 0 ? 1 : 0) nooutput
N_PLAIN_POS = STATS_sum
stats ANG using (column("t") > 0 && column("L_rel_drift_compensated") > 0 ? 1 : 0) nooutput
N_COMP_POS = STATS_sum
Z0 = sprintf("(x, y, p_x, p_y)(0) = (%s, %s, %s, %s)", scene_num('first_integrals.initial.0.0'), \
             scene_num('first_integrals.initial.0.1'), scene_num('first_integrals.initial.0.2'), scene_num('first_integrals.initial.0.3'))
eval need_num('LMAX_PLAIN', summary_num('reproduced.cartesian_L_max_rel_drift_plain'))
eval need_num('LMAX_COMP', summary_num('reproduced.cartesian_L_max_rel_drift'))
# a curve with no positive value at all would make gnuplot warn: say so in the key instead
curve(col, ls, title) = sprintf("ANG using (column('t') > 0 ? column('t') : NaN):(pos('%s')) with lines ls %d lw 0.8 title '%s'", col, ls, title)
nocurve(title) = sprintf("keyentry with points ps 0 title '%s: 0 at every sample (not drawn)'", title)
PLAIN = N_PLAIN_POS > 0 ? curve('L_rel_drift_plain', LS_SE, \
                        sprintf('plain summation%s', N_PLAIN_POS < N_ANG ? sprintf('; gaps: 0 at %d of %d t', N_ANG - N_PLAIN_POS, N_ANG) : '')) : nocurve('plain summation')
COMP  = N_COMP_POS > 0 ? curve('L_rel_drift_compensated', LS_COMP, \
                                sprintf('compensated (Kahan); gaps: 0 at %d of %d t', N_ANG - N_COMP_POS, N_ANG)) \
                       : nocurve('compensated (Kahan) summation')

do for [fmt in FORMATS] {
    eval term(fmt, 'energy_map_first_integrals', 17, 9)
    set multiplot layout 1,2 title "{/:Bold " . made_by('first_integrals') . ":} free point mass, symplectic Euler: first integrals of the other coordinate system"
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set key outside below center vertical Left reverse samplen 2.5 width -4
    set bmargin 7.5   # same for both panels, so that their axes line up
    set tmargin 4

    set title "polar coordinates: linear momentum (Sec. 5.2.1)"
    set xlabel "step size h"
    set ylabel "|p_x^{1} − p_x^{0}|  after one step"
    eval LOGTICS("1 2 5")
    set format x "%g"
    set autoscale xfix
    set offsets graph 0.05, graph 0.05, 0, 0
    set rmargin -1
    plot FI using "h":"px_change_per_step" with points ls LS_SE title sprintf("max |Δp_x| over the initial states, p_x from (66)"), \
         [h=HMIN:HMAX] '+' using (h):(powerlaw(h, LOG10C, ORDER)) with lines ls LS_SE_FIT \
                title sprintf("least-squares fit, order %.3f", ORDER), \
         [h=H_SMALLEST:HMAX] '+' using (h):(ref(h)) with lines lc rgb '#606060' lw 0.9 dt (2,3) \
                title sprintf("slope %g (paper: O(h^%g)), through the smallest h", ORDER_PAPER, ORDER_PAPER)

    set title "Cartesian coordinates: angular momentum (Sec. 5.2.2)\n{/*0.85 ".Z0."}"
    set xlabel sprintf("time t   (h = %g, %d steps, sampled every %d)", H_ANG, JMAX, JMAX / N_ANG)
    set ylabel "|L_j − L_0| / |L_0|,   L = x p_y − y p_x"
    set rmargin 4
    set xtics auto
    set format x LOGFMT
    set offsets 0, 0, 0, 0
    set autoscale xfix
    plot @PLAIN, @COMP, \
         keyentry with points ps 0 title sprintf("max over all steps: %.2g, %.2g", LMAX_PLAIN, LMAX_COMP)
    unset multiplot
    unset output
}

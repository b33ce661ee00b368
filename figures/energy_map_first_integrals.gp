# The first_integrals study's figure (its item in the title: made_by('first_integrals'), a section of Takács &
# Fülöp (2025)): first integrals of a free point mass (61)–(62) under symplectic Euler in the "wrong"
# coordinates. Left (the item's first subsection), an order panel (figures/convergence.gpi): in polar coordinates
# the linear momentum is not preserved: |Δp_x| after one step (the largest over the scene's
# first_integrals.initial states), p_x from (66), against h, with the least-squares fit of orders.csv (dashed)
# and a line of the paper's order through the point at the smallest h (expected 2: p_x^{j+1} = p_x^j + O(h²)).
# Right (its second subsection): in Cartesian coordinates the angular momentum (69), L = x p_y − y p_x, is a quadratic
# invariant, preserved up to round-off: its relative drift |L_j − L_0| / |L_0| along one run (from the first
# initial state, at the smallest h), with plain and with compensated (Kahan) summation of the updates. Zeros
# (exact preservation) cannot be drawn on the log axis and are left out.
# Input: first_integrals.csv, orders.csv, angular_momentum.csv, summary values (the paper's order, maximal
# drifts), scene values (the initial state of the angular-momentum run).
if (!exists("results")) results = 'results/energy_map'
load 'figures/common.gp'
set encoding utf8
ANG = csv('angular_momentum.csv')
pos(c) = (column(c) > 0) ? column(c) : NaN            # log axes: zeros and "nan" are skipped

# ---- left: first_integrals.csv's column px_change_per_step, fit polar_px_change_per_step (orders.csv). The
# study steps symplectic Euler (42)–(43) itself (summary methods.first_integrals names it).
eval need_num('ORDER_PAPER', summary_num('comparisons.polar_px_change_per_step.published'))
CONV_NAME = 'energy_map_first_integrals'
CONV_PAPER = "000"
CONVS1_CSV = 'first_integrals.csv'
CONVS1_METHODS = summary_words('methods.first_integrals')
CONVS1_COLUMNS = 'px_change_per_step'
CONVS1_FITS = 'polar_px_change_per_step'
CONVS1_KEYS = "''"   # (the panel's title says what is measured)
CONVS1_YLABEL = "|p_x^{1} − p_x^{0}|  after one step"
CONVS1_SLOPE = ORDER_PAPER
CONVS1_SLOPE_KEY = sprintf("slope %g (paper: O(h^%g)), through the smallest h", ORDER_PAPER, ORDER_PAPER)

# ---- right: the angular-momentum run, drawn by CONV_LAST_PANEL ----------------------------------------
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
# the two summations are no methods: role colours (figures/common.gp LS_UNCORRECTED, LS_CORRECTED)
# a curve with no positive value at all would make gnuplot warn: say so in the key instead
curve(col, ls, title) = sprintf("ANG using (column('t') > 0 ? column('t') : NaN):(pos('%s')) with lines ls %d lw 0.8 title '%s'", col, ls, title)
nocurve(title) = sprintf("keyentry with points ps 0 title '%s: 0 at every sample (not drawn)'", title)
PLAIN = N_PLAIN_POS > 0 ? curve('L_rel_drift_plain', LS_UNCORRECTED, \
                        sprintf('plain summation%s', N_PLAIN_POS < N_ANG ? sprintf('; gaps: 0 at %d of %d t', N_ANG - N_PLAIN_POS, N_ANG) : '')) : nocurve('plain summation')
COMP  = N_COMP_POS > 0 ? curve('L_rel_drift_compensated', LS_CORRECTED, \
                                sprintf('compensated (Kahan); gaps: 0 at %d of %d t', N_ANG - N_COMP_POS, N_ANG)) \
                       : nocurve('compensated (Kahan) summation')
CONV_LAST_PANEL = sprintf("set xlabel 'time t   (h = %g, %d steps, sampled every %d)'; ", H_ANG, JMAX, JMAX / N_ANG) \
    . "set ylabel '|L_j − L_0| / |L_0|,   L = x p_y − y p_x'; set rmargin 4; " \
    . "set xtics auto; set format x LOGFMT; set offsets 0, 0, 0, 0; set autoscale xfix; " \
    . "plot " . PLAIN . ", " . COMP . ", " \
    . sprintf("keyentry with points ps 0 title 'max over all steps: %.2g, %.2g'", LMAX_PLAIN, LMAX_COMP)
CONV_LAST_PANEL_KEYS = 3

SECTION = item_name(made_by('first_integrals'))   # (the panels: its subsections .1 and .2)
CONV_PANEL_TITLES = "'polar coordinates: linear momentum (" . SECTION . ".1)\n{/*0.85 max |Δp_x| over the initial states, p_x from (66)}' " \
                  . "'Cartesian coordinates: angular momentum (" . SECTION . ".2)\n{/*0.85 " . Z0 . "}'"
CONV_TITLE = "{/:Bold " . made_by('first_integrals') . ":} free point mass, symplectic Euler: first integrals of the other coordinate system"
CONV_KEY_WIDTH = -4
load 'figures/convergence.gpi'

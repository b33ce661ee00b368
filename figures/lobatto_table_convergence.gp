# Convergence of the Lobatto scheme of Dubois & Rojas-Quintero (2025), an order figure (figures/convergence.gpi).
# Left, the table of the study table1 (its item in the title: made_by('table1')): harmonic oscillator over one
# period, N steps, h = T/N; maxima over the steps of
# the absolute errors of p, q and H (Lobatto), of the discrete energy H_d (15) (round-off: not fitted), and
# of q for the methods of the scene key table1.methods (the paper scene: the Simpson scheme and the
# implicit midpoint rule). Large black rings behind the markers: the values printed in that table of the paper
# (summary values comparisons.*_err.published.<N>), so that both show where they agree.
# Right, beyond the paper (study nonlinear): nonlinear Lagrangians (Newton on the internal nodes), phase-space
# error |z_N − z(t_end)|_2 against an odeint reference: the pendulum L = q̇²/2 + cos q (Lobatto and
# the methods of nonlinear.methods; the paper scene: Simpson, midpoint) and a 2-DOF elastic pendulum (Lobatto);
# the gray line: the floor of the fits (errors below it are at the reference's accuracy, not fitted).
# Dashed: the least-squares fits of table1_orders.csv and nonlinear_orders.csv, over the h range fitted.
# Lobatto's curves (its quantities) are in its colour, told apart by marker (convergence.gpi, CONVS<P>_METHODS).
# Input: table1.csv, table1_orders.csv, nonlinear.csv, nonlinear_orders.csv, summary values (the compared
# methods methods.table1 and methods.nonlinear, the published table, Newton iterations, nonlinear.error_floor),
# scene values (oscillator, meshes, nonlinear).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)

eval need_num('OMEGA', scene_full('oscillator.omega'))
eval need_num('TEND', scene_full('nonlinear.t_end'))
eval need_num('Q0', scene_full('nonlinear.pendulum_q0'))
eval need_num('NFLOOR', summary_real('nonlinear.error_floor'))
eval need_num('NFLOOR_ATOL', summary_real('nonlinear.error_floor_over_atol'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('nonlinear.elastic_initial.0.0'), scene_num('nonlinear.elastic_initial.0.1'), \
             scene_num('nonlinear.elastic_initial.0.2'), scene_num('nonlinear.elastic_initial.0.3'))

# The studies' own method (summary methods.table1_scheme): their columns carry no method name (table1.csv: p_err ...;
# nonlinear.csv: pendulum_err, elastic_err) and its fits are named <it>_<...> (table1.cpp, nonlinear.cpp).
LOB = summary_words('methods.table1_scheme')
CONV_PAPER = "001"
CONV_NAME = 'lobatto_table_convergence'

# left: Lobatto's p, q, H, H_d (columns <quantity>_err, fits lobatto_<quantity>; H_d none), then the compared
# methods' q (columns <label>_q_err, fits <label>)
CONVS1_CSV = 'table1.csv'
CONVS1_ORDERS = 'table1_orders.csv'
CONVS1_METHODS = ""; CONVS1_COLUMNS = ""; CONVS1_FITS = ""
do for [q in "p q H Hd"] {
    CONVS1_METHODS = CONVS1_METHODS . LOB . " "
    CONVS1_COLUMNS = CONVS1_COLUMNS . q . "_err "
    CONVS1_FITS = CONVS1_FITS . (q eq "Hd" ? "-" : LOB . "_" . q) . " "
}
CONVS1_KEYS = "'momentum p' 'state q' 'energy H' 'discrete energy H_d (15)' "
do for [m in summary_words('methods.table1')] {
    CONVS1_METHODS = CONVS1_METHODS . m . " "
    CONVS1_COLUMNS = CONVS1_COLUMNS . m . "_q_err "
    CONVS1_FITS = CONVS1_FITS . m . " "
    CONVS1_KEYS = CONVS1_KEYS . "'state q' "
}
CONVS1_YLABEL = "max_{j = 1..N} |error at t_j|"
CONVS_NO_FIT = "round-off (no fit)"

# the published table (summary values comparisons.<q>_err.published.<N>, N from the scene key meshes): rings
set print $PUB
do for [k = 0:9] {
    n = scene_num(sprintf('meshes.%d', k))
    if (n ne "?") {
        do for [q in "p q H Hd"] {
            v = summary_num(sprintf('comparisons.%s_err.published.%d', q, int(real(n))))
            if (v ne "?") { print sprintf("%.17g,%s", 2 * pi / OMEGA / real(n), v) }
        }
    }
}
unset print
if (|$PUB| > 0) { CONVS1_MARKS = "$PUB"; CONVS1_MARKS_KEY = "paper, " . item_name(made_by('table1')) . " (p, q, H, H_d): rings" }

# right: Lobatto on the pendulum and the elastic pendulum (columns pendulum_err, elastic_err; fits
# lobatto_nonlinear_pendulum, lobatto_elastic_pendulum), then the compared methods on the pendulum
# (columns <label>_pendulum_err, fits <label>_nonlinear_pendulum)
CONVS2_CSV = 'nonlinear.csv'
CONVS2_ORDERS = 'nonlinear_orders.csv'
CONVS2_METHODS = LOB . " " . LOB . " "
CONVS2_COLUMNS = "pendulum_err elastic_err "
CONVS2_FITS = LOB . "_nonlinear_pendulum " . LOB . "_elastic_pendulum "
CONVS2_KEYS = "'pendulum' 'elastic pendulum (2 DOF)' "
do for [m in summary_words('methods.nonlinear')] {
    CONVS2_METHODS = CONVS2_METHODS . m . " "
    CONVS2_COLUMNS = CONVS2_COLUMNS . m . "_pendulum_err "
    CONVS2_FITS = CONVS2_FITS . m . "_nonlinear_pendulum "
    CONVS2_KEYS = CONVS2_KEYS . "'pendulum' "
}
CONVS2_YLABEL = "|z_N − z(t_{end})|_2  (odeint reference)"
CONVS2_FLOOR = NFLOOR
CONVS2_FLOOR_KEY = sprintf("%g × reference.atol = %s (not fitted below)", NFLOOR_ATOL, sci(NFLOOR))
# Newton iterations per step (mean over a run), their range over h: summary values nonlinear.newton_iterations
ITS(sys) = sprintf("%.2g–%.2g", real(summary_num('nonlinear.newton_iterations.'.sys.'.min')), \
                                real(summary_num('nonlinear.newton_iterations.'.sys.'.max')))
CONVS2_NOTE = sprintf("%s, Newton iterations per step (mean over the run):\npendulum %s, elastic pendulum %s", method_title(LOB), \
                      ITS('pendulum'), ITS('elastic'))

NL_ITEM = made_by('nonlinear')   # ("": no item of the papers)
CONV_PANEL_TITLES = sprintf("'harmonic oscillator, q(0) = A, p(0) = 0\none period T = %g, N steps, h = T/N' ", 2 * pi / OMEGA) \
    . sprintf("'nonlinear Lagrangians, error at t_{end} = %g\npendulum: q(0) = %g, p(0) = 0; elastic: z(0) = %s'", TEND, Q0, Z0)
CONV_TITLE = "{/:Bold " . made_by('table1') . "} (left) and " . (NL_ITEM eq "" || NL_ITEM eq "?" ? "beyond the paper" : "{/:Bold ".NL_ITEM."}") \
           . " (right): errors against the step size h\ndashed: least-squares fits over the h range fitted"
CONV_H_TICS = 1       # (the h of the runs: N = 10, 20, 40 steps per period; nonlinear.h)
CONV_Y_OFFSET = 0.04
CONV_KEY_WIDTH = -8   # (the long key texts)
set key font ",8.5"   # (kept by convergence.gpi's set key)
load 'figures/convergence.gpi'

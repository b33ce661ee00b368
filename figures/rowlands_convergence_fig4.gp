# Fig. 4 of Takács & Fülöp (2025), Sec. 3.3: convergence of Störmer–Verlet (26)–(28) and of the
# Rowlands method (kernel (31) with processors) on the planar elastic pendulum in Cartesian
# coordinates (App. A): energy error, eq. (50), against h (left); phase-space error at t_max (right).
# Besides the paper's two methods: the cheap processors (34)–(37), the kernel without processing,
# the processors (32)–(33) with the coefficient h²/24 as printed (which give only order 2), and
# Forest–Ruth, the standard fourth-order composition of three Störmer–Verlet steps (3 force
# evaluations per step), the order-4 peer of the processed method. The methods are those of the
# CSV (the scene's `methods`, by registry label): the paper's in a fixed order, any others after.
# Dashed lines: least-squares fits from orders.csv, drawn over the h range they were fitted on.
# Input: fig4_convergence.csv, orders.csv (the rows of initial condition `ic`, default 0, the one
# the paper scene draws), scene values (pendulum parameters and initial condition, for the title;
# observables, the panels), summary values (methods.convergence: the methods of the CSV, by label).
if (!exists("results")) results = 'results/rowlands_convergence'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
if (!exists("ic")) ic = 0
CONV = csv('fig4_convergence.csv')
sel(col) = (column("initial") == ic) ? column(col) : NaN     # the rows of initial condition ic

# the methods of the CSV (registry labels); the panels: the observables the scene named
# (energy_error: *_energy_rms columns, phase_error: *_phase columns)
CSV_METHODS = summary_words('methods.convergence')
HAS_ENERGY = in_list(scene_words('observables'), 'energy_error')
HAS_PHASE = in_list(scene_words('observables'), 'phase_error')
QUANTITIES = (HAS_ENERGY ? "energy " : "") . (HAS_PHASE ? "phase" : "")
PREFERRED = "sv kernel rowlands_printed rowlands rowlands_cheap forest_ruth"   # (the key's order)
eval ORDER_METHODS
eval method_styles(METHODS)   # (figures/common.gp: colours and markers from the registry)

# fitted orders of initial condition ic: eval fit_at('sv_energy') defines sv_energy_order, _c,
# _hmin, _hmax (as getfit in common.gp, which does not tell the initial conditions apart)
_row_ic(n, col) = (strcol("name") eq n && column("initial") == ic) ? column(col) : NaN
_get_ic(n, col, var) = sprintf("undefine STATS_*; stats csv('orders.csv') using (_row_ic('%s','%s')) nooutput; %s = STATS_max; ", n, col, var)
fit_at(n) = _get_ic(n, 'order', n.'_order') . _get_ic(n, 'log10_c', n.'_c') \
          . _get_ic(n, 'h_min', n.'_hmin')  . _get_ic(n, 'h_max', n.'_hmax')
do for [m in METHODS] { do for [q in QUANTITIES] { eval fit_at(m.'_'.q) } }

# t_max from the data; pendulum parameters and the initial condition from the scene (scene values)
stats CONV using (sel("h") * sel("steps")) nooutput
T = STATS_max
PARAMS = sprintf("l = %s, m = %s, k = %s, g = %s, t_{max} = %g", \
                 scene_num('pendulum.l'), scene_num('pendulum.m'), scene_num('pendulum.k'), scene_num('pendulum.g'), T)
Z0 = sprintf("initial condition (x, y, p_x, p_y) = (%s, %s, %s, %s)", scene_num(sprintf('initial.%d.0', ic)), \
             scene_num(sprintf('initial.%d.1', ic)), scene_num(sprintf('initial.%d.2', ic)), scene_num(sprintf('initial.%d.3', ic)))

do for [fmt in FORMATS] {
    NP = words(QUANTITIES)    # one panel per observable; the title in more lines on one panel
    SEP = NP == 1 ? "\n" : " "
    eval term(fmt, 'rowlands_convergence_fig4', NP == 1 ? 11 : 17, 12 + 0.5 * (words(METHODS) - 5) + (NP == 1 ? 1 : 0))
    set multiplot layout 1,NP title sprintf("{/:Bold Fig. 4:} planar elastic pendulum, Cartesian coordinates:%s%s\n%s;%sdashed lines: least-squares fits over the h range fitted", SEP, PARAMS, Z0, SEP)
    set format x "%g"
    eval LOGTICS("1 2 5")  # the h range may span less than a decade
    set logscale xy
    set format y LOGFMT
    set xlabel "step size h"
    set key outside below center vertical Left reverse samplen 3 width -6
    set bmargin 3.5 + 1.2 * words(METHODS)   # same for both panels, so that their axes line up
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, 0, 0

    if (HAS_ENERGY) {
    set title "energy error, eq. (50)"
    set ylabel "(J^{−1} Σ_{j=0}^{J} (H(q^j, p^j) − H_0)^2)^{1/2}"
    plot for [m in METHODS] CONV using "h":(sel(m.'_energy_rms')) with points ls method_ls(m) notitle, \
         for [m in METHODS] [t=0:1:1] '+' using (fit_h(m.'_energy', t)):(fit_err(m.'_energy', t)) \
                with lines ls method_fit_ls(m) notitle, \
         for [m in METHODS] keyentry with linespoints ls method_fit_ls(m) \
                title sprintf("%s, order %.2f", method_key(m, "000"), value(m.'_energy_order'))
    }

    if (HAS_PHASE) {
    set title "phase-space error at t_{max}"
    set ylabel "|z^N − z(t_{max})|_2,  z = (x, y, p_x, p_y)"
    plot for [m in METHODS] CONV using "h":(sel(m.'_phase')) with points ls method_ls(m) notitle, \
         for [m in METHODS] [t=0:1:1] '+' using (fit_h(m.'_phase', t)):(fit_err(m.'_phase', t)) \
                with lines ls method_fit_ls(m) notitle, \
         for [m in METHODS] keyentry with linespoints ls method_fit_ls(m) \
                title sprintf("%s, order %.2f", method_key(m, "000"), value(m.'_phase_order'))
    }
    unset multiplot
    unset output
}

# Fig. 9 of Takács & Fülöp (2025), App. B: convergence of the energy error of the methods the scene
# names on the harmonic oscillator (the paper's: symplectic Euler without and with the compensating
# transformation (82), RK4 for reference; left), global error of explicit Euler on eqs. (14) and (17)
# (right). Dashed lines: least-squares fits from orders.csv, drawn over the h range they were fitted on.
# Input: fig9_convergence.csv, orders.csv, summary values (methods.convergence: the left panel's methods).
load 'figures/common.gp'
CONV = csv('fig9_convergence.csv')
stats CONV using (column("h") * column("steps")) nooutput
T = STATS_max
METHODS = summary_words('methods.convergence')
eval method_styles(METHODS)
do for [n in "ee_decay ee_gompertz"] { eval getfit(n) }
do for [m in METHODS] { eval getfit(m.'_energy') }

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig9', 17, 9)
    set multiplot layout 1,2 title sprintf("{/:Bold Fig. 9:} convergence in h, errors as maxima over the steps t_j ∈ [0, T], T = %g; dashed: least-squares fits", T)
    set logscale xy
    set format x LOGFMT
    set format y LOGFMT
    set xlabel "step size h"
    set key outside below center vertical Left reverse
    set bmargin (words(METHODS) > 3 ? 5 + words(METHODS) : 8)   # same for both panels, so that their axes line up
    set autoscale xfix
    set offsets graph 0.04, graph 0.04, 0, 0

    set title "harmonic oscillator"
    set ylabel "max_{t_j ∈ [0,T]} |H(q_j, p_j) − H_0|"
    plot for [m in METHODS] CONV using "h":(column(m.'_max')) with points ls method_ls(m) notitle, \
         for [m in METHODS] [t=0:1:1] '+' using (fit_h(m.'_energy', t)):(fit_err(m.'_energy', t)) with lines ls method_fit_ls(m) notitle, \
         for [m in METHODS] keyentry with linespoints ls method_fit_ls(m) \
                title sprintf("%s, order %.2f", method_key(m, "000"), value(m.'_energy_order'))

    set title "explicit Euler in y (Figs 2, 3)"
    set ylabel "max_{t_j ∈ [0,T]} |y_j − y(t_j)|"
    plot CONV using "h":"ee_decay_max"   with points ls LS_SE  notitle, \
         CONV using "h":"ee_gompertz_max" with points ls LS_SE2 notitle, \
         [h=ee_decay_hmin:ee_decay_hmax] '+' using (h):(powerlaw(h, ee_decay_c, ee_decay_order)) \
                with lines ls LS_SE_FIT notitle, \
         [h=ee_gompertz_hmin:ee_gompertz_hmax] '+' using (h):(powerlaw(h, ee_gompertz_c, ee_gompertz_order)) \
                with lines ls LS_SE_FIT notitle, \
         keyentry with linespoints ls LS_SE_FIT pt 7 ps 0.55 title sprintf("ẏ = −αy, order %.2f", ee_decay_order), \
         keyentry with linespoints ls LS_SE_FIT pt 9 ps 0.65 title sprintf("Gompertz, order %.2f", ee_gompertz_order), \
         keyentry with points ps 0 title "Euler in ȳ: exact up to round-off (not shown)"
    unset multiplot
    unset output
}

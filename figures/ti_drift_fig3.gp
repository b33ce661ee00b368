# The hh3 study's figure (its item in the title: made_by('hh3')), after the paper on the simplified
# Takahashi–Imada method: the Hénon–Heiles problem
# U = (q_1² + q_2²)/2 + q_1²q_2 − q_2³/3 (k = 3, where the dominant term of (4.3) vanishes), integrated
# with the simplified method (1.6), α = 1/12, without processing; start q_1 = 0, q_2, p_2 from the
# scene, p_1 > 0 such that H = H_0.
#   (a) the error of the modified energy E = Ĥ + h⁴α²K/2 of (4.3): O(h⁶), bounded, no drift; dashed:
#       the least-squares line whose slope is summary values's reproduced.hh3_drift_slope (through the
#       data's centroid), the paper's slope (published.hh3_drift_slope) in the key.
#   (b) for contrast, the error of H itself: O(h²).
# The series is sampled (fig3_hh3.csv): drawn as points.
# Input: fig3_hh3.csv; summary values (slopes, max error); scene values (h, start, H_0).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.hh3')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8    # (so that the key width counts characters, not bytes)
F3 = csv('fig3_hh3.csv')

eval need_num('H', scene_real('h'))
eval need_num('Q2', scene_real('hh3.q2'))
eval need_num('P2', scene_real('hh3.p2'))
eval need_num('H0', scene_real('hh.H0'))
eval need_num('SLOPE', summary_real('reproduced.hh3_drift_slope'))
eval need_num('SLOPE_PUB', summary_real('comparisons.hh3_drift_slope.published'))
eval need_num('EMAX', summary_real('reproduced.hh3_max_E_err'))

stats F3 using "t":"E_err" nooutput
TBAR = STATS_mean_x; EBAR = STATS_mean_y; TMAX = STATS_max_x; NS = STATS_records
stats F3 using (column("t") > 0 ? column("t") : NaN) nooutput
DT = STATS_min
stats F3 using "H_err" nooutput
HABS = abs(STATS_max) > abs(STATS_min) ? abs(STATS_max) : abs(STATS_min)
# the E error in units of 10^k (k from its largest magnitude), H's likewise
EK = floor(log10(EMAX)); ES = 10.0**EK
HK = floor(log10(HABS)); HS = 10.0**HK
XK = TMAX >= 1e5 ? 3 * floor(log10(TMAX) / 3 + 1e-9) : 0; XS = 10.0**XK     # time in thousands, millions
XLABEL = XK == 0 ? "time t" : sprintf("time t  [10^{%d}]", XK)
line(t) = EBAR + SLOPE * (t - TBAR)

set style line 301 lc rgb C_M lw 1.0 pt 7 ps 0.25      # samples
set style line 302 lc rgb C_STAT lw 1.2 dt (8,4)         # the fitted line

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig3', 17, 14)
    set multiplot title "{/:Bold " . made_by('hh3') . ":} " . sprintf("Hénon–Heiles, U = (q_1^2 + q_2^2)/2 + q_1^2q_2 − q_2^3/3, start q_1 = 0, q_2 = %g, p_2 = %g, p_1 > 0 with H = %g;\n" \
        . method_key(TRAJ_METHOD, "004") . ", " . TI_ALPHA . ", h = %g, no processing; %d samples, every Δt = %g", Q2, P2, H0, H, NS, DT)
    set xrange [0:TMAX / XS]
    set format y "%g"
    set mxtics; set mytics
    set lmargin at screen 0.11; set rmargin at screen 0.97

    # ---- (a) the modified energy E ----
    set tmargin at screen 0.88; set bmargin at screen 0.42
    set xlabel ""
    set format x ""
    set ylabel sprintf("E(p_n, q_n) − E(p_0, q_0)   [10^{%d}]", EK) offset 0.5, 0
    set title sprintf("(a) modified energy E = Ĥ + h^4α^2K/2, (4.3): bounded, max |error| = %s", sci(EMAX)) offset 0, -0.3
    set key bottom right Left reverse samplen 3 width -2 font ",8"
    set offsets 0, 0, graph 0.02, graph 0.22
    plot F3 using (column("t") / XS):(column("E_err") / ES) with points ls 301 title "simplified TI, h = ".gprintf("%g", H), \
         [t=0:TMAX:TMAX] '+' using (t / XS):(line(t) / ES) with lines ls 302 \
             title sprintf("least-squares slope %s per unit time (paper: %s, no drift)", sci(SLOPE), sci(SLOPE_PUB))

    # ---- (b) the energy H ----
    set tmargin at screen 0.33; set bmargin at screen 0.08
    set format x "%g"
    set xlabel XLABEL offset 0, 0.3
    set ylabel sprintf("H(p_n, q_n) − H_0   [10^{%d}]", HK) offset 0.5, 0
    set title "(b) for contrast: the energy H = |p|^2/2 + U(q), O(h^2)"
    set offsets 0, 0, graph 0.05, graph 0.05
    unset key
    plot F3 using (column("t") / XS):(column("H_err") / HS) with points ls 301
    unset multiplot
    unset output
}

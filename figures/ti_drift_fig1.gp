# Fig. 1 of 004 (the simplified Takahashi–Imada method), Sect. 1.4: the harmonic oscillator
# H = (p² + ω²q²)/2 with ω = 1 and the start q_0 = 0, p_0 = 1 (fixed in experiments/ti_drift/main.cpp;
# the closed forms hold only for q_0 = 0), against the effective step ω h_eff at equal work:
# h_eff = h for the Takahashi–Imada methods (twice the cost per step), 2h for Störmer–Verlet.
#   left:  max over t ≤ t_ω/ω of the scaled global error (|ε_p|² + ω²|ε_q|²)^{1/2}
#   right: max over the same span of |H_n − H_0| / H_0, with the closed forms of Sect. 1.4 as lines
# TI and the simplified TI are processed (start χ_h^{-1}, output χ_h); on the oscillator the two
# methods coincide. Vertical lines: the stability bounds ω h_eff = 4 (SV: ωh < 2) and 2√3 (TI).
# Left, dashed: the least-squares lines whose slopes are summary.json's orders, drawn over the points
# they were fitted on (as in experiments/ti_drift/main.cpp: ω h_eff ≤ 0.5, error above 10^3 ε). Right:
# the fitted orders in the key only (their lines would hide under the closed forms).
# Input: oscillator.csv, oscillator_closed_forms.csv; summary.json (orders, stability bound);
# run.json (oscillator.t_omega).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
OSC = csv('oscillator.csv')
CF  = csv('oscillator_closed_forms.csv')

eval need_num('T_OMEGA', scene_real('oscillator.t_omega'))
eval need_num('TI_BOUND', summary_real('reproduced.ti_stability_bound'))
do for [n in "ti_solution ti_energy sv_energy sv_solution"] { eval need_num('ORD_'.n, summary_real('orders.'.n)) }
SV_BOUND = 4.0       # Störmer–Verlet is stable iff ωh < 2, and it runs at h = h_eff/2
FIT_XMAX = 0.5       # the fits of main.cpp: ω h_eff ≤ 0.5 ...
FIT_FLOOR = 1e3 * 2.0**-52   # ... and error above the round-off floor 10^3 ε

sel(m, col) = strcol("method") eq m ? column(col) : NaN
infit(m, col) = (strcol("method") eq m && column("omega_h") <= FIT_XMAX && column(col) > FIT_FLOOR) ? 1 : 0
# the least-squares line of log10(err) on log10(ω h_eff) with the fitted slope passes through the centroid
do for [m in "sv ti"] {
    do for [q in "solution"] {
        col = q eq "solution" ? "max_global_err" : "max_rel_H_err"
        stats OSC using (infit(m, col) ? log10(column("omega_h")) : NaN):(infit(m, col) ? log10(column(col)) : NaN) nooutput
        eval sprintf("XB_%s_%s = STATS_mean_x; YB_%s_%s = STATS_mean_y; X0_%s_%s = 10**STATS_min_x; X1_%s_%s = 10**STATS_max_x", \
                     m, q, m, q, m, q, m, q)
    }
}
fitline(m, q, x) = 10**(value(sprintf("YB_%s_%s", m, q)) + value(sprintf("ORD_%s_%s", m, q)) * (log10(x) - value(sprintf("XB_%s_%s", m, q))))
fitx(m, q, t) = value(sprintf("X0_%s_%s", m, q)) * (value(sprintf("X1_%s_%s", m, q)) / value(sprintf("X0_%s_%s", m, q)))**t

stats OSC using "omega_h" nooutput
XMIN = STATS_min / 1.5
XMAX = (STATS_max > SV_BOUND ? STATS_max : SV_BOUND) * 1.25

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig1', 17, 10)
    set multiplot layout 1,2 title sprintf("{/:Bold Fig. 1:} harmonic oscillator, ω = 1, (q_0, p_0) = (0, 1); maxima over t ≤ %g/ω; " \
        . "equal work: h_{eff} = 2h for Störmer–Verlet (SV),\nh_{eff} = h for Takahashi–Imada (TI) and the simplified TI (both processed); " \
        . "left, dashed: least-squares fits over ωh_{eff} ≤ %g; vertical lines: stability bounds", T_OMEGA, FIT_XMAX)
    set logscale xy
    set xrange [XMIN:XMAX]
    set format x "%g"
    eval LOGTICS("1 2 5")
    set format y LOGFMT
    set xlabel "effective step size ω h_{eff}"
    set key top left Left reverse samplen 3 width -3 font ",8"
    set arrow 1 from SV_BOUND, graph 0 to SV_BOUND, graph 1 nohead lc rgb C_SV lw 0.8 dt (6,3)
    set arrow 2 from TI_BOUND, graph 0 to TI_BOUND, graph 1 nohead lc rgb C_TI lw 0.8
    set label 1 "SV: ωh_{eff} = 4" at SV_BOUND, graph 0.03 left rotate by 90 offset 0.9, 0 font ",7" tc rgb C_SV
    set label 2 sprintf("TI: 2√3 = %.4f", TI_BOUND) at TI_BOUND, graph 0.03 left rotate by 90 offset -0.4, 0 font ",7" tc rgb C_TI
    set bmargin 3.5
    set tmargin 4.5

    set title "(left) global error, maximum over the run"
    set ylabel "max_n (|ε_p|^2 + ω^2 |ε_q|^2)^{1/2}"
    plot OSC using "omega_h":(sel("sv", "max_global_err")) with points ls LS_TD_SV \
             title sprintf("SV (1.3), h = h_{eff}/2: order %.2f", ORD_sv_solution), \
         OSC using "omega_h":(sel("ti", "max_global_err")) with points ls LS_TD_TI \
             title sprintf("TI (1.4), processed: order %.2f", ORD_ti_solution), \
         OSC using "omega_h":(sel("sti", "max_global_err")) with points ls LS_TD_STI \
             title "simplified TI (1.6), processed", \
         [t=0:1:1] '+' using (fitx("sv", "solution", t)):(fitline("sv", "solution", fitx("sv", "solution", t))) with lines ls LS_TD_SV_FIT notitle, \
         [t=0:1:1] '+' using (fitx("ti", "solution", t)):(fitline("ti", "solution", fitx("ti", "solution", t))) with lines ls LS_TD_TI_FIT notitle

    set title "(right) relative energy error, maximum over the run"
    set ylabel "max_n |H(p_n, q_n) − H_0| / H_0   (TI: H(p̂_n, q̂_n))"
    plot OSC using "omega_h":(sel("sv", "max_rel_H_err")) with points ls LS_TD_SV \
             title sprintf("SV: order %.2f", ORD_sv_energy), \
         OSC using "omega_h":(sel("ti", "max_rel_H_err")) with points ls LS_TD_TI \
             title sprintf("TI: order %.2f", ORD_ti_energy), \
         OSC using "omega_h":(sel("sti", "max_rel_H_err")) with points ls LS_TD_STI \
             title "simplified TI", \
         CF using "omega_h":"sv_rel_H" with lines lc rgb C_SV lw 0.8 title "SV, closed form y^2/(16 − y^2),  y = ωh_{eff}", \
         CF using "omega_h":"ti_rel_H" with lines lc rgb C_TI lw 0.8 title "TI, closed form y^6/(36 (y^4 − 12y^2 + 48))"
    unset multiplot
    unset output
}

# The pendulum study's figure (its item in the title: made_by('pendulum')), after the paper on the simplified
# Takahashi–Imada method: the unsymmetric pendulum
# U(q) = −cos q + 0.2 sin 2q (no symmetry q ↔ −q; p > 0 throughout, the pendulum turns round),
# integrated with the simplified method (1.6), α = 1/12, without processing.
#   (a) the shifted energy H + h²H_3 minus its initial value, H_3 = (U''(p,p) − |∇U|²)/12 (Takahashi–
#       Imada's, docs: shared note ti_drift.md §3.4), with the least-squares line whose slope is
#       summary values's reproduced.unsym_pendulum_drift_rate (drawn through the data's centroid, which
#       the least-squares line passes through); the key also gives the rate predicted from (4.3).
#   (b) the error of H itself: the O(h²) oscillation on top of the same drift (dashed: the slope of
#       (a) through the centroid of the H error).
#   (c) the local drift over the whole run: the least-squares slope of (a) in each of pendulum.slope_windows
#       consecutive windows (points), against the rate of (4.3) averaged over the rotating orbit of each
#       window's mean energy (line); the largest relative difference is summary values's
#       pendulum.local_slope.max_rel_difference. The rate falls as the energy falls.
# The series is sampled (fig2_pendulum.csv: every Δt, much longer than a period, so the oscillation is
# aliased): drawn as points.
# Input: fig2_pendulum.csv, fig2_local_slope.csv; summary values (drift rates); scene values (h, pendulum start).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.pendulum')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8    # (so that the key width counts characters, not bytes)
F2 = csv('fig2_pendulum.csv')
LS = csv('fig2_local_slope.csv')

eval need_num('H', scene_real('h'))
eval need_num('Q0', scene_real('pendulum.q0'))
eval need_num('P0', scene_real('pendulum.p0'))
eval need_num('RATE', summary_real('reproduced.unsym_pendulum_drift_rate'))
eval need_num('RATE_PRED', summary_real('reproduced.unsym_pendulum_drift_rate_predicted'))
eval need_num('LS_DIFF', summary_real('pendulum.local_slope.max_rel_difference'))
eval need_num('LS_W', summary_real('pendulum.local_slope.window_length'))

stats F2 using "t":"shifted_energy_err" nooutput
TBAR = STATS_mean_x; EBAR = STATS_mean_y; TMAX = STATS_max_x; NS = STATS_records
stats F2 using (column("t") > 0 ? column("t") : NaN) nooutput
DT = STATS_min
stats F2 using "H_err" nooutput
HBAR = STATS_mean
drift(t) = EBAR + RATE * (t - TBAR)
hdrift(t) = HBAR + RATE * (t - TBAR)     # (b): the same slope through the centroid of the H error

set style line 201 lc rgb C_M lw 1.0 pt 7 ps 0.25      # samples
set style line 202 lc rgb C_STAT lw 1.2 dt (8,4)         # the fitted drift
set style line 203 lc rgb C_M lw 1.0 pt 6 ps 0.6       # local slopes
set style line 204 lc rgb C_STAT lw 1.2                  # (4.3) at the current energy

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig2', 17, 19)
    set multiplot title "{/:Bold " . made_by('pendulum') . ":} " . sprintf("unsymmetric pendulum U(q) = −cos q + 0.2 sin 2q, start (q_0, p_0) = (%g, %g), " \
        . method_key(TRAJ_METHOD, "004") . ", " . TI_ALPHA . ",\nh = %g, no processing; %d samples, every Δt = %g", Q0, P0, H, NS, DT)
    set xrange [0:TMAX]
    set format x "%g"
    set format y "%g"
    set mxtics; set mytics
    set lmargin at screen 0.13; set rmargin at screen 0.97

    # ---- (a) the shifted energy ----
    set tmargin at screen 0.90; set bmargin at screen 0.62
    set xlabel ""
    set format x ""
    set ylabel "(H + h^2H_3)(p_n, q_n) − (H + h^2H_3)(p_0, q_0)" offset 0.5, 0
    set title "(a) shifted modified energy, H_3 = (U''(p, p) − |∇U(q)|^2)/12: linear drift O(t h^4)" offset 0, -0.3
    set key bottom left Left reverse samplen 3 width -2 font ",8"
    plot F2 using "t":"shifted_energy_err" with points ls 201 title "simplified TI, h = ".gprintf("%g", H), \
         [t=0:TMAX:TMAX] '+' using (t):(drift(t)) with lines ls 202 \
             title sprintf("least-squares slope %s per unit time; predicted from (4.3): %s", sci(RATE), sci(RATE_PRED))

    # ---- (b) the energy ----
    set tmargin at screen 0.56; set bmargin at screen 0.36
    set format x ""
    set ylabel "H(p_n, q_n) − H(p_0, q_0)" offset 0.5, 0
    set title "(b) energy H = p^2/2 + U(q): bounded O(h^2) oscillation plus the same drift"
    set key bottom left Left reverse samplen 3 width -2 font ",8"
    plot F2 using "t":"H_err" with points ls 201 notitle, \
         [t=0:TMAX:TMAX] '+' using (t):(hdrift(t)) with lines ls 202 title "slope of (a)"

    # ---- (c) the local drift against (4.3) at the current energy ----
    set tmargin at screen 0.30; set bmargin at screen 0.07
    set format x "%g"
    set xlabel "time t" offset 0, 0.3
    set ylabel "d/dt (H + h^2H_3)" offset 0.5, 0
    set title sprintf("(c) local drift over the run: slopes of (a) in windows of %g, and (4.3) at each window's energy (largest difference %.1f%%)", \
                      LS_W, 100 * LS_DIFF)
    set key bottom right Left reverse samplen 3 width -2 font ",8"
    plot LS using "t_mid":"local_slope" with points ls 203 title "least-squares slope of (a) in each window", \
         LS using "t_mid":"predicted_slope" with lines ls 204 title "(4.3), −h^4/2880 U^{(5)}p^5, averaged over the orbit of the window's mean H"
    unset multiplot
    unset output
}

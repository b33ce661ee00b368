# The poincare study's figure (its item in the title: made_by('poincare')), after the paper on the simplified
# Takahashi–Imada method: Poincaré cuts of one trajectory of the ensemble study (ti_drift_fig4.gp; the title names
# its item, made_by('ensemble')) (summary values reproduced.poincare_trajectory: the one with the largest error), the points
# (q_2, p_2) where q_1 crosses 0 upwards with p_1 > 0 (linear interpolation between steps). The paper:
# during linear growth of E the cuts lie on one side (p_2 < 0), otherwise they are spread symmetrically.
#   (a) the error of E of that trajectory over the whole run (fig5_episodes.csv, every recorded time), with
#       its growth (and decline) episodes shaded: where the running least-squares slope of the error over
#       ± ensemble.episode_half_width leaves its median by more than ensemble.episode_threshold robust
#       standard deviations (1.4826 MAD of the running slopes), for at least ensemble.episode_min_length;
#       the flattest of 20 equal windows (the left picture of 004) is marked (c).
#   (b) that running slope in robust standard deviations from its median, with the thresholds ±threshold.
#   (c) the cuts of the flattest window (fig5_poincare.csv, window "no_growth"), coloured by time t.
#   (d) the cuts of the longest growth episode (fig5_episode_cuts.csv), coloured by time t; the title gives
#       the share with p_2 < 0, and the change of E over the episode recorded and predicted by (4.3),
#       h Σ dE/dt along the steps (summary values poincare.episodes.longest_growth).
# Input: fig5_episodes.csv, fig5_episode_cuts.csv, fig5_poincare.csv; summary values (trajectory, windows,
# episodes); scene values (h, k, ensemble.episode_*).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.poincare')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8    # (so that the key width counts characters, not bytes)
eval PALETTE_TIME
PC  = csv('fig5_poincare.csv')
EP  = csv('fig5_episodes.csv')
EC  = csv('fig5_episode_cuts.csv')

eval need_num('H', scene_real('h'))
eval need_num('K', scene_real('hh.k'))
eval need_num('THR', scene_real('ensemble.episode_threshold'))
eval need_num('TRAJ', summary_real('reproduced.poincare_trajectory'))
eval need_num('NEP', summary_real('poincare.episodes.count'))
eval need_num('S_MED', summary_real('poincare.episodes.rule.slope_median'))
eval need_num('S_NOISE', summary_real('poincare.episodes.rule.slope_noise'))
eval need_num('F0', summary_real('reproduced.poincare_windows.no_growth.0'))
eval need_num('F1', summary_real('reproduced.poincare_windows.no_growth.1'))
HAS_GROWTH = summary_num('poincare.episodes.longest_growth.t_start') ne "?"
if (HAS_GROWTH) {
    eval need_num('G0', summary_real('poincare.episodes.longest_growth.t_start'))
    eval need_num('G1', summary_real('poincare.episodes.longest_growth.t_end'))
    eval need_num('G_SHARE', summary_real('poincare.episodes.longest_growth.share_p2_negative'))
    eval need_num('G_CHANGE', summary_real('poincare.episodes.longest_growth.E_err_change'))
    eval need_num('G_PRED', summary_real('poincare.episodes.longest_growth.E_change_predicted'))
}
do for [i = 0:NEP - 1] {
    eval need_num(sprintf('EP0_%d', i), summary_real(sprintf('poincare.episodes.list.%d.t_start', i)))
    eval need_num(sprintf('EP1_%d', i), summary_real(sprintf('poincare.episodes.list.%d.t_end', i)))
    eval need_num(sprintf('EPS_%d', i), summary_real(sprintf('poincare.episodes.list.%d.sign', i)))
}

stats EP using "t":"E_err" nooutput
TMAX = STATS_max_x
EABS = abs(STATS_max_y) > abs(STATS_min_y) ? abs(STATS_max_y) : abs(STATS_min_y)
EK = floor(log10(EABS)); ES = 10.0**EK
XK = TMAX >= 1e5 ? 3 * floor(log10(TMAX) / 3 + 1e-9) : 0; XS = 10.0**XK
TUNIT = XK == 0 ? "" : sprintf("  [10^{%d}]", XK)
fmtw(a, b) = sprintf("t ∈ [%g, %g]%s", a / XS, b / XS, XK == 0 ? "" : sprintf("·10^{%d}", XK))
eval columns('PC', PC)    # (the cut files are many rows, read several times: their columns by number)
eval columns('EC', EC)
inflat = 'strcol(PC_window) eq "no_growth"'
ingrowth(t) = HAS_GROWTH && t >= G0 && t <= G1
stats PC skip 1 using (@inflat ? column(PC_p2) : NaN):(column(PC_p2) < 0 ? 1 : 0) nooutput   # (one pass: the cuts, those with p_2 < 0)
N_F = STATS_records; NNEG_F = int(STATS_sum_y)
stats PC skip 1 using PC_q2:PC_p2 nooutput
QMIN = STATS_min_x; QMAX = STATS_max_x; PMIN = STATS_min_y; PMAX = STATS_max_y
if (HAS_GROWTH) {
    stats EC skip 1 using (ingrowth(column(EC_t)) ? column(EC_p2) : NaN) nooutput
    N_G = STATS_records
    stats EC skip 1 using EC_q2:EC_p2 nooutput
    QMIN = STATS_min_x < QMIN ? STATS_min_x : QMIN; QMAX = STATS_max_x > QMAX ? STATS_max_x : QMAX
    PMIN = STATS_min_y < PMIN ? STATS_min_y : PMIN; PMAX = STATS_max_y > PMAX ? STATS_max_y : PMAX
}

set style line 501 lc rgb '#4D4D4D' lw 0.8           # E error
set style line 502 lc rgb '#A8A8A8' lw 0.6 dt (3,3)  # p_2 = 0, thresholds
set style line 503 lc rgb '#882255' lw 0.9           # running slope

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig5', 17, 18)
    set multiplot title "{/:Bold " . made_by('poincare') . ":} " . sprintf("Poincaré cuts q_1 = 0, p_1 > 0 of trajectory no. %d of " . item_name(made_by('ensemble')) . " (Hénon–Heiles, k = %d,\n" \
                                . method_key(TRAJ_METHOD, "004") . ", h = %g): growth episodes of its error of E found from the data (shaded),\n" \
                                . "the flattest window and the longest growth episode (each cut coloured by its time t)", TRAJ, K, H) font ",9"
    set mxtics; set mytics
    set lmargin at screen 0.09; set rmargin at screen 0.92
    set xrange [0:TMAX / XS]
    set format x "%g"; set format y "%g"
    set cbrange [0:1]
    unset colorbox
    unset key

    # ---- (a) the error of E along the whole run, with the episodes ----
    set tmargin at screen 0.88; set bmargin at screen 0.74
    set yrange [*:*]
    set offsets 0, 0, graph 0.1, graph 0.1
    set format x ""
    unset xlabel
    set ylabel sprintf("E_n − E_0  [10^{%d}]", EK) offset 1, 0
    set title sprintf("(a) error of E along trajectory no. %d: episodes of linear change: %d (shaded: growth red, decline blue), flattest window (c) grey", TRAJ, NEP) offset 0, -0.4
    set object 1 rect from F0 / XS, graph 0 to F1 / XS, graph 1 behind fc rgb '#E0E0E0' fs solid 1.0 noborder
    set label 1 "(c)" at (F0 + F1) / 2 / XS, graph 0.88 center font ",8"
    do for [i = 0:NEP - 1] {
        set object 10 + i rect from value(sprintf('EP0_%d', i)) / XS, graph 0 to value(sprintf('EP1_%d', i)) / XS, graph 1 behind \
            fc rgb (value(sprintf('EPS_%d', i)) > 0 ? '#F4C2C2' : '#C2D4F4') fs solid 1.0 noborder
    }
    plot EP using (column("t") / XS):(column("E_err") / ES) with lines ls 501

    # ---- (b) the running slope in robust standard deviations ----
    set tmargin at screen 0.685; set bmargin at screen 0.565
    set offsets 0, 0, graph 0.05, graph 0.05
    set format x "%g"
    set xlabel "time t".TUNIT offset 0, 0.5
    set ylabel "slope (noise)" offset 1, 0
    set title sprintf("(b) running slope of (a), (s − median)/(1.4826 MAD); episodes beyond ±%g", THR) offset 0, -0.4
    set arrow 2 from graph 0, first THR to graph 1, first THR nohead ls 502 back
    set arrow 3 from graph 0, first -THR to graph 1, first -THR nohead ls 502 back
    plot EP using (column("t") / XS):((column("running_slope") - S_MED) / S_NOISE) with lines ls 503
    unset object 1; unset label 1; unset arrow 2; unset arrow 3
    do for [i = 0:NEP - 1] { unset object 10 + i }

    # ---- (c), (d) the cuts ----
    set tmargin at screen 0.45; set bmargin at screen 0.06
    set xrange [QMIN:QMAX]
    set yrange [PMIN:PMAX]
    set offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03
    set xlabel "q_2" offset 0, 0.3
    set ylabel "p_2" offset 1, 0
    set format cb "%g"
    set cbtics scale 0.5 out nomirror
    set cblabel "time t".TUNIT offset 0.5, 0
    set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead ls 502 back
    set lmargin at screen 0.09; set rmargin at screen 0.39
    set colorbox user origin screen 0.40, screen 0.06 size screen 0.014, screen 0.39
    set cbrange [F0 / XS:F1 / XS]
    set title sprintf("(c) flattest of 20 windows: %s\n%d cuts, %.0f%% of them with p_2 < 0", fmtw(F0, F1), N_F, 100.0 * NNEG_F / N_F) offset 0, -0.3
    plot PC skip 1 using (@inflat ? column(PC_q2) : NaN):PC_p2:(column(PC_t) / XS) with points pt 7 ps 0.12 lc palette
    set lmargin at screen 0.57; set rmargin at screen 0.87
    set colorbox user origin screen 0.88, screen 0.06 size screen 0.014, screen 0.39
    if (HAS_GROWTH) {
        set cbrange [G0 / XS:G1 / XS]
        set title sprintf("(d) longest growth episode: %s, %d cuts,\n%.1f%% with p_2 < 0; ΔE = %s, by (4.3) %s", fmtw(G0, G1), N_G, \
                          100.0 * G_SHARE, sci(G_CHANGE), sci(G_PRED)) offset 0, -0.3
        plot EC skip 1 using (ingrowth(column(EC_t)) ? column(EC_q2) : NaN):EC_p2:(column(EC_t) / XS) with points pt 7 ps 0.12 lc palette
    } else {
        set title "(d) no growth episode by the rule of (b)" offset 0, -0.3
        plot PC skip 1 using (NaN):PC_p2 with points
    }
    unset arrow 1
    unset multiplot
    unset output
}

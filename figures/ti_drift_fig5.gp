# Fig. 5 of 004 (the simplified Takahashi–Imada method), Sect. 5.2.2: Poincaré cuts of one trajectory
# of Fig. 4 (summary values reproduced.poincare_trajectory: the one with the largest error), the points
# (q_2, p_2) where q_1 crosses 0 upwards with p_1 > 0 (linear interpolation between steps), over two time
# windows (reproduced.poincare_windows): one where its E error changes fastest ("growth") and one where
# it is flattest ("no growth"). The paper: during linear growth the cuts lie on one side (p_2 < 0),
# otherwise they are spread symmetrically, so that the integral of (4.3) cancels.
#   (a) the E error of that trajectory (fig4_trajectories.csv) around the two windows (shaded); inside
#       the windows the line has the colour of the time, as the points below.
#   (b) on the same time axis, the share of the cuts with p_2 < 0 in tenths of each window (its own panel
#       and axis, so that the two quantities do not share one).
#   (c), (d) the cuts of each window, coloured by time t (colour bar), with the share of p_2 < 0.
# Input: fig5_poincare.csv, fig4_trajectories.csv; summary values (trajectory, windows); scene values (h, k).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
eval PALETTE_TIME
PC  = csv('fig5_poincare.csv')
TRJ = csv('fig4_trajectories.csv')

eval need_num('H', scene_real('h'))
eval need_num('K', scene_real('hh.k'))
eval need_num('TRAJ', summary_real('reproduced.poincare_trajectory'))
WINDOWS = "no_growth growth"                       # left, right (as the paper's Fig. 5)
WLABEL(w) = w eq "growth" ? "fastest change of E (\"growth\")" : "flattest E (\"no growth\")"
do for [w in WINDOWS] {
    eval need_num('W0_'.w, summary_real('reproduced.poincare_windows.'.w.'.0'))
    eval need_num('W1_'.w, summary_real('reproduced.poincare_windows.'.w.'.1'))
}
W0(w) = value('W0_'.w)
W1(w) = value('W1_'.w)

# counts and ranges from the data
inw(w) = strcol("window") eq w
do for [w in WINDOWS] {
    stats PC using (inw(w) ? column("p2") : NaN) nooutput
    eval sprintf("N_%s = STATS_records", w)
    stats PC using (inw(w) && column("p2") < 0 ? 1 : NaN) nooutput
    eval sprintf("NNEG_%s = STATS_records", w)
}
stats PC using "q2":"p2" nooutput
QMIN = STATS_min_x; QMAX = STATS_max_x; PMIN = STATS_min_y; PMAX = STATS_max_y
mine(col) = column("trajectory") == TRAJ ? column(col) : NaN
stats TRJ using (mine("t")):(mine("E_err")) nooutput
TMAX = STATS_max_x
EABS = abs(STATS_max_y) > abs(STATS_min_y) ? abs(STATS_max_y) : abs(STATS_min_y)
EK = floor(log10(EABS)); ES = 10.0**EK
XK = TMAX >= 1e5 ? 3 * floor(log10(TMAX) / 3 + 1e-9) : 0; XS = 10.0**XK
TUNIT = XK == 0 ? "" : sprintf("  [10^{%d}]", XK)
fmtw(w) = sprintf("t ∈ [%g, %g]%s", W0(w) / XS, W1(w) / XS, XK == 0 ? "" : sprintf("·10^{%d}", XK))
# (a): the fraction of the window elapsed, the colour (palette fraction) of the line inside window w
# (NaN outside; the y value must be NaN there too, or the line is drawn there in an undefined colour)
frac(w) = (column("t") >= W0(w) && column("t") <= W1(w)) ? (column("t") - W0(w)) / (W1(w) - W0(w)) : NaN

# the x range of (a): the windows and half their span on either side, within the run
WA = W0("no_growth") < W0("growth") ? W0("no_growth") : W0("growth")
WB = W1("no_growth") > W1("growth") ? W1("no_growth") : W1("growth")
XA = WA - 0.5 * (WB - WA); XA = XA < 0 ? 0 : XA
XB = WB + 0.5 * (WB - WA); XB = XB > TMAX ? TMAX : XB
# (b): the share of cuts with p_2 < 0 per tenth of window w (smooth unique averages y at equal x)
NBIN = 10
bin(w) = W0(w) + (floor((column("t") - W0(w)) / ((W1(w) - W0(w)) / NBIN)) + 0.5) * (W1(w) - W0(w)) / NBIN

set style line 503 lc rgb '#882255' lw 1.3           # share of p_2 < 0
set style line 501 lc rgb '#8C8C8C' lw 0.9           # E error outside the windows
set style line 502 lc rgb '#A8A8A8' lw 0.6 dt (3,3)  # p_2 = 0

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig5', 17, 18)
    set multiplot title sprintf("{/:Bold Fig. 5:} Poincaré cuts q_1 = 0, p_1 > 0 of trajectory no. %d of Fig. 4 (Hénon–Heiles, k = %d,\n" \
                                . "simplified Takahashi–Imada (1.6), h = %g): the window where its error of E changes fastest\n" \
                                . "and the one where it is flattest (each point coloured by its time t)", TRAJ, K, H) font ",9"
    set mxtics; set mytics
    set lmargin at screen 0.09; set rmargin at screen 0.92
    set xrange [XA / XS:XB / XS]
    set format x "%g"; set format y "%g"
    set cbrange [0:1]
    unset colorbox
    unset key

    # ---- (a) the error of E along the trajectory, with the windows ----
    set tmargin at screen 0.88; set bmargin at screen 0.74
    set yrange [*:*]
    set offsets 0, 0, graph 0.1, graph 0.1
    set format x ""
    unset xlabel
    set ylabel sprintf("E_n − E_0  [10^{%d}]", EK) offset 1, 0
    set title sprintf("(a) error of the modified energy E along trajectory no. %d, around the windows of (c) and (d) (shaded)", TRAJ) offset 0, -0.4
    set object 1 rect from W0("no_growth") / XS, graph 0 to W1("no_growth") / XS, graph 1 behind fc rgb '#EBEBEB' fs solid 1.0 noborder
    set object 2 rect from W0("growth") / XS, graph 0 to W1("growth") / XS, graph 1 behind fc rgb '#DCDCDC' fs solid 1.0 noborder
    set label 1 "(c)" at (W0("no_growth") + W1("no_growth")) / 2 / XS, graph 0.88 center font ",8"
    set label 2 "(d)" at (W0("growth") + W1("growth")) / 2 / XS, graph 0.88 center font ",8"
    plot TRJ using (mine("t") / XS):(mine("E_err") / ES) with lines ls 501, \
         for [w in WINDOWS] TRJ using (mine("t") / XS):(frac(w) == frac(w) ? mine("E_err") / ES : NaN):(frac(w)) \
             with linespoints lc palette lw 2 pt 7 ps 0.35
    unset label 1; unset label 2

    # ---- (b) the share of the cuts with p_2 < 0, per tenth of each window, on the same time axis ----
    set tmargin at screen 0.685; set bmargin at screen 0.585
    set yrange [-0.05:1.05]
    set ytics 0, 0.5, 1
    set offsets 0, 0, 0, 0
    set format x "%g"
    set xlabel "time t".TUNIT offset 0, 0.5
    set ylabel "share of p_2 < 0" offset 1, 0
    set title "(b) share of the cuts with p_2 < 0 in each tenth of the windows" offset 0, -0.4
    set arrow 2 from graph 0, first 0.5 to graph 1, first 0.5 nohead ls 502 back
    plot for [w in WINDOWS] PC using (inw(w) ? bin(w) / XS : NaN):(column("p2") < 0 ? 1 : 0) smooth unique with histeps ls 503
    unset object 1; unset object 2; unset arrow 2
    set ytics autofreq

    # ---- (c), (d) the cuts, one panel per window ----
    set tmargin at screen 0.46; set bmargin at screen 0.06
    set xrange [QMIN:QMAX]
    set yrange [PMIN:PMAX]
    set offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03
    set xlabel "q_2" offset 0, 0.3
    set ylabel "p_2" offset 1, 0
    set format cb "%g"
    set cbtics scale 0.5 out nomirror
    set cblabel "time t".TUNIT offset 0.5, 0
    set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead ls 502 back
    i = 0
    do for [w in WINDOWS] {
        i = i + 1
        L = i == 1 ? 0.09 : 0.57
        set lmargin at screen L; set rmargin at screen L + 0.30
        set colorbox user origin screen L + 0.31, screen 0.06 size screen 0.014, screen 0.40
        set cbrange [W0(w) / XS:W1(w) / XS]
        set title sprintf("(%s) %s: %s\n%d cuts, %.0f%% of them with p_2 < 0", i == 1 ? "c" : "d", WLABEL(w), fmtw(w), \
                          value("N_".w), 100.0 * value("NNEG_".w) / value("N_".w)) offset 0, -0.3
        plot PC using (inw(w) ? column("q2") : NaN):"p2":(column("t") / XS) with points pt 7 ps 0.12 lc palette
    }
    unset arrow 1
    unset multiplot
    unset output
}

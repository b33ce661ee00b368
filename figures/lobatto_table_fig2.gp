# The long_run study's figure (its item in the title: made_by('long_run')), after Dubois & Rojas-Quintero
# (2025): the energy error of the Lobatto scheme
# (13)–(14) on the harmonic oscillator over many periods, for the step sizes of the scene key
# long_run.h (the paper: h = 0.1, 0.05, 0.025, 10^5 periods). The run is cut into windows of
# equal length; each point is the maximum over one window.
#   (a) max |H − H_0|, H the energy: dominated by the O(h^6) oscillation of H along the orbit.
#   (b) the same maxima relative to their mean over the run, with the least-squares lines
#       whose slopes are the growth rates of summary values (the paper's caption gives a rate per
#       h); the line is drawn with the reproduced slope through the data's centroid.
#   (c) the error of the discrete energy H_d, eq. (15), which the scheme conserves exactly in
#       exact arithmetic: round-off, with the map (13) applied as x ← Φx (plain, solid) and as
#       y ← y + (Φ − I)y with compensated summation (dashed).
# Input: fig2_energy.csv; summary values (growth rates, reproduced and published); scene values (the h,
# periods, windows, oscillator).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
F2 = csv('fig2_energy.csv')
eval columns('F2', F2)          # (read some 30 times, by step size: its columns by number)

eval need_num('PERIODS', scene_full('long_run.periods'))
eval need_num('WINDOWS', scene_full('long_run.windows'))
eval need_num('OMEGA', scene_full('oscillator.omega'))
# the step sizes: HS[1] .. HS[NH] from the scene
array HS[10]
NH = 0
do for [k = 0:9] { s = scene_full(sprintf('long_run.h.%d', k)); if (s ne "?") { NH = k + 1; eval sprintf("HS[%d] = %s", NH, s) } }
if (NH == 0) { exit error "long_run.h: missing from ".results."/run.json" }
if (NH > 3) { exit error sprintf("long_run.h has %d step sizes; the figure has colours for 3", NH) }
HV(i) = HS[i]
COL(i) = i == 1 ? C_LOB_H1 : i == 2 ? C_LOB_H2 : C_LOB_H3
PT(i) = i == 1 ? 6 : i == 2 ? 4 : 8
sel(i, col) = abs(column(F2_h) / HS[i] - 1) < 1e-9 ? column(col) : NaN    # the rows of step size i (col: a column number)

# growth rates (per period) from summary values, keyed by the %.17g string of h: "?" if missing
KEY(i) = sprintf("%.17g", HV(i))
RATE(what, i) = summary_num(sprintf('%s.%s', what, KEY(i)))
fmt_rate(s) = s eq "?" ? "–" : sprintf("%+.2e", real(s))
fmt_pub(s)  = s eq "?" ? "none" : sprintf("%.2e", real(s))
array EBAR[NH]
do for [i = 1:NH] {
    s = RATE('reproduced.energy_growth_rate', i)
    if (s eq "?") { exit error sprintf("reproduced.energy_growth_rate.%s: missing from %s/summary.json", KEY(i), results) }
    eval sprintf("RATE_%d = %s", i, s)
    # centroid of the window maxima of |H − H0| (the least-squares line passes through it)
    stats F2 skip 1 using (sel(i, F2_period)):(sel(i, F2_H_err)) nooutput
    eval sprintf("PBAR_%d = STATS_mean_x; NWIN_%d = STATS_records", i, i)
    EBAR[i] = STATS_mean_y
}
stats F2 skip 1 using F2_period nooutput
PMIN = STATS_min; PMAX = STATS_max
# (a), (b): the periods in thousands when there are many
XS = PMAX >= 1e4 ? 1000 : 1
XLABEL = XS == 1 ? "periods t / T" : "periods t / T  [thousands]"
# lines with a marker on every PI-th window (about 10 per line), so that print in gray tells the h apart
PI = NWIN_1 >= 20 ? int(NWIN_1 / 10) : 1
do for [i = 1:NH] {
    eval sprintf("set style line %d lc rgb '%s' lw 1.1 dt 1 pt %d ps 0.6 pi %d", 60 + i, COL(i), PT(i), PI)       # data
    eval sprintf("set style line %d lc rgb '%s' lw 1.1 dt (6,3) pt %d ps 0.6 pi %d", 70 + i, COL(i), PT(i), PI)   # compensated
    eval sprintf("set style line %d lc rgb '#000000' lw 0.8 dt (2,2)", 80 + i)                                      # fit
}
PER_WINDOW = PMIN                    # (the first window ends after one window's periods)
RELFIT(i, p) = 100 * value(sprintf("RATE_%d", i)) * (p - value(sprintf("PBAR_%d", i))) / EBAR[i]

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_fig2', 17, 17)
    set multiplot title "{/:Bold " . made_by('long_run') . ":} " . sprintf("Lobatto scheme (13)–(14), harmonic oscillator (T = 2π/ω = %g), %g periods;\n" \
                                . "each point: the maximum over one window of %g periods (%d windows per step size h)", \
                                2 * pi / OMEGA, PERIODS, PER_WINDOW, NWIN_1)
    unset logscale                   # (from panel (c) of the previous format)
    set xrange [0:PMAX / XS]
    set format x "%g"
    set xtics autofreq
    set mxtics
    set xlabel XLABEL offset 0, 0.3

    # ---- (a) the window maxima of |H − H0| ----
    set lmargin at screen 0.10; set rmargin at screen 0.47
    set tmargin at screen 0.89; set bmargin at screen 0.575
    set logscale y
    set format y LOGFMT
    set ylabel "max_{window} |H(p_j, q_j) − H_0|" offset 0.5, 0
    set title "(a) energy error, window maxima" offset 0, -0.4
    set key top right
    set offsets 0, 0, graph 0.05, graph 0.05
    plot for [i = 1:NH] F2 skip 1 using (column(F2_period) / XS):(sel(i, F2_H_err)) with linespoints ls 60 + i title sprintf("h = %g", HV(i))

    # ---- (b) the same, relative to the mean, with the fitted growth ----
    set lmargin at screen 0.61; set rmargin at screen 0.98
    unset logscale y
    set format y "%g"
    set ylabel "window maximum / its mean − 1   [%]" offset 0.5, 0
    set title "(b) drift of (a): least-squares slopes (dotted)"
    set key top left Left reverse samplen 2 width -3 font ",8"
    set offsets 0, 0, graph 0.3, graph 0.05
    plot for [i = 1:NH] F2 skip 1 using (column(F2_period) / XS):(100 * (sel(i, F2_H_err) / EBAR[i] - 1)) \
                with linespoints ls 60 + i title sprintf("h = %g: %s / period (paper %s)", HV(i), \
                                                   fmt_rate(RATE('reproduced.energy_growth_rate', i)), \
                                                   fmt_pub(RATE('comparisons.energy_growth_rate.published', i))), \
         for [i = 1:NH] [p=PMIN:PMAX:(PMAX - PMIN)] '+' using (p / XS):(RELFIT(i, p)) with lines ls 80 + i notitle

    # ---- (c) the discrete energy H_d (15): round-off, plain and compensated ----
    set lmargin at screen 0.10; set rmargin at screen 0.98
    set tmargin at screen 0.44; set bmargin at screen 0.07
    set xrange [PMIN:PMAX]
    set logscale xy
    set xlabel "periods t / T"
    set format x LOGFMT
    set format y LOGFMT
    set ylabel "max_{window} |H_d(p_j, q_j) − H_d(p_0, q_0)|" offset 0.5, 0
    set title "(c) discrete energy H_d, eq. (15), conserved by the scheme in exact arithmetic: round-off; key: least-squares slopes per period"
    set key top left Left reverse samplen 3 width -2 font ",8" maxrows 3
    set offsets 0, 0, 0, 0
    plot for [i = 1:NH] F2 skip 1 using F2_period:(sel(i, F2_Hd_err_plain)) with linespoints ls 60 + i \
                title sprintf("h = %g, x ← Φx: %s", HV(i), fmt_rate(RATE('reproduced.energy_growth_rate_Hd', i))), \
         for [i = 1:NH] F2 skip 1 using F2_period:(sel(i, F2_Hd_err_compensated)) with linespoints ls 70 + i \
                title sprintf("h = %g, y ← y + (Φ − I)y compensated: %s", HV(i), fmt_rate(RATE('reproduced.energy_growth_rate_Hd_compensated', i)))
    unset multiplot
    unset output
}

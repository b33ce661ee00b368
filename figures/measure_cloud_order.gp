# Beyond the paper: the order of measure preservation (the paper checks one step size, Fig. 5.2).
# Harmonic potential U = (x² + y²)/2; a tiny 600-cell cloud (radius order_study.radius, around z_0) advanced by
# Φ^(ℓ)_h (E* = ℰ^(ℓ)(z) of each point) with the five discretizations (5.1), for ℓ = 0, 2, 4, 6 and nine step
# sizes h; the peak-to-peak over t ≤ ptp_window of V(t)/V(0) − 1, V the volume of the convex hull w.r.t.
# Φ^(ℓ)'s own measure μ^(ℓ)_mod (μ^(0) = μ). The claim (Corollary 4.3): O(h^(ℓ+2)).
# One panel per ℓ. Filled markers: the points of the least-squares fit (dashed, over its h range, slope = the
# fitted order, summary values fits.measure_ell<ℓ>.<m>); open markers: points left out of the fit because they
# lie within a factor 2 of the round-off noise. The noise is measured by the "probe" runs (crosses in the
# ℓ = 6 panel): Φ^(6) at h = order_study_h_probe, where the truncation error is negligible;
# reproduced.order_study_noise_floor (2 × the noise) is the gray line (shaded below it). Gray dotted: the slope ℓ + 2.
# Input: order_study.csv (method, ell, h, ptp), summary values (methods, fits, orders, reproduced.order_study_noise_floor,
# reproduced.order_study_h_probe), scene values (order_study.*, cloud.center, ptp_window).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('harmonic')
eval MC_NEED_METHODS
OS = csv('order_study.csv')

eval need_num('HPROBE', summary_real('reproduced.order_study_h_probe'))
eval need_num('R', scene_real('order_study.radius'))
eval need_num('PTPW', scene_real('ptp_window'))
eval need_num('TEND', scene_real('order_study.t_end'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
eval need_num('FLOOR', summary_real('reproduced.order_study_noise_floor'))   # twice the round-off noise
RTXT = abs(log10(R) - floor(log10(R) + 0.5)) < 1e-9 ? sprintf("10^{%d}", floor(log10(R) + 0.5)) : sci(R)
# the orders ℓ of the study (one panel each, at most 4)
ELLS = ""
do for [i = 0:9] { e = scene_num(sprintf('order_study.ells.%d', i)); if (e ne "?") { ELLS = ELLS . " " . e } }
NELL = words(ELLS)
if (NELL < 1 || NELL > 4) { exit error sprintf("order_study.ells: %d values, this figure draws 1 to 4", NELL) }
ELL(i) = int(real(word(ELLS, i)))

isprobe = 'abs(column("h") / HPROBE - 1) < 1e-9'
sel(m, e) = strcol("method") eq m && column("ell") == e
stats OS using (@isprobe ? NaN : column("h")) nooutput
HMIN = STATS_min; HMAX = STATS_max
stats OS using ((sel(word(MC_METHODS, 1), ELL(1)) && !(@isprobe)) ? column("h") : NaN) nooutput
NH = STATS_records
XLO = (HPROBE < HMIN ? HPROBE : HMIN) / 1.12; XHI = HMAX * 1.12

# fits: FO_<ℓ>_<m> order, FC_ log10 c, FLO_/FHI_ h range (NaN if summary values has no fit: fewer than 3 points above
# the noise)
fitnum(e, m, k) = (v = summary_real(sprintf('fits.measure_ell%d.%s.%s', e, m, k)), v eq "?" ? NaN : real(v))
do for [i = 1:NELL] { do for [m in MC_METHODS] {
    e = ELL(i)
    eval sprintf("FO_%d_%s = %.17g; FC_%d_%s = %.17g; FLO_%d_%s = %.17g; FHI_%d_%s = %.17g", \
                 e, m, fitnum(e, m, 'order'), e, m, fitnum(e, m, 'log10_c'), e, m, fitnum(e, m, 'h_min'), e, m, fitnum(e, m, 'h_max'))
}}
FV(k, e, m) = value(sprintf("%s_%d_%s", k, e, m))
infit(e, m) = column("h") >= FV("FLO", e, m) * (1 - 1e-9) && column("h") <= FV("FHI", e, m) * (1 + 1e-9)
ORDTXT(e, m) = FV("FO", e, m) == FV("FO", e, m) ? sprintf("%.2f", FV("FO", e, m)) : "no fit"

# per panel: the largest and smallest ptp (slope guide above the data; noise band only if within the range)
do for [i = 1:NELL] {
    e = ELL(i)
    stats OS using ((column("ell") == e && !(@isprobe)) ? column("ptp") : NaN) nooutput
    eval sprintf("PMAX_%d = %.17g; PMIN_%d = %.17g", e, STATS_max, e, STATS_min)
}
GUIDE(e, h) = 3 * value(sprintf("PMAX_%d", e)) * (h / HMAX)**(e + 2)

PL0 = 0.095; PW = 0.375; PGAP = 0.12
PT0 = 0.875; PH = 0.285; PVGAP = 0.115
setpanel(ix, iy) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set tmargin at screen %g; set bmargin at screen %g", \
                           PL0 + ix * (PW + PGAP), PL0 + ix * (PW + PGAP) + PW, PT0 - iy * (PH + PVGAP), PT0 - iy * (PH + PVGAP) - PH)
MEASURE(e) = e == 0 ? "μ" : sprintf("μ^{(%d)}_{mod}", e)

do for [fmt in FORMATS] {
    eval term(fmt, 'measure_cloud_order', 17, 15.5)
    set multiplot title sprintf("{/:Bold Order of measure preservation:} Φ^{(ℓ)}_h preserves μ^{(ℓ)}_{mod} to O(h^{ℓ+2})\n" \
        . "harmonic potential U = (x^2 + y^2)/2, 600-cell cloud of radius %s around z_0 = %s; peak-to-peak over t ≤ %g; " \
        . "%d step sizes h", RTXT, Z0, PTPW, NH)
    unset key
    set logscale xy
    set xrange [XLO:XHI]
    set format x "%g"
    set format y LOGFMT
    set xtics ()                       # the halvings of the largest step, down to the probe step
    do for [k = 0:8] { if (HMAX / 2**k >= XLO) { set xtics add (gprintf("%g", HMAX / 2**k) HMAX / 2**k) } }
    set mxtics 10; set mytics 10
    set offsets 0, 0, graph 0.04, graph 0.04

    do for [i = 1:NELL] {
        e = ELL(i)
        eval setpanel((i - 1) % 2, (i - 1) / 2)
        set title sprintf("(%s) ℓ = %d: Φ^{(%d)}_h w.r.t. %s, expected slope %d", word("a b c d", i), e, e, MEASURE(e), e + 2) offset 0, -0.4
        set xlabel ((i - 1) / 2 == (NELL - 1) / 2 ? "step size h" : "") offset 0, 0.4
        set ylabel "peak-to-peak of V/V(0) − 1" offset 1, 0
        # orders in the panel
        txt = "fitted orders:"
        do for [m in MC_METHODS] { txt = txt . sprintf("\n%s  %s", m, ORDTXT(e, m)) }
        set label 1 txt at graph 0.03, graph 0.93 left front font ",7.5"
        if (FLOOR > value(sprintf("PMIN_%d", e)) / 3) {
            set object 1 rect from graph 0, graph 0 to graph 1, first FLOOR behind fc rgb '#ececec' fs solid 1.0 noborder
            set arrow 1 from graph 0, first FLOOR to graph 1, first FLOOR nohead ls MC_LS_LIMIT
            set label 2 sprintf("2 × round-off noise = %s", sci(FLOOR)) at graph 0.97, first FLOOR * 1.6 right front font ",7.5" tc rgb MC_C_GUIDE
        }
        plot for [m in MC_METHODS] OS using (sel(m, e) && !(@isprobe) && infit(e, m) ? column("h") : NaN):"ptp" with points ls MC_LS(m) ps 0.7 notitle, \
             for [m in MC_METHODS] OS using (sel(m, e) && !(@isprobe) && !infit(e, m) ? column("h") : NaN):"ptp" with points ls MC_LS(m) + 10 notitle, \
             for [m in MC_METHODS] OS using (sel(m, e) && @isprobe ? column("h") : NaN):"ptp" with points pt 2 ps 1.0 lw 1.2 lc rgb MC_COLOR(m) notitle, \
             for [m in MC_METHODS] [t=0:1:1] '+' using (h = FV("FLO", e, m) * (FV("FHI", e, m) / FV("FLO", e, m))**t, h):(10**FV("FC", e, m) * h**FV("FO", e, m)) \
                 with lines ls MC_LS(m) + 20 notitle, \
             [t=0:1:1] '+' using (h = HMIN * (HMAX / HMIN)**t, h):(GUIDE(e, h)) with lines ls MC_LS_GUIDE notitle
        unset label 1; unset label 2; unset object 1; unset arrow 1
    }

    # ---- shared key ----
    unset logscale xy
    set lmargin at screen PL0; set rmargin at screen 0.98
    set tmargin at screen 0.06; set bmargin at screen 0.0
    unset title; unset xlabel; unset ylabel; unset border; unset tics; unset grid
    set xrange [0:1]; set yrange [0:1]
    set key at screen PL0 - 0.04, screen 0.1 left top vertical Left reverse maxrows 4 samplen 2.5 width -2 spacing 1.05 font ",7.5" nobox
    plot NaN notitle, \
         for [m in MC_METHODS] keyentry with linespoints ls MC_LS(m) + 20 title MC_DESC(m), \
         keyentry with points pt 6 ps 0.7 lc rgb MC_C_GUIDE title "open: below 2 × noise, not fitted", \
         keyentry with points pt 2 ps 1.0 lw 1.2 lc rgb MC_C_GUIDE title sprintf("noise probe: Φ^{(6)}, h = %g", HPROBE), \
         keyentry with lines ls MC_LS_GUIDE title "slope ℓ + 2 (guide)"
    set border; set tics; set grid
    set autoscale xy
    unset multiplot
    unset output
}

# Stability of the Lobatto scheme (13)–(14) of Dubois & Rojas-Quintero (2025), their Section 4, on the
# harmonic oscillator: spectral radius ρ of the one-step map Φ against h ω, drawn as ρ − 1 on a
# logarithmic axis; ρ − 1 ≤ 10^{−14} is drawn at 10^{−14}: there the eigenvalues have modulus 1 to
# round-off (the scan's ρ − 1 scatters up to a few 10^{−15} where the map is stable),
# with the methods of the scene key stability.methods for comparison (the paper scene: the Simpson
# scheme; a processed method by its kernel; summary value methods.stability: their labels). Shaded:
# the intervals where the Lobatto scan finds ρ ≤ 1 + stability.radius_tolerance (summary values
# reproduced.stable_set_h_omega, grid points of the scan). Vertical lines: the computed first loss
# of stability (summary value reproduced.stability_bound, to compare with the paper's bound (10),
# √(42 − 6√29), comparisons.stability_bound.published); and the other ends of the exact stable set
# (summary values stability.exact_set_h_omega): h ω = √10 and √30, where δ of eq. (7) vanishes, and
# the other two roots of the discriminant Δ of that section, √60 and √(42 + 6√29) (its key names the section,
# not an item of the paper: "Sec." . NBSP . "4", common.gp).
# Input: stability.csv; summary values (methods, stable sets, bound, tolerance); scene values (scan range).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
LOB = summary_words('methods.stability_scheme')   # the method of column spectral_radius, as the run names it
set encoding utf8    # (so that the key width counts characters, not bytes)
ST = csv('stability.csv')

eval need_num('BOUND', summary_num('reproduced.stability_bound'))
eval need_num('BOUND_PAPER', summary_num('comparisons.stability_bound.published'))
eval need_num('TOL', summary_num('stability.radius_tolerance'))
TOLTXT = gprintf("%.0t", TOL) eq "1" ? gprintf("10^{%T}", TOL) : sci(TOL)
FLOOR = 1e-14
clip(r) = r - 1 > FLOOR ? r - 1 : FLOOR
stats ST using "h_omega" nooutput
XMIN = STATS_min; XMAX = STATS_max
NPTS = STATS_records
# the methods scanned with Lobatto (scene key stability.methods), by label: the columns spectral_radius_<label>
METHODS = summary_words('methods.stability')
eval method_styles(METHODS)   # (figures/common.gp: colours and markers from the registry)
# the compared curves and their key entries as plot clauses (none without compared methods)
COMPARED = words(METHODS) == 0 ? "" : 'for [m in METHODS] ST using "h_omega":(clip(column("spectral_radius_".m))) with lines ls method_ls(m), '
COMPARED_KEY = words(METHODS) == 0 ? "" : 'for [m in METHODS] keyentry with lines ls method_ls(m) title method_key(m, "001"), '
stats ST using (clip(column("spectral_radius"))) nooutput
YMAX = STATS_max
do for [m in METHODS] {
    stats ST using (clip(column("spectral_radius_".m))) nooutput
    YMAX = STATS_max > YMAX ? STATS_max : YMAX
}

# the stable intervals of the scan, from summary values: SL_k, SR_k for k = 1 .. NS
NS = 0
do for [k = 0:19] {
    a = summary_num(sprintf('reproduced.stable_set_h_omega.%d.0', k))
    b = summary_num(sprintf('reproduced.stable_set_h_omega.%d.1', k))
    if (a ne "?" && b ne "?") { NS = k + 1; eval sprintf("SL_%d = %s; SR_%d = %s", NS, a, NS, b) }
}
if (NS == 0) { exit error "reproduced.stable_set_h_omega: missing from ".results."/summary.json" }
SET = ""
do for [k = 1:NS] { SET = SET . sprintf("%s[%.2f, %.2f]", k > 1 ? ", " : "", value(sprintf("SL_%d", k)), value(sprintf("SR_%d", k))) }

# the lines: position, label, style (1: bound, 2: δ = 0, 3: other roots of Δ); the ends of the second and
# third intervals of the exact stable set are √10, √30 and √60, √(42+6√29)
EX(k, e) = (_s = summary_num(sprintf('stability.exact_set_h_omega.%d.%d', k, e)), _s eq "?" ? NaN : real(_s))
if (EX(2, 1) != EX(2, 1)) { exit error "stability.exact_set_h_omega: missing from ".results."/figure_values.gp" }
NL = 5
LX(i) = i == 1 ? BOUND : i == 2 ? EX(1, 0) : i == 3 ? EX(1, 1) : i == 4 ? EX(2, 0) : EX(2, 1)
LN(i) = i == 1 ? "√(42−6√29)" : i == 2 ? "√10" : i == 3 ? "√30" : i == 4 ? "√60" : "√(42+6√29)"
LK(i) = i == 1 ? 1 : i <= 3 ? 2 : 3
# labels horizontal at the top, beside their line: left of it for the first bound and √60, right of it
# for the others (the bound and √10 are 0.05 apart: their labels point away from each other)
LLEFT(i) = i == 1 || i == 4
set style line 91 lc rgb '#000000' lw 1.0 dt 1
set style line 92 lc rgb '#000000' lw 1.0 dt (6,3)
set style line 93 lc rgb '#777777' lw 0.9 dt (2,3)

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_stability', 17, 11)
    # the plot and, below it, its key (a second plot of key entries only: the same in pdf and png)
    set multiplot title sprintf("{/:Bold Stability:} spectral radius ρ of the one-step map, harmonic oscillator, %d values of hω in [%g, %g]\n" \
                                . "%s stable (shaded) on %s;  first bound: computed %.8g, eq. (10) %.8g", \
                                NPTS, XMIN, XMAX, method_title(LOB), SET, BOUND, BOUND_PAPER)
    set lmargin at screen 0.09; set rmargin at screen 0.98
    set tmargin at screen 0.885; set bmargin at screen 0.23
    set border 31; set mxtics 2; set mytics
    set xrange [0:XMAX]
    set xtics 1
    set format x "%g"
    set logscale y
    set yrange [FLOOR / 3 : YMAX * 100]
    set ytics autofreq
    set format y LOGFMT
    set ytics add ("≤10^{-14}" FLOOR)
    set xlabel "h ω" offset 0, 0.3
    set ylabel "ρ − 1   (ρ: spectral radius of Φ)"
    unset key
    unset object; unset arrow; unset label
    do for [k = 1:NS] {
        set object k rectangle from value(sprintf("SL_%d", k)), graph 0 to value(sprintf("SR_%d", k)), graph 1 \
            behind fillcolor rgb C_STABLE fillstyle solid 1.0 noborder
    }
    do for [i = 1:NL] {
        set arrow i from LX(i), graph 0 to LX(i), graph 1 nohead ls 90 + LK(i) front
        set label i LN(i) at LX(i), graph 0.955 front font ",8" tc rgb (LK(i) == 3 ? '#555555' : '#000000') \
            offset (LLEFT(i) ? -0.4 : 0.4), 0
        if (LLEFT(i)) { set label i right } else { set label i left }
    }
    plot @COMPARED ST using "h_omega":(clip(column("spectral_radius"))) with lines lc rgb method_colour(LOB) lw 1.4

    unset object; unset arrow; unset label
    set lmargin at screen 0.02; set rmargin at screen 0.98
    set tmargin at screen 0.14; set bmargin at screen 0.01
    unset logscale; unset xlabel; unset ylabel
    set border 0; set xtics ("" 5); set ytics ("" 5); unset mxtics; unset mytics; set xrange [0:1]; set yrange [0:1]
    set key center center horizontal Left reverse maxrows 3 samplen 3 width -2
    plot 2 with lines notitle, \
         keyentry with lines lc rgb method_colour(LOB) lw 1.4 title method_key(LOB, "001"), \
         @COMPARED_KEY \
         keyentry with boxes fillcolor rgb C_STABLE fillstyle solid 1.0 noborder title sprintf("%s stable (ρ ≤ 1 + %s)", method_title(LOB), TOLTXT), \
         for [k = 1:3] keyentry with lines ls 90 + k title (k == 1 ? "computed first bound ≈ √(42−6√29), eq. (10)" \
                                                             : k == 2 ? "h ω = √10, √30: δ = 0, eq. (7)" \
                                                             : "h ω = √60, √(42+6√29): other roots of Δ, Sec." . NBSP . "4")   # (2: off the yrange)
    unset multiplot
    unset output
}

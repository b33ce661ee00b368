# figures/common.gp: settings shared by every figure script.
#
# A figure script is run from the repository root as
#     gnuplot -e "results='DIR'; out='OUTDIR'" figures/NAME.gp
# and writes OUTDIR/NAME.pdf and OUTDIR/NAME.png. It loads this file, then
#     do for [fmt in FORMATS] { eval term(fmt, 'NAME', width_cm, height_cm); plot ...; unset output }

if (!exists("results")) results = 'results/euler_compensation'
if (!exists("out"))     out = 'figures/out'
system sprintf("mkdir -p '%s'", out)

# ---- terminals: one figure in vector (pdf) and raster (png) form ----------
FORMATS = "pdf png"
FONT    = "Sans,10"
DPI     = 200                            # png resolution; fonts and lines scale with it
term(fmt, name, w, h) = (fmt eq "pdf" \
    ? sprintf("set terminal pdfcairo enhanced color font '%s' size %gcm,%gcm linewidth 1.5", FONT, w, h) \
    : sprintf("set terminal pngcairo enhanced font '%s' size %d,%d fontscale %g linewidth %g pointscale %g", \
              FONT, w*DPI/2.54, h*DPI/2.54, DPI/150.0, 1.5*DPI/144.0, DPI/72.0)) \
    . sprintf("; set output '%s/%s.%s'", out, name, fmt)

# ---- data: CSV with a header row; columns are addressed by name ----------
# (Referring to a column by name makes gnuplot read the first row as headers.
# `set datafile columnheaders` is not used: it would also drop the first
# sample of the '+' pseudo-file.) Values written as "nan" or "-nan" are not
# numbers to gnuplot: those points are skipped without a warning.
set datafile separator comma
csv(file) = results . '/' . file
# Columns by number, for a large CSV that a script reads more than once: a column named in `using` ("x") is, like
# any expression there, evaluated by gnuplot on every row; a plain column number is not (less than half the time on
# a large file). eval columns('SH', SH) sets SH_<name> to the number of each column of the header of the file SH
# (its first line, read once; the names must be gnuplot names), for
#     plot SH skip 1 using SH_x:SH_px
# (skip 1: the header is no row, as when a column is named, so that `every` and column(0) count from the first data row;
# within an expression, column(SH_t) for column("t")).
_columns(p, h, i) = (_c = strstrt(h, ","), _c > 0 ? sprintf("%s_%s = %d; ", p, h[1:_c - 1], i) . _columns(p, h[_c + 1:], i + 1) \
                                                 : sprintf("%s_%s = %d", p, h, i))
columns(p, file) = _columns(p, system(sprintf("head -n 1 '%s'", file)), 1)

# ---- methods: colour, marker, key title and equations from the registry -------------------------
# figures/methods.gpi is generated from the method registry (geomint-methods --gnuplot): a method's
# colour method_colour(m) and marker method_point(m) are the same in every figure (Okabe-Ito and, for
# the five discretizations of 003, Paul Tol's "bright": colour-blind safe; a base method is vermillion
# and its processed or compensated form blue throughout), its key text method_key(m, paper) names it
# with the equations of that paper. No two methods of the registry share colour and marker (ctest
# MethodRegistry.ColourAndMarkerNameOneMethod, palette.distinct_per_scene), so the methods of any
# figure are told apart, whichever a scene names.
load 'figures/methods.gpi'
# eval method_styles(METHODS) defines, for the i-th method m of the words METHODS (registry names or
# labels), line style method_ls(m) = 200 + i, its points (method_colour(m), method_point(m)), and
# method_fit_ls(m) = 300 + i, its least-squares fit (dashed, its marker for the key). Colour and marker
# name one method of the registry, so the methods of any figure are told apart without a map per script.
_ps(pt) = pt == 5 || pt == 7 ? 0.55 : pt == 1 || pt == 2 || pt == 3 || pt == 12 || pt == 13 ? 0.8 : 0.7
# eval method_look(m, pt, ls, fit_ls) defines line style ls, points in method m's colour with marker pt, and fit_ls,
# its fit (dashed, the marker for the key): method_styles with the registry's marker, or another for a method's
# further curves in one panel (figures/convergence.gpi)
method_look(m, pt, ls, fit_ls) = sprintf("set style line %d lc rgb '%s' lw 1.0 pt %d ps %g; ", ls, method_colour(m), pt, _ps(pt)) \
                               . sprintf("set style line %d lc rgb '%s' lw 0.9 dt (8,4) pt %d ps %g; ", fit_ls, method_colour(m), pt, _ps(pt))
_method_style(m, i) = method_look(m, method_point(m), 200 + i, 300 + i)
_method_styles(list, i) = i > words(list) ? "" : _method_style(word(list, i), i) . _method_styles(list, i + 1)
method_styles(list) = _method_styles(list, 1)
# unique_words("a b a c") = "a b c" (a figure's METHODS from several lists name each method once)
_unique(list, i, acc) = i > words(list) ? acc \
                      : _unique(list, i + 1, strstrt(" ".acc." ", " ".word(list, i)." ") > 0 ? acc : acc.(acc eq "" ? "" : " ").word(list, i))
unique_words(list) = _unique(list, 1, "")
method_ls(m) = 200 + word_index(METHODS, m)
LS_OTHER = 29; set style line LS_OTHER lc rgb C_OTHER lw 1.0 pt P_OTHER ps 0.75   # (a curve of no registry method)
method_fit_ls(m) = 300 + word_index(METHODS, m)

# A method's further curves in one panel (the same method in other coordinates, or another of its quantities): its
# colour, and further_point(m, k), the k-th of FURTHER_MARKERS that is not its own marker (figures/convergence.gpi
# takes its further markers from the same list)
FURTHER_MARKERS = "4 5 8 9 6 7 12 13 10 11 14 15 1 2 3"
_further(m, k, i) = i > words(FURTHER_MARKERS) ? P_OTHER : int(word(FURTHER_MARKERS, i)) == method_point(m) \
                  ? _further(m, k, i + 1) : k == 1 ? int(word(FURTHER_MARKERS, i)) : _further(m, k - 1, i + 1)
further_point(m, k) = _further(m, k, 1)

C_EXACT = '#000000'                                  # exact solution
LS_EXACT = 1;  set style line LS_EXACT lc rgb C_EXACT lw 1.0 dt 1
# Curves that are no method's result, a quantity as computed and the same corrected (plain and compensated (Kahan)
# summation; H at a method's variables and at the processed ones): role colours, grays, none a method's
C_UNCORRECTED = '#333333'   # as computed: plain summation, H at the method's own variables
C_CORRECTED   = '#999999'   # corrected: compensated (Kahan) summation, H at the processed variables
LS_UNCORRECTED = 2;  set style line LS_UNCORRECTED lc rgb C_UNCORRECTED lw 1.0
LS_CORRECTED   = 3;  set style line LS_CORRECTED   lc rgb C_CORRECTED   lw 1.0

# ---- look ---------------------------------------------------------------
set border lw 0.8
set grid back lc rgb '#d9d9d9' lw 0.5 dt 1
set tics out nomirror scale 0.7
set key opaque box lc rgb '#bbbbbb' lw 0.5 samplen 2.5 spacing 1.15 width 1
set mxtics; set mytics
LOGFMT = "10^{%L}"                       # tic labels on logarithmic axes

# ---- fitted orders from orders.csv -------------------------------------
# eval getfit('se_energy') defines se_energy_order, se_energy_c (log10 of the
# constant), se_energy_hmin and se_energy_hmax: the fitted line is
# err = 10^c h^order over [hmin, hmax]. A name missing from orders.csv is an error.
# eval getfit_at('sv_energy', 0): the same from the rows of initial condition 0 alone (orders.csv's
# column initial), for a study of several initial conditions (getfit takes the name's rows of any)
# eval getfit_in('table1_orders.csv', 'lobatto_p', -1): getfit_at from another orders CSV (a study's
# ConvergenceRuns::orders_csv where two studies of an experiment fit orders)
_row_at(n, ic, col) = (strcol("name") eq n && (ic < 0 || column("initial") == ic)) ? column(col) : NaN
_get_in(f, n, ic, col, var) = sprintf("undefine STATS_*; stats csv('%s') using (_row_at('%s',%d,'%s')) nooutput; %s = STATS_max; ", f, n, ic, col, var)
getfit_in(f, n, ic) = _get_in(f, n, ic, 'order', n.'_order') . _get_in(f, n, ic, 'log10_c', n.'_c') \
                    . _get_in(f, n, ic, 'h_min', n.'_hmin')  . _get_in(f, n, ic, 'h_max', n.'_hmax')
getfit_at(n, ic) = getfit_in('orders.csv', n, ic)
getfit(n) = getfit_at(n, -1)
powerlaw(h, c, order) = 10**c * h**order
# after eval getfit(n): the fitted line from h_min (t = 0) to h_max (t = 1), straight in log-log, for
# `[t=0:1:1] '+' using (fit_h(n, t)):(fit_err(n, t)) with lines`
fit_h(n, t)   = value(n.'_hmin') * (value(n.'_hmax') / value(n.'_hmin'))**t
fit_err(n, t) = powerlaw(fit_h(n, t), value(n.'_c'), value(n.'_order'))

# ---- the numbers of the run: DIR/figure_values.gp, written by the experiment (the "scene values"
# and "summary values" of the scripts' Input lines): no script reads JSON ----
# scene_num('pendulum.g') is the value of scene key pendulum.g (dotted; array elements by index
# from 0, e.g. 'initial.0.1') formatted %g, or "?" if the run has no such number.
load results . '/figure_values.gp'
_fv(key) = sum [_k = 1:|FV_KEY|] (FV_KEY[_k] eq key ? _k : 0)   # the index of key, 0 if it is not there
scene_num(key) = (_i = _fv('scene.' . key), _i > 0 ? sprintf("%g", FV_VAL[_i]) : "?")
# scene_words('methods') is a list of texts of the scene (e.g. method names) as one space-separated
# text, for `do for [m in scene_words('methods')]`; summary_words likewise; "" if there is none.
scene_words(key) = (_i = _fv('scene.' . key), _i > 0 ? FV_VAL[_i] : "")
summary_words(key) = (_i = _fv('summary.' . key), _i > 0 ? FV_VAL[_i] : "")
# made_by('convergence') is what the study made under the run's scene, the ids of its items as the study declares
# them ("<paper> <item>", as paper/papers.toml spells it): a figure's title names its item with it, and no script
# types an id or a paper's figure number (ctest report.no_typed_items); "?" if the study did not run.
made_by(study) = (_i = _fv('made.' . study), _i > 0 ? FV_VAL[_i] : "?")
# made_item('fig52') is the id of the item this run made whose name, lower case without spaces and punctuation, is
# fig52: the item that a script named <run>_fig52*.gp draws
made_item(slug) = (_i = _fv('item.' . slug), _i > 0 ? FV_VAL[_i] : "?")
# item_name(made_by('ensemble')) is an item's name without its paper (the id "<paper> <name>"), for a text that
# names another figure of the run as the paper does ("trajectory no. 3 of" and that name)
item_name(id) = id[strstrt(id, " ") + 1:]
# NBSP, a non-breaking space (U+00A0): a section of a paper that is no item, drawn as prose ("Sec." . NBSP . "4",
# as the report's LaTeX writes Sec.~4), looks like a space
NBSP = "\302\240"

# ---- x tics for logarithmic axes spanning few decades ------------------------
# eval LOGTICS("1 2 5") puts the x tics at 1, 2, 5 × 10^k (labelled with the x format, e.g. "%g")
LOGTICS(ds) = sprintf("set xtics (); do for [k=-8:8] { do for [d in '%s'] { set xtics add (real(d) * 10.0**k) } }", ds)

# ---- numbers from summary values (timings aside), through figure_values.gp ----------------
# summary_num('orders.polar_px_change_per_step') is the value of that key (dotted, as for
# scene_num) formatted %.17g, or "?" if the run has no such number.
summary_num(key) = (_i = _fv('summary.' . key), _i > 0 ? sprintf("%.17g", FV_VAL[_i]) : "?")
# eval need_num('NAME', scene_num('pendulum.g')) sets NAME to the number, or stops the script
# with an error naming the value that is missing (no silent default).
need_num(var, s) = (s eq "?") \
    ? sprintf("exit error \"%s: missing from %s/figure_values.gp\"", var, results) \
    : sprintf("%s = %s", var, s)

# ---- 001 Dubois & Rojas-Quintero, Lobatto variational integrator (figures/lobatto_table_*.gp) ----
# The paper's method is blue, as the registry colours it (its quantities in one order panel: told apart by marker,
# figures/convergence.gpi).
# lobatto_table_fig2.gp compares step sizes of the Lobatto scheme alone: a ramp of its blue, light = large h
C_LOB_H1 = '#56B4E9';  C_LOB_H2 = '#0072B2';  C_LOB_H3 = '#002338'
C_STABLE = '#CFE8F6'   # shading: h ω where the Lobatto map is stable (spectral radius 1)
# scene_full('oscillator.omega'): as scene_num, at full precision (%.17g, as summary_num): scene_num's
# %g keeps 6 digits, too few for a value that is computed with, e.g. T = 2π/ω
scene_full(key) = (_i = _fv('scene.' . key), _i > 0 ? sprintf("%.17g", FV_VAL[_i]) : "?")

# ---- 004 simplified Takahashi–Imada method, energy drift (figures/ti_drift_*.gp) ----
# scene_real('t_end') and summary_real('orders.sv_energy'): as scene_num and summary_num, written
# %.17e (a form real() and eval read whatever the value); use them with need_num.
scene_real(key)   = (_i = _fv('scene.' . key), _i > 0 ? sprintf("%.17e", FV_VAL[_i]) : "?")
summary_real(key) = (_i = _fv('summary.' . key), _i > 0 ? sprintf("%.17e", FV_VAL[_i]) : "?")
# sci(x): x as "−6.52·10^{−6}" (3 significant digits; enhanced text)
sci(x) = x == 0 ? "0" : gprintf("%.2t·10^{%T}", x)
# Statistics black. A figure of 004 names the method of its trajectories as the run does, summary methods.<study>
# (its colour method_colour), and its alpha, TI_ALPHA: "α = 1/12"
TI_ALPHA = (_a = summary_num('ti_alpha'), _a eq "?" ? "α = ?" : sprintf("α = 1/%g", 1 / real(_a)))
C_STAT = '#000000'
# time as the colour of points (ti_drift_fig5.gp): eval PALETTE_TIME (viridis, cut before its light yellow end)
PALETTE_TIME = "set palette defined (0 '#440154', 0.25 '#3B528B', 0.5 '#21908C', 0.75 '#5DC863', 1 '#B5DE2B')"

# ---- methods named by the scene (registry labels in the CSV columns) -------
in_list(list, w) = strstrt(" ".list." ", " ".w." ") > 0
word_index(list, w) = sum [i = 1:words(list)] (word(list, i) eq w ? i : 0)   # 0 if w is not in list
nosub(s) = (_u = strstrt(s, "_")) ? s[1:_u-1]." ".nosub(s[_u+1:]) : s         # a label as key text (no subscripts)
# eval ORDER_METHODS sets METHODS to the words of CSV_METHODS, those in PREFERRED first and in its order
ORDER_METHODS = 'METHODS = ""; ' \
              . 'do for [m in PREFERRED] { if (in_list(CSV_METHODS, m)) { METHODS = METHODS.m." " } }; ' \
              . 'do for [m in CSV_METHODS] { if (!in_list(PREFERRED, m)) { METHODS = METHODS.m." " } }'

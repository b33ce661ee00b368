# Convergence of the Lobatto scheme of Dubois & Rojas-Quintero (2025).
# Left, Table 1: harmonic oscillator over one period, N steps, h = T/N; maxima over the steps of
# the absolute errors of p, q and H (Lobatto), of the discrete energy H_d (15) (round-off), and
# of q for the methods of the scene key table1.methods (the paper scene: the Simpson scheme and the
# implicit midpoint rule). Large black rings around the markers: the values printed in
# the paper's Table 1 (summary values comparisons.*_err.published.<N>), drawn behind the
# reproduced markers so that both show where they agree.
# Right, beyond the paper: nonlinear Lagrangians (Newton on the internal nodes), phase-space
# error |z_N − z(t_end)|_2 against an odeint reference: the pendulum L = q̇²/2 + cos q (Lobatto and
# the methods of nonlinear.methods; the paper scene: Simpson, midpoint) and a 2-DOF elastic pendulum (Lobatto).
# Dashed: lines with the fitted order of summary values (orders.*) as slope, drawn through the
# centroid (in log–log) of the points shown; the fit itself leaves out points within the
# round-off / reference-accuracy floor (see experiments/lobatto_table).
# Input: table1.csv, nonlinear.csv, summary values (the compared methods methods.table1 and
# methods.nonlinear, orders, published Table 1, Newton iterations), scene values (scene).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
T1 = csv('table1.csv')
NL = csv('nonlinear.csv')

eval need_num('OMEGA', scene_full('oscillator.omega'))
eval need_num('TEND', scene_full('nonlinear.t_end'))
eval need_num('Q0', scene_full('nonlinear.pendulum_q0'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('nonlinear.elastic_initial.0.0'), scene_num('nonlinear.elastic_initial.0.1'), \
             scene_num('nonlinear.elastic_initial.0.2'), scene_num('nonlinear.elastic_initial.0.3'))

# the compared methods, by label: Table 1's (scene key table1.methods, columns <label>_q_err) and the
# nonlinear study's (nonlinear.methods, columns <label>_pendulum_err)
T1M = summary_words('methods.table1')
NLM = summary_words('methods.nonlinear')
METHODS = unique_words(T1M . " " . NLM)
eval method_styles(METHODS)   # (figures/common.gp: colours and markers from the registry)

# series: name, file, column, summary order key (or "" for none), style, label
LOB1(s)  = s eq "p" || s eq "q" || s eq "H" || s eq "Hd"           # (the Lobatto series of Table 1)
S1 = "p q H Hd " . T1M
S1F = "p q H " . T1M                    # (the series with an order: all but H_d)
COL1(s)  = LOB1(s) ? s."_err" : s."_q_err"
ORD1(s)  = s eq "p" ? "lobatto_p" : s eq "q" ? "lobatto_q" : s eq "H" ? "lobatto_H" : s eq "Hd" ? "" : s
STY1(s)  = s eq "p" ? LS_LOB : s eq "q" ? LS_LOB2 : s eq "H" ? LS_LOB3 : s eq "Hd" ? LS_LOB4 : method_ls(s)
FIT1(s)  = LOB1(s) ? STY1(s) + 10 : method_fit_ls(s)   # (a fitted guide: Lobatto's LS_LOB*_FIT, a method's dashed)
LAB1(s)  = s eq "p" ? "Lobatto, momentum p" : s eq "q" ? "Lobatto, state q" : s eq "H" ? "Lobatto, energy H" \
         : s eq "Hd" ? "Lobatto, discrete energy H_d (15)" : s eq "simpson" ? "Simpson [2], state q" : method_title(s).", state q"
S2 = "pendulum_err elastic_err"
do for [m in NLM] { S2 = S2 . " " . m . "_pendulum_err" }
MOF(s)   = s[1:strlen(s) - strlen("_pendulum_err")]           # (the method of a compared series)
ORD2(s)  = s eq "pendulum_err" ? "lobatto_nonlinear_pendulum" : s eq "elastic_err" ? "lobatto_elastic_pendulum" \
         : MOF(s)."_nonlinear_pendulum"
STY2(s)  = s eq "pendulum_err" ? LS_LOB : s eq "elastic_err" ? LS_LOB2 : method_ls(MOF(s))
FIT2(s)  = s eq "pendulum_err" || s eq "elastic_err" ? STY2(s) + 10 : method_fit_ls(MOF(s))
LAB2(s)  = s eq "pendulum_err" ? "Lobatto, pendulum" : s eq "elastic_err" ? "Lobatto, elastic pendulum (2 DOF)" \
         : MOF(s) eq "simpson" ? "Simpson, pendulum" : method_title(MOF(s)).", pendulum"
ORDER(key) = (o = summary_num('orders.'.key), o eq "?" ? NaN : real(o))
ORDTXT(key) = key eq "" ? "round-off, no order" : (o = summary_num('orders.'.key), o eq "?" ? "order: not in summary.json" : sprintf("order %.2f", real(o)))

# centroid in log–log of each series (the guide line passes through it) and the h range
# CX_<series>, CY_<series>; for table 1 the series names are prefixed "t1_", for nonlinear "nl_"
do for [s in S1] {
    stats T1 using (log10(column("h"))):(log10(column(COL1(s)))) nooutput
    eval sprintf("CX_t1_%s = STATS_mean_x; CY_t1_%s = STATS_mean_y", s, s)
}
stats T1 using "h" nooutput
H1MIN = STATS_min; H1MAX = STATS_max
do for [s in S2] {
    stats NL using (log10(column("h"))):(log10(column(s))) nooutput
    eval sprintf("CX_nl_%s = STATS_mean_x; CY_nl_%s = STATS_mean_y", s, s)
}
stats NL using "h" nooutput
H2MIN = STATS_min; H2MAX = STATS_max
# Newton iterations per step (mean over a run), their range over h: summary values nonlinear.newton_iterations
ITS(sys) = sprintf("%.2g–%.2g", real(summary_num('nonlinear.newton_iterations.'.sys.'.min')), \
                                real(summary_num('nonlinear.newton_iterations.'.sys.'.max')))
ITP = ITS('pendulum')
ITE = ITS('elastic')
GUIDE(tag, s, key, h) = 10**(value(sprintf("CY_%s_%s", tag, s)) + ORDER(key) * (log10(h) - value(sprintf("CX_%s_%s", tag, s))))

# the published Table 1 (summary values comparisons.<q>_err.published.<N>, N from the scene key meshes)
set print $PUB
do for [k = 0:9] {
    n = scene_num(sprintf('meshes.%d', k))
    if (n ne "?") {
        do for [q in "p q H Hd"] {
            v = summary_num(sprintf('comparisons.%s_err.published.%d', q, int(real(n))))
            if (v ne "?") { print sprintf("%.17g,%s", 2 * pi / OMEGA / real(n), v) }
        }
    }
}
unset print
NPUB = |$PUB|

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_convergence', 17, 11.5)
    set multiplot title "{/:Bold Convergence:} maximum-norm errors against the step size h; " \
                      . "dashed: slope = the fitted order, through the points' centroid"
    set tmargin at screen 0.87; set bmargin at screen 0.33
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set xlabel "step size h"
    set offsets 0, 0, graph 0.04, graph 0.04
    set key Left reverse samplen 3 width -8 font ",8.5" spacing 1.1

    # ---- left: Table 1 ----
    set lmargin at screen 0.10; set rmargin at screen 0.48
    set xrange [H1MIN / 1.15 : H1MAX * 1.15]
    set key at screen 0.08, screen 0.235 left top
    set title made_by('table1') . sprintf(": harmonic oscillator, q(0) = A, p(0) = 0\none period T = %g, N steps, h = T/N", 2 * pi / OMEGA) offset 0, -0.4
    set ylabel "max_{j = 1..N} |error at t_j|"
    plot $PUB using 1:2 with points pt 6 ps 1.6 lc rgb C_EXACT lw 0.8 notitle, \
         for [s in S1] T1 using "h":(column(COL1(s))):xtic(sprintf("%g", column("h"))) with points ls STY1(s) notitle, \
         for [s in S1] [t=0:1:1] '+' using (h = H1MIN * (H1MAX / H1MIN)**t, h):(ORD1(s) eq "" ? NaN : GUIDE("t1", s, ORD1(s), h)) \
                with lines ls FIT1(s) notitle, \
         for [s in S1F] keyentry with linespoints ls FIT1(s) title sprintf("%s, %s", LAB1(s), ORDTXT(ORD1(s))), \
         keyentry with points ls STY1("Hd") title LAB1("Hd") . ": round-off", \
         keyentry with points pt 6 ps 1.6 lc rgb C_EXACT lw 0.8 title "paper, Table 1 (p, q, H, H_d): rings"

    # ---- right: nonlinear ----
    set lmargin at screen 0.60; set rmargin at screen 0.98
    set xrange [H2MIN / 1.15 : H2MAX * 1.15]
    set key at screen 0.58, screen 0.235 left top
    set title sprintf("nonlinear Lagrangians, error at t_{end} = %g\npendulum: q(0) = %g, p(0) = 0; elastic: z(0) = %s", TEND, Q0, Z0)
    set label 1 sprintf("Lobatto, Newton iterations per step\n(mean over the run): pendulum %s,\nelastic pendulum %s", ITP, ITE) \
        at graph 0.97, graph 0.12 right front font ",8"
    set ylabel "|z_N − z(t_{end})|_2  (odeint reference)"
    plot for [s in S2] NL using "h":(column(s)):xtic(sprintf("%g", column("h"))) with points ls STY2(s) notitle, \
         for [s in S2] [t=0:1:1] '+' using (h = H2MIN * (H2MAX / H2MIN)**t, h):(GUIDE("nl", s, ORD2(s), h)) \
                with lines ls FIT2(s) notitle, \
         for [s in S2] keyentry with linespoints ls FIT2(s) \
                title sprintf("%s, %s", LAB2(s), ORDTXT(ORD2(s)))
    unset label 1
    unset multiplot
    unset output
}

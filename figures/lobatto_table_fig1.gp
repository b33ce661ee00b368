# The figure1 study's figure (its item in the title: made_by('figure1')), after Dubois & Rojas-Quintero (2025):
# the harmonic oscillator over one period with
# the Lobatto scheme (13)–(14), N = 3 (top row) and N = 10 (bottom row) steps per period, against
# the exact solution q = A cos ωt, p = −m ω A sin ωt; with the Simpson scheme and the implicit
# midpoint rule for comparison (as the paper's text says). q (left) and p (right) are drawn in
# separate panels, p unscaled (the paper's figure rescales p to share one axis with q).
# The schemes are drawn as markers alone: a scheme gives values at t_j = j h only.
# The methods are those of the scene key figure1.methods (summary value methods.figure1: their
# labels, the columns q_<label>, p_<label>).
# Input: fig1_N<N>.csv (N from the scene key figure1.meshes), fig1_exact.csv, scene values
# (oscillator parameters, the two N), summary values (the methods, their largest errors figure1.max_error).
if (!exists("results")) results = 'results/lobatto_table'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)

eval need_num('M', scene_full('oscillator.m'))
eval need_num('OMEGA', scene_full('oscillator.omega'))
eval need_num('A', scene_full('oscillator.amplitude'))
eval need_num('N1', scene_num('figure1.meshes.0'))
eval need_num('N2', scene_num('figure1.meshes.1'))
T = 2 * pi / OMEGA
EXACT = csv('fig1_exact.csv')
FIG(n) = csv(sprintf('fig1_N%d.csv', n))

# the methods of the scene key figure1.methods, by label: the columns q_<label> of the CSV
METHODS = summary_words('methods.figure1')
if (words(METHODS) == 0) { exit error sprintf("%s/figure_values.gp: no methods.figure1", results) }
eval method_styles(METHODS)   # (figures/common.gp: colours and markers from the registry)

# "max_j error: Lobatto 1.2e-03, Simpson ..." per mesh (k = 0, 1) and variable, ERRS_<k>_<var>: the
# largest errors over the steps, summary values figure1.max_error.<k>.<label>.<var>
do for [k = 0:1] {
    do for [v in "q p"] {
        e = ""
        do for [m in METHODS] {
            eval need_num('ERR', summary_num(sprintf('figure1.max_error.%d.%s.%s', k, m, v)))
            e = e . sprintf("%s %s %.1e", e eq "" ? "" : ",", method_title(m), ERR)
        }
        eval sprintf("ERRS_%d_%s = 'max_j error:%s'", k, v, e)
    }
}
ERRS(k, v) = value(sprintf("ERRS_%d_%s", k, v))

do for [fmt in FORMATS] {
    eval term(fmt, 'lobatto_table_fig1', 17, 14)
    set multiplot title "{/:Bold " . made_by('figure1') . ":} " . sprintf("harmonic oscillator over one period T = 2π/ω = %g: m = %g, ω = %.6g, q(0) = A = %.6g, p(0) = 0\n" \
                                . "exact: q = A cos ωt, p = −mωA sin ωt (black line); markers: the schemes at t_j = jh, h = T/N", \
                                T, M, OMEGA, A)
    set border 31; set xtics autofreq; set ytics autofreq; set mxtics; set mytics; set autoscale xy  # (after the key plot)
    set xrange [0:T]
    set xtics T / 4.0
    set format x "%g"
    set format y "%g"
    set offsets 0, 0, graph 0.06, graph 0.06
    unset key
    set label 1 "" at graph 0.02, graph 0.06 left front font ",7.5"   # the errors of the panel
    do for [row = 1:2] {
        n = (row == 1 ? N1 : N2)
        B = (row == 1 ? 0.535 : 0.135)         # bottom of the row, screen
        set tmargin at screen B + 0.33; set bmargin at screen B
        set xlabel (row == 2 ? "t" : "") offset 0, 0.4
        set format x (row == 2 ? "%g" : "")

        set lmargin at screen 0.09; set rmargin at screen 0.48
        set title sprintf("N = %d steps per period, h = %.4g:  state q", n, T / n) offset 0, -0.5
        set ylabel "q"
        set label 1 ERRS(row - 1, "q")
        plot EXACT using "t":"q" with lines ls LS_EXACT, \
             for [m in METHODS] FIG(n) using "t":(column("q_".m)) with points ls method_ls(m)

        set lmargin at screen 0.59; set rmargin at screen 0.98
        set title sprintf("N = %d, h = %.4g:  momentum p (not rescaled)", n, T / n)
        set ylabel "p"
        set label 1 ERRS(row - 1, "p")
        plot EXACT using "t":"p" with lines ls LS_EXACT, \
             for [m in METHODS] FIG(n) using "t":(column("p_".m)) with points ls method_ls(m)
    }
    unset label 1

    # one key for the four panels, below them (a plot of key entries only)
    set lmargin at screen 0.02; set rmargin at screen 0.98
    set tmargin at screen 0.065; set bmargin at screen 0.005
    unset title; unset xlabel; unset ylabel; unset offsets
    set border 0; set xtics ("" 5); set ytics ("" 5); unset mxtics; unset mytics; set xrange [0:1]; set yrange [0:1]
    set key center center horizontal Left reverse maxrows 1 samplen 3 width 1
    plot 2 with lines notitle, \
         keyentry with lines ls LS_EXACT title "exact", \
         for [m in METHODS] keyentry with points ls method_ls(m) title method_key(m, "001")   # (2: off the yrange)
    unset multiplot
    unset output
}

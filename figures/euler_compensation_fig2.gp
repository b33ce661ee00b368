# Fig. 2 of Takács & Fülöp (2025), Sec. 2.3.1: explicit Euler on y' = -alpha y (eq. 14),
# in the original coordinate y and in the compensating coordinate ybar = ln(y)/alpha (eq. 15).
# Input: fig2_decay.csv (steps), fig2_decay_exact.csv (dense exact curve).
load 'figures/common.gp'
STEPS = csv('fig2_decay.csv')
EXACT = csv('fig2_decay_exact.csv')
stats STEPS using (column("j") == 1 ? column("t") : NaN) nooutput
h = STATS_max

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig2', 17, 7.5)
    set multiplot layout 1,2 title "{/:Bold " . made_by('decay') . ":} " . sprintf("explicit Euler on ẏ = −αy, h = %g", h)
    set xlabel "t"
    set key top right
    set autoscale fix
    set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05
    set ylabel "y"
    plot EXACT using "t":"y_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"y_euler"       with points ls LS_SE    title "Euler in y", \
         STEPS using "t":"y_compensated" with points ls LS_COMP  title "Euler in ȳ, mapped to y"
    set ylabel "ȳ = Ψ(y) = ln(y)/α   (eq. 15)"
    plot EXACT using "t":"ybar_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"ybar_euler"       with points ls LS_SE    title "Euler in y, mapped to ȳ", \
         STEPS using "t":"ybar_compensated" with points ls LS_COMP  title "Euler in ȳ"
    unset multiplot
    unset output
}

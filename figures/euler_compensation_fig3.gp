# Fig. 3 of Takács & Fülöp (2025), Sec. 2.3.2: explicit Euler on the Gompertz equation
# y' = y (a - b ln y) (eq. 17), in y and in the compensating coordinate ybar = Psi(y) (eq. 18).
# Input: fig3_gompertz.csv (steps), fig3_gompertz_exact.csv (dense exact curve).
load 'figures/common.gp'
STEPS = csv('fig3_gompertz.csv')
EXACT = csv('fig3_gompertz_exact.csv')
stats STEPS using (column("j") == 1 ? column("t") : NaN) nooutput
h = STATS_max

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig3', 17, 7.5)
    set multiplot layout 1,2 title "{/:Bold " . made_by('gompertz') . ":} " . sprintf("explicit Euler on the Gompertz equation ẏ = y(a − b ln y), h = %g", h)
    set xlabel "t"
    set key bottom right
    set autoscale fix
    set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05
    set ylabel "y"
    plot EXACT using "t":"y_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"y_euler"       with points ls LS_SE    title "Euler in y", \
         STEPS using "t":"y_compensated" with points ls LS_COMP  title "Euler in ȳ, mapped to y"
    set ylabel "ȳ = Ψ(y)   (eq. 18)"
    plot EXACT using "t":"ybar_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"ybar_euler"       with points ls LS_SE    title "Euler in y, mapped to ȳ", \
         STEPS using "t":"ybar_compensated" with points ls LS_COMP  title "Euler in ȳ"
    unset multiplot
    unset output
}

# The gompertz study's figure (its item in the title: made_by('gompertz')), after Takács & Fülöp (2025):
# explicit Euler on the Gompertz equation
# y' = y (a - b ln y) (eq. 17), in y and in the compensating coordinate ybar = Psi(y) (eq. 18).
# One method in two coordinates (summary methods.gompertz): its registry colour, its marker for the run in y
# and a second one (further_point) for the run in ybar.
# Input: fig3_gompertz.csv (steps), fig3_gompertz_exact.csv (dense exact curve), summary values (methods.gompertz).
load 'figures/common.gp'
STEPS = csv('fig3_gompertz.csv')
EXACT = csv('fig3_gompertz_exact.csv')
stats STEPS using (column("j") == 1 ? column("t") : NaN) nooutput
h = STATS_max
METHODS = summary_words('methods.gompertz')   # the method of both runs, as the run names it
if (words(METHODS) != 1) { exit error "methods.gompertz: not one method in ".results."/figure_values.gp" }
eval method_styles(METHODS)                                                  # the run in y
LS_YBAR = 211; eval method_look(METHODS, further_point(METHODS, 1), LS_YBAR, 311)   # the run in ȳ
M = method_title(METHODS)

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig3', 17, 7.5)
    set multiplot layout 1,2 title "{/:Bold " . made_by('gompertz') . ":} " \
        . sprintf("%s on the Gompertz equation ẏ = y(a − b ln y), h = %g", method_key(METHODS, "000"), h)
    set xlabel "t"
    set key bottom right
    set autoscale fix
    set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05
    set ylabel "y"
    plot EXACT using "t":"y_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"y_euler"       with points ls method_ls(METHODS) title (M . " in y"), \
         STEPS using "t":"y_compensated" with points ls LS_YBAR title (M . " in ȳ, mapped to y")
    set ylabel "ȳ = Ψ(y)   (eq. 18)"
    plot EXACT using "t":"ybar_exact"       with lines  ls LS_EXACT title "exact", \
         STEPS using "t":"ybar_euler"       with points ls method_ls(METHODS) title (M . " in y, mapped to ȳ"), \
         STEPS using "t":"ybar_compensated" with points ls LS_YBAR title (M . " in ȳ")
    unset multiplot
    unset output
}

# The lj_steps study's figure (its item in the title: made_by('lj_steps'), the figure of ti_drift_fig6.gp at
# the printed step): the standard deviation σ over a small ensemble of the error
# of E = Ĥ + ½h^4α^2K at t = lj_steps.t_end, against the step h of the simplified method (1.6), log-log,
# with one standard error σ/√(2(M−1)) as bars (the same starts at every h, so the bars are a scale, not
# independent errors). Solid: the least-squares line of log σ on log h (slope summary values's
# lj_steps.exponent), through the centroid of the points, as lj_steps.cpp fits it; dotted: slope 4, the
# h^4 t^{1/2} of the random walk of (4.3), through the same centroid. The key gives the step at which the
# fit, carried to the published time by t^{1/2}, reaches the published σ (lj_steps.implied_step).
# Input: fig6_steps.csv; summary values (lj_steps.*); scene values (lj_steps.*).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.lj_steps')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8
ST = csv('fig6_steps.csv')

eval need_num('P_FIT', summary_real('lj_steps.exponent'))
eval need_num('P_SE', summary_real('lj_steps.exponent_stderr'))
eval need_num('H_IMPL', summary_real('lj_steps.implied_step'))
eval need_num('T_PRINT', summary_real('lj_steps.printed_t'))
eval need_num('T_END', scene_real('lj_steps.t_end'))
eval need_num('M', scene_real('lj_steps.size'))

stats ST using (log(column("h"))):(log(column("sigma"))) nooutput
LH = STATS_mean_x; LS = STATS_mean_y
HMIN = exp(STATS_min_x); HMAX = exp(STATS_max_x)
line(h, p) = exp(LS + p * (log(h) - LH))

set style line 601 lc rgb C_M lw 1.0 pt 7 ps 0.7
set style line 602 lc rgb C_M lw 1.2
set style line 603 lc rgb '#777777' lw 1.0 dt (2,3)

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig6h', 12, 9)
    set title "{/:Bold " . made_by('lj_steps') . ", the step:} " . sprintf("Lennard-Jones cluster, " . method_key(TRAJ_METHOD, "004") . ":\nσ of the error of E at t = %g over %d trajectories against h", T_END, M) font ",9"
    set logscale xy
    set format x "%g"
    set format y LOGFMT
    set xrange [HMIN / 1.3 : HMAX * 1.3]
    set xtics HMIN, 2
    set xlabel "step h"
    set ylabel "σ(t_{end}) of E_n − E_0"
    set key top left Left reverse samplen 2.5 width -4 font ",8"
    plot ST using "h":"sigma":"sigma_stderr" with yerrorbars ls 601 title "σ ± σ/√(2(M−1))", \
         [h = HMIN : HMAX : HMAX - HMIN] '+' using (h):(line(h, P_FIT)) with lines ls 602 \
             title sprintf("least squares: σ ∝ h^{%.2f ± %.2f}", P_FIT, P_SE), \
         [h = HMIN : HMAX : HMAX - HMIN] '+' using (h):(line(h, 4)) with lines ls 603 \
             title sprintf("h^4 (4.3); published σ at t = %g reached at h = %.4f", T_PRINT, H_IMPL)
    unset output
}

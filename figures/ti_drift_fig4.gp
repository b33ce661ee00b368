# The ensemble study's figure (its item in the title: made_by('ensemble')), after the paper on the simplified
# Takahashi–Imada method: Hénon–Heiles with the quintic
# term, U = (q_1² + q_2²)/2 + q_1²q_2 − q_2^k/k (k = 5 in the paper), where (4.3) predicts no
# systematic drift of E = Ĥ + h⁴α²K/2 but a random walk: an ensemble of starts near q_1 = 0,
# q_2, p_2 of the scene (perturbed uniformly), p_1 > 0 such that H = H_0; the simplified method (1.6),
# α = 1/12, without processing.
#   (a) the trajectories whose max |E error| exceeds ensemble.outlier (the paper: 2·10^{-6}); the
#       criterion is judged on the samples of fig4_stats.csv, the curves drawn from the coarser
#       fig4_trajectories.csv, so a drawn curve may stay below the threshold.
#   (b) the other trajectories (thin gray), with the mean μ(t) and μ ± σ(t) over all trajectories
#       (σ: sample standard deviation) from fig4_stats.csv.
#   (c) σ(t) in log-log, with the least-squares line whose slope is summary values's
#       reproduced.hh5_sigma_exponent (fitted on t ≥ ensemble.fit.t_min as in experiments/ti_drift/ensemble.cpp,
#       drawn through the centroid of that part) and a √t guide through the same point.
# The curves of (a) and (b) are drawn as line segments between consecutive samples of one
# trajectory (one pass over the file, 'with vectors'), so the file is read once per panel.
# Input: fig4_trajectories.csv, fig4_stats.csv; summary values (μ, σ, exponent: reproduced and
# published; outlier ids); scene values (h, k, H_0, the ensemble).
if (!exists("results")) results = 'results/ti_drift'
# the state of seg_x (below), defined before all else: gnuplot finds a variable that an expression assigns by a search
# through the variables in the order of their definition, and seg_x assigns six of them on each row, 80,000 in all
_tp = -1; _xp = 0; _yp = 0; _ok = 0; _x0 = 0; _y0 = 0
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.ensemble')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8    # (so that the key width counts characters, not bytes)
TRJ = csv('fig4_trajectories.csv')
eval columns('TRJ', TRJ)             # (the trajectories are many rows, read four times: their columns by number)
STA = csv('fig4_stats.csv')

eval need_num('H', scene_real('h'))
eval need_num('K', scene_real('hh.k'))
eval need_num('H0', scene_real('hh.H0'))
eval need_num('Q2', scene_real('hh3.q2'))
eval need_num('P2', scene_real('hh3.p2'))
eval need_num('M', scene_real('ensemble.size'))
eval need_num('PERT', scene_real('ensemble.perturbation'))
eval need_num('THR', scene_real('ensemble.outlier'))
eval need_num('MU', summary_real('reproduced.hh5_mu_final'))
eval need_num('SIG', summary_real('reproduced.hh5_sigma_final'))
eval need_num('GAM', summary_real('reproduced.hh5_sigma_exponent'))
eval need_num('MU_PUB', summary_real('comparisons.hh5_mu_final.published'))
eval need_num('SIG_PUB', summary_real('comparisons.hh5_sigma_final.published'))
eval need_num('GAM_PUB', summary_real('comparisons.hh5_sigma_exponent.published'))
# the outliers' ids, as listed in summary values
OUT_IDS = ""
do for [i = 0:999] { s = summary_real(sprintf('reproduced.hh5_outliers.%d', i)); if (s eq "?") { break }; OUT_IDS = OUT_IDS . (i > 0 ? ", " : "") . sprintf("%d", int(real(s))) }

# counts and ranges from the data
stats TRJ skip 1 using (column(TRJ_t) == 0 ? column(TRJ_outlier) : NaN) nooutput
NTRAJ = STATS_records; NOUT = int(STATS_sum)
stats TRJ skip 1 using (column(TRJ_trajectory) == 0 ? column(TRJ_t) : NaN) nooutput
NPT = STATS_records                                  # samples per drawn trajectory
stats TRJ skip 1 using TRJ_E_err nooutput
EABS = abs(STATS_max) > abs(STATS_min) ? abs(STATS_max) : abs(STATS_min)
stats STA using "t" nooutput
TMAX = STATS_max; NST = STATS_records
stats STA using (column("t") > 0 ? column("t") : NaN) nooutput
TMIN = STATS_min
# (c): the centroid of (log10 t, log10 σ) over the fit window t ≥ T_FIT (summary ensemble.fit.t_min, the scene's
# ensemble.fit_from of t_end), which the least-squares line passes through
eval need_num('T_FIT', summary_real('ensemble.fit.t_min'))
stats STA using (column("t") >= T_FIT && column("sigma") > 0 ? log10(column("t")) : NaN):(column("t") >= T_FIT && column("sigma") > 0 ? log10(column("sigma")) : NaN) nooutput
LTB = STATS_mean_x; LSB = STATS_mean_y
sigfit(t) = 10**(LSB + GAM * (log10(t) - LTB))
sqrtguide(t) = 10**(LSB + 0.5 * (log10(t) - LTB))

EK = floor(log10(EABS)); ES = 10.0**EK               # the errors in units of 10^EK
XK = TMAX >= 1e5 ? 3 * floor(log10(TMAX) / 3 + 1e-9) : 0; XS = 10.0**XK
XLABEL = XK == 0 ? "time t" : sprintf("time t  [10^{%d}]", XK)

# a segment from the previous sample to this one when both belong to the same trajectory and it is
# (o = 1) or is not (o = 0) an outlier; the first column updates the state, the others read it
seg_x(o) = (_ok = (column(TRJ_trajectory) == _tp && column(TRJ_outlier) == o), _x0 = _xp, _y0 = _yp, \
            _xp = column(TRJ_t) / XS, _yp = column(TRJ_E_err) / ES, _tp = column(TRJ_trajectory), _ok ? _x0 : NaN)
seg_y(o) = _ok ? _y0 : NaN
seg_dx(o) = _xp - _x0
seg_dy(o) = _yp - _y0
reset_seg = "_tp = -1; _xp = 0; _yp = 0; _ok = 0; _x0 = 0; _y0 = 0"

set style line 401 lc rgb C_M lw 1.0                   # outliers
set style line 402 lc rgb '#A8A8A8' lw 0.35              # the other trajectories
set style line 403 lc rgb C_STAT lw 2.2                  # μ
set style line 404 lc rgb '#882255' lw 1.8                # μ ± σ
set style line 405 lc rgb '#B0B0B0' lw 0.8 dt (3,3)      # threshold
set style line 406 lc rgb C_M lw 1.6                   # σ(t)
set style line 407 lc rgb C_STAT lw 1.0 dt (8,4)         # fitted power law
set style line 408 lc rgb '#555555' lw 1.0 dt (2,2)      # √t guide

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig4', 17, 16)
    set multiplot title "{/:Bold " . made_by('ensemble') . ":} " . sprintf("Hénon–Heiles, U = (q_1^2 + q_2^2)/2 + q_1^2q_2 − q_2^%d/%d; " . method_key(TRAJ_METHOD, "004") . ", " . TI_ALPHA . ", h = %g, no processing;\n" \
        . "%d starts: q_1 = 0, q_2 = %g ± %g, p_2 = %g ± %g (uniform), p_1 > 0 with H = %g; error of the modified energy E = Ĥ + h^4α^2K/2, (4.3)", \
        K, K, H, M, Q2, PERT, P2, PERT, H0)
    set format y "%g"
    set mxtics; set mytics
    set xrange [0:TMAX / XS]
    set lmargin at screen 0.09; set rmargin at screen 0.60
    YLAB = sprintf("E(p_n, q_n) − E(p_0, q_0)   [10^{%d}]", EK)

    # ---- (a) the outliers ----
    set tmargin at screen 0.895; set bmargin at screen 0.645
    set xlabel ""
    set format x ""
    set ylabel YLAB offset 0.5, 0
    set yrange [*:*]
    set offsets 0, 0, graph 0.08, graph 0.08
    set key bottom right Left reverse samplen 2.5 width -2 font ",8"
    if (NOUT > 0) {
        set title sprintf("(a) the %d %s with max |error| > %s (%s %s)", NOUT, NOUT == 1 ? "trajectory" : "trajectories", \
                          sci(THR), NOUT == 1 ? "no." : "nos.", OUT_IDS) offset 0, -0.4
        eval reset_seg
        plot TRJ skip 1 using (seg_x(1)):(seg_y(1)):(seg_dx(1)):(seg_dy(1)) with vectors nohead ls 401 notitle, \
             [t=0:TMAX:TMAX] '+' using (t / XS):(THR / ES) with lines ls 405 title sprintf("±%s, applied to the %d samples per trajectory of (b)'s μ, σ", sci(THR), NST), \
             [t=0:TMAX:TMAX] '+' using (t / XS):(-THR / ES) with lines ls 405 notitle
    } else {
        set title sprintf("(a) no trajectory with max |error| > %s", sci(THR)) offset 0, -0.4
        set yrange [-1.5 * THR / ES:1.5 * THR / ES]
        plot sample [t=0:TMAX:TMAX] '+' using (t / XS):(THR / ES) with lines ls 405 title sprintf("±%s, the threshold of (a)", sci(THR)), \
             [t=0:TMAX:TMAX] '+' using (t / XS):(-THR / ES) with lines ls 405 notitle
    }

    # ---- (b) the others, with μ and σ ----
    set tmargin at screen 0.56; set bmargin at screen 0.08
    set format x "%g"
    set xlabel XLABEL offset 0, 0.3
    set yrange [*:*]
    set offsets 0, 0, graph 0.22, graph 0.02
    set title NOUT > 0 ? sprintf("(b) the other %d trajectories", NTRAJ - NOUT) : sprintf("(b) all %d trajectories", NTRAJ)
    set key bottom left Left reverse samplen 2.5 width -2 font ",8"
    eval reset_seg
    plot TRJ skip 1 using (seg_x(0)):(seg_y(0)):(seg_dx(0)):(seg_dy(0)) with vectors nohead ls 402 notitle, \
         keyentry with lines ls 402 title sprintf("%d trajectories (%d samples each%s)", NTRAJ - NOUT, NPT, NOUT > 0 ? "; (a) likewise" : ""), \
         STA using (column("t") / XS):(column("mu") / ES) with lines ls 403 \
             title sprintf("mean μ over all %d (%d samples)", NTRAJ, NST), \
         STA using (column("t") / XS):((column("mu") + column("sigma")) / ES) with lines ls 404 \
             title "μ ± σ (sample standard deviation)", \
         STA using (column("t") / XS):((column("mu") - column("sigma")) / ES) with lines ls 404 notitle

    # ---- the numbers: reproduced and published, as a small table ----
    TX0 = 0.70; TX1 = 0.775; TX2 = 0.875; TY = 0.86; TDY = 0.032
    set label 91 sprintf("{/:Bold at the end of the run, t = %s}", gprintf("%.2t·10^{%T}", TMAX)) at screen TX0, screen TY left font ",9"
    set label 92 "reproduced" at screen TX1, screen TY - TDY left font ",9"
    set label 93 "paper (at its end)" at screen TX2, screen TY - TDY left font ",9"
    set label 94 "mean μ" at screen TX0, screen TY - 2 * TDY left font ",9"
    set label 95 sci(MU) at screen TX1, screen TY - 2 * TDY left font ",9"
    set label 96 sci(MU_PUB) at screen TX2, screen TY - 2 * TDY left font ",9"
    set label 97 "std. σ" at screen TX0, screen TY - 3 * TDY left font ",9"
    set label 98 sci(SIG) at screen TX1, screen TY - 3 * TDY left font ",9"
    set label 99 sci(SIG_PUB) at screen TX2, screen TY - 3 * TDY left font ",9"
    set label 100 "σ ∝ t^{γ}: γ" at screen TX0, screen TY - 4 * TDY left font ",9"
    set label 101 sprintf("%.3f", GAM) at screen TX1, screen TY - 4 * TDY left font ",9"
    set label 102 sprintf("%.2f", GAM_PUB) at screen TX2, screen TY - 4 * TDY left font ",9"
    set label 103 sprintf("(μ, σ over all %d trajectories;\n γ fitted on t ≥ t_{end}/10)", NTRAJ) at screen TX0, screen TY - 5.3 * TDY left font ",8"

    # ---- (c) σ(t) in log-log ----
    set lmargin at screen 0.72; set rmargin at screen 0.97
    set tmargin at screen 0.56; set bmargin at screen 0.08
    set logscale xy
    set xrange [TMIN:TMAX]
    set yrange [*:*]
    set offsets 0, 0, 0, 0
    set format x LOGFMT
    set format y LOGFMT
    set xtics autofreq
    set xlabel "time t" offset 0, 0.3
    set ylabel "σ(t)" offset 1, 0
    set title "(c) standard deviation"
    set key top left Left reverse samplen 2.5 width -4 font ",8"
    plot STA using (column("t") > 0 ? column("t") : NaN):"sigma" with lines ls 406 title "σ(t), all trajectories", \
         [t=T_FIT:TMAX:TMAX - T_FIT] '+' using (t):(sigfit(t)) with lines ls 407 title sprintf("fit t ≥ %g: t^{%.3f}", T_FIT, GAM), \
         [t=TMIN:TMAX:TMAX - TMIN] '+' using (t):(sqrtguide(t)) with lines ls 408 title "√t guide"
    unset label
    unset logscale xy
    unset multiplot
    unset output
}

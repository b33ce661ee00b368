# The lj study's figure (its item in the title: made_by('lj')), after the paper on the simplified
# Takahashi–Imada method: the Lennard-Jones cluster,
# N = 9 particles in the plane, V(r) = 0.4(r^{-12} − 2r^{-6}) over all pairs, started on the grid (i, j),
# i, j ∈ {1, 2, 3}, each coordinate perturbed uniformly by at most lj.perturbation, p = 0 (fixed in
# experiments/ti_drift/lj.cpp); the simplified method (1.6), α = 1/12, without processing.
#   (a) the step-size scan: max over t ≤ lj.scan_t of |H − H_0| per trajectory and step size h (points;
#       spread sideways by the trajectory index so that they do not hide each other). A run counts as
#       diverged once |H − H_0| exceeds lj.blowup (or is not finite): drawn as a triangle in the
#       "diverged" row above the threshold, with the number diverged of the runs at that h (its
#       max_H_err, the maximum before the blow-up, is not plotted). The paper prints h = 0.2, at which
#       every run diverges; the ensemble of (b)–(d) is run at lj.h (docs: shared note ti_drift.md §6).
#       Dotted: ∝ h^2 through the median at the smallest h of the scan (H itself has an O(h^2) error).
#   (b) as the paper's figure: the error of E = Ĥ + ½h^4α^2K (the modified energy, note §3.4) of the
#       trajectories of fig6_trajectories.csv (thin gray), with the mean μ(t) and μ ± σ(t) over the
#       whole ensemble (bold); key: μ and σ at t_end with their standard errors, and the published ones.
#   (c) σ(t), log-log: the least-squares line of log σ on log t over t ≥ lj.fit.t_min (as lj.cpp fits
#       it) with the slope reproduced.lj_sigma_exponent, through the centroid of those points; dotted:
#       t^γ with the published exponent (1/2, a random walk) through the same centroid.
#   (d) the RMS over the ensemble of H(p_n, q_n) − H(p_0, q_0) and of H(p̂_n, q̂_n) − H(p̂_0, q̂_0),
#       (p̂, q̂) = χ_h(p, q) of (1.5), each from its own start (column Hhat_change_rms: without the constant
#       offset H(χ_h(p_0, q_0)) − H(p_0, q_0) = O(h^2) of the start), with σ(t) of (c) dashed: in the
#       processed variables H random-walks like E (004 Sect. 5.3, last paragraph).
# Input: fig6_scan.csv, fig6_stats.csv, fig6_trajectories.csv; summary values (μ, σ, standard errors,
# exponent, max |H − H_0|, published values); scene values (lj.*).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
TRAJ_METHOD = summary_words('methods.lj')   # the method of its trajectories, as the run names it
C_M = method_colour(TRAJ_METHOD)
set encoding utf8    # (so that the key width counts characters, not bytes)
SCAN  = csv('fig6_scan.csv')
STATF = csv('fig6_stats.csv')
TRAJ  = csv('fig6_trajectories.csv')

eval need_num('H_LJ', scene_real('lj.h'))
eval need_num('T_END', scene_real('lj.t_end'))
eval need_num('M_LJ', scene_real('lj.size'))
eval need_num('PERT', scene_real('lj.perturbation'))
eval need_num('BLOWUP', scene_real('lj.blowup'))
eval need_num('SCAN_T', scene_real('lj.scan_t'))
eval need_num('SCAN_N', scene_real('lj.scan_size'))
eval need_num('MU', summary_real('reproduced.lj_mu_final'))
eval need_num('SIGMA', summary_real('reproduced.lj_sigma_final'))
eval need_num('MU_SE', summary_real('reproduced.lj_mu_final_stderr'))
eval need_num('SIGMA_SE', summary_real('reproduced.lj_sigma_final_stderr'))
eval need_num('GAMMA', summary_real('reproduced.lj_sigma_exponent'))
eval need_num('H_ERR_MAX', summary_real('reproduced.lj_H_err_max'))
eval need_num('MU_PUB', summary_real('comparisons.lj_mu_final.published'))
eval need_num('SIGMA_PUB', summary_real('comparisons.lj_sigma_final.published'))
eval need_num('GAMMA_PUB', summary_real('comparisons.lj_sigma_exponent.published'))

# ---- (a): the step sizes of the scan, HS_1 .. HS_NS (scene values lj.h_scan) ----
NS = 0
do for [k = 0:19] { s = scene_real(sprintf('lj.h_scan.%d', k)); if (s ne "?") { NS = k + 1; eval sprintf("HS_%d = %s", NS, s) } }
if (NS == 0) { exit error "lj.h_scan: missing from ".results."/run.json" }
HS(i) = value(sprintf("HS_%d", i))
NRUN(i) = value(sprintf("NRUN_%d", i))
NDIV(i) = value(sprintf("NDIV_%d", i))
ish(i) = abs(column("h") / HS(i) - 1) < 1e-9
HMIN = HS(1); HMAX = HS(1)
do for [i = 2:NS] { HMIN = HS(i) < HMIN ? HS(i) : HMIN; HMAX = HS(i) > HMAX ? HS(i) : HMAX }
# per step size: runs, diverged runs, and the median of the maxima of the others
do for [i = 1:NS] {
    stats SCAN using (ish(i) ? column("diverged") : NaN) nooutput
    eval sprintf("NRUN_%d = STATS_records; NDIV_%d = int(STATS_sum)", i, i)
    if (NRUN(i) == 0) { exit error sprintf("fig6_scan.csv: no rows with h = %g", HS(i)) }
}
stats SCAN using "max_H_err" nooutput
IMIN = 0
do for [i = 1:NS] { if (HS(i) == HMIN) { IMIN = i } }
if (NDIV(IMIN) == NRUN(IMIN)) { exit error sprintf("fig6_scan.csv: every run diverges at the smallest h = %g", HMIN) }
stats SCAN using ((ish(IMIN) && column("diverged") == 0) ? column("max_H_err") : NaN) nooutput
MED_HMIN = STATS_median
stats SCAN using (column("diverged") == 0 ? column("max_H_err") : NaN) nooutput
SCAN_YMIN = STATS_min
ALL_DIV = ""        # the step sizes at which every run diverged
do for [i = 1:NS] { if (NDIV(i) == NRUN(i)) { ALL_DIV = ALL_DIV . (ALL_DIV eq "" ? "" : ", ") . gprintf("%g", HS(i)) } }
Y_DIV = BLOWUP * 6.0                                      # the "diverged" row, above the threshold
jit(h) = h * 10**(0.05 * (column("trajectory") / (SCAN_N > 1 ? SCAN_N - 1 : 1) - 0.5))
stable(col) = column("diverged") == 0 ? column(col) : NaN
h2guide(h) = MED_HMIN * (h / HMIN)**2

# ---- (b): the trajectories and the ensemble ----
eval columns('TRAJ', TRAJ)      # (the trajectories are many rows, read once per trajectory: their columns by number)
stats TRAJ skip 1 using TRAJ_trajectory nooutput
NT = int(STATS_max) + 1
RT = int(STATS_records) / NT      # rows per trajectory: trajectory i is the rows i RT .. (i + 1) RT - 1 (checked)
stats TRAJ skip 1 using (column(TRAJ_trajectory) == int(column(0)) / RT ? 1 : 0) nooutput
if (RT * NT != STATS_records || STATS_min != 1) {
    exit error sprintf("fig6_trajectories.csv: not %d trajectories of %d rows each, one after another", NT, RT)
}
U6 = 1e-6                                                 # (b) in units of 10^{-6}
pm(x, se) = sprintf("%s%.3f ± %.3f·10^{−6}", x < 0 ? "−" : "", abs(x) / U6, se / U6)

# ---- (c): the centroid of the fitted points (t ≥ T_FIT: summary lj.fit.t_min, σ > 0), and a check of the fit ----
eval need_num('T_FIT', summary_real('lj.fit.t_min'))
infit(t, s) = (t >= T_FIT && s > 0)
stats STATF using (infit(column("t"), column("sigma")) ? log(column("t")) : NaN):(infit(column("t"), column("sigma")) ? log(column("sigma")) : NaN) nooutput
LTBAR = STATS_mean_x; LSBAR = STATS_mean_y; TFIT0 = exp(STATS_min_x); TFIT1 = exp(STATS_max_x)
if (abs(STATS_slope - GAMMA) > 1e-6 * abs(GAMMA)) {
    exit error sprintf("fig6_stats.csv: slope of log σ over t ≥ %g is %.9g, summary.json lj_sigma_exponent %.9g", T_FIT, STATS_slope, GAMMA)
}
sigfit(t, g) = exp(LSBAR + g * (log(t) - LTBAR))
stats STATF using (column("t") > 0 ? column("t") : NaN) nooutput
TPOS_MIN = STATS_min
pos(col) = column("t") > 0 ? column(col) : NaN

# ---- styles ----
set style line 201 lc rgb C_M  lw 1.0 pt 6 ps 0.55          # (a) max |H − H0|, open circles
set style line 202 lc rgb C_M  lw 1.0 pt 9 ps 0.85          # (a) diverged, filled triangles
set style line 203 lc rgb '#777777' lw 0.8 dt (5,3)           # (a) threshold; (d) value at t = 0
set style line 204 lc rgb C_STAT lw 0.9 dt (2,3)              # guides: h^2, t^{1/2}
set style line 205 lc rgb '#a6a6a6' lw 0.35                   # (b) single trajectories
set style line 206 lc rgb C_STAT lw 2.0                       # (b) μ
set style line 207 lc rgb C_STAT lw 2.0 dt (6,3)              # (b) μ ± σ
set style line 208 lc rgb C_M  lw 1.4                       # (c) σ
set style line 209 lc rgb C_STAT lw 1.0 dt (8,4)              # (c) fit
set style line 210 lc rgb C_UNCORRECTED lw 1.2                # (d) H error (a role, no method: figures/common.gp)
set style line 211 lc rgb C_CORRECTED   lw 1.2                # (d) H at the processed variables (a role, no method)
set style line 212 lc rgb C_STAT lw 1.0 dt (3,3)              # (d) sigma of E

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig6', 17, 17)
    set multiplot title "{/:Bold " . made_by('lj') . ":} " . sprintf("Lennard-Jones cluster, 9 particles in the plane (3×3 grid perturbed by ≤ %g, p_0 = 0), " \
        . method_key(TRAJ_METHOD, "004") . ", " . TI_ALPHA . ",\nno processing; (b)–(d): h = %g, %d trajectories to t = %g " \
        . "%s", PERT, H_LJ, M_LJ, T_END, \
        ALL_DIV eq "" ? "" : sprintf("(in (a) every run diverges at h = %s, the step size printed in the paper)", ALL_DIV))

    # ---- (a) the step-size scan ----
    set lmargin at screen 0.115; set rmargin at screen 0.40
    set tmargin at screen 0.875; set bmargin at screen 0.555
    set logscale xy
    set xrange [HMIN / 1.6 : HMAX * 1.6]
    set yrange [SCAN_YMIN / 3 : Y_DIV * 4]
    set format x "%g"
    set xtics ()
    do for [i = 1:NS] { set xtics add (HS(i)) }
    unset mxtics
    set ytics ()
    do for [k = -12:0] { if (10.0**k >= SCAN_YMIN / 3 && 10.0**k <= BLOWUP) { set ytics add (sprintf("10^{%d}", k) 10.0**k) } }
    set ytics add ("diverged" Y_DIV)
    unset mytics
    set xlabel "step size h" offset 0, 0.3
    set ylabel sprintf("max_{t ≤ %g} |H(p_n, q_n) − H_0|", SCAN_T) offset 2, 0
    set title sprintf("(a) step-size scan, %d runs per h", SCAN_N) offset 0, -0.4
    set key bottom right Left reverse samplen 1.5 width -3 font ",7"
    set arrow 1 from graph 0, first BLOWUP to graph 1, first BLOWUP nohead ls 203
    set label 1 sprintf("|H − H_0| = %g: diverged above", BLOWUP) at graph 0.03, first BLOWUP offset 0, -0.55 left font ",7" tc rgb '#555555'
    do for [i = 1:NS] {
        if (NDIV(i) > 0) { eval sprintf("set label %d '%d/%d' at %.17g, %.17g center font ',7'", 10 + i, NDIV(i), NRUN(i), HS(i), Y_DIV * 2.4) }
    }
    plot SCAN using (jit(column("h"))):(stable("max_H_err")) with points ls 201 title "max |H − H_0|, one run", \
         SCAN using (column("diverged") != 0 ? jit(column("h")) : NaN):(Y_DIV) with points ls 202 \
             title "diverged (count above)", \
         [h = HMIN / 1.3 : HMAX * 1.3 : HMAX] '+' using (h):(h2guide(h)) with lines ls 204 title "∝ h^2"
    unset arrow 1
    unset label
    unset logscale
    set autoscale
    set xtics autofreq; set ytics autofreq
    set mxtics; set mytics

    # ---- (b) as the paper's figure ----
    set lmargin at screen 0.50; set rmargin at screen 0.98
    set xrange [0:T_END]
    set format x "%g"
    set format y "%g"
    set xlabel "time t"
    set ylabel "E(p_n, q_n) − E(p_0, q_0)   [10^{−6}]" offset 1, 0
    set title sprintf("(b) error in E = Ĥ + ½h^4α^2K: %d trajectories, μ and μ ± σ over %d", NT, M_LJ)
    set key top left Left reverse samplen 2 width -6 font ",7"
    plot for [i = 0:NT - 1] TRAJ skip 1 every ::(i * RT)::((i + 1) * RT - 1) using TRAJ_t:(column(TRAJ_E_err) / U6) with lines ls 205 notitle, \
         STATF using "t":(column("mu") / U6) with lines ls 206 \
             title sprintf("μ(%g) = %s (paper %g·10^{−6})", T_END, pm(MU, MU_SE), MU_PUB / U6), \
         STATF using "t":((column("mu") + column("sigma")) / U6) with lines ls 207 \
             title sprintf("μ ± σ: σ(%g) = %s (paper %g·10^{−6})", T_END, pm(SIGMA, SIGMA_SE), SIGMA_PUB / U6), \
         STATF using "t":((column("mu") - column("sigma")) / U6) with lines ls 207 notitle, \
         NaN with lines ls 205 title sprintf("%d single trajectories", NT)

    # ---- (c) σ(t), log-log ----
    set lmargin at screen 0.095; set rmargin at screen 0.52
    set tmargin at screen 0.445; set bmargin at screen 0.075
    set logscale xy
    set xrange [TPOS_MIN : T_END]
    set format x LOGFMT
    set format y LOGFMT
    set xlabel "time t"
    set ylabel "standard deviation σ(t) of the E error" offset 1, 0
    set title sprintf("(c) σ(t) over %d trajectories", M_LJ)
    set key top left Left reverse samplen 2.5 width -3 font ",7"
    plot STATF using "t":(pos("sigma")) with lines ls 208 title "σ(t)", \
         [t = TFIT0 : TFIT1 : TFIT1 - TFIT0] '+' using (t):(sigfit(t, GAMMA)) with lines ls 209 \
             title sprintf("least squares, t ≥ %g: σ ∝ t^{%.3f}", T_END / 10, GAMMA), \
         [t = TPOS_MIN : T_END : T_END - TPOS_MIN] '+' using (t):(sigfit(t, GAMMA_PUB)) with lines ls 204 \
             title sprintf("paper: σ ∝ t^{%g} (random walk)", GAMMA_PUB)

    # ---- (d) the H error, unprocessed and processed ----
    set lmargin at screen 0.635; set rmargin at screen 0.98
    set ylabel "RMS over the trajectories" offset 1, 0
    set title "(d) H error, each from its own start"
    set key bottom right Left reverse samplen 2.5 width -5 font ",7"
    set yrange [*:*]
    set offsets 0, 0, graph 0.45, graph 0.1
    plot STATF using "t":(pos("H_err_rms")) with lines ls 210 \
             title sprintf("H(p_n, q_n) − H_0 (max %s)", sci(H_ERR_MAX)), \
         STATF using "t":(pos("Hhat_change_rms")) with lines ls 211 title "H(p̂_n, q̂_n) − H(p̂_0, q̂_0), (p̂, q̂) = χ_h(p, q)", \
         STATF using "t":(pos("sigma")) with lines ls 212 title "σ(t) of E, as in (c)"
    set offsets 0, 0, 0, 0
    unset logscale
    unset multiplot
    unset output
}

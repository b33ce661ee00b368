# Beyond the paper (it stops at t = 10, Figs 5.5, 5.6): energy drift of the free nonholonomic particle
# (U = 0) over a long run, z_0 = (x, y, p_x, p_y) = (0, 0, 1, 1), h = 0.25, the five discretizations (5.1).
# H(z_j) − H(z_0) along (a) Φ^(0)_h (E* = H(z_0)) and (b) Φ^(4)_h (E* = ℰ^(4)(z_0)), each panel on its own
# scale. The conformal factor N = (1 + y²)^(−1/2) tends to 0 along the motion (y grows), and the altered
# Hamiltonian K_E* = N(H − E*) stays near its conserved modified value K_mod(z_0; E*): for Φ^(0) that value is
# O(h²) ≠ 0, so H − E* ≈ K_mod/N grows without bound; for Φ^(4) it is O(h^6) and H stays near E*.
# The key gives, per method, H − H(z_0) and the error ‖z − z_ref‖_2 at the final time (summary values).
# Input: long_run.csv (t, <m>_H_phi0, <m>_H_phi4), summary values (methods, reproduced.long_H_err_phi<ℓ>,
# long_err_phi<ℓ>), scene values (h, long_run.t_end, cloud.center, potential).
if (!exists("results")) results = 'results/measure_cloud-free'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('free')
eval MC_NEED_METHODS
LR = csv('long_run.csv')

eval need_num('H', scene_real('h'))
eval need_num('TEND', scene_real('long_run.t_end'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
stats LR using "t" nooutput
TMAX = STATS_max
do for [m in MC_METHODS] { do for [l in "0 4"] {
    eval need_num(sprintf("DH%s_%s", l, m), summary_real(sprintf('reproduced.long_H_err_phi%s.%s', l, m)))
    eval need_num(sprintf("ER%s_%s", l, m), summary_real(sprintf('reproduced.long_err_phi%s.%s', l, m)))
}}
DH(l, m) = value(sprintf("DH%d_%s", l, m))
ER(l, m) = value(sprintf("ER%d_%s", l, m))
do for [l in "0 4"] {
    a = 0
    do for [m in MC_METHODS] { stats LR using (abs(column(sprintf("%s_H_phi%s", m, l)))) nooutput; a = (STATS_max > a ? STATS_max : a) }
    eval sprintf("A%s = %.17g", l, a)
}
# value with 3 significant digits, as plain text
g3(x) = gprintf("%.3g", x)

do for [fmt in FORMATS] {
    eval term(fmt, 'measure_cloud-free_long_run', 17, 13.5)
    set multiplot title sprintf("{/:Bold Long run:} free nonholonomic particle (U = 0), z_0 = (x, y, p_x, p_y) = %s, h = %g, " \
        . "five discretizations (5.1):\nenergy error H(z_j) − H(z_0) to t = %g, Φ^{(0)}_h against Φ^{(4)}_h, each on its own scale (max |H − H(z_0)|: %s against %s)", \
        Z0, H, TMAX, g3(A0), g3(A4))
    unset key
    set lmargin at screen 0.10; set rmargin at screen 0.97
    set xrange [0:TMAX]
    set xtics 10; set mxtics 2; set mytics
    set format x "%g"; set format y "%g"
    set offsets 0, 0, graph 0.05, graph 0.05
    set autoscale y

    # ---- (a) Φ^(0) ----
    set tmargin at screen 0.865; set bmargin at screen 0.575
    set title "(a) Φ^{(0)}_h, E^* = H(z_0): N → 0 while K_{E^*} = N(H − E^*) → K_{mod}(z_0; E^*) = O(h^2) ≠ 0, so H drifts" offset 0, -0.4
    set xlabel ""
    set ylabel "H(z_j) − H(z_0)" . MC_UNIT(A0) offset 1, 0
    sc = MC_SCALE(A0)
    MC_Y(m) = column(m . "_H_phi0") / sc
    plot 0 with lines ls MC_LS_REF notitle, \
         for [m in MC_METHODS] LR using "t":(MC_Y(m)) with lines ls method_ls(m) notitle, \
         for [m in MC_METHODS] LR every 25::mc_first(m, 25) using "t":(MC_Y(m)) with points ls method_ls(m) notitle

    # ---- (b) Φ^(4) ----
    set tmargin at screen 0.485; set bmargin at screen 0.195
    set title "(b) Φ^{(4)}_h, E^* = ℰ^{(4)}(z_0): K_{mod}(z_0; E^*) = O(h^6), H stays near E^*"
    set xlabel "time t" offset 0, 0.4
    set ylabel "H(z_j) − H(z_0)" . MC_UNIT(A4)
    sc = MC_SCALE(A4)
    MC_Y(m) = column(m . "_H_phi4") / sc
    plot 0 with lines ls MC_LS_REF notitle, \
         for [m in MC_METHODS] LR using "t":(MC_Y(m)) with lines ls method_ls(m) notitle, \
         for [m in MC_METHODS] LR every 25::mc_first(m, 25) using "t":(MC_Y(m)) with points ls method_ls(m) notitle

    # ---- key: the values at the final time ----
    set lmargin at screen 0.10; set rmargin at screen 0.97
    set tmargin at screen 0.08; set bmargin at screen 0.0
    unset title; unset xlabel; unset ylabel; unset border; unset tics; unset grid
    set xrange [0:1]; set yrange [0:1]
    set key at screen 0.06, screen 0.105 left top vertical Left reverse maxrows 3 samplen 2.5 width -3 spacing 1.1 font ",8" nobox
    set label 1 sprintf("at t = %g:  H − H(z_0) for Φ^{(0)} / Φ^{(4)};  error ‖z − z_{ref}‖_2 for Φ^{(0)} / Φ^{(4)}   " \
        . "((5.1): first letter the quadrature of N, second of L; M midpoint, T trapezoidal)", TMAX) \
        at screen 0.06, screen 0.125 left font ",8"
    plot NaN notitle, \
         keyentry with lines ls MC_LS_REF title "exact flow: H − H(z_0) = 0", \
         for [m in MC_METHODS] keyentry with linespoints ls method_ls(m) \
             title sprintf("%s:  %s / %s;  %s / %s", method_key(m, '003'), g3(DH(0, m)), g3(DH(4, m)), g3(ER(0, m)), g3(ER(4, m)))
    unset label 1
    set border; set tics; set grid
    set autoscale xy
    unset multiplot
    unset output
}

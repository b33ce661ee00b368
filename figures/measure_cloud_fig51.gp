# The shape study's figure (its item in the title: made_by('shape')), after García-Naranjo & Vermeeren:
# the nonholonomic particle in the harmonic
# potential U = (x² + y²)/2, exact flow (reference, no discretization). A cloud of points on the
# 3-sphere of radius r around z_0 = (x, y, p_x, p_y) = (0, 0, 1, 1), at the times 0, Δt, …, kΔt,
# projected to the (x, p_x) and (y, p_y) planes; later times lighter (as in the paper: black at t = 0).
# The key gives the areas of the convex hulls of the two projections and their sum, a description of
# the shadows only: that sum is not a symplectic invariant. Panel (c) tests symplecticity: the defect
# max|Φᵀ Ω Φ − Ω| of the Jacobian Φ of the exact flow along the trajectory from z_0 (odeint variational
# equations) against time, beside the same for the flow of H with N = 1 and for Ψ_{h,E} at fixed E
# (symplectic: round-off).
# Input: shape.csv (t, x, y, px, py), shape_areas.csv (t, area_x_px, area_y_py, area_sum),
# shape_symplecticity.csv (t, conformal_flow, hamiltonian_flow, measure_identity_err, psi_<method>...),
# scene values (shape.points, shape.radius, shape.snapshot_dt, shape.snapshots, cloud.center, h), summary values (methods).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
eval mc_need_potential('harmonic')
SH = csv('shape.csv')
eval columns('SH', SH)                  # (shape.csv is large and read many times: its columns by number)
SA = csv('shape_areas.csv')
SY = csv('shape_symplecticity.csv')
eval MC_NEED_METHODS
eval need_num('HSTEP', scene_real('h'))

eval need_num('NPTS', scene_real('shape.points'))
eval need_num('R', scene_real('shape.radius'))
eval need_num('DT', scene_real('shape.snapshot_dt'))
eval need_num('NSNAP', scene_real('shape.snapshots'))
Z0 = sprintf("(%s, %s, %s, %s)", scene_num('cloud.center.0'), scene_num('cloud.center.1'), \
             scene_num('cloud.center.2'), scene_num('cloud.center.3'))
NSNAP = int(NSNAP)

# snapshot k at t = k Δt, the rows k NPTS .. (k + 1) NPTS - 1 of shape.csv (checked below): grey level
# from black (k = 0) to light grey (k = NSNAP)
TK(k) = k * DT
at(k) = abs(column("t") - TK(k)) < 1e-9 * (1 + TK(k))   # a row of snapshot k (shape_areas.csv)
GREY(k) = (g = k == 0 ? 0 : int(255 * (0.25 + 0.5 * (k - 1) / (NSNAP > 1 ? NSNAP - 1 : 1))), sprintf("#%02x%02x%02x", g, g, g))
stats SH skip 1 using SH_t nooutput
if (STATS_records != (NSNAP + 1) * NPTS) { exit error sprintf("shape.csv: %d rows, expected %d", STATS_records, (NSNAP + 1) * NPTS) }
do for [k = 0:NSNAP] {
    stats SH skip 1 every ::(k * NPTS)::((k + 1) * NPTS - 1) using SH_t nooutput
    if (STATS_records != NPTS || abs(STATS_min - TK(k)) > 1e-9 * (1 + TK(k)) || abs(STATS_max - TK(k)) > 1e-9 * (1 + TK(k))) {
        exit error sprintf("shape.csv: rows %d to %d are not all at t = %g", k * NPTS, (k + 1) * NPTS - 1, TK(k))
    }
    do for [c in "x y"] {            # centroid of the projection: where the snapshot's time is written
        stats SH skip 1 every ::(k * NPTS)::((k + 1) * NPTS - 1) using value("SH_" . c):value("SH_p" . c) nooutput
        eval sprintf("C%s_%d = STATS_mean_x; Cp%s_%d = STATS_mean_y", c, k, c, k)
    }
    stats SA using (at(k) ? column("area_x_px") : NaN) nooutput
    eval sprintf("AX_%d = STATS_min", k)
    stats SA using (at(k) ? column("area_y_py") : NaN) nooutput
    eval sprintf("AY_%d = STATS_min", k)
}
PS = NPTS > 2000 ? 0.07 : 0.15          # point size: small, the clouds are dense
set style textbox opaque fc rgb '#ffffff' noborder margins 0.8, 0.4
TLABEL(k, cx, cy) = sprintf("set label %d 't = %g' at %.17g, %.17g center front boxed font ',7.5' tc rgb '#000000'", \
    10 + k, TK(k), value(sprintf("C%s_%d", cx, k)), value(sprintf("C%s_%d", cy, k)))
AX(k) = value(sprintf("AX_%d", k))
AY(k) = value(sprintf("AY_%d", k))

do for [fmt in FORMATS] {
    eval term(fmt, 'measure_cloud_fig51', 22, 10.5)
    set autoscale xy
    set multiplot title "{/:Bold " . made_by('shape') . ":} " . sprintf("nonholonomic particle, U = (x^2 + y^2)/2, exact flow: %d points on the 3-sphere " \
        . "of radius %g around z_0 = (x, y, p_x, p_y) = %s,\nat t = 0, %g, …, %g (later times lighter), projected to the (x, p_x) " \
        . "and (y, p_y) planes", NPTS, R, Z0, DT, TK(NSNAP))
    set tmargin at screen 0.85; set bmargin at screen 0.35
    set format x "%g"; set format y "%g"
    set mxtics; set mytics
    set offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03
    unset key

    # ---- (a) (x, p_x) ----
    set lmargin at screen 0.06; set rmargin at screen 0.33
    set title "(a) projection to the (x, p_x) plane" offset 0, -0.3
    set xlabel "x" offset 0, 0.3
    set ylabel "p_x" offset 1, 0
    do for [k = 0:NSNAP] { eval TLABEL(k, "x", "px") }
    plot for [k = NSNAP:0:-1] SH skip 1 every ::(k * NPTS)::((k + 1) * NPTS - 1) using SH_x:SH_px with points pt 5 ps PS lc rgb GREY(k) notitle

    # ---- (b) (y, p_y) ----
    set lmargin at screen 0.39; set rmargin at screen 0.66
    set title "(b) projection to the (y, p_y) plane"
    set xlabel "y"
    set ylabel "p_y"
    do for [k = 0:NSNAP] { eval TLABEL(k, "y", "py") }
    plot for [k = NSNAP:0:-1] SH skip 1 every ::(k * NPTS)::((k + 1) * NPTS - 1) using SH_y:SH_py with points pt 5 ps PS lc rgb GREY(k) notitle

    # ---- (c) symplecticity defect against t ----
    do for [k = 0:NSNAP] { unset label 10 + k }
    set lmargin at screen 0.74; set rmargin at screen 0.98
    set title "(c) defect max|Φ^TΩΦ − Ω| of the flow map"
    set xlabel "t"
    set ylabel "defect" offset 1, 0
    set logscale y
    set format y LOGFMT
    set xrange [0:TK(NSNAP)]
    set yrange [1e-17:1e2]
    set label 2 "exact flow (3.8)" at graph 0.5, graph 0.97 center front font ",8"
    set label 3 sprintf("flow of H with N = 1 (grey) and Ψ_{h,E}, E = H(z_0), h = %g\n(each method its colour): round-off", HSTEP) \
        at graph 0.5, graph 0.25 center front font ",7.5"
    plot SY using "t":(column("conformal_flow") > 0 ? column("conformal_flow") : NaN) with lines ls MC_LS_REF notitle, \
         SY using "t":(column("hamiltonian_flow") > 0 ? column("hamiltonian_flow") : NaN) with lines ls MC_LS_GUIDE notitle, \
         for [m in MC_METHODS] SY using "t":(column("psi_" . m) > 0 ? column("psi_" . m) : NaN) with points ls method_ls(m) notitle
    unset label 2; unset label 3
    unset logscale y; set format y "%g"; set autoscale xy

    # ---- key: the snapshots and the projected areas ----
    unset title; unset xlabel; unset ylabel; unset border; unset tics; unset grid
    set lmargin at screen 0.09; set rmargin at screen 0.98
    set tmargin at screen 0.22; set bmargin at screen 0.01
    set xrange [0:1]; set yrange [0:1]
    set key at screen 0.09, screen 0.235 left top Left reverse maxrows 3 samplen 0.8 width 2 spacing 1.25 font ",8.5" nobox
    set label 1 "convex-hull areas of the projections: a description, their sum is no symplectic invariant;\n" \
              . "(c): the flow is not symplectic (it preserves μ = N^{−1} d^4z, N = (1 + y^2)^{−1/2})" \
              at screen 0.09, screen 0.065 left font ",8.5"
    plot NaN notitle, \
         for [k = 0:NSNAP] keyentry with points pt 7 ps 0.7 lc rgb GREY(k) \
            title sprintf("t = %-5g  area(x, p_x) + area(y, p_y) = %.3f + %.3f = %.3f", TK(k), AX(k), AY(k), AX(k) + AY(k))
    unset label 1
    set border; set tics; set grid
    unset multiplot
    unset output
}

# Beyond the paper: the order of measure preservation (the paper checks one step size, measure_cloud_fig52.gp).
# Harmonic potential U = (x² + y²)/2; a tiny 600-cell cloud (radius order_study.radius, around z_0) advanced by
# Φ^(ℓ)_h (E* = ℰ^(ℓ)(z) of each point) with the five discretizations (5.1), for each ℓ of order_study.ells and
# each step h of order_study.h; the peak-to-peak over t ≤ ptp_window of V(t)/V(0) − 1, V the volume of the convex
# hull w.r.t. Φ^(ℓ)'s own measure μ^(ℓ)_mod (μ^(0) = μ). The claim (Corollary 4.3): O(h^(ℓ+2)).
# One panel per ℓ (figures/convergence.gpi): the points, the least-squares fit (dashed, over its h range) and
# the fitted order of each discretization (orders.csv: <m>_ell<ℓ>; "no order" where fewer than 3 points lie
# above the floor). The floor (gray line) is 2 × the round-off noise measured by the probe runs (crosses, in
# the panel of Φ^(6)): Φ^(6) at h = order_study_h_probe, half the smallest step, where the truncation error
# is negligible; points below it are left out of the fits.
# Input: order_study.csv (h, steps, <m>_ell<ℓ>), orders.csv, order_study_probe.csv (h, steps, <m>_ell6),
# summary values (methods, reproduced.order_study_noise_floor, reproduced.order_study_h_probe), scene values
# (order_study.*, cloud.center, ptp_window, potential).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
if (scene_words('potential') ne 'harmonic') { exit error sprintf("%s: potential '%s', expected 'harmonic'", results, scene_words('potential')) }
eval need_num('FLOOR', summary_real('reproduced.order_study_noise_floor'))   # twice the round-off noise
eval need_num('HPROBE', summary_real('reproduced.order_study_h_probe'))
eval need_num('R', scene_real('order_study.radius'))
ELLS = ""
do for [i = 0:9] { e = scene_num(sprintf('order_study.ells.%d', i)); if (e ne "?") { ELLS = ELLS . " " . e } }
CONV_NAME = 'measure_cloud_order'
CONV_CSV = 'order_study.csv'
CONV_PAPER = '003'
METHODS = summary_words('methods')
CONV_QUANTITIES = ""
CONV_PANEL_TITLES = ""
MEASURE(e) = e == 0 ? "μ" : sprintf("μ^{(%d)}_{mod}", e)
do for [i = 1:words(ELLS)] {
    e = word(ELLS, i)
    CONV_QUANTITIES = CONV_QUANTITIES . " ell" . e
    CONV_PANEL_TITLES = CONV_PANEL_TITLES . sprintf(' "(%s) ℓ = %s: Φ^{(%s)}_h w.r.t. %s, expected order %d"', \
                                                    word("a b c d e f g h", i), e, e, MEASURE(int(real(e))), int(real(e)) + 2)
}
CONV_YLABEL(q) = "peak-to-peak of V/V(0) − 1"
CONV_ROWS = 2
CONV_FLOOR = FLOOR
CONV_FLOOR_KEY = sprintf("2 × round-off noise = %s (not fitted below)", sci(FLOOR))
CONV_PROBE_CSV = 'order_study_probe.csv'
CONV_PROBE_QUANTITIES = "ell6"
CONV_PROBE_KEY = sprintf("noise probe: Φ^{(6)}, h = %g", HPROBE)
CONV_NO_ORDER = 1
CONV_TITLE = sprintf("{/:Bold Order of measure preservation:} Φ^{(ℓ)}_h preserves μ^{(ℓ)}_{mod} to O(h^{ℓ+2}) (003 Cor. 4.3)\n" \
    . "harmonic potential U = (x^2 + y^2)/2, 600-cell cloud of radius %s around z_0 = (%s, %s, %s, %s); peak-to-peak over t ≤ %s", \
    sci(R), scene_num('cloud.center.0'), scene_num('cloud.center.1'), scene_num('cloud.center.2'), scene_num('cloud.center.3'), \
    scene_num('ptp_window'))
load 'figures/convergence.gpi'

# Fig. 5.2 of García-Naranjo & Vermeeren (Sec. 5.2.1): measure preservation of Φ^(4)_h (E* = ℰ^(4)(z_0)
# of each point), harmonic potential U = (x² + y²)/2, h = 0.25, the five discretizations (5.1) and the
# exact flow. A 600-cell cloud of radius 0.01 around z_0 = (0, 0, 1, 1): relative volume V(t)/V(0) − 1 of
# its convex hull w.r.t. (a) μ = N⁻¹d⁴z, (b) μ^(2)_mod, (c) μ^(4)_mod (each method's own N^(k)_mod; the
# reference w.r.t. μ throughout); (d) the peak-to-peak over t ≤ ptp_window against the measure, with
# h^6 (Corollary 4.3: Φ^(4) preserves μ^(4)_mod to O(h^6)) and the paper's "≈ 2·10⁻⁴".
# The oscillations shrink from μ to μ^(2)_mod to μ^(4)_mod, down to the size of the convex-hull artefact
# that the exact flow shows as well.
# Input: volumes_phi4.csv, summary values, scene values (see figures/measure_cloud_volumes.gpi).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
ELL = 4
NAME = 'measure_cloud_fig52'
FIGNO = "5.2"
load 'figures/measure_cloud_volumes.gpi'

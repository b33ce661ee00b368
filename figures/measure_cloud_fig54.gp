# The volumes study's second figure (its item in the title: made_item('fig54')), after García-Naranjo &
# Vermeeren: the same experiment as measure_cloud_fig52.gp with Φ^(0)_h
# (E* = H(z_0) of each point: the method of the earlier literature), harmonic potential U = (x² + y²)/2,
# h = 0.25, the five discretizations (5.1) and the exact flow, on the authors' cloud (as in the published
# figure) and the full 600-cell cloud (the correction), radius 0.01 around z_0 = (0, 0, 1, 1): relative volume
# V(t)/V(0) − 1 of the convex hull w.r.t. μ, μ^(2)_mod and μ^(4)_mod; (g) peak-to-peak over t ≤ ptp_window against
# the measure. The oscillations are large and do not shrink with the order of the modified measure (Φ^(0)
# preserves none of them beyond O(h^2)).
# Input: volumes_phi0.csv, volumes_authors_phi0.csv, summary values, scene values (see figures/measure_cloud_volumes.gpi).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
ELL = 0
NAME = 'measure_cloud_fig54'
ITEM = 'fig54'
load 'figures/measure_cloud_volumes.gpi'

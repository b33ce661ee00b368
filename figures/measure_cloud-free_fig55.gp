# The energies study's first figure in the free scene (its item in the title: made_item('fig55')), after
# García-Naranjo & Vermeeren: the free nonholonomic particle (U = 0) with Φ^(4)_h
# (E* = ℰ^(4)(z_0)), h = 0.25, z_0 = (0, 0, 1, 1), the five discretizations (5.1): (a) H, (b) K_E = N(H − 1),
# (c) K^(4)_mod(z; E*), (d) the error ‖z_j − z_ref(t_j)‖_2 (log scale). K_E tends to 0 (N → 0 along the
# motion) and H hardly drifts.
# Input: energies_phi4.csv, summary values, scene values (see figures/measure_cloud_energies.gpi).
if (!exists("results")) results = 'results/measure_cloud-free'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
ELL = 4
POT = "free"
LAST = "err"
NAME = 'measure_cloud-free_fig55'
ITEM = 'fig55'
load 'figures/measure_cloud_energies.gpi'

# The energies study's second figure in the free scene (its item in the title: made_item('fig56')), after
# García-Naranjo & Vermeeren: as measure_cloud-free_fig55.gp with Φ^(0)_h (E* = H(z_0) = 1, the method of
# the earlier literature): the free nonholonomic particle (U = 0), h = 0.25, z_0 = (0, 0, 1, 1), the five
# discretizations (5.1): (a) H, (b) K_E = N(H − 1), (c) K^(4)_mod(z; 1), (d) the error ‖z_j − z_ref(t_j)‖_2
# (log scale). K_E tends to the nonzero value of K^(4)_mod; as N → 0, H − 1 grows: H drifts.
# Input: energies_phi0.csv, summary values, scene values (see figures/measure_cloud_energies.gpi).
if (!exists("results")) results = 'results/measure_cloud-free'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
ELL = 0
POT = "free"
LAST = "err"
NAME = 'measure_cloud-free_fig56'
ITEM = 'fig56'
load 'figures/measure_cloud_energies.gpi'

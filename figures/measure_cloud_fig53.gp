# The energies study's figure (its item in the title: made_item('fig53')), after García-Naranjo & Vermeeren:
# energy functions along Φ^(4)_h (E* = ℰ^(4)(z_0)),
# harmonic potential U = (x² + y²)/2, h = 0.25, z_0 = (0, 0, 1, 1), the five discretizations (5.1):
# (a) H, (b) K_E = N(H − 1), (c) K^(4)_mod(z; E*) (O(h^6)), (d) ℰ^(4)(z_j) − ℰ^(4)(z_0) (the paper plots
# ℰ^(4) itself; its values E* are in the key).
# Input: energies_phi4.csv, summary values, scene values (see figures/measure_cloud_energies.gpi).
if (!exists("results")) results = 'results/measure_cloud'
load 'figures/common.gp'
load 'figures/measure_cloud_style.gpi'
ELL = 4
POT = "harmonic"
LAST = "E4"
NAME = 'measure_cloud_fig53'
ITEM = 'fig53'
load 'figures/measure_cloud_energies.gpi'

# The convergence study's figure (its item in the title: made_by('convergence')), after Takács & Fülöp (2025):
# convergence of Störmer–Verlet (26)–(28) and of the
# Rowlands method (kernel (31) with processors) on the planar elastic pendulum in Cartesian
# coordinates (App. A): energy error, eq. (50), against h (left); phase-space error at t_max (right).
# Besides the paper's two methods: the cheap processors (34)–(37), the kernel without processing,
# the processors (32)–(33) with the coefficient h²/24 as printed (which give only order 2), and
# Forest–Ruth, the standard fourth-order composition of three Störmer–Verlet steps (3 force
# evaluations per step), the order-4 peer of the processed method. The methods are those of the
# CSV (the scene's `methods`, by registry label), in the scene's order.
# Dashed lines: least-squares fits from orders.csv, drawn over the h range they were fitted on.
# Input: fig4_convergence.csv, orders.csv (the rows of initial condition `ic`, default 0, the one
# the paper scene draws), scene values (pendulum parameters, initial condition and t_end, for the title;
# observables, the panels), summary values (methods.convergence: the methods of the CSV, by label).
if (!exists("results")) results = 'results/rowlands_convergence'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
if (!exists("ic")) ic = 0
CONV_NAME = 'rowlands_convergence_fig4'
CONV_CSV = 'fig4_convergence.csv'
CONV_INITIAL = ic
CONV_PAPER = "000"
CONV_KEY_WIDTH = -6    # (the long key texts of the processors)
METHODS = summary_words('methods.convergence')
# the panels: the observables the scene named (energy_error: fits *_energy of the *_energy_rms columns;
# phase_error: *_phase)
HAS_ENERGY = in_list(scene_words('observables'), 'energy_error')
HAS_PHASE = in_list(scene_words('observables'), 'phase_error')
CONV_QUANTITIES = (HAS_ENERGY ? "energy " : "") . (HAS_PHASE ? "phase" : "")
CONV_COLUMNS = (HAS_ENERGY ? "energy_rms " : "") . (HAS_PHASE ? "phase" : "")
CONV_PANEL_TITLES = (HAS_ENERGY ? "'energy error, eq. (50)' " : "") . (HAS_PHASE ? "'phase-space error at t_{max}'" : "")
CONV_YLABEL(q) = q eq "energy" ? "(J^{−1} Σ_{j=0}^{J} (H(q^j, p^j) − H_0)^2)^{1/2}" : "|z^N − z(t_{max})|_2,  z = (x, y, p_x, p_y)"

PARAMS = sprintf("l = %s, m = %s, k = %s, g = %s, t_{max} = %s", scene_num('pendulum.l'), scene_num('pendulum.m'), \
                 scene_num('pendulum.k'), scene_num('pendulum.g'), scene_num('t_end'))
Z0 = sprintf("initial condition (x, y, p_x, p_y) = (%s, %s, %s, %s)", scene_num(sprintf('initial.%d.0', ic)), \
             scene_num(sprintf('initial.%d.1', ic)), scene_num(sprintf('initial.%d.2', ic)), scene_num(sprintf('initial.%d.3', ic)))
SEP = words(CONV_QUANTITIES) == 1 ? "\n" : " "   # (the title in more lines on one panel)
CONV_TITLE = "{/:Bold " . made_by('convergence') . ":} " . sprintf("planar elastic pendulum, Cartesian coordinates:%s%s\n%s;%sdashed lines: least-squares fits over the h range fitted", \
                     SEP, PARAMS, Z0, SEP)
load 'figures/convergence.gpi'

# The convergence study's figure (its item in the title: made_by('convergence')), after Takács & Fülöp (2025),
# App. B: convergence of the energy error of the methods the scene
# names on the harmonic oscillator (the paper's: symplectic Euler without and with the compensating
# transformation (82), RK4 for reference; left), global error of explicit Euler on eqs. (14) and (17)
# (right). Dashed lines: least-squares fits from orders.csv, drawn over the h range they were fitted on.
# Input: fig9_convergence.csv, orders.csv, scene values (convergence.t_end), summary values
# (methods.convergence: the left panel's methods; methods.convergence_scalar: the right panel's).
load 'figures/common.gp'
CONV_NAME = 'euler_compensation_fig9'
CONV_CSV = 'fig9_convergence.csv'
CONV_PAPER = "000"
METHODS = summary_words('methods.convergence')
CONV_QUANTITIES = "energy"                    # fits <method>_energy of the columns <method>_max
CONV_COLUMNS = "max"
CONV_YLABEL(q) = "max_{t_j ∈ [0,T]} |H(q_j, p_j) − H_0|"
# right: the study's explicit Euler on (14) and (17), columns <method>_decay_max, <method>_gompertz_max
CONV2_METHODS = summary_words('methods.convergence_scalar')
CONV2_QUANTITIES = "decay gompertz"
CONV2_COLUMNS = "decay_max gompertz_max"
CONV2_KEYS = "'ẏ = −αy' 'Gompertz'"
CONV2_YLABEL = "max_{t_j ∈ [0,T]} |y_j − y(t_j)|"
CONV2_NOTE = "Euler in ȳ: exact up to round-off (not shown)"
CONV_PANEL_TITLES = "'harmonic oscillator' 'explicit Euler in y (Figs 2, 3)'"
CONV_TITLE = "{/:Bold " . made_by('convergence') . ":} " . sprintf("convergence in h, errors as maxima over the steps t_j ∈ [0, T], T = %s; dashed: least-squares fits", \
                     scene_num('convergence.t_end'))
load 'figures/convergence.gpi'

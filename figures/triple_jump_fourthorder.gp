# 005 (Yoshida 1990): the triple jump S(x1 h) S(x0 h) S(x1 h) of Störmer–Verlet is of fourth order. The
# largest energy error over [0, T] on the quartic oscillator against h, with the fitted orders.
# Input: order.csv, orders.csv, scene values (order.q0, order.p0, order.t_end), summary values (methods.order).
load 'figures/common.gp'
CONV_NAME = 'triple_jump_fourthorder'
CONV_CSV = 'order.csv'
CONV_QUANTITIES = "energy"
CONV_YLABEL(q) = "max_{t_j ∈ [0,T]} |H(q_j, p_j) − H_0|"
METHODS = summary_words('methods.order')
CONV_TITLE = "{/:Bold " . made_by('order') . ":} " . sprintf("quartic oscillator H = p^2/2 + q^4/4, (q_0, p_0) = (%s, %s),\nerrors as maxima over the steps t_j ∈ [0, T], T = %s; dashed: least-squares fits", \
                     scene_num('order.q0'), scene_num('order.p0'), scene_num('order.t_end'))
load 'figures/convergence.gpi'

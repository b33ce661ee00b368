# What an energy error of the map study's figure (energy_map_fig6.gp) costs in either coordinate system
# (work-precision), beyond the paper: the energy error ε of eq. (50) over [0, t_end] of symplectic
# Euler (42)–(43) on the elastic pendulum, from a few starts (x0, y0) at rest of the map (scene key
# cost.starts), at the steps cost.dt, in Cartesian (73) and polar (72) coordinates, against the wall
# time of one run (left; the scalar loop energy_map_scalar in both systems, single thread, a start's
# share of one timed function per system and step) and the number of force evaluations of one run
# (right; one gradient of U per step in either system). One row per start: the work-precision set
# start_<i> of the cost study (figures/cost.gpi). Colours as in energy_map_fig6.gp (blue Cartesian, red polar: the
# method, symplectic Euler, is the same: the first coordinate system of the run blue, the second red). The reference is H_0 = H(z_0), conserved by the flow; its
# own error is the round-off of evaluating H (summary value work_precision.reference_error_max).
# Input: cost_start_<i>.csv (one per start: method = coordinate system, h, steps, wall_s, wall_q1_s,
# wall_q3_s, wall_spread, wall_timed, force_evals, err = ε); scene values (cost.t_end, cost.starts, pendulum, timing.repeats);
# summary values (work_precision: start_count, dt_range, reference_error_max, labels; cost.start_0.methods).
if (!exists("results")) results = 'results/energy_map'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
eval need_num('T_END', scene_num('cost.t_end'))
eval need_num('REF_ERR', summary_real('work_precision.reference_error_max'))
eval need_num('NSTARTS', summary_num('work_precision.start_count'))
eval need_num('H_MAX', summary_num('work_precision.dt_range.max'))
eval need_num('H_MIN', summary_num('work_precision.dt_range.min'))
set style line 201 lc rgb '#2166ac' lw 1.0 pt 7 ps 0.6            # energy_map_fig6.gp's blue
set style line 202 lc rgb '#b2182b' lw 1.0 dt (5,3) pt 6 ps 0.7   # energy_map_fig6.gp's red
METHODS = summary_words('cost.start_0.methods')
COST_OWN_STYLES = 1   # (its curves are coordinate systems, not registry methods: named by the run)
LABEL(m) = summary_words('work_precision.labels.' . m)
STYLE(m) = 200 + word_index(METHODS, m)
start_x(i) = scene_num(sprintf('cost.starts.%d.0', i))
start_y(i) = scene_num(sprintf('cost.starts.%d.1', i))
COST_SETS = ""
do for [i = 0:NSTARTS - 1] { COST_SETS = COST_SETS . sprintf(" start_%d", i) }
# the start of a set start_<i>, in its row's y label
set_start(cs) = int(cs[7:])
COST_YLABEL(cs) = sprintf("ε from (x_0, y_0) = (%s, %s)", start_x(set_start(cs)), start_y(set_start(cs)))
COST_NAME = 'energy_map_cost'
COST_TITLE = sprintf("{/:Bold Cost:} energy error (50) of symplectic Euler, elastic pendulum, g = %s, one row per start at rest; h = %g … %g, t_{end} = %g\n" \
                     . "wall time: scalar loop, median of %s interleaved runs of ≥ 20 ms, single thread; reference H_0 = H(z_0), its own error ≤ %s", \
                     scene_num('pendulum.g'), H_MAX, H_MIN, T_END, scene_num('timing.repeats'), sci(REF_ERR))
COST_EVALS = "force evaluations in one run (one gradient of U per step)"
load 'figures/cost.gpi'

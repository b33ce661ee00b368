# Fig. 1 of 004 (the simplified Takahashi–Imada method), Sect. 1.4: the harmonic oscillator
# H = (p² + ω²q²)/2 with ω = 1 and the start q_0 = 0, p_0 = 1 (fixed in experiments/ti_drift/oscillator.cpp;
# the closed forms hold only for q_0 = 0), against the effective step ω h_eff at equal work: a method
# with e force evaluations per step (gradient, force or Hessian-vector product) runs at h = e h_eff/2:
# h = h_eff for the Takahashi–Imada methods (e = 2), h_eff/2 for Störmer–Verlet (e = 1), 3h_eff/2 for
# Forest–Ruth (e = 3, the standard fourth-order composition; not in 004).
#   left:  max over t ≤ t_ω/ω of the scaled global error (|ε_p|² + ω²|ε_q|²)^{1/2}
#   right: max over the same span of |H_n − H_0| / H_0, with the closed forms of Sect. 1.4 as lines
# TI and the simplified TI are processed (start χ_h^{-1}, output χ_h); on the oscillator the two
# methods coincide. Vertical lines: the stability bounds in ω h_eff (summary values: equal_work, and
# TI's bisected 2√3). The methods are those of oscillator.csv (the scene's oscillator.methods).
# Left, dashed: the least-squares lines whose slopes are summary values's orders, drawn over the
# points they were fitted on (as in experiments/ti_drift/oscillator.cpp: ω h_eff ≤ 0.5, error above 10^3 ε).
# Right: the fitted orders in the key only (their lines would hide under the closed forms).
# Input: oscillator.csv, oscillator_closed_forms.csv; summary values (the methods, orders, stability bounds, force
# evaluations per step); scene values (oscillator.t_omega).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
OSC = csv('oscillator.csv')
CF  = csv('oscillator_closed_forms.csv')

eval need_num('T_OMEGA', scene_real('oscillator.t_omega'))
eval need_num('TI_BOUND', summary_real('reproduced.ti_stability_bound'))
FIT_XMAX = 0.5       # the fits of oscillator.cpp: ω h_eff ≤ 0.5 ...
FIT_FLOOR = 1e3 * 2.0**-52   # ... and error above the round-off floor 10^3 ε

# the methods of oscillator.csv (registry labels, summary value equal_work.methods), in the key's order;
# the fitted lines of all but the simplified TI (it coincides with TI on the oscillator)
CSV_METHODS = summary_words('equal_work.methods')
if (CSV_METHODS eq "") { exit error "equal_work.methods: missing from ".results."/figure_values.gp" }
PREFERRED = "sv ti sti forest_ruth"
eval ORDER_METHODS
FITTED = ""
do for [m in METHODS] { if (m ne "sti") { FITTED = FITTED.m." " } }
do for [m in METHODS] {
    do for [q in "solution energy"] { eval need_num('ORD_'.m.'_'.q, summary_real('orders.'.m.'_'.q)) }
    eval need_num('EVALS_'.m, summary_real('equal_work.evals_per_step.'.m))
    eval need_num('BOUND_'.m, summary_real('equal_work.omega_h_eff_bound.'.m))
}
eval method_styles(METHODS)   # (figures/common.gp: colours and markers from the registry)
SHORT(m) = method_title(m)
NAME(m) = method_key(m, "004")
STEP(m) = (_e = value('EVALS_'.m)) == 2 ? "h = h_{eff}" : _e == 1 ? "h = h_{eff}/2" : sprintf("h = %gh_{eff}/2", _e)
LEFT(m) = m eq "sti" ? NAME(m) : sprintf("%s, %s: order %.2f", NAME(m), STEP(m), value('ORD_'.m.'_solution'))
RIGHT(m) = m eq "sti" ? SHORT(m) : sprintf("%s: order %.2f", SHORT(m), value('ORD_'.m.'_energy'))
EQUAL_WORK = ""
do for [m in METHODS] { EQUAL_WORK = EQUAL_WORK.(EQUAL_WORK eq "" ? "" : ", ").sprintf("%s %g", SHORT(m), value('EVALS_'.m)) }
SV_BOUND = exists("BOUND_sv") ? BOUND_sv : 0   # (the x range reaches past SV's bound)

sel(m, col) = strcol("method") eq m ? column(col) : NaN
infit(m, col) = (strcol("method") eq m && column("omega_h") <= FIT_XMAX && column(col) > FIT_FLOOR) ? 1 : 0
# the least-squares line of log10(err) on log10(ω h_eff) with the fitted slope passes through the centroid
do for [m in FITTED] {
    do for [q in "solution"] {
        col = q eq "solution" ? "max_global_err" : "max_rel_H_err"
        stats OSC using (infit(m, col) ? log10(column("omega_h")) : NaN):(infit(m, col) ? log10(column(col)) : NaN) nooutput
        eval sprintf("XB_%s_%s = STATS_mean_x; YB_%s_%s = STATS_mean_y; X0_%s_%s = 10**STATS_min_x; X1_%s_%s = 10**STATS_max_x", \
                     m, q, m, q, m, q, m, q)
    }
}
fitline(m, q, x) = 10**(value(sprintf("YB_%s_%s", m, q)) + value(sprintf("ORD_%s_%s", m, q)) * (log10(x) - value(sprintf("XB_%s_%s", m, q))))
fitx(m, q, t) = value(sprintf("X0_%s_%s", m, q)) * (value(sprintf("X1_%s_%s", m, q)) / value(sprintf("X0_%s_%s", m, q)))**t

stats OSC using "omega_h" nooutput
XMIN = STATS_min / 1.5
XMAX = (STATS_max > SV_BOUND ? STATS_max : SV_BOUND) * 1.25

do for [fmt in FORMATS] {
    eval term(fmt, 'ti_drift_fig1', 17, 12.5)
    set multiplot layout 1,2 title sprintf("{/:Bold Fig. 1:} harmonic oscillator, ω = 1, (q_0, p_0) = (0, 1), maxima over t ≤ %g/ω\n" \
        . "TI and the simplified TI processed; equal work: h = e h_{eff}/2 for e force evaluations per step\n" \
        . "(%s); left, dashed: fits over ωh_{eff} ≤ %g; vertical lines: stability bounds", \
        T_OMEGA, EQUAL_WORK, FIT_XMAX) font ",9"
    set logscale xy
    set xrange [XMIN:XMAX]
    set format x "%g"
    eval LOGTICS("1 2 5")
    set format y LOGFMT
    set xlabel "effective step size ω h_{eff}"
    set key outside below center vertical Left reverse samplen 3 width -3 font ",8"
    # stability bounds in ω h_eff: TI's bisected 2√3 (the simplified TI's is the same), the others' from the registry
    _a = 0
    do for [m in METHODS] {
        if (m ne "sti") {
            _a = _a + 1
            _x = m eq "ti" ? TI_BOUND : value('BOUND_'.m)
            _text = m eq "ti" ? sprintf("TI: 2√3 = %.4f", TI_BOUND) : sprintf("%s: ωh_{eff} = %.4g", SHORT(m), _x)
            eval sprintf("set arrow %d from %.17g, graph 0 to %.17g, graph 1 nohead lc rgb '%s' lw 0.8 dt %s", \
                         _a, _x, _x, method_colour(m), m eq "ti" ? "1" : "(6,3)")
            eval sprintf("set label %d \"%s\" at %.17g, graph 0.03 left rotate by 90 offset %s, 0 font \",7\" tc rgb '%s'", \
                         _a, _text, _x, m eq "ti" ? "-0.4" : "0.9", method_colour(m))
        }
    }
    set bmargin 9.5   # (the same for both panels, room for the longer key, so that the axes line up)
    set tmargin 5

    set title "(left) global error, maximum over the run"
    set ylabel "max_n (|ε_p|^2 + ω^2 |ε_q|^2)^{1/2}"
    plot for [m in METHODS] OSC using "omega_h":(sel(m, "max_global_err")) with points ls method_ls(m) title LEFT(m), \
         for [m in FITTED] [t=0:1:1] '+' using (fitx(m, "solution", t)):(fitline(m, "solution", fitx(m, "solution", t))) \
                with lines ls method_fit_ls(m) notitle

    set title "(right) relative energy error, maximum over the run"
    set ylabel "max_n |H(p_n, q_n) − H_0| / H_0   (TI: H(p̂_n, q̂_n))"
    plot for [m in METHODS] OSC using "omega_h":(sel(m, "max_rel_H_err")) with points ls method_ls(m) title RIGHT(m), \
         CF using "omega_h":"sv_rel_H" with lines lc rgb C_SV lw 0.8 title "SV, closed form y^2/(16 − y^2),  y = ωh_{eff}", \
         CF using "omega_h":"ti_rel_H" with lines lc rgb C_TI lw 0.8 title "TI, closed form y^6/(36 (y^4 − 12y^2 + 48))"
    unset multiplot
    unset output
}

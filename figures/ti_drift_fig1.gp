# The oscillator study's figure (its item in the title: made_by('oscillator')), after the paper on the
# simplified Takahashi–Imada method: the harmonic oscillator
# H = (p² + ω²q²)/2 with ω = 1 and the start q_0 = 0, p_0 = 1 (fixed in experiments/ti_drift/oscillator.cpp;
# the closed forms hold only for q_0 = 0), against the effective step ω h_eff at equal work: a method
# with e force evaluations per step (gradient, force or Hessian-vector product) runs at h = e h_eff/2:
# h = h_eff for the Takahashi–Imada methods (e = 2), h_eff/2 for Störmer–Verlet (e = 1), 3h_eff/2 for
# Forest–Ruth (e = 3, the standard fourth-order composition; not in 004). An order figure (figures/convergence.gpi):
#   left:  max over t ≤ t_ω/ω of the scaled global error (|ε_p|² + ω²|ε_q|²)^{1/2} (<method>_solution),
#          dashed: the least-squares fits of orders.csv (ω h_eff ≤ 0.5, error above round-off)
#   right: max over the same span of |H_n − H_0| / H_0 (<method>_energy), with the closed forms of Sect. 1.4
#          as lines; the fitted orders in the key only (their lines would hide under the closed forms)
# TI and the simplified TI are processed (start χ_h^{-1}, output χ_h); on the oscillator the two
# methods coincide. Vertical lines: the stability bounds in ω h_eff (summary values: equal_work, and
# TI's bisected 2√3). The methods are those of oscillator.csv (the scene's oscillator.methods).
# Input: oscillator.csv, orders.csv, oscillator_closed_forms.csv; summary values (the methods, stability bounds,
# force evaluations per step); scene values (oscillator.t_omega).
if (!exists("results")) results = 'results/ti_drift'
load 'figures/common.gp'
set encoding utf8    # (so that the key width counts characters, not bytes)
CONV_NAME = 'ti_drift_fig1'
CONV_CSV = 'oscillator.csv'
CONV_QUANTITIES = "solution energy"
CONV_PAPER = "004"
CONV_XLABEL = "effective step size ω h_{eff}"
CONV_YLABEL(q) = q eq "solution" ? "max_n (|ε_p|^2 + ω^2 |ε_q|^2)^{1/2}" : "max_n |H(p_n, q_n) − H_0| / H_0   (TI: H(p̂_n, q̂_n))"

eval need_num('T_OMEGA', scene_real('oscillator.t_omega'))
eval need_num('TI_BOUND', summary_real('reproduced.ti_stability_bound'))
eval need_num('FIT_MAX', summary_real('oscillator.fit.max_omega_h'))   # the fits' window in ω h_eff
# the methods of oscillator.csv (registry labels, summary value equal_work.methods), in the key's order
CSV_METHODS = summary_words('equal_work.methods')
if (CSV_METHODS eq "") { exit error "equal_work.methods: missing from ".results."/figure_values.gp" }
PREFERRED = "sv ti sti forest_ruth"
eval ORDER_METHODS
do for [m in METHODS] {
    eval need_num('EVALS_'.m, summary_real('equal_work.evals_per_step.'.m))
    eval need_num('BOUND_'.m, summary_real('equal_work.omega_h_eff_bound.'.m))
}
EQUAL_WORK = ""
do for [m in METHODS] { EQUAL_WORK = EQUAL_WORK.(EQUAL_WORK eq "" ? "" : ", ").sprintf("%s %g", method_title(m), value('EVALS_'.m)) }

CONV_FIT_LINES = ""   # the left panel's fits, but the simplified TI's (it coincides with TI's on the oscillator)
do for [m in METHODS] { if (m ne "sti") { CONV_FIT_LINES = CONV_FIT_LINES.m.'_solution ' } }
# the closed forms of Sect. 1.4, right: the columns <m>_rel_H of the methods m of summary
# methods.oscillator_closed_forms, in that order; CF_FORM(k, y) and word(CF_TEXTS, k) the k-th's formula in
# y = ωh_eff (Störmer–Verlet's, then Takahashi–Imada's), checked against its column below
CONV_CURVES_CSV = 'oscillator_closed_forms.csv'
CONV_CURVES_X = "omega_h"
CF_METHODS = summary_words('methods.oscillator_closed_forms')
if (words(CF_METHODS) != 2) {
    exit error "methods.oscillator_closed_forms: not two methods in ".results."/figure_values.gp"
}
CF_FORM(k, y) = k == 1 ? y**2 / (16 - y**2) : y**6 / (36 * (y**4 - 12 * y**2 + 48))
CF_TEXTS = "'y^2/(16 − y^2),  y = ωh_{eff}' 'y^6/(36 (y^4 − 12y^2 + 48))'"
cf_dev(k) = (_c = column(word(CF_METHODS, k).'_rel_H'), _c == _c ? abs(_c / CF_FORM(k, column("omega_h")) - 1) : NaN)
do for [k = 1:2] {
    stats csv(CONV_CURVES_CSV) using (cf_dev(k)) nooutput
    if (STATS_max > 1e-9) {
        exit error sprintf("oscillator_closed_forms.csv: %s_rel_H is not %s", word(CF_METHODS, k), word(CF_TEXTS, k))
    }
}
CF_CURVES = ""; do for [m in CF_METHODS] { CF_CURVES = CF_CURVES . m . "_rel_H " }
cf_method(c) = c[1:strlen(c) - strlen("_rel_H")]   # (the method of column c)
CONV_CURVES(q) = q eq "energy" ? CF_CURVES : ""
CONV_CURVE_COLOUR(c) = method_colour(cf_method(c))
CONV_CURVE_TITLE(c) = method_title(cf_method(c)) . ", closed form " \
                    . word(CF_TEXTS, word_index(CF_METHODS, cf_method(c)))
CONV_TITLE = "{/:Bold " . made_by('oscillator') . ":} " . sprintf("harmonic oscillator, ω = 1, (q_0, p_0) = (0, 1), maxima over t ≤ %g/ω; TI and the simplified TI processed\n" \
    . "equal work: h = e h_{eff}/2 for e force evaluations per step (%s)\n" \
    . "left, dashed: least-squares fits (ωh_{eff} ≤ %g, above round-off); vertical lines: stability bounds", T_OMEGA, EQUAL_WORK, FIT_MAX)

# stability bounds in ω h_eff: TI's bisected 2√3 (the simplified TI's is the same), the others' from the registry
_a = 0
do for [m in METHODS] {
    if (m ne "sti") {
        _a = _a + 1
        _x = m eq "ti" ? TI_BOUND : value('BOUND_'.m)
        _text = m eq "ti" ? sprintf("%s: 2√3 = %.4f", method_title(m), TI_BOUND) : sprintf("%s: ωh_{eff} = %.4g", method_title(m), _x)
        eval sprintf("set arrow %d from %.17g, graph 0 to %.17g, graph 1 nohead lc rgb '%s' lw 0.8 dt %s", \
                     _a, _x, _x, method_colour(m), m eq "ti" ? "1" : "(6,3)")
        eval sprintf("set label %d \"%s\" at %.17g, graph 0.03 left rotate by 90 offset %s, 0 font \",7\" tc rgb '%s'", \
                     _a, _text, _x, m eq "ti" ? "-0.4" : "0.9", method_colour(m))
    }
}
set key font ",8" width -3   # (kept by convergence.gpi's set key)
load 'figures/convergence.gpi'

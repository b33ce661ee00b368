# The oscillator study's figure (its item in the title: made_by('oscillator')), after Takács & Fülöp (2025),
# App. B: phase portrait of symplectic Euler on the harmonic
# oscillator H = (p^2 + q^2)/2 (eq. 74), without and with the compensating transformation (82).
# Input: fig8_phase.csv (steps of both runs), fig8_exact.csv (exact circle), summary values (methods.oscillator:
# the methods of the columns q_se, p_se, then of q_compensated, p_compensated).
load 'figures/common.gp'
PHASE = csv('fig8_phase.csv')
EXACT = csv('fig8_exact.csv')
stats PHASE using (column("j") == 1 ? column("t") : NaN) nooutput
h = STATS_max
stats PHASE using "j" nooutput
steps = STATS_max
METHODS = summary_words('methods.oscillator')   # the two runs' methods, as the run names them
if (words(METHODS) != 2) { exit error "methods.oscillator: not two methods in ".results."/figure_values.gp" }
eval method_styles(METHODS)
M_SE = word(METHODS, 1); M_COMP = word(METHODS, 2)   # (columns *_se; *_compensated)

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig8', 11, 11.5)
    set title "{/:Bold " . made_by('oscillator') . ":} " \
        . sprintf("%s on the harmonic oscillator, h = %g, %d steps", method_title(M_SE), h, steps)
    set size ratio -1
    set xlabel "q"
    set ylabel "p"
    set xrange [-1.25:1.25]
    set yrange [-1.25:1.25]
    set xtics 0.5
    set ytics 0.5
    set key at graph 0.5, graph 0.5 center center samplen 1.5
    # every step as a small dot (the method's marker); keyentry shows the markers at a readable size
    plot PHASE using "q_se":"p_se"                   with points ls method_ls(M_SE)   ps 0.2 notitle, \
         PHASE using "q_compensated":"p_compensated" with points ls method_ls(M_COMP) ps 0.2 notitle, \
         EXACT using "q":"p"                         with lines  ls LS_EXACT lw 0.8 title "exact: q^2 + p^2 = 1", \
         keyentry with points ls method_ls(M_SE)   title method_key(M_SE, "000"), \
         keyentry with points ls method_ls(M_COMP) title method_key(M_COMP, "000")
    unset output
}

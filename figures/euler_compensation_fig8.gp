# Fig. 8 of Takács & Fülöp (2025), App. B: phase portrait of symplectic Euler on the harmonic
# oscillator H = (p^2 + q^2)/2 (eq. 74), without and with the compensating transformation (82).
# Input: fig8_phase.csv (steps of both runs), fig8_exact.csv (exact circle).
load 'figures/common.gp'
PHASE = csv('fig8_phase.csv')
EXACT = csv('fig8_exact.csv')
stats PHASE using (column("j") == 1 ? column("t") : NaN) nooutput
h = STATS_max
stats PHASE using "j" nooutput
steps = STATS_max

do for [fmt in FORMATS] {
    eval term(fmt, 'euler_compensation_fig8', 11, 11.5)
    set title "{/:Bold " . made_by('oscillator') . ":} " . sprintf("symplectic Euler on the harmonic oscillator, h = %g, %d steps", h, steps)
    set size ratio -1
    set xlabel "q"
    set ylabel "p"
    set xrange [-1.25:1.25]
    set yrange [-1.25:1.25]
    set xtics 0.5
    set ytics 0.5
    set key at graph 0.5, graph 0.5 center center samplen 1.5
    # every step as a small dot; keyentry shows the markers at a readable size
    plot PHASE using "q_se":"p_se"                   with points ls LS_SE   pt 7 ps 0.2 notitle, \
         PHASE using "q_compensated":"p_compensated" with points ls LS_COMP pt 7 ps 0.2 notitle, \
         EXACT using "q":"p"                         with lines  ls LS_EXACT lw 0.8 title "exact: q^2 + p^2 = 1", \
         keyentry with points ls LS_SE   pt 7 title "symplectic Euler", \
         keyentry with points ls LS_COMP pt 7 title "symplectic Euler with transformation (82)"
    unset output
}

# The map study's figure (its item in the title: made_by('map')), after Takács & Fülöp (2025): difference of
# the energy errors, eq. (50), of
# symplectic Euler on the planar elastic pendulum (App. A) in Cartesian and in polar coordinates,
# ε_(x,y) − ε_(r,φ), over the initial positions (x0, y0) with p(0) = 0. Blue: Cartesian better,
# red: polar better. The colour scale is a signed logarithm, asinh(Δε / ε_lin) (|Δε| spans several
# decades; ε_lin, a power of ten near the lower quartile of |Δε|, is where it turns from linear to
# logarithmic), over the range of the data, white at 0, each side's darkest colour at its extreme. Dark gray: a run diverged (polar, Cartesian or both).
# Gray: isolines of H_0 = H(x0, y0, 0, 0); white dashed: the analytic boundary of the initial
# conditions for which the polar run passes through r = 0, r = 2l + (2mg/k) cos θ (θ from +y),
# which is the isoline H_0 = kl²/2 (the energy at r = 0).
# The y axis points down (gravity along +y, eq. (73)); it is drawn downwards, so that the
# pendulum hangs down in the picture.
# The counts of the map (which run is better, which diverged) are in the caption of the report's
# figure, from summary.json (map_statistics).
# Input: map.csv, map_grid.csv (x0, y0, H0 in grid scans, for the isolines), summary values (grid
# size), scene values (grid extent, pendulum, dt, t_max).
if (!exists("results")) results = 'results/energy_map'
load 'figures/common.gp'
set encoding utf8
MAP = csv('map.csv')
eval columns('MAP', MAP)               # (map.csv is large and read several times: its columns by number)

# ---- parameters: from scene values (scene) and summary values; none has a default here ----
eval need_num('NX', summary_num('grid.nx'))
eval need_num('NY', summary_num('grid.ny'))
eval need_num('XMIN', scene_num('grid.x_min'));  eval need_num('XMAX', scene_num('grid.x_max'))
eval need_num('YMIN', scene_num('grid.y_min'));  eval need_num('YMAX', scene_num('grid.y_max'))
eval need_num('L', scene_num('pendulum.l'));     eval need_num('M', scene_num('pendulum.m'))
eval need_num('K', scene_num('pendulum.k'));     eval need_num('G', scene_num('pendulum.g'))
eval need_num('DT', scene_num('dt'));            eval need_num('TMAX', scene_num('t_max'))
eval need_num('DMIN', summary_num('map_statistics.eps_difference.min'))   # range of Δε over the map
eval need_num('DMAX', summary_num('map_statistics.eps_difference.max'))
DX = (XMAX - XMIN) / (NX - 1.0)
DY = (YMAX - YMIN) / (NY - 1.0)

# ---- analytic boundary of the polar runs through r = 0 (Takács & Fülöp, Section 4.1) ----
rb(t) = 2 * L + 2 * M * G / K * cos(t)                # θ = t from +y: x = r sin θ, y = r cos θ

# ---- the data ----------------------------------------------------------------
diff(c, p) = column(c) - column(p)                     # NaN if either run diverged
DEPS = 'diff(MAP_eps_cartesian, MAP_eps_polar)'
diverged = '(column(MAP_diverged_cartesian) != 0 || column(MAP_diverged_polar) != 0)'
stats MAP skip 1 using (abs(@DEPS)) nooutput
ADMAX = STATS_max
EPS_LIN = 10.0**floor(log10(STATS_lo_quartile))       # linear part of the colour scale
stats MAP skip 1 using MAP_x0 nooutput
N_ALL = STATS_records
stats MAP skip 1 using MAP_H0 nooutput
HMIN = STATS_min
HMAX = STATS_max
if (N_ALL != NX * NY) { exit error sprintf("map.csv has %d rows, the grid %d x %d", N_ALL, NX, NY) }

# colour = asinh(Δε / ε_lin), over the range of the finite differences (0 inside it)
sl(d) = asinh(d / EPS_LIN)
CBMIN = sl(DMIN < 0 ? DMIN : -EPS_LIN)
CBMAX = sl(DMAX > 0 ? DMAX : EPS_LIN)
DECADE_LO = floor(log10(EPS_LIN) + 0.5)
DECADE_HI = floor(log10(ADMAX))

# ---- H_0 isolines: contour the H0 column of map_grid.csv (the rows of map.csv, x fastest, with
# a blank line after every NX rows: the grid scans splot needs) ------------------------
H_STEP = 0.1
HLEVELS = sprintf("%g", (kl2 = 0.5 * K * L**2))       # the isoline H_0 = kl²/2 and a step H_STEP
do for [i = -20:20] { h = kl2 + i * H_STEP; if (i != 0 && h > HMIN && h < HMAX) { HLEVELS = HLEVELS . sprintf(", %g", h) } }
MAPGRID = csv('map_grid.csv')
eval columns('MAPGRID', MAPGRID)
set contour base
unset surface
eval "set cntrparam linear levels discrete " . HLEVELS
set table $HISO0
splot MAPGRID skip 1 using MAPGRID_x0:MAPGRID_y0:MAPGRID_H0 with lines notitle
unset table
set print $HISO          # (the table is written with blanks between columns: rewrite with commas)
do for [i = 1:|$HISO0|] {
    s = $HISO0[i]
    if (words(s) >= 2 && strstrt(s, "#") == 0) { print word(s, 1) . "," . word(s, 2) } else { print "" }
}
unset print
unset contour
set surface


# ---- colours -----------------------------------------------------------------
C_DIV  = '#3a3a3a'     # diverged
C_HISO = '#8c8c8c'     # H_0 isolines
# diverging blue – white – red (ColorBrewer RdBu), white at 0, each side scaled to its extreme
B = -CBMIN; R = CBMAX
set palette defined (-B '#053061', -0.75*B '#2166ac', -0.5*B '#4393c3', -0.25*B '#92c5de', -0.08*B '#d1e5f0', \
                      0 '#f7f7f7', 0.08*R '#fddbc7', 0.25*R '#f4a582', 0.5*R '#d6604d', 0.75*R '#b2182b', R '#67001f')
set palette maxcolors 0

set cbrange [CBMIN:CBMAX]
set cbtics () scale 0.5
set cbtics add ("0" 0)
do for [k = DECADE_LO:DECADE_HI] {
    set cbtics add (sprintf("10^{%d}", k) sl(10.0**k), sprintf("−10^{%d}", k) sl(-10.0**k))
}
set mcbtics
set cblabel sprintf("ε_{(x,y)} − ε_{(r,φ)}   (signed log scale, linear for |·| < 10^{%d})", DECADE_LO) offset 0.5,0
# the square plot: S cm a side on a W × H cm canvas
W = 17.0; H = 15.4; S = 11.0
PL = 0.115; PT = 1 - 1.45 / H; PR = PL + S / W; PB = PT - S / H
set colorbox user origin screen PR + 0.045, screen PB size screen 0.025, screen S / H

TITLE = "{/:Bold " . made_by('map') . ":} " . sprintf("symplectic Euler, elastic pendulum: energy error (50) in Cartesian minus polar coordinates\n" \
              . "l = %g, m = %g, k = %g, g = %g, Δt = %g, t_{max} = %g, p(0) = 0, grid %d × %d in (x_0, y_0)", \
                L, M, K, G, DT, TMAX, NX, NY)
do for [fmt in FORMATS] {
    eval term(fmt, 'energy_map_fig6', W, H)
    set title TITLE
    set lmargin at screen PL
    set rmargin at screen PR
    set tmargin at screen PT
    set bmargin at screen PB
    set xrange [XMIN - DX / 2 : XMAX + DX / 2]
    set yrange [YMAX + DY / 2 : YMIN - DY / 2]        # y grows downwards, as the physics' y
    set xtics 0.5 out nomirror
    set ytics 0.5 out nomirror
    set mxtics 5; set mytics 5
    set xlabel "x_0" offset 0, 0.3
    set ylabel "y_0   (y axis down: gravity along +y)"
    unset grid
    set border front
    set clip two
    set samples 721
    set key at screen PL, screen PB - 1.35 / H left top vertical Left reverse samplen 2.5 spacing 1.15 width -4 \
            opaque fc rgb '#c4c4c4' box lc rgb '#bbbbbb' lw 0.5

    plot MAP skip 1 using MAP_x0:MAP_y0:(sl(@DEPS)) with image notitle, \
         MAP skip 1 using MAP_x0:MAP_y0:(58):(58):(58):(@diverged ? 255 : 0) with rgbalpha notitle, \
         $HISO using 1:2 with lines lc rgb C_HISO lw 0.6 notitle, \
         [t=-pi:pi] '+' using (rb(t) * sin(t)):(rb(t) * cos(t)) with lines lc rgb '#ffffff' lw 1.3 dt (5,3) notitle, \
         keyentry with boxes fs solid 1.0 noborder lc rgb C_DIV title "run diverged (polar or Cartesian; |H_j − H_0| beyond the scene's blow-up limit)", \
         keyentry with lines lc rgb C_HISO lw 0.8 title sprintf("isolines of H_0 = H(x_0, y_0, 0, 0), step %g", H_STEP), \
         keyentry with lines lc rgb '#ffffff' lw 1.3 dt (5,3) \
                  title sprintf("r_0 = 2l + (2mg/k) cos θ_0: beyond it the exact polar motion reaches r = 0 (isoline H_0 = kl^2/2 = %g)", kl2)
    unset output
}

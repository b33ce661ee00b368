#!/usr/bin/env python3
"""LaTeX tables and macros for paper/main.tex from the experiments' summary.json.

Usage: python3 scripts/paper_tables.py RESULTS_ROOT OUT_DIR

RESULTS_ROOT holds one directory per experiment (RESULTS_ROOT/<name>/summary.json,
as written by build/bin/<name>). For every known experiment, and for every other
directory of RESULTS_ROOT that holds a summary.json, this writes

  OUT_DIR/<name>_table.tex   published vs reproduced (booktabs table float)
  OUT_DIR/<name>_timing.tex  ns per step per method, their ratio, error at equal wall time
  OUT_DIR/<name>_macros.tex  \\newcommand macros for the numbers the text cites

and, for an experiment with an entry in ORDER_TABLES (summary["orders_by_initial"]),

  OUT_DIR/<name>_orders.tex  fitted orders for every initial condition

and, for one with an entry in EXTRA_TABLES, OUT_DIR/<name>_<suffix>.tex (measure_cloud:
_orders.tex, the order of measure preservation per method). A directory
RESULTS_ROOT/<name>-<variant> of SCENE_VARIANTS holds the results of a second paper scene of
<name> (measure_cloud-free: the free particle); it is read together with <name> and gets no
files of its own. Without it, the quantities it provides are "n/a".

A known experiment without results gets placeholder files ("not yet reproduced"),
and its macros are defined as "n/a", so that main.tex always compiles.

Each published key is paired with summary["orders"][key] if present, else with
summary["reproduced"][key]. A published value is a number or an object of numbers (one
value per parameter, e.g. per step size, paired key by key with an object of numbers or
null). An experiment in RESULTS_TABLES has its own table layout (lobatto_table: Table 1 of
001 with published and reproduced values side by side, and the growth rates of its Fig. 2
beside their value in exact arithmetic, from the closed form of 001 eqs. (13)-(14); ti_drift:
004 Figs. 1-6 with the reproduced values that have no published number below a line;
measure_cloud: the statements of 003 Sec. 5 beside the values of its five methods), and one in
TIMING_TABLES its own timing table (ti_drift: ns per step and force evaluations per step of the
three methods, and the wall times of the Fig. 4 and Fig. 6 ensembles; measure_cloud: ns and
Newton iterations per step, errors and order of the five methods);
DERIVED_SUMMARIES adds quantities computed from its CSV files and scene for the macros.
Orders are printed to 3 decimals; other values to
4 significant digits in the tables and 2 in the macros, in scientific notation
(plain LaTeX, $1.8\\times10^{-15}$) below 1e-3. The crossover of two methods'
work-precision curves (CROSSOVERS), and the cost of reaching given error levels and
the errors at equal wall time (COST_TARGETS), are read from <name>/timing.csv; ratios
of two methods' errors (ERROR_RATIOS) from another CSV of <name>/; the scene
parameters the text cites from <name>/run.json; all only when those files exist.

Exit status: 0 on success, 2 on a usage error or a malformed summary.json
(the message names the file and the offending key). Python standard library only.
"""

import csv
import json
import math
import os
import sys
import tempfile

# ---------------------------------------------------------------------------
# Per-experiment presentation: row descriptions, method names, cited macros.
# ---------------------------------------------------------------------------

# Experiments the paper has a section for, in the order of main.tex.
KNOWN = [
    "euler_compensation",
    "rowlands_convergence",
    "energy_map",
    "lobatto_table",
    "measure_cloud",
    "ti_drift",
]

TITLES = {
    "euler_compensation": r"[000] Figs.~2, 3, 8, 9 (\texttt{euler\_compensation})",
    "rowlands_convergence": r"[000] Fig.~4 (\texttt{rowlands\_convergence})",
    "energy_map": r"[000] Fig.~6 (\texttt{energy\_map})",
    "lobatto_table": r"[001] Table~1, Figs.~1, 2 (\texttt{lobatto\_table})",
    "measure_cloud": r"[003] Figs.~5.1--5.6 (\texttt{measure\_cloud})",
    "ti_drift": r"[004] Figs.~1--6 (\texttt{ti\_drift})",
}

# Row descriptions of the published-vs-reproduced table (LaTeX).
DESCRIPTIONS = {
    "euler_compensation": {
        "ee_decay": r"Order of explicit Euler (9) on (14) in $y$",
        "se_energy": r"Order of symplectic Euler (42)--(43) in $(q,p)$, error in $H$ (Fig.~9)",
        "se_compensated_energy": r"Order of symplectic Euler in $(\bar q,\bar p)$ of (82), error in $H$ (Fig.~9)",
        "decay_compensated_max_rel_err": r"Fig.~2: explicit Euler in $\bar y$ of (15), max.\ relative error of $y$",
        "gompertz_compensated_max_rel_err": r"Fig.~3: explicit Euler in $\bar y$ of (18), max.\ relative error of $y$",
    },
    "rowlands_convergence": {
        "sv_energy": r"Order of St\"ormer--Verlet (26)--(28), energy error (50) (Fig.~4)",
        "sv_phase": r"Order of St\"ormer--Verlet, $\ell^2$ phase error at $t_{\max}$ (Fig.~4)",
        "rowlands_energy": r"Effective order of the Rowlands kernel (31) with (32)--(33), "
                           r"coefficient $h^2/12$, energy error (50) (Fig.~4)",
        "rowlands_phase": r"The same, $\ell^2$ phase error at $t_{\max}$ (Fig.~4)",
        "rowlands_cheap_phase": r"Effective order of (31) with the cheap processors (34)--(37), "
                                r"$\ell^2$ phase error at $t_{\max}$ (Section~3.3)",
    },
    "energy_map": {
        "polar_px_change_per_step": r"Sec.~5.2.1: order in $h$ of the change of $p_x$ in one step of "
                                    r"symplectic Euler in polar coordinates, free particle (62)",
        "cartesian_L_max_rel_drift": r"Sec.~5.2.2: max.\ relative drift of $L=xp_y-yp_x$ (69) under "
                                     r"symplectic Euler in Cartesian coordinates, free particle (61), "
                                     r"compensated summation",
    },
}

# Further rows of the published-vs-reproduced table, with no published value:
# (description, path into summary.json, format).
EXTRA_ROWS = {
    "energy_map": [
        (r"Fig.~6: grid points (origin excluded) at which the polar run diverges if and only if "
         r"$r(0)\ge 2l+\frac{2mg}{k}\cos\varphi(0)$", ("reproduced", "boundary_agreement"), "percent"),
        (r"Fig.~6: runs finite in both coordinate systems with "
         r"$\varepsilon_{(r,\varphi)}<\varepsilon_{(x,y)}$ (polar more accurate)",
         ("reproduced", "fraction_polar_better"), "percent"),
        (r"Fig.~6: polar runs that diverge", ("reproduced", "fraction_diverged_polar"), "percent"),
        (r"Fig.~6: Cartesian runs that diverge", ("reproduced", "fraction_diverged_cartesian"), "percent"),
        (r"Sec.~5.2.2: the drift of $L$ with plain floating-point updates",
         ("reproduced", "cartesian_L_max_rel_drift_plain"), "err"),
        (r"Fig.~6: initial positions, $n_x\times n_y$", ("grid", "points"), "int"),
        (r"Fig.~6: steps per run, $J=t_{\max}/\Delta t$", ("grid", "steps"), "int"),
    ],
}

# Method names of the timing table (LaTeX).
METHODS = {
    "euler_compensation": {
        "se": r"Symplectic Euler (42)--(43) in $(q,p)$",
        "se_compensated": r"Symplectic Euler in $(\bar q,\bar p)$ of (82)",
        "rk4": r"Classical Runge--Kutta 4 (not symplectic)",
    },
    "rowlands_convergence": {
        "sv": r"St\"ormer--Verlet",
        "rowlands": r"Rowlands, $h^2/12$",
        "rowlands_cheap": r"Rowlands, cheap",
        "odeint_rk4": r"odeint \texttt{runge\_kutta4}",
        "odeint_rkn_sb3a": r"odeint \texttt{symplectic\_rkn\_\allowbreak sb3a\_mclachlan}",
        "odeint_velocity_verlet": r"odeint \texttt{velocity\_verlet}",
    },
    "lobatto_table": {
        "lobatto": r"Lobatto (P3, (2))",
        "simpson": r"Simpson (P2)",
        "midpoint": r"Implicit midpoint",
        "odeint_rk4": r"odeint \texttt{runge\_kutta4}",
        "odeint_rkf78": r"odeint \texttt{runge\_kutta\_\allowbreak fehlberg78}",
    },
}

# What "error" means in the timing table of an experiment (LaTeX).
ERROR_NAMES = {
    "euler_compensation": r"$\max_{t_j\le T}|H_j-H_0|$",
    "rowlands_convergence": r"the $\ell^2$ phase error at $t_{\max}$",
    "lobatto_table": r"the phase-space error $|z_J-z(t_{\text{end}})|_2$",
}

# Crossover of two work-precision curves, read from <dir>/timing.csv
# (columns method, wall_s and the named error column): (method a, method b, column).
CROSSOVERS = {
    "euler_compensation": ("se", "se_compensated", "energy_err_max"),
}

# Cost of reaching given error levels, read from <dir>/timing.csv (columns method, steps,
# wall_s, force_evals and the error column): for every method the wall time and the number
# of force evaluations at which the error first reaches each target (log-log interpolation
# between measured points, never extrapolated), the force evaluations per step at the
# smallest step, and every method's error at the wall time of the most expensive run of
# the method "equal_wall". The timing table shows these in place of
# summary["timing"]["error_at_equal_wall_time"].
COST_TARGETS = {
    "rowlands_convergence": {
        "error": "phase_err", "targets": [1e-6, 1e-8], "equal_wall": "sv",
        "legend": r"St\"ormer--Verlet: (26)--(28); Rowlands, $h^2/12$: the kernel (31) with the "
                  r"processors (32)--(33), coefficient $h^2/12$; Rowlands, cheap: the kernel with (34)--(37).",
    },
    "lobatto_table": {
        "error": "error", "targets": [1e-10, 1e-12], "equal_wall": "odeint_rkf78",
        "evals_name": r"evaluations of $V'$ and $V''$",
        "run_note": r"One run integrates the pendulum $L=\dot q^2/2+\cos q$ from $q(0)=1$, $p(0)=0$ "
                    r"to $t_{\text{end}}$ with fixed steps.",
        "legend": r"Lobatto and Simpson: the Galerkin variational schemes built from their definition, "
                  r"internal values by Newton's method with the exact Jacobian; implicit midpoint: Newton on "
                  r"the midpoint. The two odeint steppers are explicit and not symplectic; "
                  r"\texttt{runge\_kutta\_fehlberg78} is used with fixed steps (order 8).",
    },
}

# Batched kernels timed against a straightforward scalar loop (summary["timing"]: kernel_isa,
# ns_per_step_per_core, scalar_ns_per_step, speedup_vs_scalar, map_wall_s, each per coordinate
# system; the scene's timing.scalar_points and timing.scalar_steps): the timing
# table shows these beside the target of each kernel and the hardware ceiling, both given here.
# The ceilings are estimates from the project's performance measurements on the machine type the
# results come from (AMD EPYC, Zen 5 generation, about 4.1 GHz, AVX-512; g++ 12.2): Cartesian,
# one square root and one division per step share the divider (11.5 cycles per 8 lanes); polar,
# one vector sine and cosine per step (0.65-0.8 ns per value), which the kernel avoids within its
# blocks of steps (the angle-addition formula). Values in ns per trajectory-step per core.
KERNEL_TIMING = {
    "energy_map": {
        "rows": [("cartesian", r"Cartesian (73)"), ("polar", r"Polar (72)")],
        "target": {"cartesian": 0.6, "polar": 1.4},
        "ceiling": {"cartesian": (0.35, 0.35), "polar": (0.8, 1.2)},
        "ceiling_note": r"Hardware ceiling: an estimate from the project's performance measurements "
                        r"on this machine type (AMD EPYC, Zen~5 generation, about 4.1\,GHz, AVX-512), "
                        r"not measured in this run. Cartesian: one square root and one division per "
                        r"step share the divider, 11.5 cycles per 8 lanes; polar: one vector sine and "
                        r"cosine per step, 0.65--0.8\,ns per value (the kernel evaluates them once per "
                        r"block of 128 steps). Target: the time per step set as the goal "
                        r"of the kernel.",
    },
}

# Fitted orders for every initial condition (summary["orders_by_initial"]), written to
# <name>_orders.tex: rows (key, method, error norm, order expected from the analysis);
# the column headers show the initial conditions of run.json's scene[initial_key].
ORDER_TABLES = {
    "rowlands_convergence": {
        "initial_key": "initial",
        "initial_names": r"$(x,y,p_x,p_y)(0)$",
        "rows": [
            ("sv_energy", r"St\"ormer--Verlet (26)--(28)", r"energy (50)", 2),
            ("sv_energy_max", "", r"energy, max.", 2),
            ("sv_phase", "", r"phase, $\ell^2$", 2),
            ("rowlands_energy", r"Rowlands, $h^2/12$", r"energy (50)", 4),
            ("rowlands_energy_max", "", r"energy, max.", 4),
            ("rowlands_phase", "", r"phase, $\ell^2$", 4),
            ("rowlands_cheap_energy", r"Rowlands, cheap", r"energy (50)", 4),
            ("rowlands_cheap_energy_max", "", r"energy, max.", 4),
            ("rowlands_cheap_phase", "", r"phase, $\ell^2$", 4),
            ("kernel_unprocessed_energy", r"Kernel (31) alone", r"energy (50)", 2),
            ("kernel_unprocessed_energy_max", "", r"energy, max.", 2),
            ("kernel_unprocessed_phase", "", r"phase, $\ell^2$", 2),
            ("rowlands_printed_energy", r"Rowlands, $h^2/24$ (printed)", r"energy (50)", 2),
            ("rowlands_printed_energy_max", "", r"energy, max.", 2),
            ("rowlands_printed_phase", "", r"phase, $\ell^2$", 2),
        ],
        "caption": r"Fitted orders of [000] Fig.~4 (\texttt{rowlands\_convergence}) for every initial "
                   r"condition: least-squares slopes of $\log(\text{error})$ against $\log h$ over "
                   r"the points above the round-off and reference floor. Energy: the "
                   r"$\ell^2$ norm (50) over the steps and the maximum over the steps; phase: the "
                   r"$\ell^2$ distance in $(x,y,p_x,p_y)$ from the reference at $t_{\max}$. Rowlands, "
                   r"$h^2/12$ and $h^2/24$: the kernel (31) with the processors (32)--(33) with that "
                   r"coefficient ($h^2/24$ as printed); cheap: with the processors (34)--(37). Expected: "
                   r"the order of the method, or its effective order with the processors "
                   r"(for $h^2/24$ see the text). The first initial condition is the one drawn.",
        # Ranges of the fitted orders over all initial conditions, for the text: group -> keys.
        "groups": {
            "second": ["sv_energy", "sv_energy_max", "sv_phase",
                       "kernel_unprocessed_energy", "kernel_unprocessed_energy_max", "kernel_unprocessed_phase",
                       "rowlands_printed_energy", "rowlands_printed_energy_max", "rowlands_printed_phase"],
            "fourth": ["rowlands_energy", "rowlands_energy_max", "rowlands_phase",
                       "rowlands_cheap_energy", "rowlands_cheap_energy_max", "rowlands_cheap_phase"],
        },
    },
}

# Ratio of two methods' errors at the smallest step, over all initial conditions and the
# given error columns of a CSV in <dir>/ (columns initial, h and <method><suffix>):
# (file, numerator method, denominator method, column suffixes). Gives min and max.
ERROR_RATIOS = {
    "rowlands_convergence": ("fig4_convergence.csv", "rowlands_printed", "kernel", ["_phase", "_energy_rms"]),
}

def free_particle_end(sc):
    """(|q_J|, eps |q_J| |p| / |L_0|) of the free-particle run of energy_map (m = 1, J steps of the
    smallest h from the first initial state): the round-off scale of evaluating L at its end."""
    fi = sc["first_integrals"]
    x, y, px, py = fi["initial"][0]
    t_end = fi["steps"] * min(fi["h"])
    q_end = math.hypot(x + t_end * px, y + t_end * py)
    return q_end, sys.float_info.epsilon * q_end * math.hypot(px, py) / abs(x * py - y * px)


# The local order between the two smallest step sizes, read from a CSV of <dir>/:
# (file, step column, error column, key of derived).
LOCAL_ORDERS = {
    "energy_map": ("first_integrals.csv", "h", "px_change_per_step", "px_local_order"),
}


# The map of energy_map (<dir>/map.csv with the scene of run.json), for the text: where the
# polar runs diverge against the analytic boundary r(0) >= 2l + (2mg/k) cos(phi(0)) of 000
# Sec. 4.1, and where polar is the more accurate. "ring_half_width": the initial radii
# |r(0) - l| < ring_half_width * l counted separately for the share where polar is better.
MAP_STATS = {
    "energy_map": {"file": "map.csv", "ring_half_width": 0.2},
}


# Quantities computed from run.json's resolved scene, for the text: {name: function(scene)};
# a function that fails on a missing or malformed scene gives n/a.
SCENE_DERIVED = {
    "energy_map": {
        "dx": lambda sc: (sc["grid"]["x_max"] - sc["grid"]["x_min"]) / (sc["grid"]["nx"] - 1),
        # U at r = 0, (72) or (73): for p(0) = 0 the boundary r(0) = 2l + (2mg/k) cos(phi(0)) is
        # the isoline H_0 = k l^2 / 2
        "H_threshold": lambda sc: 0.5 * sc["pendulum"]["k"] * sc["pendulum"]["l"] ** 2,
        "dt_times_omega": lambda sc: sc["dt"] * math.sqrt(sc["pendulum"]["k"] / sc["pendulum"]["m"]),
        # the Cartesian angular-momentum run (free particle, m = 1): |q| at its end and the
        # round-off of evaluating L = x p_y - y p_x there, eps |q| |p| / |L_0|
        "L_q_end": lambda sc: free_particle_end(sc)[0],
        "L_eval_roundoff": lambda sc: free_particle_end(sc)[1],
    },
    "rowlands_convergence": {
        # 000 eq. (73), y pointing down: the pendulum hangs at x = 0, y = l + m g / k
        "y_equilibrium": lambda sc: (sc["pendulum"]["l"]
                                     + sc["pendulum"]["m"] * sc["pendulum"]["g"] / sc["pendulum"]["k"]),
    },
}

# ---------------------------------------------------------------------------
# lobatto_table (001): Table 1 side by side, the growth rates of Fig. 2, the closed form of (13)-(14).
# ---------------------------------------------------------------------------

# Rows of Table 1: (key prefix of summary["published"] and ["reproduced"] as <prefix>_err_N<N>,
# label, key of summary["orders"] or None, published order as printed (LaTeX), format of the
# reproduced errors).
LOBATTO_ROWS = [
    ("p", r"$p$", "lobatto_p", "6", "sci4"),
    ("q", r"$q$", "lobatto_q", "6", "sci4"),
    ("H", r"$H(p,q)$", "lobatto_H", "6", "sci4"),
    ("Hd", r"$H_d(p,q)$ (15)", None, r"\text{exact}", "err"),
]
# Rows of <dir>/table1.csv beyond the paper's Table 1: (column, label, key of summary["orders"]).
LOBATTO_EXTRA_ROWS = [
    ("simpson_q_err", r"$q$, Simpson", "simpson"),
    ("midpoint_q_err", r"$q$, midpoint", "midpoint"),
]
# Macro names of the first, second, ... entry of a list of the scene (long_run.h, stable intervals).
ORDINALS = ["One", "Two", "Three", "Four", "Five", "Six"]


def lobatto_map(h, m, w):
    """(delta~, a, b, c) of 001 eq. (14): Phi = [[a, b], [c, a]] / delta~ acting on (p, q)."""
    x = (h * w) ** 2
    dt = 1 + x / 30 + x * x / 1800
    a = 1 - 7 * x / 15 + 23 * x * x / 900 - x ** 3 / 3600
    b = m * h * w * w / 43200 * (x - 60) * (x * x - 84 * x + 720)
    c = h / m * (1 - 2 * x / 15 + x * x / 300)
    return dt, a, b, c


def lobatto_exact_orbit(h, m, w, A):
    """The orbit of (13)-(14) from q = A, p = 0 in exact arithmetic where b < 0 < c (the first and
    the third stability interval): q_j = A cos(j theta), p_j = -sqrt(-b/c) A sin(j theta), so
    H_j - H_0 = K sin^2(j theta). Returns {theta, K, H0, Hd0}, or None where b < 0 < c fails."""
    dt, a, b, c = lobatto_map(h, m, w)
    if not (b < 0 < c and dt > 0):
        return None
    theta = math.atan2(math.sqrt(-b * c), a)  # cos theta = a/delta~, sin theta = sqrt(-bc)/delta~ (det = 1)
    return {"theta": theta, "K": 0.5 * A * A * (-b / (m * c) - m * w * w),
            "H0": 0.5 * m * w * w * A * A, "Hd0": -b * A * A / (2 * dt)}


def lsq_slope(ys):
    """Least-squares slope of ys against their index."""
    n = len(ys)
    if n < 2:
        return None
    mx, my = (n - 1) / 2, sum(ys) / n
    sxx = sum((i - mx) ** 2 for i in range(n))
    return sum((i - mx) * (y - my) for i, y in enumerate(ys)) / sxx


def lobatto_exact_growth(h, m, w, A, periods, windows):
    """Fig. 2's growth rate in exact arithmetic: the least-squares slope, per period, of the window
    maxima of |H_j - H_0| = |K| sin^2(j theta) over the steps j = 1..n (windows of n // windows steps,
    complete windows only, as the executable), and the number of periods after which a sample
    first reaches the peak |K|. With N = round(T/h) steps per period, j theta = 2 pi k/N + j eps on
    the residue class j = k mod N; within a window each class moves by at most N eps per step, so its
    maximum is at an end of the window or at a peak inside it. None if the orbit or N is unsuitable."""
    orb = lobatto_exact_orbit(h, m, w, A)
    T = 2 * math.pi / w
    N = round(T / h)
    if orb is None or N < 1:
        return None
    eps = orb["theta"] - 2 * math.pi / N
    if abs(N * eps) > 1e-3:
        return None
    n = round(periods * T / h)
    W = max(1, n // windows)
    maxima = []
    half = math.pi / 2
    for i in range(n // W):
        s, e = i * W + 1, (i + 1) * W
        best = 0.0
        for k in range(N):
            j0, j1 = s + (k - s) % N, e - (e - k) % N
            if j0 > e:
                continue
            phi = 2 * math.pi * k / N
            a0, a1 = phi + j0 * eps, phi + j1 * eps
            lo, hi = min(a0, a1), max(a0, a1)
            peak = half + math.pi * math.ceil((lo - half) / math.pi)
            best = max(best, 1.0 if peak <= hi else max(math.sin(a0) ** 2, math.sin(a1) ** 2))
        maxima.append(abs(orb["K"]) * best)
    slope = lsq_slope(maxima)
    # periods until a sample first reaches the peak (0 if one starts on it, as for N divisible by 4)
    dist = []
    for k in range(N):
        phi = 2 * math.pi * k / N
        d = ((half - phi) if eps > 0 else (phi - half)) % math.pi
        dist.append(0.0 if min(d, math.pi - d) < 1e-12 else d)
    to_peak = min(dist) / abs(eps) * h / T if eps != 0 else None
    return {"slope": None if slope is None else slope / (W * h / T), "K": orb["K"], "bound": abs(orb["K"]),
            "H0": orb["H0"], "Hd0": orb["Hd0"], "eps": eps, "periods_to_peak": to_peak,
            "first": maxima[0] if maxima else None, "last": maxima[-1] if maxima else None}


def keyed_by_h(d, h):
    """d[key] for the key of d (a JSON object keyed by formatted step sizes) equal to h, else None."""
    if not isinstance(d, dict):
        return None
    for k, v in d.items():
        try:
            if math.isclose(float(k), h, rel_tol=1e-12):
                return v
        except ValueError:
            continue
    return None


def stable_intervals(rows, col, tol=1e-12):
    """[[lo, hi], ...] of the scan points (h_omega) at which rows[col] <= 1 + tol."""
    out, start, prev = [], None, None
    for r in rows:
        hw, rho = float(r["h_omega"]), float(r[col])
        if rho <= 1 + tol and start is None:
            start = hw
        if not rho <= 1 + tol and start is not None:
            out.append([start, prev])
            start = None
        prev = hw
    if start is not None:
        out.append([start, prev])
    return out


def table1_meshes(s):
    """The meshes N of Table 1, from the keys p_err_N<N> of summary["published"], ascending."""
    ns = []
    for k in (s.get("published") or {}):
        if k.startswith("p_err_N") and k[len("p_err_N"):].isdigit():
            ns.append(int(k[len("p_err_N"):]))
    return sorted(ns)


def lobatto_summary(s, scene, exp_dir):
    """Derived quantities of lobatto_table for the tables and macros (missing inputs give None)."""
    pub, rep = s.get("published") or {}, s.get("reproduced") or {}
    osc = scene.get("oscillator") if isinstance(scene, dict) else None
    try:
        m, w, A = (float(osc[k]) for k in ("m", "omega", "amplitude"))
    except (TypeError, KeyError, ValueError):
        m = w = A = None
    out = {"table": {}, "growth": [], "stable": {}, "bound_runs": {}, "nonlinear": {}}
    # Table 1 against the published three digits
    agree = count = 0
    dev = []
    for prefix in ("p", "q", "H"):
        for N in table1_meshes(s):
            key = f"{prefix}_err_N{N}"
            p, r = pub.get(key), rep.get(key)
            if is_number(p) and is_number(r) and p != 0:
                count += 1
                agree += f"{p:.2e}" == f"{r:.2e}"
                dev.append(abs(r - p) / abs(p))
    out["table"].update({"agree": agree, "count": count, "max_dev": max(dev) if dev else None})
    hd_rel = []
    for i, N in enumerate(table1_meshes(s)):
        orb = lobatto_exact_orbit(2 * math.pi / w / N, m, w, A) if w else None
        r = rep.get(f"Hd_err_N{N}")
        if orb and is_number(r):
            out["table"][f"hd_rel_{i}"] = r / orb["Hd0"]
            out["table"][f"hd0_{i}"] = orb["Hd0"]
            hd_rel.append(r / orb["Hd0"])
    hd = [rep.get(f"Hd_err_N{N}") for N in table1_meshes(s)]
    hd_pub = [pub.get(f"Hd_err_N{N}") for N in table1_meshes(s)]
    out["table"]["hd_min"] = min((v for v in hd if is_number(v)), default=None)
    out["table"]["hd_max"] = max((v for v in hd if is_number(v)), default=None)
    out["table"]["hd_pub_min"] = min((v for v in hd_pub if is_number(v)), default=None)
    out["table"]["hd_pub_max"] = max((v for v in hd_pub if is_number(v)), default=None)
    out["table"]["hd_rel_min"] = min(hd_rel, default=None)
    out["table"]["hd_rel_max"] = max(hd_rel, default=None)
    # Fig. 2: per step size of long_run.h
    long_run = scene.get("long_run") if isinstance(scene, dict) else None
    hs = long_run.get("h") if isinstance(long_run, dict) else None
    if isinstance(long_run, dict) and is_number(long_run.get("periods")) and is_number(long_run.get("windows")):
        out["window_periods"] = long_run["periods"] / long_run["windows"]
    fig2 = read_csv_rows(os.path.join(exp_dir, "fig2_energy.csv"),
                         ("h", "period", "Hd_err_plain", "Hd_err_compensated", "H_err"))
    if isinstance(hs, list) and all(is_number(h) for h in hs):
        for i, h in enumerate(hs):
            g = {"h": h, "steps_per_period": (2 * math.pi / w) / h if w else None,
                 "pub": keyed_by_h(pub.get("energy_growth_rate"), h),
                 "rep": keyed_by_h(rep.get("energy_growth_rate"), h),
                 "hd": keyed_by_h(rep.get("energy_growth_rate_Hd"), h),
                 "hd_comp": keyed_by_h(rep.get("energy_growth_rate_Hd_compensated"), h)}
            ex = None
            if w and is_number(long_run.get("periods")) and is_number(long_run.get("windows")):
                ex = lobatto_exact_growth(h, m, w, A, long_run["periods"], int(long_run["windows"]))
            if ex:
                g.update({"exact": ex["slope"], "bound": ex["bound"], "periods_to_peak": ex["periods_to_peak"],
                          "exact_first": ex["first"], "exact_last": ex["last"], "ratio": ex["H0"] / ex["Hd0"]})
                if is_number(g["hd"]):
                    # the drift of H_d, seen in H: (H_0 / H_d(0)) |slope of |H_d - H_d(0)||
                    g["roundoff"] = ex["H0"] / ex["Hd0"] * abs(g["hd"])
                    # |det Phi - 1| per step implied by that drift
                    g["det_defect"] = abs(g["hd"]) * h / (2 * math.pi / w) / ex["Hd0"]
                if is_number(g["rep"]) and is_number(ex["slope"]):
                    g["rep_minus_exact"] = g["rep"] - ex["slope"]
            if fig2:
                rows = [r for r in fig2 if math.isclose(float(r["h"]), h, rel_tol=1e-12)]
                if rows:
                    g["hd_plain_max"] = max(float(r["Hd_err_plain"]) for r in rows)
                    g["hd_comp_max"] = max(float(r["Hd_err_compensated"]) for r in rows)
                    g["H_first"], g["H_last"] = float(rows[0]["H_err"]), float(rows[-1]["H_err"])
                    g["H_change"] = g["H_last"] - g["H_first"]
                    if is_number(g.get("ratio")):
                        g["hd_plain_max_in_H"] = g["ratio"] * g["hd_plain_max"]
            out["growth"].append(g)
    # stability
    sets = rep.get("stable_set_h_omega")
    if isinstance(sets, list):
        out["stable"]["count"] = len(sets)
        out["stable"]["intervals"] = [{"lo": iv[0], "hi": iv[1]} if isinstance(iv, list) and len(iv) == 2 else {}
                                      for iv in sets]
    st = scene.get("stability") if isinstance(scene, dict) else None
    if isinstance(st, dict) and all(is_number(st.get(k)) for k in ("hw_min", "hw_max", "points")) and st["points"] > 1:
        out["stable"]["grid_step"] = (st["hw_max"] - st["hw_min"]) / (st["points"] - 1)
    bound = rep.get("stability_bound")
    if is_number(bound):
        out["stable"]["h_over_T"] = bound / (2 * math.pi)  # the largest h/T of the first interval
        out["stable"]["min_steps_per_period"] = 2 * math.pi / bound
    scan = read_csv_rows(os.path.join(exp_dir, "stability.csv"),
                         ("h_omega", "spectral_radius", "spectral_radius_simpson"))
    if scan:
        near = min(scan, key=lambda r: abs(float(r["h_omega"]) - math.pi))  # h = T/2
        out["stable"]["hw_near_pi"], out["stable"]["rho_near_pi"] = float(near["h_omega"]), float(near["spectral_radius"])
        simp = stable_intervals(scan, "spectral_radius_simpson")
        out["stable"]["simpson"] = [{"lo": lo, "hi": hi} for lo, hi in simp]
        out["stable"]["simpson_count"] = len(simp)
    runs = rep.get("bound_runs")
    if isinstance(runs, dict):
        for k, v in runs.items():
            try:
                f = float(k)
            except ValueError:
                continue
            if isinstance(v, dict):
                side = "below" if f < 1 else "above"
                out["bound_runs"][side] = dict(v, factor=f)
    # Fig. 1: the largest errors of q and p over the steps of one period, per N and method
    fig1 = {}
    for i, N in enumerate(lookup(scene or {}, ("figure1", "meshes")) or []):
        rows = read_csv_rows(os.path.join(exp_dir, f"fig1_N{int(N)}.csv"),
                             ("t", "q_lobatto", "p_lobatto", "q_simpson", "p_simpson", "q_midpoint", "p_midpoint"))
        if not rows or not w:
            continue
        e = {}
        for meth in ("lobatto", "simpson", "midpoint"):
            e[meth] = {"q": max(abs(float(r[f"q_{meth}"]) - A * math.cos(w * float(r["t"]))) for r in rows),
                       "p": max(abs(float(r[f"p_{meth}"]) + m * w * A * math.sin(w * float(r["t"]))) for r in rows)}
        fig1[i] = e
    out["fig1"] = [fig1.get(i) for i in range(len(fig1))]
    # nonlinear: Newton iterations and the points of the fits
    nl = read_csv_rows(os.path.join(exp_dir, "nonlinear.csv"),
                       ("h", "pendulum_err", "pendulum_newton_iterations", "elastic_err", "elastic_newton_iterations"))
    atol = lookup(scene or {}, ("reference", "atol"))
    if nl:
        for sysname in ("pendulum", "elastic"):
            its = [float(r[f"{sysname}_newton_iterations"]) for r in nl]
            out["nonlinear"][f"{sysname}_it_min"], out["nonlinear"][f"{sysname}_it_max"] = min(its), max(its)
            if is_number(atol):
                fitted = [float(r["h"]) for r in nl if float(r[f"{sysname}_err"]) >= 100 * atol]
                out["nonlinear"][f"{sysname}_fit_points"] = len(fitted)
                out["nonlinear"][f"{sysname}_fit_hmin"] = min(fitted) if fitted else None
        if is_number(atol):
            out["nonlinear"]["floor"] = 100 * atol
    return out


def lobatto_results_table(name, s, src, derived):
    """Table 1 of 001 with published and reproduced values side by side, and Fig. 2's growth rates."""
    pub, rep, orders = s.get("published") or {}, s.get("reproduced") or {}, s.get("orders") or {}
    meshes = table1_meshes(s)
    lt = derived.get("lt") or {}
    t1 = read_csv_rows(os.path.join(os.path.dirname(src), "table1.csv"), ["N"] + [c for c, _, _ in LOBATTO_EXTRA_ROWS])
    nm = len(meshes)

    def cell(v, kind):
        if kind == "sci4":
            c = sci(v, 4) if is_number(v) and math.isfinite(v) and v != 0 else fmt(v, "err")
        elif kind == "pub":
            c = sci(v, 3) if is_number(v) and math.isfinite(v) and v != 0 else fmt(v, "err")
        else:
            c = fmt(v, kind)
        return math_cell(c)

    lines = [HEADER.format(src=src)]
    lines.append("\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
    lines.append(f"\\caption{{Table~1 of [001], published (Pub.) and reproduced (Rep.): the largest absolute "
                 "error over the steps $j=1,\\dots,N$ of one period, $N$ steps per period, for the harmonic "
                 "oscillator with $m=1$, $\\omega=2\\pi$, $q(0)=\\pi/2$, $p(0)=0$: momentum $p$, state $q$, energy $H$ "
                 "and discrete energy $H_d$. Published orders: the "
                 "closest integer to the ratio of successive errors as a power of $2^{-1}$, as printed; reproduced "
                 "orders: least-squares slopes of $\\log(\\text{error})$ against $\\log h$. Below the line (not in "
                 "Table~1 of [001]): the state error of Simpson's scheme (P2 elements and Simpson's rule, [2] of [001]) "
                 "and of the implicit midpoint rule in the same runs (\\texttt{table1.csv}).}\n")
    lines.append(f"\\label{{tab:{name}-table}}\n")
    lines.append("\\setlength{\\tabcolsep}{2.5pt}\n")
    lines.append("\\begin{tabular}{@{}l" + "rr" * (nm + 1) + "@{}}\n\\toprule\n")
    lines.append(" & " + " & ".join(f"\\multicolumn{{2}}{{c}}{{$N={N}$}}" for N in meshes)
                 + " & \\multicolumn{2}{c}{Order} \\\\\n")
    lines.append("".join(f"\\cmidrule(lr){{{2 + 2 * i}-{3 + 2 * i}}}" for i in range(nm))
                 + f"\\cmidrule(l){{{2 + 2 * nm}-{3 + 2 * nm}}}\n")
    lines.append("Quantity & " + " & ".join(["Pub.", "Rep."] * (nm + 1)) + " \\\\\n\\midrule\n")
    for prefix, label, okey, porder, kind in LOBATTO_ROWS:
        cells = []
        for N in meshes:
            cells += [cell(pub.get(f"{prefix}_err_N{N}"), "pub"), cell(rep.get(f"{prefix}_err_N{N}"), kind)]
        cells += [f"${porder}$", cell(orders.get(okey), "order") if okey else "---"]
        lines.append(f"{label} & " + " & ".join(cells) + " \\\\\n")
    if t1:
        lines.append("\\midrule\n")
        by_n = {}
        for r in t1:
            try:
                by_n[int(float(r["N"]))] = r
            except ValueError:
                raise Malformed(f"{src}: table1.csv: non-numeric N in row {r}") from None
        for col, label, okey in LOBATTO_EXTRA_ROWS:
            cells = []
            for N in meshes:
                v = by_n.get(N, {}).get(col)
                try:
                    v = float(v) if v is not None else None
                except ValueError:
                    v = None
                cells += ["---", cell(v, "sci4")]
            cells += ["---", cell(orders.get(okey), "order")]
            lines.append(f"{label} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    tab = lt.get("table") or {}
    if is_number(tab.get("count")) and tab["count"]:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize "
                     f"${tab['agree']}$ of the ${tab['count']}$ reproduced errors of $p$, $q$ and $H$ round to the "
                     f"three published digits; the largest relative deviation is {math_cell(fmt(tab['max_dev'], 'percent'))}. "
                     "$H_d$: round-off in both (see the text).}\n")
    lines.append("\\end{table}\n")
    growth = lt.get("growth") or []
    if growth:
        lines.append("\n\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
        lines.append(f"\\caption{{Fig.~2 of [001]: growth rate of the energy error over the long runs, per period. "
                     "Published: the ``$\\ell^\\infty$ energy error growth rate'' of the caption of Fig.~2. "
                     "Reproduced: the least-squares slope of the window maxima of $|H_j-H(0)|$ (\\texttt{fig2\\_energy.csv}). "
                     "Exact arithmetic: the same slope for the orbit of (13)--(14) in closed form, "
                     "$H_j-H(0)=K\\sin^2(j\\theta)$ (computed by \\texttt{paper\\_tables.py}). "
                     "$H_d$ plain and compensated: the slopes of the window maxima of $|H_d-H_d(0)|$, with the "
                     "update (13) added plainly and by compensated summation. Round-off in $H$: the plain $H_d$ slope "
                     "times $H(0)/H_d(0)$, the change of $H$ that goes with a drift of $H_d$, to be compared "
                     "with reproduced $-$ exact.}\n")
        lines.append(f"\\label{{tab:{name}-growth}}\n")
        lines.append("\\setlength{\\tabcolsep}{3pt}\n")
        lines.append("\\begin{tabular}{@{}rrrrrrrrr@{}}\n\\toprule\n")
        lines.append("$h$ & $N$ & Published & Reproduced & Exact & Reproduced & Round-off & "
                     "\\multicolumn{2}{c}{$H_d$} \\\\\n")
        lines.append("\\cmidrule(l){8-9}\n")
        lines.append(" & & & & arithmetic & $-$ exact & in $H$ & plain & compensated \\\\\n\\midrule\n")
        for g in growth:
            cells = [math_cell(fmt(g.get("h"), "plain")), math_cell(fmt(g.get("steps_per_period"), "int")),
                     cell(g.get("pub"), "pub"), cell(g.get("rep"), "sci4"), cell(g.get("exact"), "sci4"),
                     cell(g.get("rep_minus_exact"), "err"), cell(g.get("roundoff"), "err"), cell(g.get("hd"), "err"), cell(g.get("hd_comp"), "err")]
            lines.append(" & ".join(cells) + " \\\\\n")
        lines.append("\\bottomrule\n\\end{tabular}\n\\end{table}\n")
    return "".join(lines)


# ---------------------------------------------------------------------------
# ti_drift (004): Figs. 1-6 of the simplified Takahashi-Imada method.
# ---------------------------------------------------------------------------

# Constants of the executable (experiments/ti_drift/main.cpp) that the derived quantities need.
TI_FIT_MAX_WH = 0.5        # Fig. 1: the orders are fitted over omega h_eff <= 0.5 ...
TI_FIT_FLOOR = 1e3 * sys.float_info.epsilon  # ... and over the errors above this floor
TI_BOUND = 2 * math.sqrt(3)  # 004 Sect. 1.4: TI is stable for omega h < 2 sqrt(3)
TI_PUBLISHED_T = 2.5e6     # 004 Fig. 4: the time at which mu and sigma are printed

# Rows of the published-vs-reproduced table with a published value: (key, description, format).
TI_PUBLISHED_ROWS = [
    ("ti_solution", r"Fig.~1 left: order of the global error $(|\varepsilon_p|^2+\omega^2|\varepsilon_q|^2)^{1/2}$ "
                    r"of TI (1.4) in the variables $(\hat p,\hat q)$ of (1.5)", "order"),
    ("ti_energy", r"Fig.~1 right: order of the largest relative error of $H$ of TI in $(\hat p,\hat q)$", "order"),
    ("sv_energy", r"Fig.~1 right: the same for St\"ormer--Verlet (1.3)", "order"),
    ("ti_stability_bound", r"Sect.~1.4: stability bound $\omega h<2\sqrt3$ of TI on the oscillator "
                           r"(bisection on the spectral radius)", "fixed12"),
    ("hh3_drift_slope", r"Fig.~3 ($k=3$): least-squares slope per unit time of the error of "
                        r"$E=\hat H+\frac12h^4\alpha^2K$ (``no drift'')", "err"),
    ("hh5_mu_final", r"Fig.~4 ($k=5$): mean $\mu$ of the error of $E$ over the ensemble at $t_{\text{end}}$", "sci3"),
    ("hh5_sigma_final", r"Fig.~4: standard deviation $\sigma$ at $t_{\text{end}}$", "sci3"),
    ("hh5_sigma_exponent", r"Fig.~4: exponent $\gamma$ of $\sigma\propto t^\gamma$ over "
                           r"$[t_{\text{end}}/10,t_{\text{end}}]$ (``like the square root of time'')", "fixed3"),
    # Fig. 6 (the Lennard-Jones cluster), when the results contain it
    ("lj_mu_final", r"Fig.~6 (at the step $h$ of the text, not the printed 0.2): mean $\mu$ of the error of $E$ "
                    r"over the ensemble at $t_{\text{end}}$", "sci3"),
    ("lj_sigma_final", r"Fig.~6: standard deviation $\sigma$ at $t_{\text{end}}$", "sci3"),
    ("lj_sigma_exponent", r"Fig.~6: exponent $\gamma$ of $\sigma\propto t^\gamma$ over "
                          r"$[t_{\text{end}}/10,t_{\text{end}}]$", "fixed3"),
]

# Further rows: (description, (source, path...), format[, path of a published value computed from
# summary["published"]]); source "summary" or "derived". Without that path the row has no published value.
TI_EXTRA_ROWS = [
    (r"Fig.~1 left: order of the global error of St\"ormer--Verlet", ("summary", "orders", "sv_solution"), "order"),
    (r"Fig.~2: drift per unit time of $H+h^2H_3$ along (1.6), least-squares slope",
     ("summary", "reproduced", "unsym_pendulum_drift_rate"), "sci3"),
    (r"Fig.~2: the same predicted by (4.3), $-\frac{h^4\alpha^2}{20}\langle U^{(5)}(p^5)\rangle$ along the exact orbit",
     ("summary", "reproduced", "unsym_pendulum_drift_rate_predicted"), "sci3"),
    (r"Fig.~3: largest $|E_n-E_0|$ at the output times", ("summary", "reproduced", "hh3_max_E_err"), "err"),
    (r"Fig.~3: slope times $t_{\text{end}}$, against the largest error above", ("derived", "td", "fig3", "drift_over_run"), "err"),
    (r"Fig.~4: $\sigma^2/t$ at $t_{\text{end}}$ (published: from $\sigma$ at $t=2.5\cdot10^6$)",
     ("derived", "td", "fig4", "D_end"), "sci3", ("derived", "td", "fig4", "D_pub")),
    (r"Fig.~4: trajectories with $\max|E_n-E_0|>2\cdot10^{-6}$ ([004]: 2)", ("summary", "reproduced", "hh5_outliers"),
     "len:int"),
    (r"Fig.~5: Poincar\'e cuts per unit time, window of steepest growth ([004]: 25\,220 cuts on "
     r"$[1\,225\,782,1\,415\,265]$, 0.133)", ("derived", "td", "fig5", "growth", "rate"), "fixed3"),
    (r"Fig.~5: the same, flattest window ([004]: 12\,827 cuts on $[1.0,1.1]\cdot10^6$, 0.128)",
     ("derived", "td", "fig5", "no_growth", "rate"), "fixed3"),
    (r"Fig.~5: share of the cuts with $p_2<0$, window of steepest growth ([004]: the cuts ``lie in the region "
     r"$p_2<0$'')", ("derived", "td", "fig5", "growth", "share_p2_negative"), "percent"),
    (r"Fig.~5: the same, flattest window", ("derived", "td", "fig5", "no_growth", "share_p2_negative"), "percent"),
    # Fig. 6, shown only when the results contain it (summary["reproduced"]["lj_mu_final"])
    (r"Fig.~6: standard error $\sigma/\sqrt M$ of $\mu$ at $t_{\text{end}}$ ($M$ trajectories)",
     ("summary", "reproduced", "lj_mu_final_stderr"), "sci3"),
    (r"Fig.~6: standard error $\sigma/\sqrt{2(M-1)}$ of $\sigma$ at $t_{\text{end}}$",
     ("summary", "reproduced", "lj_sigma_final_stderr"), "sci3"),
    (r"Fig.~6: largest $|H_n-H_0|$ over the ensemble at the output times ([004]: ``an error in $H$ of size "
     r"$10^{-3}$'')", ("summary", "reproduced", "lj_H_err_max"), "err"),
    (r"Fig.~6: runs of the step-size scan that diverge at the printed $h=0.2$ ([004]: ``sufficiently small'')",
     ("derived", "td", "fig6", "div_first"), "int"),
    (r"Sect.~1.3: $\max|J^{\mathsf T}\Omega J-\Omega|$ of one step of TI (1.4), H\'enon--Heiles $k=3$",
     ("summary", "reproduced", "ti_symplecticity_defect"), "err"),
    (r"Sect.~1.3: the same for the simplified method (1.6)", ("summary", "reproduced", "sti_symplecticity_defect"), "err"),
    (r"Sect.~1.3: $\det J-1$ of one step of (1.6)", ("summary", "reproduced", "sti_det_minus_one"), "err"),
]

# The timing table: (key of timing.ns_per_step, method, force evaluations per step).
TI_TIMING_ROWS = [
    ("sv", r"St\"ormer--Verlet (1.3)", r"1 gradient"),
    ("ti", r"Takahashi--Imada (1.4)", r"1 gradient, 1 Hessian--vector product"),
    ("sti", r"Simplified Takahashi--Imada (1.6)", r"2 gradients"),
]


def pendulum_u_max():
    """max of U = -cos q + 0.2 sin 2q (004 (5.1)): a grid over one period, refined by golden sections."""
    u = lambda q: -math.cos(q) + 0.2 * math.sin(2 * q)
    n = 3600
    q = max((2 * math.pi * i / n for i in range(n)), key=u)
    a, b = q - 2 * math.pi / n, q + 2 * math.pi / n
    r = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        c, d = b - r * (b - a), a + r * (b - a)
        a, b = (c, b) if u(c) < u(d) else (a, d)
    return u(0.5 * (a + b))


PENDULUM_U_MAX = pendulum_u_max()


def ti_potential_hh(q1, q2, k):
    """The Henon-Heiles-type potential of 004 Sect. 5.2."""
    return 0.5 * (q1 * q1 + q2 * q2) + q1 * q1 * q2 - q2 ** k / k


def ti_slope(xs, ys):
    """Least-squares slope of ys against xs, or None."""
    n = len(xs)
    if n < 2:
        return None
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    return None if sxx == 0 else sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def ti_gamma(ts, sigmas, t0):
    """Slope of log sigma against log t over t >= t0 (sigma > 0), or None."""
    pts = [(math.log(t), math.log(s)) for t, s in zip(ts, sigmas) if t >= t0 and t > 0 and s > 0]
    return ti_slope([p[0] for p in pts], [p[1] for p in pts])


def csv_floats(rows, path, cols):
    """The columns cols of CSV rows as floats (Malformed on a non-numeric value)."""
    try:
        return [[float(r[c]) for c in cols] for r in rows]
    except ValueError:
        raise Malformed(f"{path}: non-numeric value in the columns {list(cols)}") from None


def ti_summary(s, scene, exp_dir):
    """Derived quantities of ti_drift for the tables and macros (missing inputs give None)."""
    rep, pub = s.get("reproduced") or {}, s.get("published") or {}
    sc = scene if isinstance(scene, dict) else {}
    out = {"scene": {}, "osc": {}, "fig2": {}, "fig3": {}, "fig4": {}, "fig5": {}, "fig6": {}, "cost": {}, "stability": {}}

    def num(*path):
        v = lookup(sc, path)
        return float(v) if is_number(v) else None

    h, samples = num("h"), num("samples")

    def steps_and_dt(t_end):
        if not (h and samples and t_end):
            return None, None
        n = round(t_end / h)
        every = max(1, n // int(samples))
        return n, every * h

    # the scene: starts, steps and output intervals
    d = out["scene"]
    q0, p0 = num("pendulum", "q0"), num("pendulum", "p0")
    if q0 is not None and p0 is not None:
        d["pendulum_H0"] = 0.5 * p0 * p0 - math.cos(q0) + 0.2 * math.sin(2 * q0)
    q2, p2, H0, k = num("hh3", "q2"), num("hh3", "p2"), num("hh", "H0"), num("hh", "k")
    for key, kk in (("hh3_p1", 3), ("hh_p1", k)):
        if None not in (q2, p2, H0, kk):
            arg = 2 * (H0 - ti_potential_hh(0.0, q2, int(kk))) - p2 * p2
            d[key] = math.sqrt(arg) if arg >= 0 else None
    for key, t_end in (("pendulum", num("pendulum", "t_end")), ("hh3", num("hh3", "t_end")), ("fig4", num("t_end"))):
        d[f"{key}_steps"], d[f"{key}_sample_dt"] = steps_and_dt(t_end)
    whs = lookup(sc, ("oscillator", "omega_h"))
    if isinstance(whs, list) and whs and all(is_number(w) for w in whs):
        d["wh_min"], d["wh_max"], d["wh_count"] = min(whs), max(whs), len(whs)
        d["wh_ti_count"] = sum(1 for w in whs if w < TI_BOUND)
        t_omega = num("oscillator", "t_omega")
        if t_omega:
            d["steps_ti_min"] = math.floor(t_omega / max(w for w in whs if w < TI_BOUND)) if d["wh_ti_count"] else None

    # Fig. 1: the sampled maxima against the closed forms of Sect. 1.4 (start q0 = 0)
    path = os.path.join(exp_dir, "oscillator.csv")
    rows = read_csv_rows(path, ("method", "omega_h", "max_global_err", "max_rel_H_err"))
    if rows:
        vals = csv_floats(rows, path, ("omega_h", "max_global_err", "max_rel_H_err"))
        by = {}
        for r, (wh, g, e) in zip(rows, vals):
            by.setdefault(r["method"], {})[wh] = (g, e)
        sv, ti = by.get("sv", {}), by.get("ti", {})

        def closed(method, y):
            if method == "sv":
                return y * y / (16 - y * y)
            return y ** 6 / (36 * (y ** 4 - 12 * y * y + 48)) if y < TI_BOUND else None

        o = out["osc"]
        common = [w for w in ti if w in sv]
        o["common"] = len(common)
        o["ti_better_energy"] = sum(1 for w in common if ti[w][1] < sv[w][1])
        o["ti_better_global"] = sum(1 for w in common if ti[w][0] < sv[w][0])
        o["fit_points_global"] = sum(1 for w in ti if w <= TI_FIT_MAX_WH and ti[w][0] >= TI_FIT_FLOOR)
        o["fit_points_energy"] = sum(1 for w in ti if w <= TI_FIT_MAX_WH and ti[w][1] >= TI_FIT_FLOOR)
        o["fit_points_sv"] = sum(1 for w in sv if w <= TI_FIT_MAX_WH and sv[w][1] >= TI_FIT_FLOOR)
        below = [w for w in ti if ti[w][1] < TI_FIT_FLOOR]
        o["ti_roundoff_wh_max"] = max(below) if below else None
        for m, data in (("sv", sv), ("ti", ti)):
            small = [abs(data[w][1] / closed(m, w) - 1) for w in data
                     if w <= 1 and closed(m, w) and data[w][1] >= TI_FIT_FLOOR]
            o[f"{m}_dev_small"] = max(small) if small else None
            large = [(data[w][1] / closed(m, w), w) for w in data if w > 1 and closed(m, w)]
            if large:
                ratio, where = min(large)
                o[f"{m}_ratio_large"], o[f"{m}_ratio_large_wh"] = ratio, where
        if ti:
            w_last = max(ti)
            o["ti_last_wh"], o["ti_last_energy"] = w_last, ti[w_last][1]
        if sv:
            near = min(sv, key=lambda w: abs(w - 0.1))
            o["wh_ref"] = near
            o["sv_global_ref"], o["sv_energy_ref"] = sv[near]
            if near in ti:
                o["ti_global_ref"], o["ti_energy_ref"] = ti[near]

    # stability bound against 2 sqrt(3)
    b, bp = rep.get("ti_stability_bound"), pub.get("ti_stability_bound")
    if is_number(b) and is_number(bp):
        out["stability"]["diff"] = b - bp

    # Fig. 2: the pendulum
    path = os.path.join(exp_dir, "fig2_pendulum.csv")
    rows = read_csv_rows(path, ("t", "shifted_energy_err", "H_err"))
    if rows and len(rows) > 2:
        t, e, H = zip(*csv_floats(rows, path, ("t", "shifted_energy_err", "H_err")))
        f = out["fig2"]
        f["change"] = e[-1]
        f["U_max"] = PENDULUM_U_MAX
        for key, ys in (("shifted", e), ("H", H)):
            sl = ti_slope(t, ys)
            mt, my = sum(t) / len(t), sum(ys) / len(ys)
            res = [y - my - sl * (x - mt) for x, y in zip(t, ys)]
            f[f"{key}_slope"], f[f"{key}_residual_p2p"] = sl, max(res) - min(res)
        r, pr = rep.get("unsym_pendulum_drift_rate"), rep.get("unsym_pendulum_drift_rate_predicted")
        if is_number(r) and is_number(pr) and pr != 0:
            f["rel_diff"] = abs(r - pr) / abs(pr)
        H0p = out["scene"].get("pendulum_H0")
        if is_number(r) and r != 0 and is_number(H0p):
            f["turnover_time"] = (H0p - PENDULUM_U_MAX) / abs(r)

    # Fig. 3: Henon-Heiles k = 3
    path = os.path.join(exp_dir, "fig3_hh3.csv")
    rows = read_csv_rows(path, ("t", "E_err", "H_err"))
    if rows and len(rows) > 2:
        t, e, H = zip(*csv_floats(rows, path, ("t", "E_err", "H_err")))
        f = out["fig3"]
        f["H_max"] = max(abs(v) for v in H)
        f["E_p2p"] = max(e) - min(e)
        sl = rep.get("hh3_drift_slope")
        if is_number(sl):
            f["drift_over_run"] = sl * t[-1]
            mx = rep.get("hh3_max_E_err")
            if is_number(mx) and mx > 0:
                f["drift_over_max"] = abs(sl * t[-1]) / mx

    # Fig. 4: the ensemble
    M = num("ensemble", "size")
    t_end = num("t_end")
    path = os.path.join(exp_dir, "fig4_stats.csv")
    rows = read_csv_rows(path, ("t", "mu", "sigma"))
    f = out["fig4"]
    if rows and len(rows) > 2 and t_end:
        t, mu, sigma = zip(*csv_floats(rows, path, ("t", "mu", "sigma")))
        f["mu_first"], f["t_first"] = mu[1], t[1]
        late = [m for x, m in zip(t, mu) if x >= t_end / 10]
        if late:
            f["mu_late_mean"], f["mu_late_min"], f["mu_late_max"] = sum(late) / len(late), min(late), max(late)
        f["D_end"] = sigma[-1] ** 2 / t[-1]
        f["gamma_tenth"] = ti_gamma(t, sigma, t_end / 10)
        f["gamma_hundredth"] = ti_gamma(t, sigma, t_end / 100)
        pts = [(x, sg * sg) for x, sg in zip(t, sigma) if x >= t_end / 10]
        f["D_fit"] = ti_slope([p[0] for p in pts], [p[1] for p in pts])
        if M and M > 1:
            f["mu_se"] = sigma[-1] / math.sqrt(M)
            f["sigma_rel_se"] = 1 / math.sqrt(2 * (M - 1))
    ps = pub.get("hh5_sigma_final")
    if is_number(ps):
        f["D_pub"] = ps * ps / TI_PUBLISHED_T
    path = os.path.join(exp_dir, "fig4_trajectories.csv")
    rows = read_csv_rows(path, ("trajectory", "t", "E_err"))
    traj = {}
    if rows:
        for r, (i, x, e) in zip(rows, csv_floats(rows, path, ("trajectory", "t", "E_err"))):
            traj.setdefault(int(i), []).append((x, e))
    outliers = rep.get("hh5_outliers")
    outliers = [int(i) for i in outliers if is_number(i)] if isinstance(outliers, list) else []
    keep = [i for i in traj if i not in outliers]
    if len(keep) > 1 and t_end and len({len(traj[i]) for i in keep}) == 1:
        times = [x for x, _ in traj[keep[0]]]
        mus, sds = [], []
        for j in range(len(times)):
            v = [traj[i][j][1] for i in keep]
            m = sum(v) / len(v)
            mus.append(m)
            sds.append(math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)))
        f["kept"] = len(keep)
        f["mu_end_kept"], f["sigma_end_kept"] = mus[-1], sds[-1]
        f["gamma_tenth_kept"] = ti_gamma(times, sds, t_end / 10)
        f["output_dt_thinned"] = times[1] - times[0] if len(times) > 1 else None

    # Fig. 5: the Poincare cuts of one trajectory in two windows
    wins = rep.get("poincare_windows")
    path = os.path.join(exp_dir, "fig5_poincare.csv")
    rows = read_csv_rows(path, ("window", "t", "q2", "p2"))
    if isinstance(wins, dict):
        idx = rep.get("poincare_trajectory")
        series = traj.get(int(idx)) if is_number(idx) else None
        for label, w in wins.items():
            if not (isinstance(w, list) and len(w) == 2 and all(is_number(x) for x in w)):
                continue
            g = {"lo": w[0], "hi": w[1], "length": w[1] - w[0]}
            if rows is not None:
                sel = [r for r in rows if r["window"] == label]
                p2s = [v[0] for v in csv_floats(sel, path, ("p2",))]
                g["cuts"] = len(p2s)
                if g["length"] > 0:
                    g["rate"] = len(p2s) / g["length"]
                if p2s:
                    g["share_p2_negative"] = sum(1 for v in p2s if v < 0) / len(p2s)
                    g["mean_p2"] = sum(p2s) / len(p2s)
            if series:
                a = min(series, key=lambda te: abs(te[0] - w[0]))
                z = min(series, key=lambda te: abs(te[0] - w[1]))
                if z[0] > a[0]:
                    g["E_lo"], g["E_hi"] = a[1], z[1]
                    g["change"] = z[1] - a[1]
                    g["slope"] = (z[1] - a[1]) / (z[0] - a[0])
            out["fig5"][label] = g

    # Fig. 6: the Lennard-Jones cluster, the step-size scan and the ensemble at lj.h
    f = out["fig6"]
    lh, lt_end, lM = num("lj", "h"), num("lj", "t_end"), num("lj", "size")
    if lh and lt_end:
        f["steps"] = round(lt_end / lh)
        if samples:
            f["sample_dt"] = max(1, f["steps"] // int(samples)) * lh
    hs = lookup(sc, ("lj", "h_scan"))
    path = os.path.join(exp_dir, "fig6_scan.csv")
    rows = read_csv_rows(path, ("h", "trajectory", "max_H_err", "diverged", "diverge_step"))
    if rows and isinstance(hs, list) and len(hs) >= 2 and all(is_number(x) for x in hs):
        vals = csv_floats(rows, path, ("h", "max_H_err", "diverged", "diverge_step"))
        per_h = []
        for x in hs:
            sel = [v for v in vals if abs(v[0] / x - 1) < 1e-9]
            div = [v for v in sel if v[2] != 0]
            ok = sorted(v[1] for v in sel if v[2] == 0)
            per_h.append({"h": x, "runs": len(sel), "diverged": len(div),
                          "t_div": [v[3] * x for v in div if v[3] >= 0],
                          "median": (ok[len(ok) // 2] if len(ok) % 2 else 0.5 * (ok[len(ok) // 2 - 1] + ok[len(ok) // 2]))
                          if ok else None,
                          "max": ok[-1] if ok else None})
        first, second = per_h[0], per_h[1]
        smallest = min(per_h, key=lambda g: g["h"])
        f["runs"] = first["runs"]
        f["h_first"], f["div_first"] = first["h"], first["diverged"]
        f["h_second"], f["div_second"] = second["h"], second["diverged"]
        if first["t_div"]:
            f["t_div_first_min"], f["t_div_first_max"] = min(first["t_div"]), max(first["t_div"])
        if second["t_div"]:
            f["t_div_second_min"], f["t_div_second_max"] = min(second["t_div"]), max(second["t_div"])
        f["stable_count"] = sum(1 for g in per_h if g["diverged"] == 0)
        f["h_smallest"], f["median_smallest"], f["max_smallest"] = smallest["h"], smallest["median"], smallest["max"]
    mu, sg = rep.get("lj_mu_final"), rep.get("lj_sigma_final")
    mu_se, sg_se = rep.get("lj_mu_final_stderr"), rep.get("lj_sigma_final_stderr")
    pmu, psg = pub.get("lj_mu_final"), pub.get("lj_sigma_final")
    for key, v in (("mu_u", mu), ("mu_se_u", mu_se), ("sigma_u", sg), ("sigma_se_u", sg_se),
                   ("mu_pub_u", pmu), ("sigma_pub_u", psg)):
        if is_number(v):
            f[key] = v / 1e-6  # in units of 10^-6, as the paper prints them
    if all(is_number(v) for v in (mu, pmu, mu_se)) and mu_se > 0:
        f["mu_z_pub"] = abs(mu - pmu) / mu_se
        f["mu_z_zero"] = abs(mu) / mu_se
    if all(is_number(v) for v in (sg, psg, sg_se)) and sg_se > 0:
        f["sigma_z_pub"] = abs(sg - psg) / sg_se
        f["sigma_rel_diff"] = (sg - psg) / psg
    path = os.path.join(exp_dir, "fig6_stats.csv")
    rows = read_csv_rows(path, ("t", "mu", "sigma", "H_err_rms", "Hhat_err_rms"))
    if rows and len(rows) > 2:
        t, H, Hh = zip(*csv_floats(rows, path, ("t", "H_err_rms", "Hhat_err_rms")))
        later = [(a, b) for x, a, b in zip(t, H, Hh) if x > 0]
        f["Hhat_start"] = Hh[0] if t[0] == 0 else None
        f["H_rms_mean"] = sum(a for a, _ in later) / len(later)
        f["H_rms_max"] = max(a for a, _ in later)
        f["Hhat_rms_min"], f["Hhat_rms_max"] = min(b for _, b in later), max(b for _, b in later)
        hb = sum(b for _, b in later) / len(later)
        if hb > 0:
            f["H_over_Hhat"] = f["H_rms_mean"] / hb
        if f["Hhat_start"]:
            f["Hhat_rel_var"] = max(abs(b / f["Hhat_start"] - 1) for _, b in later)

    # cost
    timing = s.get("timing") or {}
    ns = timing.get("ns_per_step") or {}
    c = out["cost"]
    if isinstance(ns, dict) and is_number(ns.get("sv")) and ns["sv"] > 0:
        for m in ("ti", "sti"):
            if is_number(ns.get(m)):
                c[f"ratio_{m}"] = ns[m] / ns["sv"]
    run = {}
    if os.path.isfile(os.path.join(exp_dir, "run.json")):
        run = load_json(os.path.join(exp_dir, "run.json"))
    threads = run.get("threads") if isinstance(run, dict) else None
    c["threads"] = threads if is_number(threads) else None
    n4 = out["scene"].get("fig4_steps")
    w4 = timing.get("fig4_wall_s")
    if is_number(w4) and c["threads"] and n4 and M:
        c["fig4_ns_per_step_thread"] = 1e9 * w4 * c["threads"] / (M * n4)
        c["fig4_steps_total"] = M * n4
    n6, w6 = out["fig6"].get("steps"), timing.get("fig6_wall_s")
    if is_number(w6) and c["threads"] and n6 and lM:
        c["fig6_ns_per_step_thread"] = 1e9 * w6 * c["threads"] / (lM * n6)
        c["fig6_steps_total"] = lM * n6
    return out


def ti_results_table(name, s, src, derived):
    """Published and reproduced values of ti_drift, and the reproduced values without a published one."""
    pub, rep, orders = s.get("published") or {}, s.get("reproduced") or {}, s.get("orders") or {}
    sources = {"summary": s, "derived": derived or {}}

    def cell(v, kind):
        if kind == "fixed12":
            return math_cell(f"{v:.12f}" if is_number(v) and math.isfinite(v) else None)
        if kind.startswith("len:"):
            return math_cell(fmt(len(v), kind[4:]) if isinstance(v, list) else None)
        return math_cell(fmt(v, kind))

    lines = [HEADER.format(src=src)]
    lines.append("\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
    lines.append(f"\\caption{{Published and reproduced values of {experiment_title(name)}. Orders: least-squares "
                 "slopes of $\\log(\\text{error})$ against $\\log(\\omega h_{\\text{eff}})$ over "
                 f"$\\omega h_{{\\text{{eff}}}}\\le{TI_FIT_MAX_WH:g}$ and the errors above $10^3$ machine epsilons; "
                 "published orders: the powers of $h$ stated in Sect.~1.4 of [004]; published slope of Fig.~3: "
                 "``no drift''; published exponent of Fig.~4: ``like the square root of time''. Difference = "
                 "reproduced $-$ published. Below the line: reproduced values without a published number "
                 "(the statements of [004] in brackets), and $\\sigma^2/t$ computed from the published $\\sigma$. $E=\\hat H+\\frac12h^4\\alpha^2K$ of (3.3) and (4.2); "
                 "$H_3$ of Fig.~2: that of TI in (3.3). Figs.~2--6 evaluate these at the unprocessed $(p_n,q_n)$.}\n")
    lines.append(f"\\label{{tab:{name}-table}}\n")
    lines.append("\\begin{tabular}{@{}p{0.50\\linewidth}rrr@{}}\n\\toprule\n")
    lines.append("Quantity & Published & Reproduced & Difference \\\\\n\\midrule\n")
    known = [k for k, _, _ in TI_PUBLISHED_ROWS]
    rows = [r for r in TI_PUBLISHED_ROWS if r[0] in pub]
    rows += [(k, tex_escape(k), "general") for k in pub if k not in known]
    for key, label, kind in rows:
        p = pub[key]
        r = orders[key] if key in orders else rep.get(key)
        if isinstance(p, dict):  # one row per parameter
            for sub, pv in p.items():
                rv = r.get(sub) if isinstance(r, dict) else None
                cells = [math_cell(general(pv)), math_cell(None if not is_number(rv) else general(rv)),
                         math_cell(None if not is_number(rv) else general(rv - pv))]
                lines.append(f"{label} (\\texttt{{{tex_escape(sub)}}}) & " + " & ".join(cells) + " \\\\\n")
            continue
        diff = r - p if is_number(r) and is_number(p) else None
        if kind == "order":
            cells = [math_cell(fmt(p, "porder")), cell(r, "order"), math_cell(fmt(diff, "dorder"))]
        elif kind == "general":
            cells = [math_cell(general(p)), math_cell(general(r) if is_number(r) else None),
                     math_cell(general(diff) if diff is not None else None)]
        else:
            dkind = "err" if kind in ("fixed12", "sci3") else kind
            cells = [cell(p, kind), cell(r, kind), cell(diff, dkind if diff != 0 else "plain")]
        lines.append(f"\\raggedright {label} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\midrule\n")
    has_lj = "lj_mu_final" in rep
    for label, path, kind, *pub_path in TI_EXTRA_ROWS:
        if label.startswith("Fig.~6") and not has_lj:
            continue
        v = lookup(sources.get(path[0]) or {}, path[1:])
        if pub_path:
            pv = lookup(sources.get(pub_path[0][0]) or {}, pub_path[0][1:])
            diff = v - pv if is_number(v) and is_number(pv) else None
            lines.append(f"\\raggedright {label} & {cell(pv, kind)} & {cell(v, kind)} & {cell(diff, 'err')} \\\\\n")
        else:
            lines.append(f"\\raggedright {label} & --- & {cell(v, kind)} & --- \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n\\end{table}\n")
    return "".join(lines)


def ti_timing_table(name, s, src, derived):
    """Cost of ti_drift: ns per step of the three methods and the wall time of the ensemble."""
    timing = s.get("timing") or {}
    ns = timing.get("ns_per_step") or {}
    c = (derived.get("td") or {}).get("cost") or {}
    lines = [HEADER.format(src=src)]
    if not isinstance(ns, dict) or not ns:
        lines.append("\\begin{center}\\small No timing recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    base = ns.get("sv") if is_number(ns.get("sv")) and ns["sv"] > 0 else None
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    lines.append(f"\\caption{{Cost of {experiment_title(name)}: time per step on the H\\'enon--Heiles problem "
                 "($k$ of Fig.~4, $h=0.2$, from the first start of the ensemble, no processing), the force "
                 "evaluations per step (the force at the end of a step is reused by the next one) and the "
                 "cost relative to St\\\"ormer--Verlet.}\n")
    lines.append(f"\\label{{tab:{name}-timing}}\n")
    lines.append("\\begin{tabular}{@{}llrr@{}}\n\\toprule\n")
    lines.append("Method & Evaluations per step & ns per step & Relative cost \\\\\n\\midrule\n")
    listed = [k for k, _, _ in TI_TIMING_ROWS]
    rows = [r for r in TI_TIMING_ROWS if r[0] in ns] + [(k, tex_escape(k), "") for k in ns if k not in listed]
    for key, label, evals in rows:
        v = ns.get(key)
        rel = v / base if is_number(v) and base else None
        lines.append(f"{label} & {evals} & {math_cell(fmt(v, 'ns'))} & {math_cell(fmt(rel, 'ratio'))} \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    notes = []
    if isinstance(timing.get("method"), str):
        notes.append("measurement: " + tex_escape(timing["method"]))
    w4 = timing.get("fig4_wall_s")
    if is_number(w4):
        text = f"the ensemble of Fig.~4 takes ${fmt(w4, 'seconds')}$\\,s"
        if is_number(c.get("threads")):
            text += f" on {int(c['threads'])} thread{'s' if c['threads'] != 1 else ''}"
        if is_number(c.get("fig4_steps_total")):
            text += f" for ${sci(c['fig4_steps_total'], 3)}$ steps"
        if is_number(c.get("fig4_ns_per_step_thread")):
            text += f", ${fmt(c['fig4_ns_per_step_thread'], 'ns')}$\\,ns per step and thread"
        notes.append(text)
    w6 = timing.get("fig6_wall_s")
    if is_number(w6):
        text = f"the ensemble of Fig.~6 (Lennard-Jones) takes ${fmt(w6, 'seconds')}$\\,s"
        if is_number(c.get("threads")):
            text += f" on {int(c['threads'])} thread{'s' if c['threads'] != 1 else ''}"
        if is_number(c.get("fig6_steps_total")):
            text += f" for ${sci(c['fig6_steps_total'], 3)}$ steps"
        if is_number(c.get("fig6_ns_per_step_thread")):
            text += f", ${fmt(c['fig6_ns_per_step_thread'], 'ns')}$\\,ns per step and thread"
        notes.append(text)
    if is_number(timing.get("wall_s")):
        notes.append(f"wall time of the whole run ${fmt(timing['wall_s'], 'seconds')}$\\,s")
    if notes:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize " + "; ".join(notes) + ".}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


# ---------------------------------------------------------------------------
# measure_cloud (003): Figs. 5.1-5.6 of the measure-preserving discretization of the
# nonholonomic particle. Two result directories: <root>/measure_cloud (harmonic potential:
# Figs. 5.1-5.4, the order study, the cost) and <root>/measure_cloud-free (free particle:
# Figs. 5.5, 5.6, the long run), the second paper scene (SCENE_VARIANTS).
# ---------------------------------------------------------------------------

MC_METHODS = ["M", "MT", "TM", "TT", "T"]
MC_GROUPS = {"": MC_METHODS, "Mid": ["M", "MT"], "Trap": ["TM", "TT", "T"]}  # quadrature of N
MC_ELLS = [0, 2, 4, 6]
MC_WORD = {0: "Zero", 2: "Two", 4: "Four", 6: "Six"}
MC_MEASURE_TEX = {0: r"\mu", 2: r"\mu^{(2)}_{\text{mod}}", 4: r"\mu^{(4)}_{\text{mod}}", 6: r"\mu^{(6)}_{\text{mod}}"}


def mc_measure(m):
    """Column/key suffix of the measure mu^(m)_mod (m = 0: mu itself)."""
    return "mu" if m == 0 else f"mu{m}"


def mc_ranges(d):
    """{group: {min, max, absmin, absmax}} over the methods of each MC_GROUPS group of a
    {method: number} object (groups with a missing value are left out)."""
    out = {}
    if not isinstance(d, dict):
        return out
    for g, ms in MC_GROUPS.items():
        vals = [d.get(m) for m in ms]
        if all(is_number(v) and math.isfinite(v) for v in vals):
            out[g or "all"] = {"min": min(vals), "max": max(vals),
                               "absmin": min(abs(v) for v in vals), "absmax": max(abs(v) for v in vals)}
    return out


def mc_per_method_ranges(tree):
    """mc_ranges of every {method: number} object of a JSON object, by key."""
    out = {}
    for k, v in (tree or {}).items() if isinstance(tree, dict) else ():
        if isinstance(v, dict) and any(m in v for m in MC_METHODS):
            out[k] = mc_ranges(v)
    return out


def mc_load_variant(path):
    """{"summary", "scene", "run"} of a second-scene directory, or None without its summary.json."""
    summary_path = os.path.join(path, "summary.json")
    if not os.path.isfile(summary_path):
        return None
    s = load_json(summary_path)
    if not isinstance(s, dict):
        raise Malformed(f"{summary_path}: top level must be a JSON object")
    for section in ("reproduced", "orders", "timing"):
        if s.get(section) is not None and not isinstance(s[section], dict):
            raise Malformed(f'{summary_path}: "{section}" must be an object')
    run = {}
    if os.path.isfile(os.path.join(path, "run.json")):
        run = load_json(os.path.join(path, "run.json"))
        run = run if isinstance(run, dict) else {}
    scene = run.get("scene") if isinstance(run.get("scene"), dict) else {}
    return {"summary": s, "scene": scene, "run": run}


def mc_summary(s, scene, exp_dir, variants=None):
    """Derived quantities of measure_cloud for the tables and macros (missing inputs give None).

    s, scene and exp_dir are those of the harmonic scene (None if it has no results);
    variants["free"] is mc_load_variant of the free-particle directory, or None."""
    s = s or {}
    sc = scene if isinstance(scene, dict) else {}
    rep = s.get("reproduced") or {}
    out = {"scene": {}, "scene_raw": sc, "ref": {}, "corr": {}, "raw": {}, "small": {}, "cost": {},
           "range": {}, "ratio": {}, "free": {}}

    def num(tree, *path):
        v = lookup(tree, path)
        return float(v) if is_number(v) else None

    h, window = num(sc, "h"), num(sc, "ptp_window")
    d = out["scene"]
    if h:
        d["h6"] = h ** 6
    dt, snaps = num(sc, "shape", "snapshot_dt"), num(sc, "shape", "snapshots")
    if dt is not None and snaps is not None:
        d["shape_t_end"] = dt * snaps
    te = num(sc, "energies", "t_end")
    if h and te:
        d["energy_steps"] = math.floor(te / h + 1e-9)
    if exp_dir and os.path.isfile(os.path.join(exp_dir, "run.json")):
        run = load_json(os.path.join(exp_dir, "run.json"))
        if isinstance(run, dict) and is_number(run.get("threads")):
            d["threads"] = run["threads"]
    phi = (1 + math.sqrt(5)) / 2
    d["hull_exact"] = 25 / 4 * (2 + math.sqrt(5)) / phi ** 4  # 600-cell of circumradius 1, edge 1/phi
    hv = rep.get("hull_volume_initial_over_r4")
    if is_number(hv):
        d["hull_rel_err"] = abs(hv / d["hull_exact"] - 1)

    # Figs. 5.2, 5.4: peak-to-peak over t <= window of V/V(0) - 1 in the method's own measure
    # mu^(ell)_mod, raw and minus the reference's (the convex-hull artefact, common to both)
    for ell in MC_ELLS:
        path = os.path.join(exp_dir, f"volumes_phi{ell}.csv") if exp_dir else None
        cols = ["t", "reference_mu"] + [f"{m}_{mc_measure(ell)}" for m in MC_METHODS]
        rows = read_csv_rows(path, cols) if path else None
        if not rows or window is None:
            continue
        vals = [v for v in csv_floats(rows, path, cols) if v[0] <= window + 1e-9]
        ref = [v[1] / vals[0][1] - 1 for v in vals]
        allref = [v[0] / vals[0][1] - 1 for v in csv_floats(rows, path, ["reference_mu"])]
        if not out["ref"]:
            out["ref"] = {"at_window": ref[-1], "at_end": allref[-1], "ptp": max(ref) - min(ref)}
        raw, corr = {}, {}
        for k, m in enumerate(MC_METHODS):
            rel = [v[2 + k] / vals[0][2 + k] - 1 for v in vals]
            raw[m] = max(rel) - min(rel)
            diff = [a - b for a, b in zip(rel, ref)]
            corr[m] = max(diff) - min(diff)
        out["raw"][str(ell)], out["corr"][str(ell)] = raw, corr

    # the order study: peak-to-peak at the largest step (r = order_study.radius)
    path = os.path.join(exp_dir, "order_study.csv") if exp_dir else None
    rows = read_csv_rows(path, ("method", "ell", "h", "ptp")) if path else None
    hs = lookup(sc, ("order_study", "h"))
    if rows and isinstance(hs, list) and hs and all(is_number(x) for x in hs):
        hmax = max(hs)
        for r, (ell, hh, p) in zip(rows, csv_floats(rows, path, ("ell", "h", "ptp"))):
            if abs(hh / hmax - 1) < 1e-12:
                out["small"].setdefault(str(int(ell)), {})[r["method"]] = p
    noise = rep.get("order_study_noise")
    if is_number(noise):
        out["scene"]["noise_floor"] = 2 * noise

    # cost: Phi^(4) from the centre for every order_study.h, N = floor(energies.t_end / h) steps, the
    # error taken at t_N = N h against the reference there; the table shows the errors of the step
    # sizes with t_N = energies.t_end.
    path = os.path.join(exp_dir, "timing_cost.csv") if exp_dir else None
    cols = ("method", "h", "steps", "err", "wall_s", "ns_per_step", "newton_iterations_per_step")
    rows = read_csv_rows(path, cols) if path else None
    if rows and te:
        per = {}
        for r, v in zip(rows, csv_floats(rows, path, cols[1:])):
            per.setdefault(r["method"], []).append(dict(zip(cols[1:], v)))
        c = out["cost"]
        c["exact"], c["iters_first"], c["order"] = {}, {}, {}
        for m, runs in per.items():
            runs.sort(key=lambda x: -x["h"])
            exact = [x for x in runs if abs(x["steps"] * x["h"] / te - 1) < 1e-9]
            c["exact"][m] = [(x["h"], x["err"]) for x in exact]
            if h is not None:
                first = [x for x in runs if abs(x["h"] / h - 1) < 1e-12]
                if first:
                    c["iters_first"][m] = first[0]["newton_iterations_per_step"]
            pts = [(math.log(x["h"]), math.log(x["err"])) for x in runs if x["h"] > 0 and x["err"] > 0]
            slope = ti_slope([a for a, _ in pts], [b for _, b in pts]) if len(pts) >= 2 else None
            if slope is not None:
                c["order"][m] = slope
        c["exact_h"] = sorted({x[0] for m in c["exact"] for x in c["exact"][m]}, reverse=True)
        c["fit_count"] = len({x["h"] for runs in per.values() for x in runs})

    def ratio(a, b):
        """{method: a/b} of two {method: value}, or None."""
        if not (isinstance(a, dict) and isinstance(b, dict)):
            return None
        return {m: a[m] / b[m] for m in MC_METHODS if is_number(a.get(m)) and is_number(b.get(m)) and b[m]}

    # ratios per method
    q = ratio(rep.get("ptp_phi0_mu4"), rep.get("ptp_phi4_mu4"))
    if q is not None:
        out["ratio"]["zero_over_four_mu4"] = q

    # the free particle (second scene)
    fv = (variants or {}).get("free")
    if fv:
        fs, fsc = fv["summary"], fv["scene"]
        frep = fs.get("reproduced") or {}
        f = out["free"]
        f["reproduced"] = frep
        f["timing"] = fs.get("timing") or {}
        f["scene"] = fsc
        for key, stem in (("err_ratio", "err_at_t_end"), ("long_err_ratio", "long_err"),
                          ("max_H_ratio", "max_abs_H_err")):
            q = ratio(frep.get(f"{stem}_phi0"), frep.get(f"{stem}_phi4"))
            if q is not None:
                f[key] = q
        f["range"] = mc_per_method_ranges(frep)
        for k in ("err_ratio", "long_err_ratio", "max_H_ratio"):
            if k in f:
                f["range"][k] = mc_ranges(f[k])
        wall = (fs.get("timing") or {}).get("wall_s")
        f["wall_s"] = wall if is_number(wall) else None

    # ranges over the methods
    rg = out["range"]
    rg.update(mc_per_method_ranges(rep))
    rg.update({f"order_{k}": v for k, v in mc_per_method_ranges(s.get("orders") or {}).items()})
    for ell in MC_ELLS:
        for src_key, tree in (("raw", out["raw"]), ("corr", out["corr"]), ("small", out["small"])):
            if str(ell) in tree:
                rg[f"{src_key}_{ell}"] = mc_ranges(tree[str(ell)])
    for k, v in out["ratio"].items():
        rg[f"ratio_{k}"] = mc_ranges(v)
    fits = s.get("fits") or {}
    for ell in MC_ELLS:
        pts = {m: lookup(fits, (f"measure_ell{ell}", m, "points")) for m in MC_METHODS}
        rg[f"fit_points_{ell}"] = mc_ranges(pts)
    rg["ns_per_step"] = mc_ranges((s.get("timing") or {}).get("ns_per_step"))
    rg["iters_first"] = mc_ranges(out["cost"].get("iters_first"))
    rg["cost_order"] = mc_ranges(out["cost"].get("order"))
    return out


# Rows of the published-vs-reproduced table: (description, published statement, source, kind).
# source: ("sum", key) summary["reproduced"][key][method]; ("derived", tree, key...) a
# {method: value} of mc_summary; ("free", key) the free run's reproduced[key][method];
# ("order", key) summary["orders"][key][method]; ("one", path) one value for all methods;
# None: a group heading.
MC_TABLE_ROWS = [
    (r"\emph{Harmonic potential, 600-cell cloud, $r=@R@$ (Figs.~5.2, 5.4): ptp of $V(t)/V(0)-1$, "
     r"$t\le@W@$}", None, None, None),
    (r"Reference flow, in $\mu$", r"``nicely preserves'' until $t\approx20$",
     ("one", ("summary", "reproduced", "ptp_reference_mu")), "sci"),
    (r"$\Phi^{(4)}_h$, in $\mu$", r"oscillates", ("sum", "ptp_phi4_mu"), "sci"),
    (r"$\Phi^{(4)}_h$, in $\mu^{(2)}_{\text{mod}}$", r"smaller", ("sum", "ptp_phi4_mu2"), "sci"),
    (r"$\Phi^{(4)}_h$, in $\mu^{(4)}_{\text{mod}}$", "PTP4", ("sum", "ptp_phi4_mu4"), "sci"),
    (r"\quad minus the reference (hull artefact removed)", r"---", ("derived", "corr", "4"), "sci"),
    (r"$\Phi^{(0)}_h$, in $\mu$", r"large oscillations", ("sum", "ptp_phi0_mu"), "sci"),
    (r"$\Phi^{(0)}_h$, in $\mu^{(2)}_{\text{mod}}$", r"that do not", ("sum", "ptp_phi0_mu2"), "sci"),
    (r"$\Phi^{(0)}_h$, in $\mu^{(4)}_{\text{mod}}$", r"diminish", ("sum", "ptp_phi0_mu4"), "sci"),
    (r"\emph{Harmonic potential, from $z_0$, $t\le@TE@$ (Fig.~5.3)}", None, None, None),
    (r"$\Phi^{(4)}_h$: $\max_t|K^{(4)}_{\text{mod}}|$", r"order $h^6\approx2\cdot10^{-4}$ or smaller",
     ("sum", "max_abs_K_mod4_phi4"), "sci01"),
    (r"$\Phi^{(4)}_h$: $\max_t|H-H_0|$", r"close to $H_0=1$", ("sum", "max_abs_H_err_phi4"), "sci01"),
    (r"$|H(@TE@)-H_0|$ of $\Phi^{(0)}_h$ over that of $\Phi^{(4)}_h$", r"little difference",
     ("sum", "harmonic_H_drift_ratio"), "sig3"),
    (r"\emph{Free particle, from $z_0$, $t\le@FTE@$ (Figs.~5.5, 5.6)}", None, None, None),
    (r"$\Phi^{(4)}_h$: $\max_t|K^{(4)}_{\text{mod}}|$", r"very close to zero", ("free", "max_abs_K_mod4_phi4"), "sci01"),
    (r"$\Phi^{(0)}_h$: $\max_t|K^{(4)}_{\text{mod}}|$", r"not so close to zero", ("free", "max_abs_K_mod4_phi0"), "sci01"),
    (r"$\Phi^{(4)}_h$: $|H(@FTE@)-H_0|$", r"very little drift", ("free", "H_err_at_t_end_phi4"), "sci01"),
    (r"$\Phi^{(0)}_h$: $|H(@FTE@)-H_0|$", r"drift", ("free", "H_err_at_t_end_phi0"), "sci01"),
    (r"\quad the same over that of $\Phi^{(4)}_h$", r"---", ("free", "free_H_drift_ratio"), "sig3"),
    (r"$\Phi^{(4)}_h$: error $\|z_j-z(t_j)\|_2$ at $t=@FTE@$", r"outperforms $\Phi^{(0)}_h$", ("free", "err_at_t_end_phi4"), "sci01"),
    (r"$\Phi^{(0)}_h$: error at $t=@FTE@$", r"faster growth", ("free", "err_at_t_end_phi0"), "sci01"),
    (r"\emph{Free particle, long run to $T=@T@$ (not in [003])}", None, None, None),
    (r"$\Phi^{(4)}_h$: $H(T)-H_0$", r"---", ("free", "long_H_err_phi4"), "sci01"),
    (r"$\Phi^{(0)}_h$: $H(T)-H_0$", r"---", ("free", "long_H_err_phi0"), "sci01"),
    (r"$\Phi^{(4)}_h$: error at $T$", r"---", ("free", "long_err_phi4"), "sci01"),
    (r"$\Phi^{(0)}_h$: error at $T$", r"---", ("free", "long_err_phi0"), "sci01"),
    (r"\emph{Order of preservation of $\mu^{(\ell)}_{\text{mod}}$ by $\Phi^{(\ell)}_h$ (Cor.~4.3), $r=@RS@$}",
     None, None, None),
    (r"$\ell=0$", r"$2$", ("order", "measure_ell0"), "order"),
    (r"$\ell=2$", r"$4$", ("order", "measure_ell2"), "order"),
    (r"$\ell=4$", r"$6$", ("order", "measure_ell4"), "order"),
    (r"$\ell=6$ (terms of order $h^6$ not used in [003])", r"($8$)", ("order", "measure_ell6"), "order"),
]


def mc_scene_tokens(derived):
    """Values of the scenes that the generated table texts cite ("@H@" -> 0.25, ...)."""
    mc = (derived or {}).get("mc") or {}
    sc = mc.get("scene_raw") or {}
    fsc = lookup(mc, ("free", "scene")) or {}

    def tok(tree, path, kind):
        v = lookup(tree, path)
        if kind in ("vec", "max"):
            ok = isinstance(v, list) and v and all(is_number(x) for x in v)
            if kind == "max":
                return fmt(max(v), "plain") if ok else NA
            return "(" + ",".join(f"{x:g}" for x in v) + ")" if ok else NA
        c = fmt(v, kind)
        return NA if c is None else c

    return {"@H@": tok(sc, ("h",), "plain"), "@R@": tok(sc, ("cloud", "radius"), "plain"),
            "@W@": tok(sc, ("ptp_window",), "plain"), "@TE@": tok(sc, ("energies", "t_end"), "plain"),
            "@FTE@": tok(fsc, ("energies", "t_end"), "plain"), "@T@": tok(fsc, ("long_run", "t_end"), "plain"),
            "@RS@": tok(sc, ("order_study", "radius"), "tol"), "@Z0@": tok(sc, ("cloud", "center"), "vec"),
            "@HMAX@": tok(sc, ("order_study", "h"), "max")}


def mc_subst(text, tokens):
    for k, v in tokens.items():
        text = text.replace(k, v)
    return text


def mc_results_table(name, s, src, derived):
    """Published statements of 003 Sec. 5 beside the reproduced values of the five methods."""
    mc = (derived or {}).get("mc") or {}
    rep, orders = s.get("reproduced") or {}, s.get("orders") or {}
    frep = (mc.get("free") or {}).get("reproduced") or {}
    pub_per_method = (s.get("published") or {}).get("ptp_phi4_mu4") or {}
    pub = next((v for v in pub_per_method.values() if is_number(v)), None)  # the same for every method
    tokens = mc_scene_tokens(derived)
    lines = [HEADER.format(src=src)]
    lines.append("\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
    free_note = ("" if frep else
                 " (free particle: no results, \\texttt{results/measure\\_cloud-free/summary.json} is missing)")
    lines.append(mc_subst(
        "\\caption{Published statements of Section~5 of [003] and the reproduced values of "
        f"{experiment_title(name)} for the five discrete Lagrangians (5.1), $h=@H@$, $z_0=@Z0@${free_note}. "
        "The column [003] quotes the text of the paper; its only number, the fluctuation in "
        "$\\mu^{(4)}_{\\text{mod}}$ of Fig.~5.2, is read off the plot. Peak-to-peak (ptp) values are relative "
        "to the initial volume in the same measure. $H_0=H(z_0)=1$; error: $\\|z_j-z(t_j)\\|_2$ against "
        "the reference. Orders: least-squares slopes of the peak-to-peak value against $h$ "
        "(Table~\\ref{tab:measure_cloud-orders}).}\n", tokens))
    lines.append(f"\\label{{tab:{name}-table}}\n")
    lines.append("\\setlength{\\tabcolsep}{3pt}\n")
    lines.append("\\begin{tabular}{@{}p{0.27\\linewidth}p{0.15\\linewidth}rrrrr@{}}\n\\toprule\n")
    lines.append("Quantity & [003] & M & MT & TM & TT & T \\\\\n\\midrule\n")
    first = True
    for label, published, source, kind in MC_TABLE_ROWS:
        label = mc_subst(label, tokens)
        if source is None:
            if not first:
                lines.append("\\addlinespace\n")
            lines.append(f"\\multicolumn{{7}}{{@{{}}l}}{{{label}}} \\\\\n")
            first = False
            continue
        if published == "PTP4":
            published = (f"about ${sci(pub, 1)}$ (read off)" if is_number(pub) else NA)
        if source[0] == "one":
            v = lookup(s, source[1][1:]) if source[1][0] == "summary" else None
            cells = [f"\\multicolumn{{5}}{{c}}{{{math_cell(fmt(v, kind))}}}"]
        else:
            if source[0] == "sum":
                d = rep.get(source[1])
            elif source[0] == "free":
                d = frep.get(source[1])
            elif source[0] == "order":
                d = orders.get(source[1])
            else:
                d = lookup(mc, source[1:])
            d = d if isinstance(d, dict) else {}
            if kind == "sci01":  # one notation per row: scientific if any value is below 0.01
                small = any(is_number(d.get(m)) and abs(d[m]) < 1e-2 for m in MC_METHODS)
                kind = "sci" if small else "sci01"
            cells = [math_cell(fmt(d.get(m), kind)) for m in MC_METHODS]
        lines.append(f"\\raggedright {label} & \\raggedright {published} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n\\end{table}\n")
    return "".join(lines)


def mc_orders_table(name, s, src, derived):
    """The order of measure preservation per method and ell, with the peak-to-peak values at
    h = 0.25 on the tiny cloud and on the paper's cloud (raw and minus the reference)."""
    mc = (derived or {}).get("mc") or {}
    orders, fits = s.get("orders") or {}, s.get("fits") or {}
    sc = mc.get("scene") or {}
    lines = [HEADER.format(src=src)]
    if not orders:
        lines.append("\\begin{center}\\small No order study recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    lines.append("\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
    floor = sc.get("noise_floor")
    floor_text = f"${fmt(floor, 'sci')}$" if is_number(floor) else NA
    tokens = mc_scene_tokens(derived)
    lines.append(mc_subst(
        "\\caption{Order of measure preservation (not a table of [003]): $\\Phi^{(\\ell)}_h$ in its own "
        "measure $\\mu^{(\\ell)}_{\\text{mod}}$, harmonic potential, peak-to-peak of $V(t)/V(0)-1$ over "
        "$t\\le@W@$. Order: least-squares slope against $h$ on 600-cell clouds of radius $@RS@$, "
        "in brackets the number of step sizes above twice the measured round-off noise "
        f"({floor_text}) that enter the fit. Then the peak-to-peak value at $h=@HMAX@$ on that cloud, and on "
        "the paper's cloud of radius $@R@$ (at $h=@H@$) minus the reference's peak-to-peak (the convex-hull "
        "artefact), and as measured.}\n", tokens))
    lines.append(f"\\label{{tab:{name}-orders}}\n")
    lines.append("\\setlength{\\tabcolsep}{4pt}\n")
    lines.append("\\begin{tabular}{@{}clrrrrr@{}}\n\\toprule\n")
    lines.append("$\\ell$ & Quantity & M & MT & TM & TT & T \\\\\n\\midrule\n")
    for i, ell in enumerate(MC_ELLS):
        if i:
            lines.append("\\addlinespace\n")
        key = f"measure_ell{ell}"
        o = orders.get(key) if isinstance(orders.get(key), dict) else {}
        cells = []
        for m in MC_METHODS:
            v, pts = o.get(m), lookup(fits, (key, m, "points"))
            c = math_cell(fmt(v, "order"))
            if is_number(v) and is_number(pts):
                c += f"\\,({int(pts)})"
            cells.append(c)
        expected = f"$\\ell+2={ell + 2}$"
        lines.append(f"${ell}$ & order (expected {expected}) & " + " & ".join(cells) + " \\\\\n")
        for label, tree in (("$r=@RS@$, $h=@HMAX@$", "small"), ("$r=@R@$ minus reference", "corr"),
                            ("$r=@R@$, as measured", "raw")):
            label = mc_subst(label, tokens)
            d = (mc.get(tree) or {}).get(str(ell)) or {}
            lines.append(f" & {label} & " + " & ".join(math_cell(fmt(d.get(m), "sci")) for m in MC_METHODS)
                         + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n\\end{table}\n")
    return "".join(lines)


def mc_timing_table(name, s, src, derived):
    """Cost of measure_cloud: ns and Newton iterations per step of Phi^(4), and its error at t = 10."""
    mc = (derived or {}).get("mc") or {}
    timing = s.get("timing") or {}
    ns = timing.get("ns_per_step") or {}
    c = mc.get("cost") or {}
    lines = [HEADER.format(src=src)]
    if not isinstance(ns, dict) or not ns:
        lines.append("\\begin{center}\\small No timing recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    hexact = c.get("exact_h") or []
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    tokens = mc_scene_tokens(derived)
    order_text = (f"the least-squares slope of $\\log(\\text{{error}})$ against $\\log h$ over all "
                  f"{fmt(c.get('fit_count'), 'int') or NA} step sizes of the order study, each error taken at "
                  "the last step $t_N=\\lfloor @TE@/h\\rfloor h$ against the reference there")
    lines.append(mc_subst(
        f"\\caption{{Cost of {experiment_title(name)}: time of one step of $\\Phi^{{(4)}}_h$ (Newton's method on "
        "the discrete momentum equation, exact $2\\times2$ Jacobian by forward-mode automatic "
        "differentiation) at $h=@H@$ on the harmonic particle from $z_0=@Z0@$, median of the timed runs on one "
        "thread; the Newton iterations per step there; the error at $t=@TE@$ for the step sizes that divide "
        f"@TE@; and the order, {order_text}.}}\n", tokens))
    lines.append(f"\\label{{tab:{name}-timing}}\n")
    lines.append("\\begin{tabular}{@{}lrr" + "r" * len(hexact) + "r@{}}\n\\toprule\n")
    hcells = " & ".join(f"$h={fmt(x, 'plain')}$" for x in hexact)
    lines.append(f"Method & ns per step & Newton iterations & "
                 + (mc_subst(f"\\multicolumn{{{len(hexact)}}}{{c}}{{Error at $t=@TE@$}} & ", tokens) if hexact else "")
                 + "Order \\\\\n")
    if hexact:
        lines.append(f"\\cmidrule(lr){{4-{3 + len(hexact)}}}\n")
    lines.append(" & & per step & " + (hcells + " & " if hexact else "") + " \\\\\n\\midrule\n")
    errs = c.get("exact") or {}
    for m in MC_METHODS:
        e = dict(errs.get(m) or [])
        cells = [math_cell(fmt(ns.get(m), "ns3")), math_cell(fmt((c.get("iters_first") or {}).get(m), "sig3"))]
        cells += [math_cell(fmt(e.get(x), "sci")) for x in hexact]
        cells.append(math_cell(fmt((c.get("order") or {}).get(m), "order")))
        lines.append(f"{m} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    notes = []
    if is_number(timing.get("newton_iterations_mean")):
        notes.append(f"Newton iterations per step over all runs of the harmonic scene: "
                     f"${fmt(timing['newton_iterations_mean'], 'sig3')}$")
    fnewton = lookup(mc, ("free", "timing", "newton_iterations_mean"))
    if is_number(fnewton):
        notes.append(f"free particle: ${fmt(fnewton, 'sig3')}$")
    if is_number(timing.get("wall_s")):
        text = f"wall time of the harmonic run ${fmt(timing['wall_s'], 'seconds')}$\\,s"
        threads = lookup(mc, ("scene", "threads"))
        if is_number(threads):
            text += f" on {int(threads)} thread{'s' if threads != 1 else ''}"
        notes.append(text)
    if notes:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize " + "; ".join(notes) + ".}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


# Experiment-specific derived quantities (derived[key] = function(summary, scene, exp_dir)) and
# published-vs-reproduced tables (function(name, summary, summary_path, derived)).
DERIVED_SUMMARIES = {"lobatto_table": ("lt", lobatto_summary), "ti_drift": ("td", ti_summary),
                     "measure_cloud": ("mc", mc_summary)}
RESULTS_TABLES = {"lobatto_table": lobatto_results_table, "ti_drift": ti_results_table,
                  "measure_cloud": mc_results_table}
# Timing tables of their own (function(name, summary, summary_path, derived)).
TIMING_TABLES = {"ti_drift": ti_timing_table, "measure_cloud": mc_timing_table}
# Further tables of an experiment: {suffix: function(name, summary, summary_path, derived)},
# written to OUT_DIR/<name>_<suffix>.tex (placeholders without results).
EXTRA_TABLES = {"measure_cloud": {"orders": mc_orders_table}}
# Second paper scenes: RESULTS_ROOT/<name>-<variant> is read together with <name> (its
# quantities enter <name>'s tables and macros) and is not an experiment of its own. The
# derived-summary function of <name> gets them as variants={variant: {"summary", "scene",
# "run"} or None}.
SCENE_VARIANTS = {"measure_cloud": ["free"]}
# Published keys whose reproduced counterpart has another key and shape:
# Macros the text cites: (name, path into summary.json or a derived quantity, format).
# A path starts with "summary", "scene" (run.json's resolved scene) or "derived".
MACROS = {
    "euler_compensation": [
        ("ECeeDecayOrder", ("summary", "orders", "ee_decay"), "order"),
        ("ECeeGompertzOrder", ("summary", "orders", "ee_gompertz"), "order"),
        ("ECseOrder", ("summary", "orders", "se_energy"), "order"),
        ("ECcompOrder", ("summary", "orders", "se_compensated_energy"), "order"),
        ("ECrkOrder", ("summary", "orders", "rk4_energy"), "order"),
        ("ECseRmsOrder", ("summary", "orders", "se_energy_rms"), "order"),
        ("ECcompRmsOrder", ("summary", "orders", "se_compensated_energy_rms"), "order"),
        ("ECfitPoints", ("summary", "fits", "se_energy", "points"), "int"),
        ("ECfitHmin", ("summary", "fits", "se_energy", "h_min"), "plain"),
        ("ECfitHmax", ("summary", "fits", "se_energy", "h_max"), "plain"),
        ("ECdecayCompErr", ("summary", "reproduced", "decay_compensated_max_rel_err"), "err"),
        ("ECdecayEulerErr", ("summary", "reproduced", "decay_euler_max_rel_err"), "err"),
        ("ECgompertzCompErr", ("summary", "reproduced", "gompertz_compensated_max_rel_err"), "err"),
        ("ECgompertzEulerErr", ("summary", "reproduced", "gompertz_euler_max_rel_err"), "err"),
        ("ECfigEightSeErr", ("summary", "reproduced", "fig8_max_energy_err_se"), "err"),
        ("ECfigEightCompErr", ("summary", "reproduced", "fig8_max_energy_err_compensated"), "err"),
        ("ECfigEightQhat", ("summary", "reproduced", "fig8_max_abs_qhat"), "fixed3"),
        ("ECnsSe", ("summary", "timing", "ns_per_step", "se"), "ns"),
        ("ECnsComp", ("summary", "timing", "ns_per_step", "se_compensated"), "ns"),
        ("ECnsRk", ("summary", "timing", "ns_per_step", "rk4"), "ns"),
        ("ECratio", ("summary", "timing", "ns_per_step_ratio_compensated_over_se"), "ratio"),
        ("ECeqWall", ("summary", "timing", "error_at_equal_wall_time", "wall_s"), "sci"),
        ("ECeqErrSe", ("summary", "timing", "error_at_equal_wall_time", "se"), "err"),
        ("ECeqErrComp", ("summary", "timing", "error_at_equal_wall_time", "se_compensated"), "err"),
        ("ECeqErrRk", ("summary", "timing", "error_at_equal_wall_time", "rk4"), "err"),
        ("ECrunWall", ("summary", "timing", "wall_s"), "seconds"),
        ("ECcrossWall", ("derived", "crossover", "wall_s"), "sci"),
        ("ECcrossErr", ("derived", "crossover", "err"), "err"),
        ("ECdecayAlpha", ("scene", "decay", "alpha"), "plain"),
        ("ECdecayYzero", ("scene", "decay", "y0"), "plain"),
        ("ECdecayH", ("scene", "decay", "h"), "plain"),
        ("ECdecaySteps", ("scene", "decay", "steps"), "int"),
        ("ECgompertzA", ("scene", "gompertz", "a"), "plain"),
        ("ECgompertzB", ("scene", "gompertz", "b"), "plain"),
        ("ECgompertzYzero", ("scene", "gompertz", "y0"), "plain"),
        ("ECgompertzH", ("scene", "gompertz", "h"), "plain"),
        ("ECgompertzSteps", ("scene", "gompertz", "steps"), "int"),
        ("ECoscQzero", ("scene", "oscillator", "q0"), "plain"),
        ("ECoscPzero", ("scene", "oscillator", "p0"), "plain"),
        ("ECoscH", ("scene", "oscillator", "h"), "plain"),
        ("ECoscK", ("scene", "oscillator", "k"), "plain"),
        ("ECoscSteps", ("scene", "oscillator", "steps"), "int"),
        ("ECtEnd", ("scene", "convergence", "t_end"), "plain"),
        ("ECtimingHmax", ("scene", "timing", "h"), "max:err"),
        ("ECtimingHmin", ("scene", "timing", "h"), "min:err"),
        ("ECtimingSteps", ("scene", "timing", "steps"), "int"),
        ("ECtimingRepeats", ("scene", "timing", "repeats"), "int"),
    ],
    "rowlands_convergence": [
        # scene (run.json)
        ("RCl", ("scene", "pendulum", "l"), "plain"),
        ("RCm", ("scene", "pendulum", "m"), "plain"),
        ("RCk", ("scene", "pendulum", "k"), "plain"),
        ("RCg", ("scene", "pendulum", "g"), "plain"),
        ("RCyEq", ("derived", "scene", "y_equilibrium"), "plain"),
        ("RCtEnd", ("scene", "t_end"), "plain"),
        ("RChMax", ("scene", "h"), "max:plain"),
        ("RChMin", ("scene", "h"), "min:plain"),
        ("RChCount", ("scene", "h"), "len:int"),
        ("RCicOne", ("scene", "initial", 0), "vec"),
        ("RCicTwo", ("scene", "initial", 1), "vec"),
        ("RCicThree", ("scene", "initial", 2), "vec"),
        ("RCicCount", ("scene", "initial"), "len:int"),
        ("RCrtol", ("scene", "reference", "rtol"), "tol"),
        ("RCatol", ("scene", "reference", "atol"), "tol"),
        ("RCtimingRepeats", ("scene", "timing", "repeats"), "int"),
        # fitted orders, first initial condition (the one drawn)
        ("RCsvEnergyOrder", ("summary", "orders", "sv_energy"), "order"),
        ("RCsvEnergyMaxOrder", ("summary", "orders", "sv_energy_max"), "order"),
        ("RCsvPhaseOrder", ("summary", "orders", "sv_phase"), "order"),
        ("RCrowEnergyOrder", ("summary", "orders", "rowlands_energy"), "order"),
        ("RCrowEnergyMaxOrder", ("summary", "orders", "rowlands_energy_max"), "order"),
        ("RCrowPhaseOrder", ("summary", "orders", "rowlands_phase"), "order"),
        ("RCcheapEnergyOrder", ("summary", "orders", "rowlands_cheap_energy"), "order"),
        ("RCcheapPhaseOrder", ("summary", "orders", "rowlands_cheap_phase"), "order"),
        ("RCkernelEnergyOrder", ("summary", "orders", "kernel_unprocessed_energy"), "order"),
        ("RCkernelPhaseOrder", ("summary", "orders", "kernel_unprocessed_phase"), "order"),
        ("RCprintedEnergyOrder", ("summary", "orders", "rowlands_printed_energy"), "order"),
        ("RCprintedPhaseOrder", ("summary", "orders", "rowlands_printed_phase"), "order"),
        # ranges over all initial conditions (ORDER_TABLES groups)
        ("RCsecondOrderMin", ("derived", "order_range", "second", "min"), "order"),
        ("RCsecondOrderMax", ("derived", "order_range", "second", "max"), "order"),
        ("RCfourthOrderMin", ("derived", "order_range", "fourth", "min"), "order"),
        ("RCfourthOrderMax", ("derived", "order_range", "fourth", "max"), "order"),
        # fit ranges (first initial condition)
        ("RCfitPointsSecond", ("summary", "fits", "sv_phase", "points"), "int"),
        ("RCfitHminSecond", ("summary", "fits", "sv_phase", "h_min"), "plain"),
        ("RCfitPointsFourth", ("summary", "fits", "rowlands_phase", "points"), "int"),
        ("RCfitHminFourth", ("summary", "fits", "rowlands_phase", "h_min"), "plain"),
        # reference
        ("RCrefSelfCheck", ("summary", "reproduced", "reference_self_check"), "err"),
        ("RCrefMargin", ("summary", "reproduced", "reference_margin"), "int"),
        # h^2/24 against the unprocessed kernel (ERROR_RATIOS)
        ("RCprintedKernelRatioMin", ("derived", "error_ratio", "min"), "sig7"),
        ("RCprintedKernelRatioMax", ("derived", "error_ratio", "max"), "sig7"),
        ("RCprintedKernelRatioH", ("derived", "error_ratio", "h"), "plain"),
        # cost (summary timing and timing.csv via COST_TARGETS)
        ("RCrunWall", ("summary", "timing", "wall_s"), "seconds"),
        ("RCnsSv", ("summary", "timing", "ns_per_step", "sv"), "ns"),
        ("RCnsRow", ("summary", "timing", "ns_per_step", "rowlands"), "ns"),
        ("RCnsCheap", ("summary", "timing", "ns_per_step", "rowlands_cheap"), "ns"),
        ("RCnsRk", ("summary", "timing", "ns_per_step", "odeint_rk4"), "ns"),
        ("RCnsRkn", ("summary", "timing", "ns_per_step", "odeint_rkn_sb3a"), "ns"),
        ("RCnsVv", ("summary", "timing", "ns_per_step", "odeint_velocity_verlet"), "ns"),
        ("RCratio", ("summary", "timing", "ns_per_step_ratio_rowlands_over_sv"), "ratio"),
        ("RCevalsSv", ("derived", "cost", "sv", "evals_per_step"), "ratio"),
        ("RCevalsRow", ("derived", "cost", "rowlands", "evals_per_step"), "ratio"),
        ("RCevalsRk", ("derived", "cost", "odeint_rk4", "evals_per_step"), "ratio"),
        ("RCevalsRkn", ("derived", "cost", "odeint_rkn_sb3a", "evals_per_step"), "ratio"),
        ("RCsvMinPhase", ("derived", "cost", "sv", "min_err"), "err"),
        ("RCwallSvEsix", ("derived", "cost", "sv", "wall_to", "1e-06"), "us"),
        ("RCwallRowEsix", ("derived", "cost", "rowlands", "wall_to", "1e-06"), "us"),
        ("RCwallRkEsix", ("derived", "cost", "odeint_rk4", "wall_to", "1e-06"), "us"),
        ("RCwallRknEsix", ("derived", "cost", "odeint_rkn_sb3a", "wall_to", "1e-06"), "us"),
        ("RCwallRowEeight", ("derived", "cost", "rowlands", "wall_to", "1e-08"), "us"),
        ("RCwallCheapEeight", ("derived", "cost", "rowlands_cheap", "wall_to", "1e-08"), "us"),
        ("RCwallRkEeight", ("derived", "cost", "odeint_rk4", "wall_to", "1e-08"), "us"),
        ("RCwallRknEeight", ("derived", "cost", "odeint_rkn_sb3a", "wall_to", "1e-08"), "us"),
        ("RCevalsSvEsix", ("derived", "cost", "sv", "evals_to", "1e-06"), "int"),
        ("RCevalsRowEsix", ("derived", "cost", "rowlands", "evals_to", "1e-06"), "int"),
        ("RCevalsRowEeight", ("derived", "cost", "rowlands", "evals_to", "1e-08"), "int"),
        ("RCevalsCheapEeight", ("derived", "cost", "rowlands_cheap", "evals_to", "1e-08"), "int"),
        ("RCevalsRkEeight", ("derived", "cost", "odeint_rk4", "evals_to", "1e-08"), "int"),
        ("RCevalsRknEeight", ("derived", "cost", "odeint_rkn_sb3a", "evals_to", "1e-08"), "int"),
        ("RCeqWall", ("derived", "equal_wall_s"), "us"),
        ("RCeqErrSv", ("derived", "cost", "sv", "err_at_equal_wall"), "err"),
        ("RCeqErrRow", ("derived", "cost", "rowlands", "err_at_equal_wall"), "err"),
        ("RCeqErrCheap", ("derived", "cost", "rowlands_cheap", "err_at_equal_wall"), "err"),
        ("RCeqErrRk", ("derived", "cost", "odeint_rk4", "err_at_equal_wall"), "err"),
        ("RCeqErrRkn", ("derived", "cost", "odeint_rkn_sb3a", "err_at_equal_wall"), "err"),
        ("RCeqErrVv", ("derived", "cost", "odeint_velocity_verlet", "err_at_equal_wall"), "err"),
    ],
    "energy_map": [
        # scene (run.json) and run
        ("EMl", ("scene", "pendulum", "l"), "plain"),
        ("EMm", ("scene", "pendulum", "m"), "plain"),
        ("EMk", ("scene", "pendulum", "k"), "plain"),
        ("EMg", ("scene", "pendulum", "g"), "plain"),
        ("EMdt", ("scene", "dt"), "plain"),
        ("EMdtOmega", ("derived", "scene", "dt_times_omega"), "plain"),
        ("EMtMax", ("scene", "t_max"), "int"),
        ("EMxMin", ("scene", "grid", "x_min"), "plain"),
        ("EMxMax", ("scene", "grid", "x_max"), "plain"),
        ("EMyMin", ("scene", "grid", "y_min"), "plain"),
        ("EMyMax", ("scene", "grid", "y_max"), "plain"),
        ("EMdx", ("derived", "scene", "dx"), "plain"),
        ("EMblowup", ("scene", "divergence", "blowup"), "tol"),
        ("EMhThreshold", ("derived", "scene", "H_threshold"), "plain"),
        ("EMfiHmax", ("scene", "first_integrals", "h"), "max:plain"),
        ("EMfiHmin", ("scene", "first_integrals", "h"), "min:plain"),
        ("EMfiHcount", ("scene", "first_integrals", "h"), "len:int"),
        ("EMfiIcCount", ("scene", "first_integrals", "initial"), "len:int"),
        ("EMfiIcOne", ("scene", "first_integrals", "initial", 0), "vec"),
        ("EMfiSteps", ("scene", "first_integrals", "steps"), "int"),
        ("EMqEnd", ("derived", "scene", "L_q_end"), "ns3"),
        ("EMLroundoff", ("derived", "scene", "L_eval_roundoff"), "err"),
        ("EMscalarPoints", ("scene", "timing", "scalar_points"), "int"),
        ("EMscalarSteps", ("scene", "timing", "scalar_steps"), "int"),
        ("EMthreads", ("derived", "kernel", "threads"), "int"),
        # grid and summary
        ("EMnx", ("summary", "grid", "nx"), "int"),
        ("EMny", ("summary", "grid", "ny"), "int"),
        ("EMpoints", ("summary", "grid", "points"), "int"),
        ("EMsteps", ("summary", "grid", "steps"), "int"),
        ("EMagreement", ("summary", "reproduced", "boundary_agreement"), "percent"),
        ("EMpolarBetter", ("summary", "reproduced", "fraction_polar_better"), "percent"),
        ("EMdivPolar", ("summary", "reproduced", "fraction_diverged_polar"), "percent"),
        ("EMdivCart", ("summary", "reproduced", "fraction_diverged_cartesian"), "percent"),
        ("EMLdrift", ("summary", "reproduced", "cartesian_L_max_rel_drift"), "err"),
        ("EMLdriftPlain", ("summary", "reproduced", "cartesian_L_max_rel_drift_plain"), "err"),
        ("EMpxOrder", ("summary", "orders", "polar_px_change_per_step"), "order"),
        ("EMpxOrderLocal", ("derived", "px_local_order"), "order"),
        # the map (map.csv, MAP_STATS)
        ("EMcounted", ("derived", "map", "counted"), "int"),
        ("EMdisagree", ("derived", "map", "disagree"), "int"),
        ("EMcriterion", ("derived", "map", "criterion"), "int"),
        ("EMdivPolarCount", ("derived", "map", "diverged_polar"), "int"),
        ("EMdivInside", ("derived", "map", "diverged_inside"), "int"),
        ("EMaliveOutside", ("derived", "map", "alive_outside"), "int"),
        ("EMcartDivOffOrigin", ("derived", "map", "cartesian_diverged_off_origin"), "int"),
        ("EMinner", ("derived", "map", "inner"), "int"),
        ("EMinnerRmax", ("derived", "map", "inner_r_max"), "fixed3"),
        ("EMinnerCandidates", ("derived", "map", "inner_candidates"), "int"),
        ("EMouter", ("derived", "map", "outer"), "int"),
        ("EMouterDistMax", ("derived", "map", "outer_dist_max"), "fixed3"),
        ("EMouterDistAll", ("derived", "map", "outer_dist_all"), "fixed3"),
        ("EMouterCandidates", ("derived", "map", "outer_candidates"), "int"),
        ("EMhMinDiverged", ("derived", "map", "H0_min_diverged"), "fixed3"),
        ("EMhMaxAlive", ("derived", "map", "H0_max_alive"), "fixed3"),
        ("EMinsideStepMedian", ("derived", "map", "inside_step_median"), "int"),
        ("EMinsideStepMax", ("derived", "map", "inside_step_max"), "int"),
        ("EMinsideTimeMax", ("derived", "map", "inside_time_max"), "int"),
        ("EMoutsideStepMedian", ("derived", "map", "outside_step_median"), "int"),
        ("EMoutsideStepMax", ("derived", "map", "outside_step_max"), "int"),
        ("EMoutsideTimeMax", ("derived", "map", "outside_time_max"), "int"),
        ("EMbothFinite", ("derived", "map", "both_finite"), "int"),
        ("EMringHalfWidth", ("derived", "map", "ring_half_width"), "plain"),
        ("EMringPolarBetter", ("derived", "map", "ring_polar_better"), "percent"),
        ("EMoffRingPolarBetter", ("derived", "map", "off_ring_polar_better"), "percent"),
        ("EMratioLo", ("derived", "map", "ratio_p05"), "ns3"),
        ("EMratioMedian", ("derived", "map", "ratio_median"), "ns3"),
        ("EMratioHi", ("derived", "map", "ratio_p95"), "ns3"),
        # cost (summary timing, KERNEL_TIMING)
        ("EMisa", ("summary", "timing", "kernel_isa"), "isa"),
        ("EMmaxTurn", ("summary", "timing", "kernel_max_turn"), "plain"),
        ("EMnsCart", ("summary", "timing", "ns_per_step_per_core", "cartesian"), "ns3"),
        ("EMnsPolar", ("summary", "timing", "ns_per_step_per_core", "polar"), "ns3"),
        ("EMscalarCart", ("summary", "timing", "scalar_ns_per_step", "cartesian"), "ns3"),
        ("EMscalarPolar", ("summary", "timing", "scalar_ns_per_step", "polar"), "ns3"),
        ("EMspeedupCart", ("summary", "timing", "speedup_vs_scalar", "cartesian"), "ratio"),
        ("EMspeedupPolar", ("summary", "timing", "speedup_vs_scalar", "polar"), "ratio"),
        ("EMwallCart", ("summary", "timing", "map_wall_s", "cartesian"), "seconds"),
        ("EMwallPolar", ("summary", "timing", "map_wall_s", "polar"), "seconds"),
        ("EMmapWall", ("derived", "kernel", "map_wall_s"), "seconds"),
        ("EMrunWall", ("summary", "timing", "wall_s"), "seconds"),
        ("EMtrajSteps", ("derived", "kernel", "trajectory_steps"), "sci"),
        ("EMtargetCart", ("derived", "kernel", "target", "cartesian"), "plain"),
        ("EMtargetPolar", ("derived", "kernel", "target", "polar"), "plain"),
        ("EMverdictCart", ("derived", "kernel", "verdict", "cartesian"), "text"),
        ("EMverdictPolar", ("derived", "kernel", "verdict", "polar"), "text"),
        ("EMceilCart", ("derived", "kernel", "ceiling", "cartesian", "lo"), "plain"),
        ("EMceilPolarLo", ("derived", "kernel", "ceiling", "polar", "lo"), "plain"),
        ("EMceilPolarHi", ("derived", "kernel", "ceiling", "polar", "hi"), "plain"),
        ("EMceilFracCart", ("derived", "kernel", "fraction", "cartesian", "lo"), "percent"),
        ("EMceilFracPolarLo", ("derived", "kernel", "fraction", "polar", "lo"), "percent"),
        ("EMceilFracPolarHi", ("derived", "kernel", "fraction", "polar", "hi"), "percent"),
    ],
}

def _lt_growth_macros():
    """The macros of lobatto_table for each step size of long_run.h (One, Two, ...)."""
    out = []
    for i, o in enumerate(ORDINALS[:3]):
        g = ("derived", "lt", "growth", i)
        out += [
            (f"LTlongH{o}", ("scene", "long_run", "h", i), "plain"),
            (f"LTstepsPerPeriod{o}", g + ("steps_per_period",), "int"),
            (f"LTgrowthPub{o}", g + ("pub",), "sci3"),
            (f"LTgrowthRep{o}", g + ("rep",), "sci4"),
            (f"LTgrowthExact{o}", g + ("exact",), "sci4"),
            (f"LTgrowthRoundoff{o}", g + ("roundoff",), "err"),
            (f"LTgrowthRepMinusExact{o}", g + ("rep_minus_exact",), "err"),
            (f"LTgrowthHd{o}", g + ("hd",), "err"),
            (f"LTgrowthHdComp{o}", g + ("hd_comp",), "err"),
            (f"LTdetDefect{o}", g + ("det_defect",), "err"),
            (f"LTboundK{o}", g + ("bound",), "err"),
            (f"LTperiodsToPeak{o}", g + ("periods_to_peak",), "sci"),
            (f"LTratioHHd{o}", g + ("ratio",), "ns3"),
            (f"LTHdPlainMax{o}", g + ("hd_plain_max",), "err"),
            (f"LTHdCompMax{o}", g + ("hd_comp_max",), "err"),
            (f"LTHdPlainMaxInH{o}", g + ("hd_plain_max_in_H",), "err"),
            (f"LTHfirst{o}", g + ("H_first",), "sci4"),
            (f"LTHlast{o}", g + ("H_last",), "sci4"),
            (f"LTHchange{o}", g + ("H_change",), "err"),
        ]
    return out


def _lt_table_macros():
    """The macros of lobatto_table for Table 1 (meshes 10, 20, 40 of the paper scene)."""
    out = []
    for n, word in ((10, "Ten"), (20, "Twenty"), (40, "Forty")):
        for prefix, mac in (("p", "p"), ("q", "q"), ("H", "H"), ("Hd", "Hd")):
            kind = "err" if prefix == "Hd" else "sci4"
            out.append((f"LT{mac}Err{word}", ("summary", "reproduced", f"{prefix}_err_N{n}"), kind))
            out.append((f"LT{mac}Pub{word}", ("summary", "published", f"{prefix}_err_N{n}"), "sci3"))
    for i, o in enumerate(ORDINALS[:3]):
        out.append((f"LTmesh{o}", ("scene", "meshes", i), "int"))
        out.append((f"LTHdZero{o}", ("derived", "lt", "table", f"hd0_{i}"), "ns3"))
        out.append((f"LTHdRel{o}", ("derived", "lt", "table", f"hd_rel_{i}"), "err"))
    return out


def _lt_stability_macros():
    out = []
    for i, o in enumerate(ORDINALS[:3]):
        out.append((f"LTstable{o}Lo", ("derived", "lt", "stable", "intervals", i, "lo"), "plain"))
        out.append((f"LTstable{o}Hi", ("derived", "lt", "stable", "intervals", i, "hi"), "plain"))
    for i, o in enumerate(ORDINALS[:2]):
        out.append((f"LTsimpsonStable{o}Lo", ("derived", "lt", "stable", "simpson", i, "lo"), "plain"))
        out.append((f"LTsimpsonStable{o}Hi", ("derived", "lt", "stable", "simpson", i, "hi"), "plain"))
    for side, word in (("below", "Below"), ("above", "Above")):
        b = ("derived", "lt", "bound_runs", side)
        out += [(f"LT{word}Factor", b + ("factor",), "plain"),
                (f"LT{word}Hw", b + ("h_omega",), "fixed3"),
                (f"LT{word}Steps", b + ("steps",), "int"),
                (f"LT{word}Diverged", b + ("diverged_at_step",), "int"),
                (f"LT{word}Norm", b + ("max_norm_over_initial",), "sci3")]
    return out


def _lt_cost_macros():
    out = []
    for m, word in (("lobatto", "Lobatto"), ("simpson", "Simpson"), ("midpoint", "Midpoint"),
                    ("odeint_rk4", "Rk"), ("odeint_rkf78", "Rkf")):
        c = ("derived", "cost", m)
        out += [(f"LTns{word}", ("summary", "timing", "ns_per_step", m), "ns"),
                (f"LTevals{word}", c + ("evals_per_step",), "ratio"),
                (f"LTminErr{word}", c + ("min_err",), "err"),
                (f"LTeqErr{word}", c + ("err_at_equal_wall",), "err"),
                (f"LTwall{word}Eten", c + ("wall_to", "1e-10"), "us"),
                (f"LTwall{word}Etwelve", c + ("wall_to", "1e-12"), "us"),
                (f"LTevalsTo{word}Eten", c + ("evals_to", "1e-10"), "int"),
                (f"LTevalsTo{word}Etwelve", c + ("evals_to", "1e-12"), "int")]
    out.append(("LTeqWall", ("derived", "equal_wall_s"), "us"))
    return out


MACROS["lobatto_table"] = [
    # scene (run.json)
    ("LTm", ("scene", "oscillator", "m"), "plain"),
    ("LTomega", ("scene", "oscillator", "omega"), "plain"),
    ("LTamp", ("scene", "oscillator", "amplitude"), "plain"),
    ("LTfigMeshOne", ("scene", "figure1", "meshes", 0), "int"),
    ("LTfigMeshTwo", ("scene", "figure1", "meshes", 1), "int"),
    ("LTperiods", ("scene", "long_run", "periods"), "int"),
    ("LTwindows", ("scene", "long_run", "windows"), "int"),
    ("LTwindowPeriods", ("derived", "lt", "window_periods"), "plain"),
    ("LTstabMin", ("scene", "stability", "hw_min"), "plain"),
    ("LTstabMax", ("scene", "stability", "hw_max"), "plain"),
    ("LTstabPoints", ("scene", "stability", "points"), "int"),
    ("LTstabStep", ("derived", "lt", "stable", "grid_step"), "plain"),
    ("LTnlHmax", ("scene", "nonlinear", "h"), "max:plain"),
    ("LTnlHmin", ("scene", "nonlinear", "h"), "min:plain"),
    ("LTnlHcount", ("scene", "nonlinear", "h"), "len:int"),
    ("LTnlTend", ("scene", "nonlinear", "t_end"), "plain"),
    ("LTnlQzero", ("scene", "nonlinear", "pendulum_q0"), "plain"),
    ("LTnlElasticIc", ("scene", "nonlinear", "elastic_initial", 0), "vec"),
    ("LTrtol", ("scene", "reference", "rtol"), "tol"),
    ("LTatol", ("scene", "reference", "atol"), "tol"),
    ("LTrepeats", ("scene", "timing", "repeats"), "int"),
    ("LTrunWall", ("summary", "timing", "wall_s"), "seconds"),
    # Table 1
    ("LTtabAgree", ("derived", "lt", "table", "agree"), "int"),
    ("LTtabCount", ("derived", "lt", "table", "count"), "int"),
    ("LTtabMaxDev", ("derived", "lt", "table", "max_dev"), "percent"),
    ("LTHdMin", ("derived", "lt", "table", "hd_min"), "err"),
    ("LTHdMax", ("derived", "lt", "table", "hd_max"), "err"),
    ("LTHdPubMin", ("derived", "lt", "table", "hd_pub_min"), "err"),
    ("LTHdPubMax", ("derived", "lt", "table", "hd_pub_max"), "err"),
    ("LTHdRelMin", ("derived", "lt", "table", "hd_rel_min"), "err"),
    ("LTHdRelMax", ("derived", "lt", "table", "hd_rel_max"), "err"),
] + _lt_table_macros() + [
    # orders
    ("LTorderP", ("summary", "orders", "lobatto_p"), "order"),
    ("LTorderQ", ("summary", "orders", "lobatto_q"), "order"),
    ("LTorderH", ("summary", "orders", "lobatto_H"), "order"),
    ("LTorderSimpson", ("summary", "orders", "simpson"), "order"),
    ("LTorderMidpoint", ("summary", "orders", "midpoint"), "order"),
    ("LTorderPendulum", ("summary", "orders", "lobatto_nonlinear_pendulum"), "order"),
    ("LTorderElastic", ("summary", "orders", "lobatto_elastic_pendulum"), "order"),
    ("LTorderSimpsonPendulum", ("summary", "orders", "simpson_nonlinear_pendulum"), "order"),
    ("LTorderMidpointPendulum", ("summary", "orders", "midpoint_nonlinear_pendulum"), "order"),
    # stability
    ("LTboundPub", ("summary", "published", "stability_bound"), "fixed5"),
    ("LTbound", ("summary", "reproduced", "stability_bound"), "fixed5"),
    ("LTstableCount", ("derived", "lt", "stable", "count"), "int"),
    ("LTboundHoverT", ("derived", "lt", "stable", "h_over_T"), "sig4"),
    ("LTboundMinN", ("derived", "lt", "stable", "min_steps_per_period"), "fixed3"),
    ("LThwNearPi", ("derived", "lt", "stable", "hw_near_pi"), "plain"),
    ("LTrhoNearPi", ("derived", "lt", "stable", "rho_near_pi"), "fixed3"),
    ("LTsimpsonStableCount", ("derived", "lt", "stable", "simpson_count"), "int"),
] + _lt_stability_macros() + _lt_growth_macros() + [
    (f"LTfig{o}{meth.capitalize()}{var.upper()}", ("derived", "lt", "fig1", i, meth, var), "err")
    for i, o in enumerate(ORDINALS[:2]) for meth in ("lobatto", "simpson", "midpoint") for var in ("q", "p")
] + [
    # nonlinear
    ("LTsympPendulum", ("summary", "reproduced", "symplecticity_defect_pendulum"), "err"),
    ("LTsympElastic", ("summary", "reproduced", "symplecticity_defect_elastic"), "err"),
    ("LTnewtonPendMin", ("derived", "lt", "nonlinear", "pendulum_it_min"), "plain"),
    ("LTnewtonPendMax", ("derived", "lt", "nonlinear", "pendulum_it_max"), "plain"),
    ("LTnewtonElasticMin", ("derived", "lt", "nonlinear", "elastic_it_min"), "plain"),
    ("LTnewtonElasticMax", ("derived", "lt", "nonlinear", "elastic_it_max"), "plain"),
    ("LTnlFitPoints", ("derived", "lt", "nonlinear", "pendulum_fit_points"), "int"),
    ("LTnlFitHmin", ("derived", "lt", "nonlinear", "pendulum_fit_hmin"), "plain"),
    ("LTnlElasticFitPoints", ("derived", "lt", "nonlinear", "elastic_fit_points"), "int"),
    ("LTnlFloor", ("derived", "lt", "nonlinear", "floor"), "tol"),
] + _lt_cost_macros()


def _td_window_macros():
    out = []
    for label, word in (("growth", "Growth"), ("no_growth", "Flat")):
        w = ("derived", "td", "fig5", label)
        out += [(f"TDwin{word}Lo", w + ("lo",), "int"),
                (f"TDwin{word}Hi", w + ("hi",), "int"),
                (f"TDwin{word}Length", w + ("length",), "int"),
                (f"TDcuts{word}", w + ("cuts",), "int"),
                (f"TDcutRate{word}", w + ("rate",), "fixed3"),
                (f"TDcutNeg{word}", w + ("share_p2_negative",), "percent"),
                (f"TDcutMeanPtwo{word}", w + ("mean_p2",), "err"),
                (f"TDwinChange{word}", w + ("change",), "err"),
                (f"TDwinSlope{word}", w + ("slope",), "err"),
                (f"TDwinElo{word}", w + ("E_lo",), "err"),
                (f"TDwinEhi{word}", w + ("E_hi",), "err")]
    return out


MACROS["ti_drift"] = [
    # scene (run.json) and quantities derived from it
    ("TDh", ("scene", "h"), "plain"),
    ("TDsamples", ("scene", "samples"), "int"),
    ("TDtOmega", ("scene", "oscillator", "t_omega"), "plain"),
    ("TDwhMin", ("derived", "td", "scene", "wh_min"), "plain"),
    ("TDwhMax", ("derived", "td", "scene", "wh_max"), "plain"),
    ("TDwhCount", ("derived", "td", "scene", "wh_count"), "int"),
    ("TDwhTiCount", ("derived", "td", "scene", "wh_ti_count"), "int"),
    ("TDstepsTiMin", ("derived", "td", "scene", "steps_ti_min"), "int"),
    ("TDpendQzero", ("scene", "pendulum", "q0"), "plain"),
    ("TDpendPzero", ("scene", "pendulum", "p0"), "plain"),
    ("TDpendHzero", ("derived", "td", "scene", "pendulum_H0"), "plain"),
    ("TDpendTend", ("scene", "pendulum", "t_end"), "int"),
    ("TDpendSteps", ("derived", "td", "scene", "pendulum_steps"), "int"),
    ("TDpendDt", ("derived", "td", "scene", "pendulum_sample_dt"), "plain"),
    ("TDhhQtwo", ("scene", "hh3", "q2"), "plain"),
    ("TDhhPtwo", ("scene", "hh3", "p2"), "plain"),
    ("TDhhHzero", ("scene", "hh", "H0"), "plain"),
    ("TDhhK", ("scene", "hh", "k"), "int"),
    ("TDhhThreePone", ("derived", "td", "scene", "hh3_p1"), "sig7"),
    ("TDhhPone", ("derived", "td", "scene", "hh_p1"), "sig7"),
    ("TDhhThreeTend", ("scene", "hh3", "t_end"), "int"),
    ("TDhhThreeSteps", ("derived", "td", "scene", "hh3_steps"), "int"),
    ("TDhhThreeDt", ("derived", "td", "scene", "hh3_sample_dt"), "plain"),
    ("TDtEnd", ("scene", "t_end"), "sci"),
    ("TDfourSteps", ("derived", "td", "scene", "fig4_steps"), "sci3"),
    ("TDfourDt", ("derived", "td", "scene", "fig4_sample_dt"), "plain"),
    ("TDensSize", ("scene", "ensemble", "size"), "int"),
    ("TDensSeed", ("scene", "ensemble", "seed"), "intplain"),
    ("TDensPert", ("scene", "ensemble", "perturbation"), "plain"),
    ("TDensOutlier", ("scene", "ensemble", "outlier"), "sci"),
    # Fig. 1
    ("TDorderTiSol", ("summary", "orders", "ti_solution"), "order"),
    ("TDorderTiEnergy", ("summary", "orders", "ti_energy"), "order"),
    ("TDorderSvEnergy", ("summary", "orders", "sv_energy"), "order"),
    ("TDorderSvSol", ("summary", "orders", "sv_solution"), "order"),
    ("TDfitPointsGlobal", ("derived", "td", "osc", "fit_points_global"), "int"),
    ("TDfitPointsEnergy", ("derived", "td", "osc", "fit_points_energy"), "int"),
    ("TDroundoffWh", ("derived", "td", "osc", "ti_roundoff_wh_max"), "plain"),
    ("TDcommon", ("derived", "td", "osc", "common"), "int"),
    ("TDtiBetterEnergy", ("derived", "td", "osc", "ti_better_energy"), "int"),
    ("TDtiBetterGlobal", ("derived", "td", "osc", "ti_better_global"), "int"),
    ("TDsvDevSmall", ("derived", "td", "osc", "sv_dev_small"), "percent"),
    ("TDtiDevSmall", ("derived", "td", "osc", "ti_dev_small"), "percent"),
    ("TDsvRatioLarge", ("derived", "td", "osc", "sv_ratio_large"), "sig3"),
    ("TDsvRatioLargeWh", ("derived", "td", "osc", "sv_ratio_large_wh"), "plain"),
    ("TDtiRatioLarge", ("derived", "td", "osc", "ti_ratio_large"), "sig3"),
    ("TDtiRatioLargeWh", ("derived", "td", "osc", "ti_ratio_large_wh"), "plain"),
    ("TDtiLastWh", ("derived", "td", "osc", "ti_last_wh"), "plain"),
    ("TDtiLastEnergy", ("derived", "td", "osc", "ti_last_energy"), "sig4"),
    ("TDwhRef", ("derived", "td", "osc", "wh_ref"), "plain"),
    ("TDsvGlobalRef", ("derived", "td", "osc", "sv_global_ref"), "err"),
    ("TDtiGlobalRef", ("derived", "td", "osc", "ti_global_ref"), "err"),
    ("TDsvEnergyRef", ("derived", "td", "osc", "sv_energy_ref"), "err"),
    ("TDtiEnergyRef", ("derived", "td", "osc", "ti_energy_ref"), "err"),
    ("TDbound", ("summary", "reproduced", "ti_stability_bound"), "sig7"),
    ("TDboundDiff", ("derived", "td", "stability", "diff"), "err"),
    # Fig. 2
    ("TDdriftRate", ("summary", "reproduced", "unsym_pendulum_drift_rate"), "sci3"),
    ("TDdriftPred", ("summary", "reproduced", "unsym_pendulum_drift_rate_predicted"), "sci3"),
    ("TDdriftRateWhole", ("summary", "reproduced", "unsym_pendulum_drift_rate_whole"), "sci3"),
    ("TDpendFitT", ("scene", "pendulum", "fit_t"), "int"),
    ("TDdriftRelDiff", ("derived", "td", "fig2", "rel_diff"), "percent"),
    ("TDdriftChange", ("derived", "td", "fig2", "change"), "err"),
    ("TDdriftHslope", ("derived", "td", "fig2", "H_slope"), "sci3"),
    ("TDshiftedResidual", ("derived", "td", "fig2", "shifted_residual_p2p"), "err"),
    ("TDHresidual", ("derived", "td", "fig2", "H_residual_p2p"), "err"),
    ("TDpendUmax", ("derived", "td", "fig2", "U_max"), "sig3"),
    ("TDturnover", ("derived", "td", "fig2", "turnover_time"), "sci"),
    # Fig. 3
    ("TDhhThreeMax", ("summary", "reproduced", "hh3_max_E_err"), "err"),
    ("TDhhThreeSlope", ("summary", "reproduced", "hh3_drift_slope"), "err"),
    ("TDhhThreeDrift", ("derived", "td", "fig3", "drift_over_run"), "err"),
    ("TDhhThreeDriftShare", ("derived", "td", "fig3", "drift_over_max"), "percent"),
    ("TDhhThreePtp", ("derived", "td", "fig3", "E_p2p"), "err"),
    ("TDhhThreeHmax", ("derived", "td", "fig3", "H_max"), "err"),
    # Fig. 4
    ("TDmu", ("summary", "reproduced", "hh5_mu_final"), "sci3"),
    ("TDmuPub", ("summary", "published", "hh5_mu_final"), "sci"),
    ("TDsigma", ("summary", "reproduced", "hh5_sigma_final"), "sci3"),
    ("TDsigmaPub", ("summary", "published", "hh5_sigma_final"), "sci"),
    ("TDgamma", ("summary", "reproduced", "hh5_sigma_exponent"), "fixed3"),
    ("TDgammaHundredth", ("derived", "td", "fig4", "gamma_hundredth"), "fixed3"),
    ("TDgammaKept", ("derived", "td", "fig4", "gamma_tenth_kept"), "fixed3"),
    ("TDkept", ("derived", "td", "fig4", "kept"), "int"),
    ("TDmuKept", ("derived", "td", "fig4", "mu_end_kept"), "sci3"),
    ("TDsigmaKept", ("derived", "td", "fig4", "sigma_end_kept"), "sci3"),
    ("TDthinnedDt", ("derived", "td", "fig4", "output_dt_thinned"), "plain"),
    ("TDmuFirst", ("derived", "td", "fig4", "mu_first"), "sci3"),
    ("TDtFirst", ("derived", "td", "fig4", "t_first"), "plain"),
    ("TDmuLateMean", ("derived", "td", "fig4", "mu_late_mean"), "sci3"),
    ("TDmuLateMin", ("derived", "td", "fig4", "mu_late_min"), "sci3"),
    ("TDmuLateMax", ("derived", "td", "fig4", "mu_late_max"), "sci3"),
    ("TDmuSe", ("derived", "td", "fig4", "mu_se"), "sci"),
    ("TDsigmaRelSe", ("derived", "td", "fig4", "sigma_rel_se"), "percent"),
    ("TDDend", ("derived", "td", "fig4", "D_end"), "sci3"),
    ("TDDfit", ("derived", "td", "fig4", "D_fit"), "sci3"),
    ("TDDpub", ("derived", "td", "fig4", "D_pub"), "sci3"),
    ("TDoutliers", ("summary", "reproduced", "hh5_outliers"), "len:int"),
    ("TDpoincareTraj", ("summary", "reproduced", "poincare_trajectory"), "int"),
    # Fig. 6: the Lennard-Jones cluster
    ("TDljH", ("scene", "lj", "h"), "plain"),
    ("TDljTend", ("scene", "lj", "t_end"), "sci"),
    ("TDljSize", ("scene", "lj", "size"), "int"),
    ("TDljSeed", ("scene", "lj", "seed"), "intplain"),
    ("TDljPert", ("scene", "lj", "perturbation"), "plain"),
    ("TDljBlowup", ("scene", "lj", "blowup"), "plain"),
    ("TDljScanT", ("scene", "lj", "scan_t"), "plain"),
    ("TDljScanSize", ("scene", "lj", "scan_size"), "int"),
    ("TDljScanHs", ("scene", "lj", "h_scan"), "vec"),
    ("TDljSteps", ("derived", "td", "fig6", "steps"), "sci3"),
    ("TDljDt", ("derived", "td", "fig6", "sample_dt"), "plain"),
    ("TDljScanRuns", ("derived", "td", "fig6", "runs"), "int"),
    ("TDljHfirst", ("derived", "td", "fig6", "h_first"), "plain"),
    ("TDljDivFirst", ("derived", "td", "fig6", "div_first"), "int"),
    ("TDljDivFirstTmin", ("derived", "td", "fig6", "t_div_first_min"), "plain"),
    ("TDljDivFirstTmax", ("derived", "td", "fig6", "t_div_first_max"), "plain"),
    ("TDljHsecond", ("derived", "td", "fig6", "h_second"), "plain"),
    ("TDljDivSecond", ("derived", "td", "fig6", "div_second"), "int"),
    ("TDljDivSecondTmin", ("derived", "td", "fig6", "t_div_second_min"), "sig3"),
    ("TDljDivSecondTmax", ("derived", "td", "fig6", "t_div_second_max"), "sig3"),
    ("TDljStableCount", ("derived", "td", "fig6", "stable_count"), "int"),
    ("TDljStableMin", ("summary", "reproduced", "lj_stable_steps"), "min:plain"),
    ("TDljStableMax", ("summary", "reproduced", "lj_stable_steps"), "max:plain"),
    ("TDljHsmallest", ("derived", "td", "fig6", "h_smallest"), "plain"),
    ("TDljScanMedSmall", ("derived", "td", "fig6", "median_smallest"), "err"),
    ("TDljScanMaxSmall", ("derived", "td", "fig6", "max_smallest"), "err"),
    ("TDljMu", ("summary", "reproduced", "lj_mu_final"), "sci3"),
    ("TDljSigma", ("summary", "reproduced", "lj_sigma_final"), "sci3"),
    ("TDljMuSe", ("summary", "reproduced", "lj_mu_final_stderr"), "sci3"),
    ("TDljSigmaSe", ("summary", "reproduced", "lj_sigma_final_stderr"), "sci3"),
    ("TDljMuU", ("derived", "td", "fig6", "mu_u"), "fixed3"),
    ("TDljMuSeU", ("derived", "td", "fig6", "mu_se_u"), "fixed3"),
    ("TDljSigmaU", ("derived", "td", "fig6", "sigma_u"), "fixed3"),
    ("TDljSigmaSeU", ("derived", "td", "fig6", "sigma_se_u"), "fixed3"),
    ("TDljMuPubU", ("derived", "td", "fig6", "mu_pub_u"), "plain"),
    ("TDljSigmaPubU", ("derived", "td", "fig6", "sigma_pub_u"), "plain"),
    ("TDljMuPub", ("summary", "published", "lj_mu_final"), "sci"),
    ("TDljSigmaPub", ("summary", "published", "lj_sigma_final"), "sci3"),
    ("TDljMuZpub", ("derived", "td", "fig6", "mu_z_pub"), "sig3"),
    ("TDljMuZzero", ("derived", "td", "fig6", "mu_z_zero"), "sig3"),
    ("TDljSigmaZpub", ("derived", "td", "fig6", "sigma_z_pub"), "sig3"),
    ("TDljSigmaRelDiff", ("derived", "td", "fig6", "sigma_rel_diff"), "percent"),
    ("TDljGamma", ("summary", "reproduced", "lj_sigma_exponent"), "fixed3"),
    ("TDljGammaPub", ("summary", "published", "lj_sigma_exponent"), "plain"),
    ("TDljHerrMax", ("summary", "reproduced", "lj_H_err_max"), "err"),
    ("TDljHrmsMean", ("derived", "td", "fig6", "H_rms_mean"), "err"),
    ("TDljHrmsMax", ("derived", "td", "fig6", "H_rms_max"), "err"),
    ("TDljHhatStart", ("derived", "td", "fig6", "Hhat_start"), "err"),
    ("TDljHhatMin", ("derived", "td", "fig6", "Hhat_rms_min"), "err"),
    ("TDljHhatMax", ("derived", "td", "fig6", "Hhat_rms_max"), "err"),
    ("TDljHhatRelVar", ("derived", "td", "fig6", "Hhat_rel_var"), "percent"),
    ("TDljHratio", ("derived", "td", "fig6", "H_over_Hhat"), "sig3"),
    ("TDljWall", ("summary", "timing", "fig6_wall_s"), "seconds"),
    ("TDljNs", ("derived", "td", "cost", "fig6_ns_per_step_thread"), "ns"),
] + _td_window_macros() + [
    # symplecticity and volume
    ("TDsympTi", ("summary", "reproduced", "ti_symplecticity_defect"), "err"),
    ("TDsympSti", ("summary", "reproduced", "sti_symplecticity_defect"), "err"),
    ("TDdetSti", ("summary", "reproduced", "sti_det_minus_one"), "err"),
    # cost
    ("TDnsSv", ("summary", "timing", "ns_per_step", "sv"), "ns"),
    ("TDnsTi", ("summary", "timing", "ns_per_step", "ti"), "ns"),
    ("TDnsSti", ("summary", "timing", "ns_per_step", "sti"), "ns"),
    ("TDratioTi", ("derived", "td", "cost", "ratio_ti"), "ratio"),
    ("TDratioSti", ("derived", "td", "cost", "ratio_sti"), "ratio"),
    ("TDfourWall", ("summary", "timing", "fig4_wall_s"), "seconds"),
    ("TDfourNs", ("derived", "td", "cost", "fig4_ns_per_step_thread"), "ns"),
    ("TDthreads", ("derived", "td", "cost", "threads"), "int"),
    ("TDrunWall", ("summary", "timing", "wall_s"), "seconds"),
]


def _mc_ptp_macros():
    out = []
    for ell in MC_ELLS:
        for mm in MC_ELLS:
            stem = f"MCptp{MC_WORD[ell]}Mu{MC_WORD[mm] if mm else ''}"
            key = f"ptp_phi{ell}_{mc_measure(mm)}"
            out += [(f"{stem}{m}", ("summary", "reproduced", key, m), "sci") for m in MC_METHODS]
            for g in MC_GROUPS:
                out += [(f"{stem}{g}Min", ("derived", "mc", "range", key, g or "all", "min"), "sci"),
                        (f"{stem}{g}Max", ("derived", "mc", "range", key, g or "all", "max"), "sci"),
                        (f"{stem}{g}Range", ("derived", "mc", "range", key, g or "all"), "range:sci")]
    return out


def _mc_per_ell_macros():
    out = []
    for ell in MC_ELLS:
        w = MC_WORD[ell]
        for stem, tree, kind in (("Corr", "corr", "sci"), ("Small", "small", "sci"), ("Raw", "raw", "sci")):
            out += [(f"MC{stem.lower()}{w}{m}", ("derived", "mc", tree, str(ell), m), kind) for m in MC_METHODS]
            for g in MC_GROUPS:
                out += [(f"MC{stem.lower()}{w}{g}Min", ("derived", "mc", "range", f"{tree}_{ell}", g or "all", "min"), kind),
                        (f"MC{stem.lower()}{w}{g}Max", ("derived", "mc", "range", f"{tree}_{ell}", g or "all", "max"), kind),
                        (f"MC{stem.lower()}{w}{g}Range", ("derived", "mc", "range", f"{tree}_{ell}", g or "all"),
                         f"range:{kind}")]
        out += [(f"MCorder{w}{m}", ("summary", "orders", f"measure_ell{ell}", m), "order") for m in MC_METHODS]
        out += [(f"MCorder{w}Min", ("derived", "mc", "range", f"order_measure_ell{ell}", "all", "min"), "order"),
                (f"MCorder{w}Max", ("derived", "mc", "range", f"order_measure_ell{ell}", "all", "max"), "order"),
                (f"MCorder{w}Range", ("derived", "mc", "range", f"order_measure_ell{ell}", "all"), "range:order"),
                (f"MCfitPoints{w}Min", ("derived", "mc", "range", f"fit_points_{ell}", "all", "min"), "int"),
                (f"MCfitPoints{w}Max", ("derived", "mc", "range", f"fit_points_{ell}", "all", "max"), "int"),
                (f"MCfitPoints{w}Range", ("derived", "mc", "range", f"fit_points_{ell}", "all"), "range:int")]
        out += [(f"MCfitHmin{w}{m}", ("summary", "fits", f"measure_ell{ell}", m, "h_min"), "sig3") for m in MC_METHODS]
    return out


def _mc_method_macros(prefix, src, key, kind, absolute=False):
    """Per-method macros and their ranges (all, Mid = M and MT, Trap = TM, TT and T)."""
    base = ("derived", "mc", "free") if src == "free" else ("summary",)
    rbase = ("derived", "mc", "free", "range") if src == "free" else ("derived", "mc", "range")
    if src == "derived":
        base, rbase = ("derived", "mc"), ("derived", "mc", "range")
    out = [(f"{prefix}{m}", base + (("reproduced",) if src in ("summary", "free") else ()) + (key, m), kind)
           for m in MC_METHODS]
    lo, hi = ("absmin", "absmax") if absolute else ("min", "max")
    for g in MC_GROUPS:
        out += [(f"{prefix}{g}Min", rbase + (key, g or "all", lo), kind),
                (f"{prefix}{g}Max", rbase + (key, g or "all", hi), kind),
                (f"{prefix}{g}Range", rbase + (key, g or "all"), ("absrange:" if absolute else "range:") + kind)]
    return out


MACROS["measure_cloud"] = [
    # scene of the harmonic run (run.json) and quantities derived from it
    ("MCh", ("scene", "h"), "plain"),
    ("MChSix", ("derived", "mc", "scene", "h6"), "sci"),
    ("MCtEnd", ("scene", "t_end"), "plain"),
    ("MCwindow", ("scene", "ptp_window"), "plain"),
    ("MCradius", ("scene", "cloud", "radius"), "plain"),
    ("MCcenter", ("scene", "cloud", "center"), "vec"),
    ("MCseed", ("scene", "seed"), "intplain"),
    ("MCshapePoints", ("scene", "shape", "points"), "int"),
    ("MCshapeRadius", ("scene", "shape", "radius"), "plain"),
    ("MCshapeDt", ("scene", "shape", "snapshot_dt"), "plain"),
    ("MCshapeTend", ("derived", "mc", "scene", "shape_t_end"), "plain"),
    ("MCenergyTend", ("scene", "energies", "t_end"), "plain"),
    ("MCenergySteps", ("derived", "mc", "scene", "energy_steps"), "int"),
    ("MCorderRadius", ("scene", "order_study", "radius"), "tol"),
    ("MCorderHmax", ("scene", "order_study", "h"), "max:plain"),
    ("MCorderHmin", ("scene", "order_study", "h"), "min:plain"),
    ("MCorderHcount", ("scene", "order_study", "h"), "len:int"),
    ("MCorderTend", ("scene", "order_study", "t_end"), "plain"),
    ("MCrtol", ("scene", "reference", "rtol"), "tol"),
    ("MCatol", ("scene", "reference", "atol"), "tol"),
    ("MCrepeats", ("scene", "timing", "repeats"), "int"),
    ("MCthreads", ("derived", "mc", "scene", "threads"), "int"),
    ("MCrunWall", ("summary", "timing", "wall_s"), "seconds"),
    ("MCmaxOrder", ("summary", "reproduced", "max_modified_order"), "int"),
    # checks
    ("MCgoldenErr", ("summary", "reproduced", "golden_max_rel_err"), "err"),
    ("MCrefSelfCheck", ("summary", "reproduced", "reference_self_check"), "err"),
    ("MChullVolume", ("summary", "reproduced", "hull_volume_initial_over_r4"), "sig7"),
    ("MChullExact", ("derived", "mc", "scene", "hull_exact"), "sig7"),
    ("MChullRelErr", ("derived", "mc", "scene", "hull_rel_err"), "err"),
    # Fig. 5.1
    ("MCareaFirst", ("summary", "reproduced", "shape_area_sum", 0), "fixed3"),
    ("MCareaLast", ("summary", "reproduced", "shape_area_sum", -1), "fixed3"),
    # Figs. 5.2, 5.4: the reference
    ("MCptpRef", ("summary", "reproduced", "ptp_reference_mu"), "sci"),
    ("MCrefAtWindow", ("derived", "mc", "ref", "at_window"), "sci"),
    ("MCrefAtEnd", ("derived", "mc", "ref", "at_end"), "sci"),
] + _mc_ptp_macros() + _mc_per_ell_macros() + [
    ("MCnoise", ("summary", "reproduced", "order_study_noise"), "sci"),
    ("MCnoiseFloor", ("derived", "mc", "scene", "noise_floor"), "sci"),
    ("MChProbe", ("summary", "reproduced", "order_study_h_probe"), "plain"),
    ("MCratioZeroFourMin", ("derived", "mc", "range", "ratio_zero_over_four_mu4", "all", "min"), "ns3"),
    ("MCratioZeroFourMax", ("derived", "mc", "range", "ratio_zero_over_four_mu4", "all", "max"), "ns3"),
    ("MCratioZeroFourRange", ("derived", "mc", "range", "ratio_zero_over_four_mu4", "all"), "range:ns3"),
] + (
    # Fig. 5.3 and Phi^(0) on the harmonic particle
    _mc_method_macros("MCestar", "summary", "Estar_minus_H0_phi4", "sci01", absolute=True)
    + _mc_method_macros("MCmaxHFour", "summary", "max_abs_H_err_phi4", "sci01")
    + _mc_method_macros("MCmaxHZero", "summary", "max_abs_H_err_phi0", "sci01")
    + _mc_method_macros("MCmaxKEFour", "summary", "max_abs_K_E_phi4", "sci01")
    + _mc_method_macros("MCmaxKmodFour", "summary", "max_abs_K_mod4_phi4", "sci01")
    + _mc_method_macros("MCmaxKmodZero", "summary", "max_abs_K_mod4_phi0", "sci01")
    + _mc_method_macros("MCerrFour", "summary", "err_at_t_end_phi4", "sci01")
    + _mc_method_macros("MCerrZero", "summary", "err_at_t_end_phi0", "sci01")
    + _mc_method_macros("MCharmRatio", "summary", "harmonic_H_drift_ratio", "sig3")
    # Figs. 5.5, 5.6 and the long run: the free particle
    + _mc_method_macros("MCfreeEstar", "free", "Estar_minus_H0_phi4", "sci01", absolute=True)
    + _mc_method_macros("MCfreeHFour", "free", "H_err_at_t_end_phi4", "sci01")
    + _mc_method_macros("MCfreeHZero", "free", "H_err_at_t_end_phi0", "sci01")
    + _mc_method_macros("MCfreeMaxHFour", "free", "max_abs_H_err_phi4", "sci01")
    + _mc_method_macros("MCfreeMaxHZero", "free", "max_abs_H_err_phi0", "sci01")
    + _mc_method_macros("MCfreeKEFour", "free", "max_abs_K_E_phi4", "sci01")
    + _mc_method_macros("MCfreeKEZero", "free", "max_abs_K_E_phi0", "sci01")
    + _mc_method_macros("MCfreeKmodFour", "free", "max_abs_K_mod4_phi4", "sci01")
    + _mc_method_macros("MCfreeKmodZero", "free", "max_abs_K_mod4_phi0", "sci01")
    + _mc_method_macros("MCfreeErrFour", "free", "err_at_t_end_phi4", "sci01")
    + _mc_method_macros("MCfreeErrZero", "free", "err_at_t_end_phi0", "err")
    + _mc_method_macros("MCfreeRatio", "free", "free_H_drift_ratio", "sig3")
    + _mc_method_macros("MClongHZero", "free", "long_H_err_phi0", "err", absolute=True)
    + _mc_method_macros("MClongHFour", "free", "long_H_err_phi4", "sci01", absolute=True)
    + _mc_method_macros("MClongErrZero", "free", "long_err_phi0", "err")
    + _mc_method_macros("MClongErrFour", "free", "long_err_phi4", "err")
) + [
    ("MCfreeErrRatioMin", ("derived", "mc", "free", "range", "err_ratio", "all", "min"), "sig3"),
    ("MCfreeErrRatioMax", ("derived", "mc", "free", "range", "err_ratio", "all", "max"), "sig3"),
    ("MCfreeErrRatioRange", ("derived", "mc", "free", "range", "err_ratio", "all"), "range:sig3"),
    ("MCfreeMaxHRatioMin", ("derived", "mc", "free", "range", "max_H_ratio", "all", "min"), "sig3"),
    ("MCfreeMaxHRatioMax", ("derived", "mc", "free", "range", "max_H_ratio", "all", "max"), "sig3"),
    ("MCfreeMaxHRatioRange", ("derived", "mc", "free", "range", "max_H_ratio", "all"), "range:sig3"),
    ("MClongErrRatioMin", ("derived", "mc", "free", "range", "long_err_ratio", "all", "min"), "ns3"),
    ("MClongErrRatioMax", ("derived", "mc", "free", "range", "long_err_ratio", "all", "max"), "ns3"),
    ("MClongErrRatioRange", ("derived", "mc", "free", "range", "long_err_ratio", "all"), "range:ns3"),
    ("MClongTend", ("derived", "mc", "free", "scene", "long_run", "t_end"), "plain"),
    ("MCfreeTend", ("derived", "mc", "free", "scene", "energies", "t_end"), "plain"),
    ("MCgoldenErrFree", ("derived", "mc", "free", "reproduced", "golden_max_rel_err"), "err"),
    ("MCrefSelfCheckFree", ("derived", "mc", "free", "reproduced", "reference_self_check"), "err"),
    ("MCfreeRunWall", ("derived", "mc", "free", "wall_s"), "seconds"),
    ("MCnewtonMeanFree", ("derived", "mc", "free", "timing", "newton_iterations_mean"), "sig3"),
    # cost
    ("MCnewtonMean", ("summary", "timing", "newton_iterations_mean"), "sig3"),
    ("MCnewtonFirstMin", ("derived", "mc", "range", "iters_first", "all", "min"), "sig3"),
    ("MCnewtonFirstMax", ("derived", "mc", "range", "iters_first", "all", "max"), "sig3"),
    ("MCnewtonFirstRange", ("derived", "mc", "range", "iters_first", "all"), "range:plain"),
    ("MCnsMin", ("derived", "mc", "range", "ns_per_step", "all", "min"), "ns3"),
    ("MCnsMax", ("derived", "mc", "range", "ns_per_step", "all", "max"), "ns3"),
    ("MCnsRange", ("derived", "mc", "range", "ns_per_step", "all"), "range:ns3"),
    ("MCcostOrderMin", ("derived", "mc", "range", "cost_order", "all", "min"), "order"),
    ("MCcostOrderMax", ("derived", "mc", "range", "cost_order", "all", "max"), "order"),
    ("MCcostOrderRange", ("derived", "mc", "range", "cost_order", "all"), "range:order"),
    ("MCcostFitCount", ("derived", "mc", "cost", "fit_count"), "int"),
] + [(f"MCns{m}", ("summary", "timing", "ns_per_step", m), "ns3") for m in MC_METHODS]



NA = r"\textit{n/a}"


class Malformed(Exception):
    """A summary.json that does not have the shape of the interface contract."""


# ---------------------------------------------------------------------------
# Formatting
# ---------------------------------------------------------------------------

def tex_escape(text):
    repl = {
        "\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
        "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}",
        "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}",
    }
    return "".join(repl.get(c, c) for c in str(text))


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def sci(x, digits=2):
    """x as $m\\times10^{e}$ with `digits` significant digits (plain LaTeX, math content only)."""
    if x == 0:
        return "0"
    mant, exp = f"{x:.{digits - 1}e}".split("e")
    exp = int(exp)
    if exp == 0:
        return mant
    return rf"{mant}\times10^{{{exp}}}"


def sig(x, n):
    """x in fixed notation with n significant digits, trailing zeros kept (0.20); whole numbers
    with more than n digits are not rounded further (123)."""
    decimals = max(0, n - 1 - math.floor(math.log10(abs(x))))
    return f"{x:.{decimals}f}"


def general(x):
    """A value that is not an order: scientific below 1e-3 or from 1e4, else 4 significant digits."""
    if not math.isfinite(x):
        return None
    if x == 0:
        return "0"
    if abs(x) < 1e-3 or abs(x) >= 1e4:
        return sci(x)
    return sig(x, 4)


def fmt(value, kind):
    """Math-mode content (without $) for a number, or None if it cannot be shown."""
    if value is None or not is_number(value) or not math.isfinite(value):
        return None
    if kind == "order":
        return f"{value:.3f}"
    if kind == "porder":  # a published order: as printed (an integer) or to 3 decimals
        return f"{value:.0f}" if float(value).is_integer() else f"{value:.3f}"
    if kind == "dorder":
        return f"{value:+.3f}"
    if kind == "int":
        n = int(round(value))
        return f"{n:,}".replace(",", r"\,") if abs(n) >= 10000 else f"{n}"
    if kind == "err":
        if value == 0:
            return "0"
        if abs(value) < 1e-3 or abs(value) >= 1e4:
            return sci(value)
        return sig(value, 2)
    if kind == "sci":
        return sci(value)
    if kind == "sci01":  # scientific below 0.01, else 2 significant digits (0.15, 2.3, 13)
        return "0" if value == 0 else (sci(value) if abs(value) < 1e-2 else sig(value, 2))
    if kind == "fixed3":
        return f"{value:.3f}"
    if kind == "sig7":
        return sig(value, 7)
    if kind == "sig4":
        return sig(value, 4)
    if kind == "intplain":  # an integer without digit grouping (a seed)
        return f"{int(round(value))}"
    if kind == "sig3":
        return sig(value, 3) if value != 0 else "0"
    if kind == "fixed5":
        return f"{value:.5f}"
    if kind in ("sci3", "sci4"):  # 3 or 4 significant digits, scientific below 1e-3 or from 1e4
        if value == 0:
            return "0"
        n = int(kind[-1])
        return sci(value, n) if abs(value) < 1e-3 or abs(value) >= 1e4 else sig(value, n)
    if kind == "us":  # seconds shown in microseconds
        return None if value <= 0 else sig(value * 1e6, 2)
    if kind == "tol":  # a tolerance: 10^{-14}, or m\times10^{e}
        mant, exp = f"{value:.1e}".split("e")
        return f"10^{{{int(exp)}}}" if mant == "1.0" else sci(value)
    if kind == "ns":
        return f"{value:.1f}"
    if kind == "ns3":  # 3 significant digits: 1.39, 28.4, 129
        return sig(value, 3) if value > 0 else None
    if kind == "percent":  # a fraction shown in per cent, 3 significant digits
        return "0\\,\\%" if value == 0 else sig(100 * value, 3) + "\\,\\%"
    if kind == "ratio":
        return f"{value:.1f}"
    if kind == "seconds":  # 2 significant digits, but whole seconds from 100 s (no 1.4e+02)
        return f"{value:.2g}" if abs(value) < 100 else f"{value:.0f}"
    if kind == "plain":
        return f"{value:g}"
    return general(value)


def math_cell(content):
    return NA if content is None else f"${content}$"


# ---------------------------------------------------------------------------
# Reading
# ---------------------------------------------------------------------------

def reject_constant(name):
    raise ValueError(f"non-standard JSON constant {name}")


def load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f, parse_constant=reject_constant)
    except (OSError, ValueError) as e:
        raise Malformed(f"{path}: not valid JSON: {e}") from None


def check_summary(path, s, name=None):
    if not isinstance(s, dict):
        raise Malformed(f"{path}: top level must be a JSON object")
    pub = s.get("published")
    if not isinstance(pub, dict):
        raise Malformed(f'{path}: "published" must be an object of numbers')
    for section in ("reproduced", "orders", "timing", "norms"):
        if section in s and s[section] is not None and not isinstance(s[section], dict):
            raise Malformed(f'{path}: "{section}" must be an object')
    orders = s.get("orders") or {}
    reproduced = s.get("reproduced") or {}
    for key, v in pub.items():
        nested = isinstance(v, dict)  # one published value per parameter, e.g. per step size
        if not (is_number(v) or (nested and all(is_number(x) for x in v.values()))):
            raise Malformed(f'{path}: published "{key}" must be a number or an object of numbers, '
                            f'got {json.dumps(v)}')
        if key in orders:
            r = orders[key]
        elif key in reproduced:
            r = reproduced[key]
        else:
            raise Malformed(f'{path}: published "{key}" has no value in "orders" or "reproduced"')
        if nested:
            if r is not None and not (isinstance(r, dict) and all(is_number(x) or x is None for x in r.values())):
                raise Malformed(f'{path}: reproduced "{key}" must be an object of numbers or null '
                                f'(as published), got {json.dumps(r)}')
        elif r is not None and not is_number(r):
            raise Malformed(f'{path}: reproduced "{key}" must be a number or null, got {json.dumps(r)}')
    timing = s.get("timing") or {}
    nsps = timing.get("ns_per_step")
    if nsps is not None:
        if not isinstance(nsps, dict) or not all(is_number(v) or v is None for v in nsps.values()):
            raise Malformed(f'{path}: "timing.ns_per_step" must be an object of numbers')
    eq = timing.get("error_at_equal_wall_time")
    if eq is not None:
        if not isinstance(eq, dict) or not all(is_number(v) or v is None for v in eq.values()):
            raise Malformed(f'{path}: "timing.error_at_equal_wall_time" must be an object of numbers or null')
    obi = s.get("orders_by_initial")
    if obi is not None:
        if not isinstance(obi, list) or not all(
                isinstance(o, dict) and all(is_number(v) or v is None for v in o.values()) for o in obi):
            raise Malformed(f'{path}: "orders_by_initial" must be a list of objects of numbers or null')


def lookup(tree, path):
    """tree[path[0]][path[1]]...; an int in the path indexes a list. None if absent."""
    node = tree
    for k in path:
        if isinstance(k, int):
            if not isinstance(node, list) or not -len(node) <= k < len(node):
                return None
        elif not isinstance(node, dict) or k not in node:
            return None
        node = node[k]
    return node


def read_timing_curves(path, error_column):
    """{method: [(wall_s, err), ...]} from a timing.csv, or None if there is none."""
    if not os.path.isfile(path):
        return None
    curves = {}
    with open(path, newline="", encoding="utf-8") as f:
        rows = csv.DictReader(f)
        need = {"method", "wall_s", error_column}
        if rows.fieldnames is None or not need <= set(rows.fieldnames):
            raise Malformed(f"{path}: needs the columns {sorted(need)}")
        for row in rows:
            try:
                w, e = float(row["wall_s"]), float(row[error_column])
            except ValueError:
                raise Malformed(f"{path}: non-numeric wall_s or {error_column} in row {row}") from None
            if w > 0 and e > 0 and math.isfinite(w) and math.isfinite(e):
                curves.setdefault(row["method"], []).append((w, e))
    return {m: sorted(c) for m, c in curves.items()}


def loglog_at(curve, w):
    """log err at wall time w by linear interpolation in log-log; None outside the curve."""
    for (w0, e0), (w1, e1) in zip(curve, curve[1:]):
        if w0 <= w <= w1 and w1 > w0:
            s = math.log(w / w0) / math.log(w1 / w0)
            return math.log(e0) + s * (math.log(e1) - math.log(e0))
    return None


def crossover(curve_a, curve_b):
    """First wall time at which the log-log-interpolated curves a and b cross: {wall_s, err} or None.

    Both curves are piecewise linear in (log w, log err), so their difference is piecewise
    linear between the merged break points and each crossing is found exactly.
    """
    lo = max(curve_a[0][0], curve_b[0][0])
    hi = min(curve_a[-1][0], curve_b[-1][0])
    if not lo < hi:
        return None
    ws = sorted({w for w, _ in curve_a + curve_b if lo <= w <= hi} | {lo, hi})
    prev = None
    for w in ws:
        la, lb = loglog_at(curve_a, w), loglog_at(curve_b, w)
        if la is None or lb is None:
            continue
        d = la - lb
        if prev is not None:
            w0, d0, la0 = prev
            if d0 == 0:
                return {"wall_s": w0, "err": math.exp(la0)}
            if d0 * d < 0 or d == 0:
                s = d0 / (d0 - d)
                lw = math.log(w0) + s * (math.log(w) - math.log(w0))
                wc = math.exp(lw)
                return {"wall_s": wc, "err": math.exp(loglog_at(curve_a, wc))}
        prev = (w, d, la)
    return None


def read_csv_rows(path, need):
    """The rows of a CSV file as dicts, or None if there is no such file."""
    if not os.path.isfile(path):
        return None
    with open(path, newline="", encoding="utf-8") as f:
        rows = csv.DictReader(f)
        if rows.fieldnames is None or not set(need) <= set(rows.fieldnames):
            raise Malformed(f"{path}: needs the columns {sorted(need)}")
        return list(rows)


def read_cost(path, error_column):
    """{method: [{h, steps, wall_s, force_evals, err}, ...] by decreasing h} from a timing.csv, or None."""
    numeric = ("h", "steps", "wall_s", "force_evals", error_column)
    rows = read_csv_rows(path, ("method",) + numeric)
    if rows is None:
        return None
    runs = {}
    for row in rows:
        try:
            v = {k: float(row[k]) for k in numeric}
        except ValueError:
            raise Malformed(f"{path}: non-numeric value in row {row}") from None
        v["err"] = v.pop(error_column)
        if all(math.isfinite(x) and x > 0 for x in v.values()):
            runs.setdefault(row["method"], []).append(v)
    return {m: sorted(r, key=lambda v: -v["h"]) for m, r in runs.items()}


def first_reach(runs, target, key):
    """runs[.][key] where the error first falls to `target` along decreasing h, by log-log
    interpolation between the two measurements that bracket it; None outside the measured range."""
    for a, b in zip(runs, runs[1:]):
        if a["err"] >= target >= b["err"] and a["err"] > b["err"]:
            s = math.log(a["err"] / target) / math.log(a["err"] / b["err"])
            return math.exp(math.log(a[key]) + s * (math.log(b[key]) - math.log(a[key])))
    return None


def target_key(target):
    return f"{target:g}"  # 1e-08


def cost_summary(name, exp_dir):
    """COST_TARGETS quantities of one experiment: {"cost": {method: {...}}, "equal_wall_s": W}, or None."""
    cfg = COST_TARGETS[name]
    runs = read_cost(os.path.join(exp_dir, "timing.csv"), cfg["error"])
    if not runs:
        return None
    ref = runs.get(cfg["equal_wall"])
    wall = max(v["wall_s"] for v in ref) if ref else None
    cost = {}
    for m, r in runs.items():
        finest = r[-1]
        curve = sorted((v["wall_s"], v["err"]) for v in r)
        at_w = loglog_at(curve, wall) if wall is not None else None
        cost[m] = {
            "evals_per_step": finest["force_evals"] / finest["steps"],
            "min_err": min(v["err"] for v in r),
            "err_at_equal_wall": None if at_w is None else math.exp(at_w),
            "wall_to": {target_key(t): first_reach(r, t, "wall_s") for t in cfg["targets"]},
            "evals_to": {target_key(t): first_reach(r, t, "force_evals") for t in cfg["targets"]},
        }
    return {"cost": cost, "equal_wall_s": wall}


def order_ranges(name, s):
    """{group: {min, max}} of the fitted orders over all initial conditions (ORDER_TABLES groups)."""
    obi = s.get("orders_by_initial") or []
    out = {}
    for group, keys in ORDER_TABLES[name].get("groups", {}).items():
        values = [o[k] for o in obi for k in keys if is_number(o.get(k)) and math.isfinite(o[k])]
        if values:
            out[group] = {"min": min(values), "max": max(values)}
    return out


def error_ratio(name, exp_dir):
    """ERROR_RATIOS: {min, max, h} of numerator/denominator error at the smallest h, or None."""
    file, num, den, suffixes = ERROR_RATIOS[name]
    path = os.path.join(exp_dir, file)
    rows = read_csv_rows(path, ["h"] + [m + x for m in (num, den) for x in suffixes])
    if not rows:
        return None
    try:
        hs = [float(r["h"]) for r in rows]
        h_min = min(hs)
        ratios = [float(r[num + x]) / float(r[den + x])
                  for r, h in zip(rows, hs) if h == h_min for x in suffixes if float(r[den + x]) != 0]
    except ValueError:
        raise Malformed(f"{path}: non-numeric value in the columns of {num} and {den}") from None
    ratios = [q for q in ratios if math.isfinite(q)]
    return {"min": min(ratios), "max": max(ratios), "h": h_min} if ratios else None


def local_order(name, exp_dir):
    """LOCAL_ORDERS: the slope of log(error) against log(h) between the two smallest h, or None."""
    file, hcol, ecol, _ = LOCAL_ORDERS[name]
    path = os.path.join(exp_dir, file)
    rows = read_csv_rows(path, (hcol, ecol))
    if not rows:
        return None
    try:
        pts = sorted((float(r[hcol]), float(r[ecol])) for r in rows)
    except ValueError:
        raise Malformed(f"{path}: non-numeric value in {hcol} or {ecol}") from None
    pts = [(h, e) for h, e in pts if h > 0 and e > 0 and math.isfinite(h) and math.isfinite(e)]
    if len(pts) < 2 or pts[0][0] == pts[1][0]:
        return None
    (h0, e0), (h1, e1) = pts[0], pts[1]
    return math.log(e1 / e0) / math.log(h1 / h0)


def quantile(sorted_values, q):
    """Nearest-rank quantile of a sorted non-empty list."""
    return sorted_values[int(round(q * (len(sorted_values) - 1)))]


def energy_map_stats(name, exp_dir, scene):
    """MAP_STATS quantities of the energy map, or None without map.csv or a usable scene.

    With phi(0) measured from the downward vertical (cos phi(0) = y0/r0, y pointing down), a
    release from rest oscillates radially about r* = l + (mg/k) cos phi(0) between r(0) and
    2r* - r(0); the boundary is r(0) = 2r*. A polar run that diverges inside the boundary
    counts as "inner" if r(0) < r* (its inner turning point is r(0) itself), else as "outer"
    (inner turning point 2r* - r(0), at the radial distance 2r* - r(0) inside the boundary).
    """
    cfg = MAP_STATS[name]
    path = os.path.join(exp_dir, cfg["file"])
    cols = ("x0", "y0", "H0", "eps_cartesian", "eps_polar", "diverged_cartesian", "diverged_polar",
            "diverge_step_polar")
    rows = read_csv_rows(path, cols)
    try:
        pend = scene["pendulum"]
        l, m, k, g = (float(pend[key]) for key in ("l", "m", "k", "g"))
        dt = float(scene["dt"])
    except (KeyError, TypeError, ValueError):
        return None
    if not rows or not (l > 0 and k > 0):
        return None
    pts = []
    try:
        for row in rows:
            pts.append({key: float(row[key]) for key in cols})
    except ValueError:
        raise Malformed(f"{path}: non-numeric value in a row") from None
    counted = agree = 0
    cart_div_off_origin = 0
    crit_count = polar_div = 0
    inner, outer, alive_outside, outside_steps, inside_steps = [], [], [], [], []
    inner_candidates, outer_candidates = [], []  # (r0) and (b - r0) of all points inside, by side of r*
    alive_inner_r, alive_outer_d = [], []
    div_h0, alive_h0 = [], []
    both, ring, off_ring, ratios = 0, [0, 0], [0, 0], []
    half = cfg["ring_half_width"] * l
    for p in pts:
        x, y = p["x0"], p["y0"]
        r = math.hypot(x, y)
        dc, dp = p["diverged_cartesian"] != 0, p["diverged_polar"] != 0
        polar_div += dp
        if r == 0:  # the origin: no initial condition of the polar problem
            continue
        cart_div_off_origin += dc
        counted += 1
        r_star = l + m * g / k * (y / r)
        b = 2 * l + 2 * m * g / k * (y / r)  # as in the executable
        crit = r >= b
        crit_count += crit
        agree += dp == crit
        (div_h0 if dp else alive_h0).append(p["H0"])
        if crit:
            if dp:
                outside_steps.append(p["diverge_step_polar"])
            else:
                alive_outside.append(r - b)
        else:
            if r < r_star:
                inner_candidates.append(r)
                if dp:
                    inner.append(r)
                else:
                    alive_inner_r.append(r)
            else:
                outer_candidates.append(b - r)
                if dp:
                    outer.append(b - r)
                else:
                    alive_outer_d.append(b - r)
            if dp:
                inside_steps.append(p["diverge_step_polar"])
        ec, ep = p["eps_cartesian"], p["eps_polar"]
        if not dc and not dp and math.isfinite(ec) and math.isfinite(ep):
            both += 1
            better = ep < ec
            tally = ring if abs(r - l) < half else off_ring
            tally[0] += better
            tally[1] += 1
            if ec > 0:
                ratios.append(ep / ec)
    out = {
        "counted": counted, "agreement": agree / counted if counted else None,
        "disagree": counted - agree, "criterion": crit_count, "diverged_polar": polar_div,
        "diverged_inside": len(inner) + len(outer), "alive_outside": len(alive_outside),
        "cartesian_diverged_off_origin": cart_div_off_origin,
        "inner": len(inner), "outer": len(outer),
        "both_finite": both, "ring_half_width": cfg["ring_half_width"],
        "ring_polar_better": ring[0] / ring[1] if ring[1] else None,
        "off_ring_polar_better": off_ring[0] / off_ring[1] if off_ring[1] else None,
    }
    if inner:
        r_max = max(inner)
        out["inner_r_max"] = r_max
        out["inner_candidates"] = sum(1 for r in inner_candidates if r <= r_max)
    if outer:
        d_max = max(outer)
        out["outer_dist_max"] = d_max
        out["outer_candidates"] = sum(1 for d in outer_candidates if d <= d_max)
        # every point closer to the boundary than this diverged
        out["outer_dist_all"] = min(alive_outer_d) if alive_outer_d else None
    if div_h0:
        out["H0_min_diverged"] = min(div_h0)
    if alive_h0:
        out["H0_max_alive"] = max(alive_h0)
    for key, steps in (("inside", inside_steps), ("outside", outside_steps)):
        if steps:
            steps.sort()
            out[f"{key}_step_median"] = quantile(steps, 0.5)
            out[f"{key}_step_max"] = steps[-1]
            out[f"{key}_time_max"] = steps[-1] * dt
    if ratios:
        ratios.sort()
        out["ratio_p05"], out["ratio_median"], out["ratio_p95"] = (quantile(ratios, q) for q in (0.05, 0.5, 0.95))
    return out


# ---------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------

HEADER = "% Generated by scripts/paper_tables.py from {src}; do not edit.\n"


def write_atomic(path, text):
    d = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(dir=d, prefix=".tmp-", suffix=".tex")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def placeholder_box(name, what):
    return (
        "\\begin{center}\n\\fbox{\\parbox{0.9\\linewidth}{\\centering\\small\n"
        f"{what} of \\texttt{{{tex_escape(name)}}}: not yet reproduced in this version\n"
        f"(no \\texttt{{results/{tex_escape(name)}/summary.json}}).}}}}\n\\end{{center}}\n"
    )


def experiment_title(name):
    return TITLES.get(name, r"\texttt{" + tex_escape(name) + "}")


def results_table(name, s, src):
    pub = s["published"]
    orders = s.get("orders") or {}
    reproduced = s.get("reproduced") or {}
    desc = DESCRIPTIONS.get(name, {})
    lines = [HEADER.format(src=src)]
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    lines.append(f"\\caption{{Published and reproduced values of {experiment_title(name)}. "
                 "Orders are least-squares slopes of $\\log(\\text{error})$ against $\\log h$; "
                 "difference = reproduced $-$ published.}\n")
    lines.append(f"\\label{{tab:{name}-table}}\n")
    lines.append("\\begin{tabular}{@{}p{0.52\\linewidth}rrr@{}}\n\\toprule\n")
    lines.append("Quantity & Published & Reproduced & Difference \\\\\n\\midrule\n")
    for key, p in pub.items():
        is_order = key in orders
        r = orders[key] if is_order else reproduced[key]
        label = desc.get(key, tex_escape(key))
        if isinstance(p, dict):  # one row per parameter
            for sub, pv in p.items():
                rv = r.get(sub) if isinstance(r, dict) else None
                cells = ([fmt(pv, "porder"), fmt(rv, "order"), fmt(None if rv is None else rv - pv, "dorder")]
                         if is_order else
                         [general(pv), None if rv is None else general(rv), None if rv is None else general(rv - pv)])
                lines.append(f"{label} (\\texttt{{{tex_escape(sub)}}}) & "
                             + " & ".join(math_cell(c) for c in cells) + " \\\\\n")
            continue
        if is_order:
            cells = [fmt(p, "porder"), fmt(r, "order"), fmt(None if r is None else r - p, "dorder")]
        else:
            cells = [general(p), None if r is None else general(r), None if r is None else general(r - p)]
        lines.append(f"{label} & " + " & ".join(math_cell(c) for c in cells) + " \\\\\n")
    extra = EXTRA_ROWS.get(name, [])
    if extra:
        lines.append("\\midrule\n")
    for label, path, kind in extra:
        lines.append(f"{label} & --- & {math_cell(fmt(lookup(s, path), kind))} & --- \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    norms = s.get("norms")
    if isinstance(norms, dict) and norms:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize Norms (from \\texttt{summary.json}): ")
        lines.append("; ".join(f"\\texttt{{{tex_escape(k)}}}: {tex_escape(v)}" for k, v in norms.items()))
        lines.append(".}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


def timing_table(name, s, src, cross):
    timing = s.get("timing") or {}
    nsps = timing.get("ns_per_step") or {}
    eq = timing.get("error_at_equal_wall_time")
    methods = METHODS.get(name, {})
    err_name = ERROR_NAMES.get(name, "error")
    lines = [HEADER.format(src=src)]
    if not nsps and not eq:
        lines.append("\\begin{center}\\small No timing recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        if "wall_s" in timing and is_number(timing["wall_s"]):
            lines.append(f"\\begin{{center}}\\small Wall time of the run: ${fmt(timing['wall_s'], 'seconds')}$\\,s.\\end{{center}}\n")
        return "".join(lines)
    names = list(nsps) + [m for m in (eq or {}) if m != "wall_s" and m not in nsps]
    base = next((nsps[m] for m in nsps if is_number(nsps[m]) and nsps[m] > 0), None)
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    lines.append(f"\\caption{{Cost of {experiment_title(name)}: time per step, cost relative to the first method, "
                 f"and the error, {err_name}, at equal wall time.}}\n")
    lines.append(f"\\label{{tab:{name}-timing}}\n")
    lines.append("\\begin{tabular}{@{}lrrr@{}}\n\\toprule\n")
    lines.append("Method & ns per step & Relative cost & Error at equal wall time \\\\\n\\midrule\n")
    for m in names:
        ns = nsps.get(m)
        rel = ns / base if (is_number(ns) and base) else None
        e = (eq or {}).get(m)
        lines.append(f"{methods.get(m, tex_escape(m))} & {math_cell(fmt(ns, 'ns'))} & "
                     f"{math_cell(fmt(rel, 'ratio'))} & {math_cell(fmt(e, 'err'))} \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    notes = []
    for k, v in timing.items():
        if k.startswith("ns_per_step_ratio") and is_number(v):
            notes.append(f"ratio \\texttt{{{tex_escape(k[len('ns_per_step_ratio_'):])}}} = ${fmt(v, 'ratio')}$")
    if isinstance(eq, dict) and is_number(eq.get("wall_s")):
        notes.append(f"equal wall time ${sci(eq['wall_s'])}$\\,s")
    elif "error_at_equal_wall_time" in timing and eq is None:
        notes.append("no wall-time range common to all methods")
    if cross is not None:
        a, b = (r"\texttt{" + tex_escape(m) + "}" for m in CROSSOVERS[name][:2])
        if cross.get("wall_s") is not None:
            notes.append(f"the work-precision curves of {a} and {b} (log--log interpolation of "
                         f"\\texttt{{timing.csv}}) cross at ${sci(cross['wall_s'])}$\\,s, "
                         f"error ${fmt(cross['err'], 'err')}$")
        else:
            notes.append(f"the work-precision curves of {a} and {b} do not cross in the measured range")
    if isinstance(timing.get("method"), str):
        notes.append("measurement: " + tex_escape(timing["method"]))
    if is_number(timing.get("wall_s")):
        notes.append(f"wall time of the whole run ${fmt(timing['wall_s'], 'seconds')}$\\,s")
    if notes:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize " + "; ".join(notes) + ".}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


def orders_table(name, s, scene, src):
    """The fitted orders of every initial condition (ORDER_TABLES), as a table float."""
    cfg = ORDER_TABLES[name]
    obi = s.get("orders_by_initial")
    lines = [HEADER.format(src=src)]
    if not obi:
        lines.append("\\begin{center}\\small No \\texttt{orders\\_by\\_initial} recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    n = len(obi)
    initial = (scene or {}).get(cfg["initial_key"])
    if not (isinstance(initial, list) and len(initial) == n and all(isinstance(r, list) for r in initial)):
        initial = None
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    lines.append(f"\\caption{{{cfg['caption']}}}\n")
    lines.append(f"\\label{{tab:{name}-orders}}\n")
    lines.append("\\begin{tabular}{@{}p{0.27\\linewidth}lc" + "r" * n + "@{}}\n\\toprule\n")
    lines.append(f"Method & Error & Expected & \\multicolumn{{{n}}}{{c}}{{Initial condition}} \\\\\n")
    lines.append(f"\\cmidrule(l){{4-{3 + n}}}\n")
    lines.append(" & & & " + " & ".join(str(i + 1) for i in range(n)) + " \\\\\n")
    if initial is not None:
        vecs = []
        for row in initial:
            ok = all(is_number(v) and math.isfinite(v) for v in row)
            vecs.append("\\footnotesize $(" + ",".join(f"{v:g}" for v in row) + ")$" if ok else NA)
        lines.append(f"\\footnotesize {cfg['initial_names']} & & & " + " & ".join(vecs) + " \\\\\n")
    lines.append("\\midrule\n")
    for i, (key, method, norm, expected) in enumerate(cfg["rows"]):
        if method and i > 0:
            lines.append("\\addlinespace\n")
        cells = [math_cell(fmt(o.get(key), "order")) for o in obi]
        lines.append(f"\\raggedright {method} & {norm} & ${expected}$ & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n\\end{table}\n")
    return "".join(lines)


def cost_timing_table(name, s, src, derived):
    """Timing table of an experiment with COST_TARGETS: time and force evaluations per step,
    error at equal wall time, and what each error target costs."""
    cfg = COST_TARGETS[name]
    timing = s.get("timing") or {}
    nsps = timing.get("ns_per_step") or {}
    cost = derived.get("cost") or {}
    methods = METHODS.get(name, {})
    err_name = ERROR_NAMES.get(name, "error")
    targets = cfg["targets"]
    nt = len(targets)
    lines = [HEADER.format(src=src)]
    if not nsps and not cost:
        lines.append("\\begin{center}\\small No timing recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    names = list(nsps) + [m for m in cost if m not in nsps]
    base = next((nsps[m] for m in nsps if is_number(nsps[m]) and nsps[m] > 0), None)
    first = tex_escape(names[0]) if names else ""
    lines.append("\\begin{table}[htbp]\n\\centering\n\\footnotesize\n")
    evals_name = cfg.get("evals_name", "force evaluations (gradients and Hessian--vector products)")
    run_note = cfg.get("run_note", "One run goes from the first initial condition to $t_{\\max}$, "
                                   "with pre- and postprocessing once.")
    lines.append(f"\\caption{{Cost of {experiment_title(name)}: time and {evals_name} "
                 "per step at the smallest $h$, cost relative to the first method, "
                 f"{err_name} of every method at the wall time of the most expensive run of "
                 f"\\texttt{{{tex_escape(cfg['equal_wall'])}}}, and the wall time and the force evaluations "
                 "with which each method first reaches the given error (log--log interpolation between the "
                 "measured step sizes of \\texttt{timing.csv}, not extrapolated; --- where the measured "
                 f"step sizes do not reach it). {run_note}" + (" " + cfg["legend"] if cfg.get("legend") else "")
                 + "}\n")
    lines.append(f"\\label{{tab:{name}-timing}}\n")
    lines.append("\\setlength{\\tabcolsep}{4pt}\n")
    lines.append("\\begin{tabular}{@{}p{0.22\\linewidth}rrrr" + "r" * (2 * nt) + "@{}}\n\\toprule\n")
    tcells = " & ".join(f"${fmt(t, 'tol')}$" for t in targets)
    lines.append("Method & ns per & Relative & Evaluations & Error at equal & "
                 f"\\multicolumn{{{nt}}}{{c}}{{Wall time ($\\mu$s) to}} & "
                 f"\\multicolumn{{{nt}}}{{c}}{{Evaluations to}} \\\\\n")
    lines.append(f"\\cmidrule(lr){{6-{5 + nt}}}\\cmidrule(l){{{6 + nt}-{5 + 2 * nt}}}\n")
    lines.append(f" & step & cost & per step & wall time & {tcells} & {tcells} \\\\\n\\midrule\n")
    for m in names:
        ns = nsps.get(m)
        rel = ns / base if (is_number(ns) and base) else None
        c = cost.get(m, {})
        cells = [math_cell(fmt(ns, "ns")), math_cell(fmt(rel, "ratio")),
                 math_cell(fmt(c.get("evals_per_step"), "ratio")), math_cell(fmt(c.get("err_at_equal_wall"), "err"))]
        for key, kind in (("wall_to", "us"), ("evals_to", "int")):
            for t in targets:
                v = (c.get(key) or {}).get(target_key(t))
                cells.append("---" if c and v is None else math_cell(fmt(v, kind)))
        lines.append(f"\\raggedright {methods.get(m, tex_escape(m))} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    notes = []
    for k, v in timing.items():
        if k.startswith("ns_per_step_ratio") and is_number(v):
            notes.append(f"ratio \\texttt{{{tex_escape(k[len('ns_per_step_ratio_'):])}}} = ${fmt(v, 'ratio')}$")
    if is_number(derived.get("equal_wall_s")):
        notes.append(f"equal wall time ${fmt(derived['equal_wall_s'], 'us')}\\,\\mu$s")
    if isinstance(timing.get("method"), str):
        notes.append("measurement: " + tex_escape(timing["method"]))
    if is_number(timing.get("wall_s")):
        notes.append(f"wall time of the whole run ${fmt(timing['wall_s'], 'seconds')}$\\,s")
    if notes:
        lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize " + "; ".join(notes) + ".}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


ISA_NAMES = {"avx512": "AVX-512", "avx2": "AVX2", "sse2": "SSE2"}


def kernel_summary(name, s, run, scene):
    """KERNEL_TIMING quantities: ceiling/measured per coordinate system, the total map wall time,
    the number of trajectory-steps of the map and the threads of the run."""
    cfg = KERNEL_TIMING[name]
    timing = s.get("timing") or {}
    ns = timing.get("ns_per_step_per_core") or {}
    walls = timing.get("map_wall_s") or {}
    out = {"fraction": {}, "ceiling": {}, "target": cfg["target"], "verdict": {}}
    for key, _ in cfg["rows"]:
        lo, hi = cfg["ceiling"][key]
        out["ceiling"][key] = {"lo": lo, "hi": hi}
        v = ns.get(key) if isinstance(ns, dict) else None
        if is_number(v) and v > 0:
            out["fraction"][key] = {"lo": lo / v, "hi": hi / v}
            out["verdict"][key] = "meets" if v <= cfg["target"][key] else "misses"
    if isinstance(walls, dict) and walls and all(is_number(w) for w in walls.values()):
        out["map_wall_s"] = sum(walls.values())
    grid = s.get("grid") or {}
    if isinstance(grid, dict) and is_number(grid.get("points")) and is_number(grid.get("steps")):
        out["trajectory_steps"] = len(cfg["rows"]) * grid["points"] * grid["steps"]
    threads = (run or {}).get("threads")
    out["threads"] = threads if is_number(threads) else None
    for key in ("scalar_points", "scalar_steps"):
        v = lookup(scene or {}, ("timing", key))
        out[key] = v if is_number(v) else None
    return out


def range_cell(lo, hi, kind):
    """lo, or lo--hi when they differ, as a table cell."""
    a, b = fmt(lo, kind), fmt(hi, kind)
    if a is None or b is None:
        return NA
    return f"${a}$" if a == b else f"${a}$--${b}$"


def kernel_timing_table(name, s, src, derived):
    """Timing table of an experiment with KERNEL_TIMING: the batched kernel per coordinate system
    against the scalar loop, its target and the hardware ceiling."""
    cfg = KERNEL_TIMING[name]
    timing = s.get("timing") or {}
    lines = [HEADER.format(src=src)]
    if not isinstance(timing.get("ns_per_step_per_core"), dict):
        lines.append("\\begin{center}\\small No kernel timing recorded for \\texttt{"
                     f"{tex_escape(name)}" "}.\\end{center}\n")
        return "".join(lines)
    k = derived.get("kernel") or {}

    def get(section, key):
        d = timing.get(section)
        return d.get(key) if isinstance(d, dict) else None

    isa = timing.get("kernel_isa")
    isa_name = ISA_NAMES.get(isa, tex_escape(isa)) if isinstance(isa, str) else NA
    lines.append("\\begin{table}[htbp]\n\\centering\n\\small\n")
    pts, steps = k.get("scalar_points"), k.get("scalar_steps")
    scalar_runs = (f", on ${fmt(pts, 'int')}$ initial conditions of ${fmt(steps, 'int')}$ steps"
                   if is_number(pts) and is_number(steps) else "")
    lines.append(f"\\caption{{Cost of {experiment_title(name)}: time per trajectory-step and core of the "
                 f"batched kernel ({isa_name}, chosen at run time; wall time of the map times the number of "
                 "threads, over the trajectory-steps of the map), of the straightforward scalar loop (the "
                 f"same formulas, one trajectory at a time, one thread{scalar_runs}), their ratio, the wall "
                 "time of the map, the target of the kernel and the hardware ceiling, and the ceiling as a "
                 "fraction of the measured time.}\n")
    lines.append(f"\\label{{tab:{name}-timing}}\n")
    lines.append("\\setlength{\\tabcolsep}{4pt}\n")
    lines.append("\\begin{tabular}{@{}lrrrrrrr@{}}\n\\toprule\n")
    lines.append("Coordinates & Kernel & Scalar loop & Speedup & Map wall & Target & Ceiling & "
                 "Ceiling / \\\\\n")
    lines.append(" & ns/step/core & ns/step & & time (s) & ns/step & ns/step & kernel \\\\\n\\midrule\n")
    for key, label in cfg["rows"]:
        ceil = (k.get("ceiling") or {}).get(key) or {}
        frac = (k.get("fraction") or {}).get(key) or {}
        target = cfg["target"].get(key)
        cells = [math_cell(fmt(get("ns_per_step_per_core", key), "ns3")),
                 math_cell(fmt(get("scalar_ns_per_step", key), "ns3")),
                 math_cell(fmt(get("speedup_vs_scalar", key), "ratio")),
                 math_cell(fmt(get("map_wall_s", key), "ns3")),
                 NA if target is None else f"$\\le {fmt(target, 'plain')}$",
                 range_cell(ceil.get("lo"), ceil.get("hi"), "plain"),
                 range_cell(frac.get("lo"), frac.get("hi"), "percent")]
        lines.append(f"{label} & " + " & ".join(cells) + " \\\\\n")
    lines.append("\\midrule\n")
    lines.append(f"Both & & & & {math_cell(fmt(k.get('map_wall_s'), 'ns3'))} & & & \\\\\n")
    lines.append("\\bottomrule\n\\end{tabular}\n")
    notes = []
    if is_number(k.get("trajectory_steps")):
        notes.append(f"the map is ${sci(k['trajectory_steps'])}$ trajectory-steps")
    if is_number(k.get("threads")):
        notes.append(f"{int(k['threads'])} thread{'s' if k['threads'] != 1 else ''}")
    if is_number(timing.get("wall_s")):
        notes.append(f"wall time of the whole run ${fmt(timing['wall_s'], 'seconds')}$\\,s")
    text = "; ".join(notes) + ". " if notes else ""
    lines.append("\\par\\smallskip\\parbox{\\linewidth}{\\footnotesize " + text[:1].upper() + text[1:]
                 + cfg["ceiling_note"] + "}\n")
    lines.append("\\end{table}\n")
    return "".join(lines)


def macros_file(name, s, scene, derived, src):
    lines = [HEADER.format(src=src)]
    specs = MACROS.get(name, [])
    if not specs:
        lines.append(f"% No macros are cited for {name}.\n")
    sources = {"summary": s, "scene": scene, "derived": derived or {}}
    for macro, path, kind in specs:
        value = lookup(sources.get(path[0]) or {}, path[1:])
        if kind.startswith(("min:", "max:")):  # a list reduced to its extreme
            numbers = value if isinstance(value, list) and value and all(map(is_number, value)) else None
            value = None if numbers is None else (min(numbers) if kind[:3] == "min" else max(numbers))
            kind = kind[4:]
        elif kind.startswith("len:"):  # the length of a list
            value = len(value) if isinstance(value, list) else None
            kind = kind[4:]
        if kind == "isa":  # an instruction set, as text
            body = ISA_NAMES.get(value, tex_escape(value)) if isinstance(value, str) else NA
            lines.append(f"\\newcommand{{\\{macro}}}{{{body}}}\n")
            continue
        if kind == "text":  # a word computed from the results
            body = tex_escape(value) if isinstance(value, str) else NA
            lines.append(f"\\newcommand{{\\{macro}}}{{{body}}}\n")
            continue
        if kind.startswith(("range:", "absrange:")):  # {min, max[, absmin, absmax]} as "a--b", or "a" if equal
            lo_key, hi_key = ("absmin", "absmax") if kind.startswith("abs") else ("min", "max")
            kind = kind.split(":", 1)[1]
            d = value if isinstance(value, dict) else {}
            a, b = fmt(d.get(lo_key), kind), fmt(d.get(hi_key), kind)
            body = (NA if a is None or b is None else
                    f"\\ensuremath{{{a}}}" if a == b else f"\\ensuremath{{{a}}}--\\ensuremath{{{b}}}")
            lines.append(f"\\newcommand{{\\{macro}}}{{{body}}}\n")
            continue
        if kind == "vec":  # a list of numbers as (a, b, ...)
            ok = isinstance(value, list) and value and all(is_number(v) and math.isfinite(v) for v in value)
            content = r"(" + ", ".join(f"{v:g}" for v in value) + ")" if ok else None
        else:
            content = fmt(value, kind)
        body = NA if content is None else f"\\ensuremath{{{content}}}"
        lines.append(f"\\newcommand{{\\{macro}}}{{{body}}}\n")
    return "".join(lines)


def render(name, exp_dir, root=None):
    """{suffix: text} of the files of one experiment; placeholders if exp_dir is None.

    root is RESULTS_ROOT, where the second scenes of SCENE_VARIANTS are looked up.
    Reads and checks everything first, so that a malformed input raises before any file is written.
    """
    variants = None
    if name in SCENE_VARIANTS:
        variants = {v: mc_load_variant(os.path.join(root, f"{name}-{v}")) if root else None
                    for v in SCENE_VARIANTS[name]}
    if exp_dir is None:
        src = "(no results)"
        derived = None
        if variants and any(variants.values()) and name in DERIVED_SUMMARIES:
            key, f = DERIVED_SUMMARIES[name]
            derived = {key: f(None, None, None, variants=variants)}
        files = {"table": HEADER.format(src=src) + placeholder_box(name, "Published vs reproduced"),
                 "timing": HEADER.format(src=src) + placeholder_box(name, "Timing"),
                 "macros": macros_file(name, None, None, derived, src)}
        if name in ORDER_TABLES:
            files["orders"] = HEADER.format(src=src) + placeholder_box(name, "Orders per initial condition")
        for suffix in EXTRA_TABLES.get(name, {}):
            files[suffix] = HEADER.format(src=src) + placeholder_box(name, suffix.capitalize())
        return files
    summary_path = os.path.join(exp_dir, "summary.json")
    s = load_json(summary_path)
    check_summary(summary_path, s, name)
    if s.get("experiment") not in (None, name):
        print(f"paper_tables.py: warning: {summary_path} names experiment {s.get('experiment')!r}",
              file=sys.stderr)
    scene, run = {}, {}
    run_path = os.path.join(exp_dir, "run.json")
    if os.path.isfile(run_path):
        run = load_json(run_path)
        if not isinstance(run, dict):
            run = {}
        if isinstance(run.get("scene"), dict):
            scene = run["scene"]
    cross = None
    if name in CROSSOVERS:
        a, b, col = CROSSOVERS[name]
        curves = read_timing_curves(os.path.join(exp_dir, "timing.csv"), col)
        if curves and a in curves and b in curves and len(curves[a]) > 1 and len(curves[b]) > 1:
            cross = crossover(curves[a], curves[b]) or {"wall_s": None, "err": None}
    derived = {"crossover": cross} if cross else {}
    if name in SCENE_DERIVED:
        derived["scene"] = {}
        for key, f in SCENE_DERIVED[name].items():
            try:
                derived["scene"][key] = f(scene)
            except (KeyError, IndexError, TypeError, ValueError, ZeroDivisionError):
                derived["scene"][key] = None
    if name in COST_TARGETS:
        derived.update(cost_summary(name, exp_dir) or {})
    if name in ORDER_TABLES:
        derived["order_range"] = order_ranges(name, s)
    if name in ERROR_RATIOS:
        ratio = error_ratio(name, exp_dir)
        if ratio is not None:
            derived["error_ratio"] = ratio
    if name in LOCAL_ORDERS:
        derived[LOCAL_ORDERS[name][3]] = local_order(name, exp_dir)
    if name in MAP_STATS:
        stats = energy_map_stats(name, exp_dir, scene)
        if stats is not None:
            derived["map"] = stats
    if name in KERNEL_TIMING:
        derived["kernel"] = kernel_summary(name, s, run, scene)
    if name in DERIVED_SUMMARIES:
        key, f = DERIVED_SUMMARIES[name]
        derived[key] = f(s, scene, exp_dir, variants=variants) if name in SCENE_VARIANTS else f(s, scene, exp_dir)
    if name in COST_TARGETS:
        timing_text = cost_timing_table(name, s, summary_path, derived)
    elif name in KERNEL_TIMING:
        timing_text = kernel_timing_table(name, s, summary_path, derived)
    elif name in TIMING_TABLES:
        timing_text = TIMING_TABLES[name](name, s, summary_path, derived)
    else:
        timing_text = timing_table(name, s, summary_path, cross)
    table_text = (RESULTS_TABLES[name](name, s, summary_path, derived) if name in RESULTS_TABLES
                  else results_table(name, s, summary_path))
    files = {"table": table_text,
             "timing": timing_text,
             "macros": macros_file(name, s, scene, derived, summary_path)}
    if name in ORDER_TABLES:
        files["orders"] = orders_table(name, s, scene, summary_path)
    for suffix, f in EXTRA_TABLES.get(name, {}).items():
        files[suffix] = f(name, s, summary_path, derived)
    return files


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    root, out_dir = argv[1], argv[2]
    if not os.path.isdir(root):
        print(f"paper_tables.py: RESULTS_ROOT {root!r} is not a directory", file=sys.stderr)
        return 2
    present = sorted(d for d in os.listdir(root)
                     if os.path.isfile(os.path.join(root, d, "summary.json")))
    variant_dirs = {f"{n}-{v}" for n, vs in SCENE_VARIANTS.items() for v in vs}
    names = KNOWN + [d for d in present if d not in KNOWN and d not in variant_dirs]
    try:
        files = {name: render(name, os.path.join(root, name) if name in present else None, root)
                 for name in names}
    except Malformed as e:
        print(f"paper_tables.py: malformed results: {e}", file=sys.stderr)
        return 2
    os.makedirs(out_dir, exist_ok=True)
    for name, texts in files.items():
        for suffix, text in texts.items():
            write_atomic(os.path.join(out_dir, f"{name}_{suffix}.tex"), text)
        state = "tables written" if name in present else "not yet reproduced (placeholder)"
        for v in SCENE_VARIANTS.get(name, []):
            found = os.path.isfile(os.path.join(root, f"{name}-{v}", "summary.json"))
            state += f"; scene {v} ({name}-{v}): " + ("read" if found else "no results")
        print(f"paper_tables.py: {name}: {state}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

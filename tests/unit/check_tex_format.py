#!/usr/bin/env python3
"""check_tex_format.py SOURCE_DIR: the report's free text (scripts/tex_format.py) sets the ASCII math of
published.toml's descriptions and notes, the tests' records and the registry's citations as LaTeX math (h^2 as
$h^{2}$, -> as \\to, sqrt(3) as \\sqrt{3}, <= as \\le, omega as \\omega, Phi(4) as \\Phi^{(4)}) and leaves ordinary
text alone (Stormer-Verlet, (32)-(33), a 3 x 3 grid, the machine epsilon, --set); a comparison's key becomes its
reference; a path of the machine that ran a test is shown relative to its source tree, or as DIR/<name>; a
paper's formula quoted without its $ is math."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(sys.argv[1]) / "scripts"))
from tex_format import ascii_math, prose, quote_tex, repo_paths  # noqa: E402

MATH = {  # free text -> its LaTeX
    "h^2/24": "$h^{2}/24$",
    "the coefficient h^2/12 in (32)-(33)": "the coefficient $h^{2}/12$ in (32)-(33)",
    "remains bounded when omega h -> 2 sqrt(3)": r"remains bounded when $\omega h \to 2 \sqrt{3}$",
    "TI is stable for omega h < 2 sqrt(3)": r"TI is stable for $\omega h < 2 \sqrt{3}$",
    "stable only for omega h <= 2 (a necessary condition)": r"stable only for $\omega h \le 2$ (a necessary condition)",
    "must be >= 1": r"must be $\ge 1$",
    "tends to 1/24 as h -> 0 instead": r"tends to 1/24 as $h \to 0$ instead",
    "an integer of 2^53 + 2, not exact": "an integer of $2^{53} + 2$, not exact",
    "for h omega < sqrt(42 - 6 sqrt(29))": r"for $h \omega < \sqrt{42 - 6 \sqrt{29}}$",
    "errors as 2^-alpha": r"errors as $2^{-\alpha}$",
    "the volume in mu(4) under Phi(4) up to t = 20": r"the volume in $\mu^{(4)}$ under $\Phi^{(4)}$ up to t = 20",
    "with Phi^(4), |H - H0|": r"with $\Phi^{(4)}$, $|H - H_{0}|$",
    "largest e_{k+1} / e_k^2 over": "largest $e_{k+1}/e_{k}^{2}$ over",
    "largest |Q(Q^-1(qbar)) - qbar| at": r"largest $|Q(Q^{-1}(\bar{q})) - \bar{q}|$ at",
    "x1 = 1/(2 - 2^(1/3)), next": "$x_{1} = 1/(2 - 2^{1/3})$, next",
    "E = E^(ell)(z_0)": r"$E = E^{(\ell)}(z_{0})$",
    "sigma ~ t^gamma of Fig. 6": r"$\sigma \sim t^{\gamma}$ of Fig. 6",
    "change per step is O(h^2)": "change per step is $O(h^{2})$",
    "< 0.00063": "$< 0.00063$",
    "E <= max U": r"E $\le$ max U",
    "Stormer-Verlet, (32)-(33), a 3 x 3 grid, that and what, 1e-7": "Stormer-Verlet, (32)-(33), a 3 x 3 grid, that and "
                                                                  "what, 1e-7",
    "a thousand machine epsilon, is a - 1": "a thousand machine epsilon, is a - 1",
    "--set decay.h=-1 & 50 %": r"-{}-set decay.h=-1 \& 50 \%",
}
problems = [f"ascii_math({text!r}) = {ascii_math(text)!r}, not {want!r}" for text, want in MATH.items()
            if ascii_math(text) != want]
refs = {"rowlands_printed_phase": r"\hyperref[cmp:r:rowlands_printed_phase]{\#3}", "lj_h": r"\hyperref[cmp:t:lj_h]{\#9}"}
PROSE = {"of order 2 (rowlands_printed_phase), h^2": r"of order 2 (\hyperref[cmp:r:rowlands_printed_phase]{\#3}), "
                                                    "$h^{2}$",
         "h = 0.01 (lj_h)": r"h = 0.01 (\hyperref[cmp:t:lj_h]{\#9})",
         "preserve p_x; see cost.phase.h_max": r"preserve $p_{x}$; see \texttt{cost.\allowbreak{}phase.\allowbreak{}h\_"
                                               r"\allowbreak{}max}"}
problems += [f"prose({text!r}) = {prose(text, refs)!r}, not {want!r}" for text, want in PROSE.items()
             if prose(text, refs) != want]
ROOTS = ["/work/main", "/home/u/geomint/"]
for text, want in {"--scene /work/main/build/test-results/cli-1/deep.toml: exit code":
                   "--scene build/test-results/cli-1/deep.toml: exit code",
                   "(in /home/u/geomint/experiments/x/quick.toml): at most": "(in experiments/x/quick.toml): at most",
                   "delete /tmp/geomint_checkpoint_test_365/tasks.checkpoint.* to": "delete DIR/tasks.checkpoint.* to",
                   "/tmp/geomint_published_test_1_0.toml: [a]": "DIR/geomint_published_test_1_0.toml: [a]",
                   "--out /proc/self/x, https://doi.org/1, a/b": "--out /proc/self/x, https://doi.org/1, a/b"}.items():
    if repo_paths(text, ROOTS) != want:
        problems.append(f"repo_paths({text!r}) = {repo_paths(text, ROOTS)!r}, not {want!r}")
for text, want in {r"\frac{1}{2}k(r - l)^2 - mgr \cos(\theta).": r"$\frac{1}{2}k(r - l)^2 - mgr \cos(\theta)$.",
                   "these cuts lie in the region p2 < 0 (right)": "these cuts lie in the region $p_{2} < 0$ (right)",
                   "when ωh → 2 √ 3.": r"when $\omega$h $\to$ 2 $\surd$ 3.",
                   "$$(63) \\quad x$$ and $y$": r"\[(63) \quad x\] and $y$"}.items():
    if quote_tex(text) != want:
        problems.append(f"quote_tex({text!r}) = {quote_tex(text)!r}, not {want!r}")
for p in problems:
    print("check_tex_format:", p)
print(f"check_tex_format: {len(problems)} problems")
sys.exit(1 if problems else 0)

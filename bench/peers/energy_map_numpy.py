#!/usr/bin/python3
"""The energy map of 000 Fig. 6 in numpy, written as a Python user writes it.

Symplectic Euler, p first (000 eq. (42)-(43)), on the elastic pendulum
(l = m = k = 1, g = 0.02, h = 0.2) from N initial conditions at rest, in
Cartesian (73) and polar (72) coordinates, accumulating for each trajectory
eps = sqrt(sum_j (H_j - H_0)^2 / J), eq. (50). Vectorised across trajectories
(arrays of x, y, px, py over the N initial conditions), loop over steps in
Python; force and energy are separate functions, as one would write them.
The sum is a plain one (no compensated summation), diverged trajectories are
not masked (they become NaN or inf and are counted).

The peer baseline for build/bin/geomint_energy_map_bench (same physics, same
initial-condition box x0 in [-1, 1], y0 in [0.3, 1.4]); the first trajectories
are the benchmark's check points, whose eps are printed for comparison.
Run with Debian's interpreter (python3-numpy): /usr/bin/python3.

    /usr/bin/python3 bench/peers/energy_map_numpy.py [--n 4096] [--steps 20000] [--repeat 3] [--json]
"""
import argparse
import json
import statistics
import sys
import time

import numpy as np

L, M, K, G, H = 1.0, 1.0, 1.0, 0.02, 0.2
CHECK_POINTS = [(0.2, 1.0), (-0.5, 0.8), (0.7, 1.3)]  # as kCheckPoints in bench/energy_map_bench.cpp


# ---- Cartesian, 000 eq. (73): H = |p|^2/(2m) + (k/2)(|q| - l)^2 - m g y -------------------
def force_cartesian(x, y):
    r = np.sqrt(x * x + y * y)
    f = K * (1.0 - L / r)
    return -f * x, -(f * y - M * G)


def energy_cartesian(x, y, px, py):
    r = np.sqrt(x * x + y * y)
    return (px * px + py * py) / (2 * M) + 0.5 * K * (r - L) ** 2 - M * G * y


def run_cartesian(x0, y0, steps):
    x, y = x0.copy(), y0.copy()
    px, py = np.zeros_like(x), np.zeros_like(y)
    E0 = energy_cartesian(x, y, px, py)
    acc = np.zeros_like(x)
    for _ in range(steps):
        fx, fy = force_cartesian(x, y)  # (42): p first, force at q^j
        px = px + H * fx
        py = py + H * fy
        x = x + H * px / M  # (43): q with the new p
        y = y + H * py / M
        d = energy_cartesian(x, y, px, py) - E0
        acc += d * d
    return np.sqrt(acc / steps)


# ---- polar, 000 eq. (72), theta from +y (x = r sin(theta), y = r cos(theta)) -------------
# H = (p_r^2 + p_theta^2 / r^2)/(2m) + (k/2)(r - l)^2 - m g r cos(theta). Symplectic Euler
# p first is explicit when p_theta is updated first (dH/dtheta has no p), then p_r.
def energy_polar(r, th, pr, pth):
    return (pr * pr + pth * pth / (r * r)) / (2 * M) + 0.5 * K * (r - L) ** 2 - M * G * r * np.cos(th)


def run_polar(x0, y0, steps):
    r, th = np.hypot(x0, y0), np.arctan2(x0, y0)
    pr, pth = np.zeros_like(r), np.zeros_like(r)
    E0 = energy_polar(r, th, pr, pth)
    acc = np.zeros_like(r)
    for _ in range(steps):
        pth = pth - H * (M * G * r * np.sin(th))  # (42), dH/dtheta
        pr = pr - H * (-pth * pth / (M * r**3) + K * (r - L) - M * G * np.cos(th))  # (42), dH/dr
        th = th + H * pth / (M * r * r)  # (43) with r^j
        r = r + H * pr / M
        d = energy_polar(r, th, pr, pth) - E0
        acc += d * d
    return np.sqrt(acc / steps)


def initial_conditions(n):
    """The check points, then a regular grid on [-1, 1] x [0.3, 1.4] (about n points in all)."""
    side = max(int(round(np.sqrt(max(n - len(CHECK_POINTS), 1)))), 2)
    gx, gy = np.meshgrid(np.linspace(-1.0, 1.0, side), np.linspace(0.3, 1.4, side))
    x0 = np.concatenate([[p[0] for p in CHECK_POINTS], gx.ravel()])
    y0 = np.concatenate([[p[1] for p in CHECK_POINTS], gy.ravel()])
    return x0, y0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=4096, help="trajectories (default 4096)")
    ap.add_argument("--steps", type=int, default=20000, help="steps per trajectory (default 20000)")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per coordinate system; the median is reported")
    ap.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    a = ap.parse_args()
    if a.n < 1 or a.steps < 1 or a.repeat < 1:
        ap.error("--n, --steps and --repeat must be positive")

    x0, y0 = initial_conditions(a.n)
    n = x0.size
    result = {"implementation": "numpy", "numpy": np.__version__, "trajectories": n, "steps": a.steps,
              "repeat": a.repeat, "ns_per_step": {}, "eps": {}, "diverged": {}}
    for coords, run in (("cartesian", run_cartesian), ("polar", run_polar)):
        times = []
        with np.errstate(all="ignore"):  # diverged trajectories: NaN/inf, counted below
            for _ in range(a.repeat):
                t0 = time.perf_counter()
                eps = run(x0, y0, a.steps)
                times.append(time.perf_counter() - t0)
        result["ns_per_step"][coords] = statistics.median(times) / (n * a.steps) * 1e9
        result["eps"][coords] = [[float(x0[i]), float(y0[i]), float(eps[i])] for i in range(len(CHECK_POINTS))]
        result["diverged"][coords] = int(np.count_nonzero(~np.isfinite(eps)))

    if a.json:
        json.dump(result, sys.stdout)
        print()
        return
    print(f"numpy {np.__version__}: {n} trajectories x {a.steps} steps, median of {a.repeat}, one thread")
    for coords in ("cartesian", "polar"):
        print(f"  {coords:9s} {result['ns_per_step'][coords]:8.3f} ns per step per trajectory"
              f"  ({result['diverged'][coords]} diverged)")
    print(f"eps (000 eq. (50)) after {a.steps} steps:")
    for coords in ("cartesian", "polar"):
        for x, y, e in result["eps"][coords]:
            print(f"  {coords:9s} ({x:g}, {y:g})  {e:.17g}")


if __name__ == "__main__":
    main()

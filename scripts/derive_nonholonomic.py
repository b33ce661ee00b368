#!/usr/bin/env python3
"""Modified quantities of the nonholonomic-particle variational integrators -> C++ header.

Paper: L. C. Garcia-Naranjo and M. Vermeeren, "Structure preserving discretization of
time-reparametrized Hamiltonian systems with application to nonholonomic mechanics",
Section 5 (Example 3.1, discrete Lagrangians (5.1)).

Method (for each of the five discrete Lagrangians M, MT, TM, TT, T of (5.1) and each
potential U = (x^2+y^2)/2 "harmonic" and U = 0 "free"), through h^MAX_ORDER:
  1. Modified equation. Expand the discrete Euler-Lagrange expression
       R[q](t) = d_{q1} Lambda_d(q(t-h), q(t)) + d_{q0} Lambda_d(q(t), q(t+h))
     in h along the ansatz q'' = F = F0 + h^2 F2 + h^4 F4 + ..., with jets q^(k) = D^(k-2) F;
     R = 0 is solved order by order for F0, F2, ... (the jets are rebuilt from the full
     known part of F at every order, so the jet corrections delta q^(k) are included).
  2. Modified Lagrangian by action matching: G(t) = Lambda_d(q(t-h/2), q(t+h/2)) on the jets
     of F, and L_mod = [(hD/2)/sinh(hD/2)] G, the inverse of the midpoint-rule expansion of
     (1/h) int_{t-h/2}^{t+h/2}, so that int L_mod dt = S_d = h Lambda_d step by step.
     Check: EL(L_mod) = 0 on q'' = F through the highest order.
  3. Legendre transform of L_mod: the modified altered Hamiltonian (4.2)
       K_mod = N [ (H - E) + h^2 kappa2 + h^4 kappa4 + ... ].
  4. Series inversion K_mod(z; Ecal(z)) = 0 for the modified conformal Hamiltonian (4.3)-(4.4)
     Ecal = H + h^2 E2 + ..., and the modified conformal factor (4.7), (4.9)
     N_mod = -dK_mod/dE at E = Ecal = N + h^2 N2 + ....
N(y) = (1+y^2)^(-1/2) is factored out of every object and all other y-dependence goes through
w = 1/(1+y^2), reduced modulo w(1+y^2) = 1, so every object is an exact polynomial with
rational coefficients (sparse rings of sympy.polys.rings).

Usage: python3 scripts/derive_nonholonomic.py [--output PATH] [--max-order 6|4]
Writes src/geomint/systems/nonholonomic_modified.hpp (relative to the repository root) unless
--output is given. Timings and check results go to stderr. Exit status 1 if a check fails.
"""

import argparse
import functools
import math
import os
import sys
import time

import sympy
from sympy.polys.domains import QQ
from sympy.polys.rings import ring

# ---------------------------------------------------------------------------
# Polynomial ring. (vx, vy) are the velocities q' (steps 1-2) and, in step 3, the scaled
# velocities u = v/N; E is the parameter of the altered Hamiltonian K_E; w = 1/(1+y^2).
# ---------------------------------------------------------------------------
RING, x, y, vx, vy, px, py, E, w = ring("x,y,vx,vy,px,py,E,w", QQ)
IY, IVX, IVY, IE, IW = 1, 2, 3, 6, 7
ZERO, ONE = RING.zero, RING.one
HALF = QQ(1, 2)


class CheckFailed(Exception):
    pass


def check(cond, what):
    if not cond:
        raise CheckFailed(what)


@functools.lru_cache(maxsize=None)
def _canon_yw(a, b):
    """Canonical form of y^a w^b modulo w(1+y^2) = 1, as a tuple of ((a', b'), coeff).

    Canonical monomials are y^a (no w) and y^e w^b with e in {0, 1}: the partial-fraction
    basis of Q[y, 1/(1+y^2)], so a polynomial is zero iff its canonical form is."""
    if a < 2 or b == 0:
        return (((a, b), QQ(1)),)
    out = {}
    # y^a w^b = y^(a-2) w^(b-1) (y^2 w) = y^(a-2) w^(b-1) (1 - w)
    for sign, (aa, bb) in ((1, (a - 2, b - 1)), (-1, (a - 2, b))):
        for key, c in _canon_yw(aa, bb):
            out[key] = out.get(key, 0) + sign * c
    return tuple(sorted((k, c) for k, c in out.items() if c))


def red(p):
    """Reduce a ring element modulo w(1+y^2) = 1 (canonical form)."""
    if all(m[IY] < 2 or m[IW] == 0 for m in p.keys()):
        return p
    out = {}
    for m, c in p.items():
        a, b = m[IY], m[IW]
        if a < 2 or b == 0:
            out[m] = out.get(m, 0) + c
            continue
        for (aa, bb), cc in _canon_yw(a, b):
            mm = m[:IY] + (aa,) + m[IY + 1:IW] + (bb,) + m[IW + 1:]
            out[mm] = out.get(mm, 0) + c * cc
    return RING.from_dict({m: c for m, c in out.items() if c})


def d_y(p):
    """Total y-derivative of a polynomial in (y, w): P_y + P_w dw/dy, dw/dy = -2 y w^2."""
    return red(p.diff(y) - 2 * y * w**2 * p.diff(w))


# ---------------------------------------------------------------------------
# Truncated power series in h: lists of ring elements, index = power of h.
# ---------------------------------------------------------------------------
def s_const(p, T):
    return [p] + [ZERO] * T


def s_add(a, b, T):
    return [(a[n] if n < len(a) else ZERO) + (b[n] if n < len(b) else ZERO) for n in range(T + 1)]


def s_sub(a, b, T):
    return [(a[n] if n < len(a) else ZERO) - (b[n] if n < len(b) else ZERO) for n in range(T + 1)]


def s_scale(c, a, T):
    """c * a for a scalar or ring element c."""
    return [red(c * a[n]) if n < len(a) else ZERO for n in range(T + 1)]


def s_mul(a, b, T):
    out = [ZERO] * (T + 1)
    for i in range(min(len(a), T + 1)):
        if not a[i]:
            continue
        for j in range(min(len(b), T + 1 - i)):
            if b[j]:
                out[i + j] += a[i] * b[j]
    return [red(c) for c in out]


def s_div_h(a, T):
    """a / h for a series with vanishing h^0 coefficient, through h^T."""
    check(not a[0], "division by h of a series with nonzero h^0 term")
    return [a[n + 1] if n + 1 < len(a) else ZERO for n in range(T + 1)]


def s_is_zero(a, upto):
    return all(not a[n] for n in range(min(len(a), upto + 1)))


def s_odd_zero(a):
    return all(not a[n] for n in range(1, len(a), 2))


def s_compose(P, subs, T):
    """Substitute series for generators of the ring element / series P, through h^T.

    P is a ring element or a series; subs maps a generator index to a series."""
    if not isinstance(P, list):
        P = [P]
    idx = sorted(subs)
    out = [ZERO] * (T + 1)
    powers = {i: [s_const(ONE, T)] for i in idx}

    def power(i, k):
        while len(powers[i]) <= k:
            powers[i].append(s_mul(powers[i][-1], subs[i], T))
        return powers[i][k]

    for n in range(min(len(P), T + 1)):
        if not P[n]:
            continue
        groups = {}
        for m, c in P[n].items():
            key = tuple(m[i] for i in idx)
            mm = list(m)
            for i in idx:
                mm[i] = 0
            g = groups.setdefault(key, {})
            g[tuple(mm)] = g.get(tuple(mm), 0) + c
        for key in sorted(groups):
            term = s_const(RING.from_dict(groups[key]), T - n)
            for i, k in zip(idx, key):
                if k:
                    term = s_mul(term, power(i, k), T - n)
            for j in range(T - n + 1):
                out[n + j] += term[j]
    return [red(c) for c in out]


# ---------------------------------------------------------------------------
# N(y) = (1+y^2)^(-1/2) and its Taylor expansion, N^(k)/N = r_k(y, w).
# ---------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def r_coef(k):
    """r_k = N^(k)(y)/N(y): r_0 = 1, r_1 = -y w, r_{k+1} = r_k' + r_k r_1."""
    if k == 0:
        return ONE
    if k == 1:
        return -y * w
    rk = r_coef(k - 1)
    return red(d_y(rk) + rk * r_coef(1))


def n_ratio(delta, T, order=0):
    """N^(order)(y + delta)/N(y) as a series, for a series delta with delta_0 = 0."""
    check(not delta[0], "N expanded about a shifted point")
    out = s_const(r_coef(order), T)
    dk = s_const(ONE, T)
    for k in range(1, T + 1):
        dk = s_mul(dk, delta, T)
        if s_is_zero(dk, T):
            break
        out = s_add(out, s_scale(r_coef(order + k) * QQ(1, math.factorial(k)), dk, T), T)
    return out


# ---------------------------------------------------------------------------
# The model (Section 3, Example 3.1): reduced Lagrangian (3.7), H, N.
# ---------------------------------------------------------------------------
POTENTIALS = {"harmonic": HALF * (x**2 + y**2), "free": ZERO}


def hamiltonian(U):
    """H = (px^2 + (1+y^2) py^2)/2 + U."""
    return HALF * (px**2 + (1 + y**2) * py**2) + U


# The five discrete Lagrangians (5.1), written as sums of terms c N(eta) (L(xi, v) + E), where
# v = (q1 - q0)/h and the nodes eta = a0 q0 + a1 q1 (of N) and xi = b0 q0 + b1 q1 (of L) are
# midpoint (1/2, 1/2) or endpoints (1, 0), (0, 1). First letter: quadrature of N; second: of L.
Q4 = QQ(1, 4)
MID, LEFT, RIGHT = (HALF, HALF), (QQ(1), QQ(0)), (QQ(0), QQ(1))
DISCRETE_LAGRANGIANS = {
    # Lambda_M = N(ybar) (L(qbar, v) + E)
    "M": [(QQ(1), MID, MID)],
    # Lambda_MT = N(ybar) (L(q0, v)/2 + L(q1, v)/2 + E)
    "MT": [(HALF, MID, LEFT), (HALF, MID, RIGHT)],
    # Lambda_TM = (N(y0) + N(y1))/2 (L(qbar, v) + E)
    "TM": [(HALF, LEFT, MID), (HALF, RIGHT, MID)],
    # Lambda_TT = (N(y0) + N(y1))/2 (L(q0, v)/2 + L(q1, v)/2 + E)
    "TT": [(Q4, LEFT, LEFT), (Q4, LEFT, RIGHT), (Q4, RIGHT, LEFT), (Q4, RIGHT, RIGHT)],
    # Lambda_T = N(y0) (L(q0, v) + E)/2 + N(y1) (L(q1, v) + E)/2
    "T": [(HALF, LEFT, LEFT), (HALF, RIGHT, RIGHT)],
}
METHODS = ["M", "MT", "TM", "TT", "T"]


def lagrangian_at(U, xi, v, T):
    """L, L_q, L_v of (3.7) at the point xi = (x*, y*) (series) with velocity v (series)."""
    Ux, Uy = U.diff(x), U.diff(y)
    sub = {0: xi[0], IY: xi[1]}
    vx2 = s_mul(v[0], v[0], T)
    m11 = s_add(s_const(ONE, T), s_mul(xi[1], xi[1], T), T)  # 1 + y*^2
    L = s_sub(s_scale(HALF, s_add(s_mul(m11, vx2, T), s_mul(v[1], v[1], T), T), T),
              s_compose(U, sub, T), T)
    Lq = (s_scale(-1, s_compose(Ux, sub, T), T),
          s_sub(s_mul(xi[1], vx2, T), s_compose(Uy, sub, T), T))
    Lv = (s_mul(m11, v[0], T), v[1][:T + 1])
    return L, Lq, Lv


# ---------------------------------------------------------------------------
# Jets along q'' = F and the total derivative D = q'.d_q + F.d_q'.
# Quantities "with N factored out" represent N(y) * P; for them D(N P) = N (D P + r_1 y' P).
# ---------------------------------------------------------------------------
def total_derivative(S, F, T, with_N=False):
    """D S through h^T for a series S in (x, y, vx, vy, E, w); F = (Fx, Fy) series."""
    out = [ZERO] * (T + 1)
    for n in range(min(len(S), T + 1)):
        P = S[n]
        if not P:
            continue
        base = vx * P.diff(x) + vy * d_y(P)
        if with_N:
            base += r_coef(1) * vy * P
        out[n] += base
        Pvx, Pvy = P.diff(vx), P.diff(vy)
        for j in range(0, T - n + 1):
            fx = F[0][j] if j < len(F[0]) else ZERO
            fy = F[1][j] if j < len(F[1]) else ZERO
            if fx and Pvx:
                out[n + j] += fx * Pvx
            if fy and Pvy:
                out[n + j] += fy * Pvy
    return [red(c) for c in out]


def jets(F, T):
    """J[k] = (x^(k), y^(k)) for k = 0..T; J[k] is needed (and truncated) through h^(T-k)."""
    J = [(s_const(x, T), s_const(y, T)), (s_const(vx, T - 1), s_const(vy, T - 1))]
    if T >= 2:
        J.append((F[0][:T - 1] + [ZERO] * max(0, T - 1 - len(F[0])),
                  F[1][:T - 1] + [ZERO] * max(0, T - 1 - len(F[1]))))
    for k in range(3, T + 1):
        J.append(tuple(total_derivative(c, F, T - k) for c in J[k - 1]))
    return J


def shifted_point(J, c, T):
    """q(t + c h) = sum_k c^k h^k / k! q^(k)(t) through h^T."""
    out = []
    for comp in (0, 1):
        s = [ZERO] * (T + 1)
        for k in range(min(len(J), T + 1)):
            fac = QQ(c) ** k / math.factorial(k)
            jk = J[k][comp]
            for n in range(0, T - k + 1):
                if n < len(jk) and jk[n]:
                    s[n + k] += fac * jk[n]
        out.append([red(t) for t in s])
    return tuple(out)


def combine(a, p0, p1, T):
    """a0 p0 + a1 p1 for points p0, p1 (pairs of series) and weights a = (a0, a1)."""
    return tuple(s_add(s_scale(a[0], p0[i], T), s_scale(a[1], p1[i], T), T) for i in (0, 1))


# ---------------------------------------------------------------------------
# Step 1: modified equation from the discrete Euler-Lagrange equations.
# ---------------------------------------------------------------------------
def del_residual(method, U, F, T):
    """R = d_{q1} Lambda_d(q(t-h), q(t)) + d_{q0} Lambda_d(q(t), q(t+h)), divided by N(y),
    through h^T. Here d_{q1} Lambda_d = (partial_{q1} at fixed v) + (1/h) partial_v."""
    Tp = T + 2
    J = jets(F, Tp)
    Qm, Q0, Qp = shifted_point(J, -1, Tp), shifted_point(J, 0, Tp), shifted_point(J, 1, Tp)
    vA = tuple(s_div_h(s_sub(Q0[i], Qm[i], Tp), T + 1) for i in (0, 1))
    vB = tuple(s_div_h(s_sub(Qp[i], Q0[i], Tp), T + 1) for i in (0, 1))
    Rq = [[ZERO] * (T + 1), [ZERO] * (T + 1)]   # partial_q parts, through h^T
    Rv = [[ZERO] * (T + 2), [ZERO] * (T + 2)]   # partial_v parts, through h^(T+1)
    for c, a, b in DISCRETE_LAGRANGIANS[method]:
        # pair A = (q(t-h), q(t)) enters through d_{q1}; pair B = (q(t), q(t+h)) through d_{q0}
        for q0, q1, v, i, sign in ((Qm, Q0, vA, 1, 1), (Q0, Qp, vB, 0, -1)):
            Tv = T + 1
            eta_y = s_add(s_scale(a[0], q0[1], Tv), s_scale(a[1], q1[1], Tv), Tv)
            delta = s_sub(eta_y, s_const(y, Tv), Tv)
            n0 = n_ratio(delta, Tv, 0)        # N(eta)/N(y)
            n1 = n_ratio(delta, T, 1)         # N'(eta)/N(y)
            xi = combine(b, q0, q1, Tv)
            L, Lq, Lv = lagrangian_at(U, xi, v, Tv)
            LE = s_add(L, s_const(E, Tv), Tv)
            # c [ a_i N'(eta) (L + E) e_y + b_i N(eta) L_q(xi, v) ]
            for comp in (0, 1):
                part = s_scale(c * b[i], s_mul(n0, Lq[comp], T), T)
                if comp == 1:
                    part = s_add(part, s_scale(c * a[i], s_mul(n1, LE, T), T), T)
                Rq[comp] = s_add(Rq[comp], part, T)
                # +-(c/h) N(eta) L_v(xi, v)
                Rv[comp] = s_add(Rv[comp], s_scale(sign * c, s_mul(n0, Lv[comp], Tv), Tv), Tv)
    return tuple(s_add(Rq[i], s_div_h(Rv[i], T), T) for i in (0, 1))


def modified_equation(method, U, M, log):
    """F = F0 + h^2 F2 + ... with R[q] = O(h^(M+1)) on q'' = F. R = A q'' + b + O(h^2) with
    A = -diag(1+y^2, 1), so the h^n coefficient r_n (computed with F_n = 0) gives
    F_n = -A^(-1) r_n = diag(w, 1) r_n."""
    F = [[ZERO] * (M + 1), [ZERO] * (M + 1)]
    for n in range(0, M + 1, 2):
        t0 = time.time()
        R = del_residual(method, U, F, n)
        for comp in (0, 1):
            check(s_is_zero(R[comp], n - 1),
                  f"{method}: DEL residual does not vanish below h^{n} (component {comp})")
        F[0][n] = red(w * R[0][n])
        F[1][n] = R[1][n]
        log(f"    F{n}: {len(F[0][n])}+{len(F[1][n])} terms  ({time.time() - t0:.1f} s)")
    return F


# ---------------------------------------------------------------------------
# Step 2: modified Lagrangian by action matching, and the EL consistency check.
# ---------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def inverse_midpoint_coefficients(M):
    """a_k with (hD/2)/sinh(hD/2) = sum_k a_k (hD)^(2k): the inverse of the midpoint-rule
    expansion (1/h) int_{t-h/2}^{t+h/2} f = sinh(hD/2)/(hD/2) f = f + h^2/24 f'' + ...."""
    t = sympy.Symbol("t")
    ser = sympy.series((t / 2) / sympy.sinh(t / 2), t, 0, M + 1).removeO()
    return tuple(QQ(int(sympy.fraction(c)[0]), int(sympy.fraction(c)[1]))
                 for c in (sympy.Rational(ser.coeff(t, 2 * k)) for k in range(M // 2 + 1)))


def modified_lagrangian(method, U, F, M):
    """L_mod / N(y) through h^M, from G(t) = Lambda_d(q(t-h/2), q(t+h/2)) / N(y)."""
    Tp = M + 1
    J = jets(F, Tp)
    Qm, Qp = shifted_point(J, -HALF, Tp), shifted_point(J, HALF, Tp)
    v = tuple(s_div_h(s_sub(Qp[i], Qm[i], Tp), M) for i in (0, 1))
    G = [ZERO] * (M + 1)
    for c, a, b in DISCRETE_LAGRANGIANS[method]:
        eta_y = s_add(s_scale(a[0], Qm[1], M), s_scale(a[1], Qp[1], M), M)
        n0 = n_ratio(s_sub(eta_y, s_const(y, M), M), M, 0)
        L, _, _ = lagrangian_at(U, combine(b, Qm, Qp, M), v, M)
        G = s_add(G, s_scale(c, s_mul(n0, s_add(L, s_const(E, M), M), M), M), M)
    check(s_odd_zero(G), f"{method}: odd powers of h in G")
    a = inverse_midpoint_coefficients(M)
    Lmod = list(G)
    DkG = G
    for k in range(1, M + 1):
        DkG = total_derivative(DkG, F, M - k, with_N=True)
        if k % 2 == 0:
            Lmod = s_add(Lmod, [ZERO] * k + s_scale(a[k // 2], DkG, M - k), M)
    return Lmod, a


def el_residual(Lmod, F, M):
    """EL(L_mod)/N = [D (d_v L_mod) - d_q L_mod]/N on q'' = F, through h^M."""
    out = []
    for var in (0, 1):
        dv = [P.diff(vx if var == 0 else vy) for P in Lmod]
        if var == 0:
            dq = [P.diff(x) for P in Lmod]
        else:
            dq = [red(d_y(P) + r_coef(1) * P) for P in Lmod]   # d_y (N P) = N (P_y + r_1 P)
        out.append(s_sub(total_derivative(dv, F, M, with_N=True), dq, M))
    return out


# ---------------------------------------------------------------------------
# Step 3: Legendre transform -> kappa_n with K_mod = N [ (H - E) + sum_n h^n kappa_n ] (4.2).
# ---------------------------------------------------------------------------
def legendre(Lmod, U, M):
    """With v = N u: L_mod = N Pt(q, u) and p = d_u Pt, K_mod = N (p.u - Pt)."""
    Pt = []
    for P in Lmod:
        d = {}
        for m, c in P.items():
            deg = m[IVX] + m[IVY]
            check(deg % 2 == 0, "L_mod is not even in the velocities")
            mm = m[:IW] + (m[IW] + deg // 2,)          # v^deg = N^deg u^deg = w^(deg/2) u^deg
            d[mm] = d.get(mm, 0) + c
        Pt.append(red(RING.from_dict(d)))
    check(Pt[0] == red(HALF * vx**2 + HALF * w * vy**2 + E - U), "unexpected L_mod at h^0")
    Ph = [ZERO] + Pt[1:]
    dPx = [P.diff(vx) for P in Ph]
    dPy = [P.diff(vy) for P in Ph]
    # p = (ux, w uy) + d_u Ph  =>  u = (px - d_ux Ph, (1+y^2)(py - d_uy Ph)), by fixed point.
    # K is stationary in u, so an error O(h^(2m+2)) in u after m iterations changes K only at
    # O(h^(4m+4)); m iterations with 4m+4 > M suffice.
    u = (s_const(px, M), s_const(red((1 + y**2) * py), M))
    iterations = 1
    while 4 * iterations + 4 <= M:
        iterations += 1
    for _ in range(iterations):
        sub = {IVX: u[0], IVY: u[1]}
        u = (s_sub(s_const(px, M), s_compose(dPx, sub, M), M),
             s_scale(1 + y**2, s_sub(s_const(py, M), s_compose(dPy, sub, M), M), M))
    sub = {IVX: u[0], IVY: u[1]}
    kappa = s_sub(s_add(s_scale(px, u[0], M), s_scale(py, u[1], M), M), s_compose(Pt, sub, M), M)
    check(kappa[0] == red(hamiltonian(U) - E), "kappa_0 != H - E")
    check(s_odd_zero(kappa), "odd powers of h in K_mod")
    return kappa


# ---------------------------------------------------------------------------
# Step 4: series inversion (4.3)-(4.4) and the modified conformal factor (4.7), (4.9).
# ---------------------------------------------------------------------------
def invert(kappa, U, M):
    """Ecal = H + sum h^n Ecal_n with kappa(z; Ecal) = 0 (kappa_0 = H - E), and
    N_mod/N = -d_E (K_mod/N) at E = Ecal = 1 - sum_{n>=2} h^n (d_E kappa_n)(Ecal)."""
    H = red(hamiltonian(U))
    rest = [ZERO] + kappa[1:]
    Ecal = s_const(H, M)
    for _ in range(M // 2):
        Ecal = s_add(s_const(H, M), s_compose(rest, {IE: Ecal}, M), M)
    check(s_is_zero(s_compose(kappa, {IE: Ecal}, M), M), "K_mod(z; Ecal) != 0")
    dE = s_compose([P.diff(E) for P in rest], {IE: Ecal}, M)
    Nrel = s_sub(s_const(ONE, M), dE, M)
    check(s_odd_zero(Ecal) and s_odd_zero(Nrel), "odd powers of h in Ecal or N_mod")
    return Ecal, Nrel


# ---------------------------------------------------------------------------
# Unit check: the midpoint rule for the harmonic oscillator (M, harmonic, y = 0).
# ---------------------------------------------------------------------------
def check_midpoint_oscillator(F, M, log):
    """On y = y' = 0 (invariant), Lambda_M is the midpoint rule for x'' = -x, whose modified
    equation is x'' = -omega^2 x with omega = (2/h) arctan(h/2)."""
    hs = sympy.Symbol("h")
    omega2 = sympy.series((2 / hs * sympy.atan(hs / 2)) ** 2, hs, 0, M + 1).removeO()
    expected = [QQ(int(sympy.fraction(c)[0]), int(sympy.fraction(c)[1]))
                for c in (sympy.Rational(omega2.coeff(hs, n)) for n in range(M + 1))]

    def on_y0(P):
        """P restricted to y = y' = 0 (and hence w = 1)."""
        d = {}
        for m, c in P.items():
            if m[IY] == 0 and m[IVY] == 0:
                mm = m[:IW] + (0,)
                d[mm] = d.get(mm, 0) + c
        return RING.from_dict({m: c for m, c in d.items() if c})

    got = []
    for n in range(M + 1):
        fx, fy = on_y0(F[0][n]), on_y0(F[1][n])
        check(not fy, f"midpoint oscillator: F_y != 0 on y = 0 at h^{n}")
        c = -fx.coeff(x)
        check(fx == -c * x, f"midpoint oscillator: F_x is not -c x at h^{n}")
        got.append(c)
    check(got == expected, f"midpoint oscillator: omega^2 coefficients {got}, expected {expected}")
    log("  check: midpoint oscillator on y = 0: F = -omega^2 x, omega^2 = " +
        " ".join(f"{'+' if c > 0 else '-'} {abs(c)} h^{n}" for n, c in enumerate(got) if c) +
        " = ((2/h) arctan(h/2))^2: ok")


# ---------------------------------------------------------------------------
# C++ emission.
# ---------------------------------------------------------------------------
# Output form of a coefficient: [N *] w^k * Num / d with w = 1/(1+y^2), d a positive integer and
# Num an integer polynomial in (y, E, x, px, py), written in Horner form in y with the inner
# polynomials expanded (as in the paper's appendix).
CXX_VARS = ["y", "E", "x", "px", "py"]
CXX_INDEX = {"y": IY, "E": IE, "x": 0, "px": 4, "py": 5}


def as_rational_in_y(P):
    """Write a canonical (y, w) polynomial as Num w^k / d with Num an integer polynomial not
    divisible by (1 + y^2). Returns ({exponents over CXX_VARS: int}, k, d)."""
    k = max((m[IW] for m in P.keys()), default=0)
    num = ZERO
    for m, c in P.items():
        num += RING.from_dict({m[:IW] + (0,): c}) * (1 + y**2) ** (k - m[IW])
    while k > 0:
        q, r = num.div([1 + y**2])
        if r:
            break
        num, k = q[0], k - 1
    d = 1
    for c in num.values():
        d = d * int(c.denominator) // math.gcd(d, int(c.denominator))
    check(d < 2**53, "denominator not exact in double precision")
    terms = {}
    for m, c in num.items():
        check(m[IVX] == m[IVY] == m[IW] == 0, "unexpected variable in an output coefficient")
        ci = c * d
        check(ci.denominator == 1 and abs(int(ci.numerator)) < 2**53,
              "coefficient not exact in double precision")
        terms[tuple(m[CXX_INDEX[v]] for v in CXX_VARS)] = int(ci.numerator)
    return terms, k, d


def _pow(v, k):
    return "*".join([v] * k)


def _sum(terms):
    """Expanded sum of integer-coefficient monomials in (E, x, px, py), in a fixed order:
    by total degree, then by exponents."""
    keys = sorted(terms, key=lambda m: (sum(m[1:]), tuple(-e for e in m[1:])))
    out = ""
    for m in keys:
        c = terms[m]
        factors = [_pow(v, e) for v, e in zip(CXX_VARS[1:], m[1:]) if e]
        mag = f"{abs(c)}.0"
        body = "*".join(([mag] if abs(c) != 1 or not factors else []) + factors)
        if not out:
            out = ("-" if c < 0 else "") + body
        else:
            out += (" - " if c < 0 else " + ") + body
    return out


def horner_y(terms):
    """Horner form in y: c0 + y*(c1 + y*(...)), with the c_k expanded by _sum."""
    groups = {}
    for m, c in terms.items():
        groups.setdefault(m[0], {})[m] = c
    def times(k, expr):   # y^k * expr, without parentheses around a single positive monomial
        if " " in expr or expr.startswith("-"):
            expr = f"({expr})"
        return f"{_pow('y', k)}*{expr}"

    ks = sorted(groups)
    acc = _sum(groups[ks[-1]])
    for i in range(len(ks) - 2, -1, -1):
        acc = f"{_sum(groups[ks[i]])} + {times(ks[i + 1] - ks[i], acc)}"
    if ks[0] > 0:
        acc = times(ks[0], acc)
    return acc


def wrap(first, expr, last, indent, width=100):
    """Greedy line breaking of first + expr + last before binary ' + ' / ' - '."""
    tokens = expr.replace(" + ", "\x00+ ").replace(" - ", "\x00- ").split("\x00")
    tokens[0] = first + tokens[0]
    tokens[-1] = tokens[-1] + last
    lines, cur = [], ""
    for t in tokens:
        if cur and len(cur) + 1 + len(t) > width:
            lines.append(cur)
            cur = indent + t
        else:
            cur = f"{cur} {t}" if cur else t
    lines.append(cur)
    return lines


def cxx_function(name, P, with_N, with_E, comment):
    """One inline C++ function for the coefficient P (times N if with_N)."""
    terms, k, d = as_rational_in_y(P)
    used = {v for m in terms for v, e in zip(CXX_VARS, m) if e}
    if k or with_N:
        used.add("y")
    params = ["x", "y", "px", "py"] + (["E"] if with_E else [])
    sig = ", ".join(f"double {v}" if v in used else f"double /*{v}*/" for v in params)
    lines = [f"// {comment}", f"inline double {name}({sig}) noexcept {{"]
    if not terms:
        return lines + ["  return 0.0;", "}"]
    if k or with_N:
        lines.append("  const double w = 1.0 / (1.0 + y * y);")
    if with_N:
        lines.append("  const double N = std::sqrt(w);")
    # factor out the common monomial in (E, x, px, py)
    common = [min(m[i] for m in terms) for i in range(len(CXX_VARS))]
    common[0] = 0
    terms = {tuple(e - c for e, c in zip(m, common)): v for m, v in terms.items()}
    prefix = "*".join((["N"] if with_N else []) + (["w"] * k) +
                      [_pow(v, e) for v, e in zip(CXX_VARS, common) if e])
    first = "  return " + (prefix + "*(" if prefix else "(")
    last = ")" + (f" / {d}.0" if d != 1 else "") + ";"
    lines += wrap(first, horner_y(terms), last, "      ")
    return lines + ["}"]


def emit_header(results, M):
    lines = [
        "#pragma once",
        "// Generated by scripts/derive_nonholonomic.py; do not edit. Modified quantities (Ecal, N_mod,",
        "// K_mod) of the five variational integrators (5.1) for the nonholonomic particle, as power",
        "// series in the step h, for the potentials U = (x^2+y^2)/2 (harmonic) and U = 0 (free).",
        "//",
        "// z = (x, y, px, py), N = (1+y^2)^(-1/2), w = 1/(1+y^2), H = (px^2 + (1+y^2) py^2)/2 + U:",
        "//   Ecal  = H + h^2 E2 + h^4 E4 + h^6 E6 + ...   modified conformal Hamiltonian (4.3)-(4.4)",
        "//   N_mod = N + h^2 N2 + h^4 N4 + h^6 N6 + ...   modified conformal factor (4.7), (4.9)",
        "//   K_mod = N (H - E) + h^2 K2 + h^4 K4 + ...    modified altered Hamiltonian (4.2), normalized",
        "//           by action matching (h Lambda_d is its exact type-I generating function)",
        "// Only even powers of h occur (the methods are symmetric).",
        "#include <cmath>",
        "",
        "namespace geomint::nonholonomic::generated {",
        "",
        f"inline constexpr int max_order = {M};  // highest power of h derived",
        "",
    ]
    for method in METHODS:
        for pot in POTENTIALS:
            Ecal, Nrel, kappa = results[(method, pot)]
            tag = f"{method}_{pot}"
            lines.append(f"// ---- {method}, {pot} " + "-" * (80 - 12 - len(method) - len(pot)))
            for n in range(2, M + 1, 2):
                lines += cxx_function(f"E{n}_{tag}", Ecal[n], False, False,
                                      f"coefficient of h^{n} in Ecal")
                lines += cxx_function(f"N{n}_{tag}", Nrel[n], True, False,
                                      f"coefficient of h^{n} in N_mod")
                if n <= 4:
                    lines += cxx_function(f"K{n}_{tag}", kappa[n], True, True,
                                          f"coefficient of h^{n} in K_mod (includes the factor N)")
                lines.append("")
    lines += [
        "struct ModifiedSeries {",
        "  // h^2, h^4, h^6 coefficients of Ecal (nullptr beyond max_order)",
        "  double (*E[3])(double, double, double, double) noexcept;",
        "  // h^2, h^4, h^6 coefficients of N_mod (nullptr beyond max_order)",
        "  double (*N[3])(double, double, double, double) noexcept;",
        "  // h^2, h^4 coefficients of K_mod (arguments x, y, px, py, E)",
        "  double (*K[2])(double, double, double, double, double) noexcept;",
        "};",
        "",
        "// [discretization][potential]; discretizations M, MT, TM, TT, T; potentials harmonic, free",
        "inline constexpr ModifiedSeries series[5][2] = {",
    ]
    for method in METHODS:
        entries = []
        for pot in POTENTIALS:
            tag = f"{method}_{pot}"

            def ptrs(q, orders):
                return "{" + ", ".join(f"&{q}{n}_{tag}" if n <= M else "nullptr"
                                       for n in orders) + "}"
            entries.append([ptrs("E", (2, 4, 6)) + ",", ptrs("N", (2, 4, 6)) + ",",
                            ptrs("K", (2, 4)) + "}"])
        lines += [f"  // {method}",
                  "  {{" + entries[0][0], "    " + entries[0][1], "    " + entries[0][2] + ",",
                  "   {" + entries[1][0], "    " + entries[1][1], "    " + entries[1][2] + "},"]
    lines += ["};", "", "}  // namespace geomint::nonholonomic::generated", ""]
    return "\n".join(lines)


# ---------------------------------------------------------------------------
def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--output", default=os.path.join(
        root, "src", "geomint", "systems", "nonholonomic_modified.hpp"))
    ap.add_argument("--max-order", type=int, default=6, choices=(4, 6),
                    help="highest power of h to derive (default 6)")
    args = ap.parse_args()
    M = args.max_order

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    t_start = time.time()
    results = {}
    try:
        for method in METHODS:
            for pot, U in POTENTIALS.items():
                t0 = time.time()
                log(f"{method} {pot}:")
                F = modified_equation(method, U, M, log)                       # step 1
                if method == "M" and pot == "harmonic":
                    check_midpoint_oscillator(F, M, log)
                t1 = time.time()
                Lmod, a = modified_lagrangian(method, U, F, M)                # step 2
                check(s_odd_zero(Lmod), f"{method} {pot}: odd powers of h in L_mod")
                t2 = time.time()
                el = el_residual(Lmod, F, M)
                check(all(s_is_zero(c, M) for c in el),
                      f"{method} {pot}: EL(L_mod) != 0 on q'' = F through h^{M}")
                t3 = time.time()
                log(f"  L_mod: {sum(len(P) for P in Lmod)} terms ({t2 - t1:.1f} s); "
                    f"check EL(L_mod) = 0 on q'' = F through h^{M}: ok ({t3 - t2:.1f} s)")
                kappa = legendre(Lmod, U, M)                                   # step 3
                Ecal, Nrel = invert(kappa, U, M)                               # step 4
                t4 = time.time()
                log(f"  K_mod, Ecal, N_mod: terms per order " +
                    ", ".join(f"h^{n}: {len(kappa[n])}/{len(Ecal[n])}/{len(Nrel[n])}"
                              for n in range(2, M + 1, 2)) +
                    f" ({t4 - t3:.1f} s); case total {t4 - t0:.1f} s")
                results[(method, pot)] = (Ecal, Nrel, kappa)
        log("  inverse midpoint coefficients: " + ", ".join(str(c) for c in a))
        log("check: only even powers of h (DEL residual, G, L_mod, K_mod, Ecal, N_mod): ok")
    except CheckFailed as e:
        log(f"CHECK FAILED: {e}")
        return 1
    header = emit_header(results, M)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w", encoding="utf-8") as f:
        f.write(header)
    log(f"wrote {args.output} ({header.count(chr(10))} lines); total {time.time() - t_start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())

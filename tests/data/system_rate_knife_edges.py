#!/usr/bin/python3
"""Exact solution sets of a 2-point rate problem at its critical directions +- a few ulps.

Independent oracle for tests/rate_problem/test_system_rate_knife_edges.cpp (issue 24): every
type tuple of the two grazing (state b) points is solved in exact rational arithmetic
(fractions) from the model's equations (docs/contact_model.md):
  equilibrium   dF - dP = A dw  (per point (T, N), points in order)
  kinematics    dw_T = C_T dP_T + dw_Ti
  separation    dP = 0,                       dw_N <= 0
  stick         dw_N = 0, dw_Ti = 0,          dP_N >= 0, |dP_T| <= mu dP_N
  slip s        dw_N = 0, dP_T = s mu dP_N,   dP_N >= 0, s dw_Ti >= 0
and the distinct admissible points are the exact set of the DOUBLE load (its exact rational
value). The loads: dF = (cos t, sin t, 0.3, -0.2) at every critical angle t (a zero of an
inequality of some tuple's solution, found with mpmath at 50 digits, where the set changes),
its dF_T1 moved by -3..3 ulps (the test accepts the exact set or complete: false), and the
loads 1e-6 rad on either side (the test requires the exact set, complete). Prints the C++ table
of the test.
Run: /usr/bin/python3 tests/data/system_rate_knife_edges.py
"""
from fractions import Fraction as Fr
import itertools, math
import mpmath

mpmath.mp.dps = 50
A = [[1, 2, 0.25, 0.1], [2, 5, 0.1, 0.5], [0.25, 0.1, 1, 0.3], [0.1, 0.5, 0.3, 2]]
MU = [1.0, 0.5]
CT = [0.0, 0.25]
F2 = (0.3, -0.2)
TYPES = ["separation", "stick", "slip+", "slip-"]


def solve(M, b):
    """Gaussian elimination in exact arithmetic; None when singular."""
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(M)]
    for c in range(n):
        p = next((r for r in range(c, n) if M[r][c] != 0), None)
        if p is None:
            return None
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c] / M[c][c]
                M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    return [M[i][n] / M[i][i] for i in range(n)]


def system(types, num):
    """Unknowns x = (dP_T1, dP_N1, dP_T2, dP_N2, dw_T1, dw_N1, dw_T2, dw_N2); `num` maps a
    float to the number type (Fr or mpf). Returns the matrix rows and the load part."""
    rows = []
    for r in range(4):  # dP_r + sum A_rc dw_c = dF_r
        rows.append([num(1) if c == r else num(0) for c in range(4)] + [num(A[r][c]) for c in range(4)])
    for i, t in enumerate(types):
        T, Nn, wT, wN = 2 * i, 2 * i + 1, 4 + 2 * i, 4 + 2 * i + 1
        e = lambda k: [num(1) if j == k else num(0) for j in range(8)]
        if t == "separation":
            rows += [e(T), e(Nn)]
        else:
            rows.append(e(wN))
            if t == "stick":  # dw_Ti = dw_T - C_T dP_T = 0
                r = e(wT); r[T] = num(-CT[i]); rows.append(r)
            else:
                s = 1 if t == "slip+" else -1
                r = e(T); r[Nn] = num(-s * MU[i]); rows.append(r)
    return rows


def ineqs(types, x, num):
    """The inequalities g >= 0 of the tuple at the solution x."""
    g = []
    for i, t in enumerate(types):
        T, Nn, wT, wN = 2 * i, 2 * i + 1, 4 + 2 * i, 4 + 2 * i + 1
        dwTi = x[wT] - num(CT[i]) * x[T]
        if t == "separation":
            g.append(-x[wN])
        elif t == "stick":
            g += [x[Nn], num(MU[i]) * x[Nn] - x[T], num(MU[i]) * x[Nn] + x[T]]
        else:
            s = 1 if t == "slip+" else -1
            g += [x[Nn], s * dwTi]
    return g


def exact_set(dF):
    dF = [Fr(v) for v in dF]
    pts = {}
    for types in itertools.product(TYPES, repeat=2):
        x = solve(system(types, Fr), dF + [Fr(0)] * 4)
        assert x is not None, types  # no continuum in this system
        if all(v >= 0 for v in ineqs(types, x, Fr)):
            pts.setdefault(tuple(x), []).append(types)
    return pts


def load(t):
    return [float(mpmath.cos(t)), float(mpmath.sin(t)), F2[0], F2[1]]


# critical angles: zeros of a cos t + b sin t + c for every inequality of every tuple (linear in
# the load: evaluate at three loads in mpmath to get a, b, c)
crit = []
for types in itertools.product(TYPES, repeat=2):
    def g_at(f):
        x = mpmath.lu_solve(mpmath.matrix(system(types, mpmath.mpf)), mpmath.matrix(list(f) + [0] * 4))
        return ineqs(types, list(x), mpmath.mpf)
    g0 = g_at([0, 0, F2[0], F2[1]])
    g1 = g_at([1, 0, F2[0], F2[1]])
    g2 = g_at([0, 1, F2[0], F2[1]])
    for c, a1, b1 in zip(g0, g1, g2):
        a, b = a1 - c, b1 - c
        r = mpmath.sqrt(a * a + b * b)
        if r == 0 or abs(c) > r:
            continue
        phi = mpmath.atan2(b, a)
        d = mpmath.acos(-c / r)
        for t in (phi + d, phi - d):
            crit.append(t % (2 * mpmath.pi))
crit = sorted(set(float(t) for t in crit))
rows = []
for t in crit:
    # only where the set changes across t (a critical direction of the problem, not of one tuple)
    before = exact_set(load(mpmath.mpf(t) - mpmath.mpf("1e-6")))
    after = exact_set(load(mpmath.mpf(t) + mpmath.mpf("1e-6")))
    key = lambda s: sorted(tuple(v) for v in s.values())
    if key(before) == key(after):
        continue
    for side, ex in ((-1, before), (1, after)):  # 1e-6 rad away: must be decided and complete
        g = load(mpmath.mpf(t) + side * mpmath.mpf("1e-6"))
        rows.append((g[0], g[1], len(ex), any(len(v) > 1 for v in ex.values()),
                     sorted("/".join(v[0]) for v in ex.values()), True))
    f = load(mpmath.mpf(t))
    for k in range(-3, 4):
        g = list(f)
        for _ in range(abs(k)):
            g[0] = math.nextafter(g[0], math.inf if k > 0 else -math.inf)
        s = exact_set(g)
        # a point of several tuples (exactly on a knife edge) is written with its first tuple
        # and flagged: only the count is compared
        amb = any(len(v) > 1 for v in s.values())
        tuples = sorted("/".join(v[0]) for v in s.values())
        rows.append((g[0], g[1], len(s), amb, tuples, False))
print("// generated by tests/data/system_rate_knife_edges.py: dF_T1, dF_N1, count, ambiguous,")
print("// must be complete (1e-6 rad from the critical direction), types")
b = lambda x: "true" if x else "false"
for r in rows:
    print('    {%s, %s, %d, %s, %s, "%s"},' % (r[0].hex(), r[1].hex(), r[2], b(r[3]), b(r[5]), " ".join(r[4])))

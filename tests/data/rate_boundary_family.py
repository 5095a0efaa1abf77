#!/usr/bin/env python3
"""The one-point rate problem at EXACT critical loads of binary data, solved in exact rationals.

Independent oracle for tests/rate_problem/test_rate_boundary_family.cpp (issue 34: the paper's
one-point rate problem on exact critical loads must be decided exactly, not "not complete").

Data (seeded): parameters are multiples of 2^-10 (A symmetric positive definite, mu > 0,
C_T >= 0; state d also P_N > 0, k_a >= 0, P_s > 0, sgn P_T, criterion 38), and the load lies
EXACTLY on a critical direction, computed exactly and representable in double:
  N = a11 dF_N - a12 dF_T = 0      dF = t (a11, a12)                      (state b)
  L_s = 0 (s = +1, -1 in b; s = sgn P_T in d)
          dF = t (mu (1 + a11 C_T), s + mu a12 C_T)
with t = +-k / 2^10 (both rays of the line). Every load is asserted exact in double.

The oracle does not use those closed forms: for each solution type it solves the model's rate
equations (docs/model.md, "Rate problem"; [Stromberg et al. 1996, Sec. 4.3]) in fractions and
keeps the types whose inequalities hold:
  equilibrium    dF - dP = A dw,  dw_T = C_T dP_T + dw_T^i
  b separation   dP = 0,                          dw_N < 0
  b stick        dw_N = 0, dw_T^i = 0,             dP_N >= 0, |dP_T| <= mu dP_N
  b slip s       dw_N = 0, dP_T = s mu dP_N,       dP_N >= 0, s dw_T^i > 0
  d stick        dw_N = 0, dw_T^i = 0,             s dP_T - mu dP_N <= 0
  d slip         dw_N = kappa lambda, dw_T^i = s lambda, s dP_T = mu dP_N, lambda > 0
(kappa = k_a P_N / (3 P_s)). The types partition the solution set; with D_s != 0 (b) and
Lambda != 0 (d), which the generator ensures with a margin, each type has one candidate. A sixth
of the state-d points lie instead on the parameter boundary Lambda = 0 exactly (a11 = s mu a12,
kappa = 0) with a dyadic load off L_s = 0 (there the slip equations are inconsistent: no slip).
Prints the C++ rows of the test (rate_boundary_rows.inc).
Run: python3 tests/data/rate_boundary_family.py > tests/rate_problem/rate_boundary_rows.inc
"""
from fractions import Fraction as Fr
import random

SEED = 34
N_B = 60  # parameter points in state b (x 3 lines x 2 rays)
N_D = 60  # parameter points in state d (x 1 line x 2 rays)


def dyadic(rng, lo, hi):
    """A multiple of 2^-10 in [lo, hi]."""
    return Fr(rng.randint(int(lo * 1024), int(hi * 1024)), 1024)


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


def solutions(P, state, dF):
    """Exact solutions {type: (dP_T, dP_N, dw_Ti)}. Unknowns (dP_T, dP_N, dw_T, dw_N, lam)."""
    a11, a12, a22, mu, CT = P["a11"], P["a12"], P["a22"], P["mu"], P["C_T"]
    eq = [[1, 0, a11, a12, 0], [0, 1, a12, a22, 0]]  # dP + A dw = dF
    rhs = [dF[0], dF[1]]
    out = {}
    cases = ["separation", "stick", "slip+", "slip-"] if state == "b" else ["stick", "slip"]
    for t in cases:
        rows, r = [list(e) for e in eq], list(rhs)

        def add(row, v=0):
            rows.append([Fr(x) for x in row]); r.append(Fr(v))
        if state == "b":
            add([0, 0, 0, 0, 1])  # lam unused in b: 0 (dw_T^i = dw_T - C_T dP_T)
            if t == "separation":
                add([1, 0, 0, 0, 0]); add([0, 1, 0, 0, 0])
            else:
                add([0, 0, 0, 1, 0])  # dw_N = 0
                if t == "stick":
                    add([-CT, 0, 1, 0, 0])  # dw_T^i = 0
                else:
                    s = 1 if t == "slip+" else -1
                    add([1, -s * mu, 0, 0, 0])  # dP_T = s mu dP_N
        else:
            s = P["sgn"]
            kappa = P["k_a"] * P["P_N"] / (3 * P["P_s"])
            if t == "stick":
                add([0, 0, 0, 0, 1]); add([0, 0, 0, 1, 0]); add([-CT, 0, 1, 0, 0])
            else:
                add([0, 0, 0, 1, -kappa])       # dw_N = kappa lam
                add([-CT, 0, 1, 0, -s])         # dw_T^i = s lam
                add([s, -mu, 0, 0, 0])          # s dP_T = mu dP_N
        x = solve(rows, r)
        if x is None and state == "d" and t == "slip":
            continue  # Lambda = 0 and the load off L_s = 0: the slip equations are inconsistent
        assert x is not None, (P, state, t)  # D_s, Lambda != 0: one candidate per type
        dPT, dPN, dwT, dwN, lam = x
        dwTi = dwT - CT * dPT
        if state == "b":
            ok = {"separation": dwN < 0,
                  "stick": dPN >= 0 and abs(dPT) <= mu * dPN,
                  "slip+": dPN >= 0 and dwTi > 0,
                  "slip-": dPN >= 0 and dwTi < 0}[t]
        else:
            ok = s * dPT - mu * dPN <= 0 if t == "stick" else lam > 0
            if t == "slip":
                t = "slip+" if s > 0 else "slip-"
        if ok:
            out[t] = (dPT, dPN, dwTi)
    return out


def exact_double(x):
    assert Fr(float(x)) == x, x  # the load is exactly representable
    return float(x)


def random_A(rng):
    while True:
        a11, a22 = dyadic(rng, 0.05, 6), dyadic(rng, 0.05, 6)
        a12 = dyadic(rng, -4, 4)
        if a11 * a22 - a12 * a12 > Fr(1, 100) * a11 * a22:
            return a11, a12, a22


rng = random.Random(SEED)
rows = []
while len(rows) < 6 * N_B:
    a11, a12, a22 = random_A(rng)
    P = {"a11": a11, "a12": a12, "a22": a22, "mu": dyadic(rng, 0.05, 3),
         "C_T": dyadic(rng, 0, 1) if rng.random() < 0.8 else Fr(0)}
    mu, CT = P["mu"], P["C_T"]
    # half of the points where the paper's set is not unique for every direction (a11 < mu|a12|)
    if (a11 < mu * abs(a12)) != (len(rows) % 12 < 6):
        continue
    # D_s = a11 - s mu a12 away from 0 (a singular block is a continuum: another family)
    if min(abs(a11 - mu * a12), abs(a11 + mu * a12)) < Fr(1, 100) * (a11 + abs(mu * a12)):
        continue
    c1 = 1 + a11 * CT
    lines = [("N=0", (a11, a12)), ("L+=0", (mu * c1, 1 + mu * a12 * CT)),
             ("L-=0", (mu * c1, -1 + mu * a12 * CT))]
    for name, d in lines:
        for sign in (1, -1):
            t = sign * Fr(rng.randint(512, 2048), 1024)
            dF = [exact_double(t * d[0]), exact_double(t * d[1])]
            rows.append(("b", P, 1, name, dF, solutions(P, "b", [Fr(v) for v in dF])))
nd = 0
while nd < N_D:
    lambda_zero = nd % 6 == 5  # the parameter boundary Lambda = 0: a11 = s mu a12, kappa = 0
    a11, a12, a22 = random_A(rng)
    P = {"a11": a11, "a12": a12, "a22": a22, "mu": dyadic(rng, 0.05, 1.5),
         "C_T": dyadic(rng, 0, 1) if rng.random() < 0.8 else Fr(0),
         "k_a": dyadic(rng, 0, 1) if rng.random() < 0.5 else Fr(0),
         "P_s": dyadic(rng, 0.1, 2), "P_N": dyadic(rng, 0.05, 2), "sgn": rng.choice((1, -1))}
    mu, CT, s = P["mu"], P["C_T"], P["sgn"]
    if lambda_zero:
        # a11 = s mu a12 (a multiple of 2^-20), A still positive definite
        P["k_a"], a11 = Fr(0), s * mu * a12
        if not (a11 > 0 and a11 * a22 - a12 * a12 > Fr(1, 100) * a11 * a22):
            continue
        P["a11"] = a11
    kappa = P["k_a"] * P["P_N"] / (3 * P["P_s"])
    det = a11 * a22 - a12 * a12
    Lam = a11 - mu * s * a12 + kappa * (s * a12 - mu * a22) - mu * kappa * CT * det
    terms = a11 + abs(mu * a12) + kappa * (abs(a12) + mu * a22) + mu * kappa * CT * det
    if lambda_zero != (Lam == 0) or (not lambda_zero and abs(Lam) < Fr(1, 100) * terms):
        continue
    nd += 1
    c1 = 1 + a11 * CT
    for sign in (1, -1):
        t = sign * Fr(rng.randint(512, 2048), 1024)
        if lambda_zero:  # a load off L_s = 0 (on it: a ray): dyadic, both signs of L_s
            d = (dyadic(rng, -2, 2), dyadic(rng, -2, 2))
            if (s + mu * a12 * CT) * d[0] - mu * c1 * d[1] == 0:
                continue
            dF, name = [exact_double(d[0]), exact_double(d[1])], "Lambda=0"
        else:
            dF, name = [exact_double(t * mu * c1), exact_double(t * (s + mu * a12 * CT))], "L=0"
        rows.append(("d", P, s, name, dF, solutions(P, "d", [Fr(v) for v in dF])))

print("// generated by tests/data/rate_boundary_family.py (seed %d): state, a11, a12, a22, mu, C_T,"
      % SEED)
print("// k_a, P_s, P_N, sgn P_T, dF_T, dF_N (exactly on the critical line), line, count, types")
print("// (sorted), then (dP_T, dP_N, dw_T^i) of each solution in that order, from exact rationals.")
order = ["separation", "slip+", "slip-", "stick"]  # Python's sorted() of the names
h = lambda x: float(x).hex()
for st, P, s, name, dF, sol in rows:
    types = [t for t in order if t in sol]
    sols = ", ".join("{%s, %s, %s}" % tuple(h(v) for v in sol[t]) for t in types)
    print('    {\'%s\', %s, %s, %s, %s, %s, %s, %s, %s, %d, %s, %s, "%s", %d, "%s", {%s}},' % (
        st, h(P["a11"]), h(P["a12"]), h(P["a22"]), h(P["mu"]), h(P["C_T"]),
        h(P.get("k_a", 0)), h(P.get("P_s", 1)), h(P.get("P_N", 0)), s, h(dF[0]), h(dF[1]),
        name, len(types), " ".join(types), sols))

#!/usr/bin/python3
"""Exact (rational) textbook lexicographic Lemke [Cottle-Pang-Stone 1992, Sec. 4.4 and 4.9;
Murty 1988, ch. 2], written independently of cpkit's C++ code as the reference for
tests/lcp/test_lemke_engines.cpp.

Tableau of  I w - M z - d z0 = q  (w = M z + q, cpkit's convention), d = all ones. The basis
inverse B^{-1} is kept in fractions. Initial pivot: z0 enters, the leaving row is the
lexicographic minimum of (q_i, e_i) / d_i. Then the complement of the leaving variable enters
and the leaving row is the lexicographic minimum over the rows with a_i > 0 of
(B^{-1} q, B^{-1})_i / a_i (a = B^{-1} times the entering column), z0 first when its ratio ties
(the run ends). With check=True the invariant is asserted after every pivot: every row of
[B^{-1} q, B^{-1}] is lexicographically positive. Pivots are counted as cpkit counts them (the
initial z0 pivot included). Returns (status, pivots, z) with status "solved", "ray" or "limit".
Input numbers are converted exactly (Fraction(float)).
Usage: exact_lemke.py FILE.json  (prints status, pivots, z)
"""
from fractions import Fraction as F
import json, sys

def lemke(M, q, d=None, maxpiv=1000, check=True):
    n = len(q)
    M = [[F(x) for x in r] for r in M]; q = [F(x) for x in q]
    d = [F(1)] * n if d is None else [F(x) for x in d]
    if min(q) >= 0: return "solved", 0, [F(0)] * n
    # columns: 0..n-1 w, n..2n-1 z, 2n z0
    def col(j):
        if j < n: return [F(1) if i == j else F(0) for i in range(n)]
        if j < 2 * n: return [-M[i][j - n] for i in range(n)]
        return [-d[i] for i in range(n)]
    Binv = [[F(1) if i == j else F(0) for j in range(n)] for i in range(n)]
    xb = q[:]
    basic = list(range(n))
    def pivot(r, a, e):
        piv = a[r]
        rowr = [v / piv for v in Binv[r]]; xr = xb[r] / piv
        for i in range(n):
            if i == r: continue
            f = a[i]
            if f != 0:
                Binv[i] = [Binv[i][k] - f * rowr[k] for k in range(n)]
                xb[i] = xb[i] - f * xr
        Binv[r] = rowr; xb[r] = xr
        basic[r] = e
    def lexpos(row):
        for v in row:
            if v != 0: return v > 0
        return False
    # initial pivot: z0 enters, leaving = lexmin (q_i, e_i)/d_i (most negative)
    e = 2 * n
    a = [sum(Binv[i][k] * col(e)[k] for k in range(n)) for i in range(n)]
    r = min(range(n), key=lambda i: [xb[i] / d[i]] + [Binv[i][k] / d[i] for k in range(n)])
    leaving = basic[r]
    pivot(r, a, e)
    piv = 1
    while True:
        if check and leaving != 2 * n:  # z0 leaving at a tie ends the run: not checked
            for i in range(n):
                assert lexpos([xb[i]] + Binv[i]), "lexico invariant violated"
        if leaving == 2 * n:
            z = [F(0)] * n
            for i, b in enumerate(basic):
                if n <= b < 2 * n: z[b - n] = xb[i]
            return "solved", piv, z
        e = leaving + n if leaving < n else leaving - n
        c = col(e)
        a = [sum(Binv[i][k] * c[k] for k in range(n)) for i in range(n)]
        rows = [i for i in range(n) if a[i] > 0]
        if not rows: return "ray", piv, None
        # z0 preferred at a tie of the ratio (ends the run)
        tmin = min(xb[i] / a[i] for i in rows)
        z0r = [i for i in rows if basic[i] == 2 * n and xb[i] / a[i] == tmin]
        if z0r: r = z0r[0]
        else: r = min(rows, key=lambda i: [xb[i] / a[i]] + [Binv[i][k] / a[i] for k in range(n)])
        leaving = basic[r]
        pivot(r, a, e)
        piv += 1
        if piv > maxpiv: return "limit", piv, None

if __name__ == "__main__":
    d = json.load(open(sys.argv[1]))
    st, piv, z = lemke(d["M"], d["q"])
    print(st, piv, [float(x) for x in z] if z else None)

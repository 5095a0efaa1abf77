#!/usr/bin/python3
"""Writes the flat-punch system file of docs/simulation.md ("Partial slip of a flat punch").

The same construction as rate::flat_punch_system (rate_problem/simulation/flat_punch.hpp):
N strips of width h = b/N on an elastic half-plane, strip compliance
C_ij = 2/(pi E*) (L0 - ln|x_i - x_j|), C_ii = 2/(pi E*) (L0 - ln(h/2) + 1), L0 = ln(b) + 2,
A = C^-1 in the tangential and the normal direction (uncoupled), pattern 1 the traction of a
rigid tangential displacement (total 1), pattern 2 a uniform pressure (total 1).

usage: make_flat_punch_system.py N mu k_a OUT.json
"""
import json
import sys

import numpy as np

n, mu, k_a, out = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
b, E = 1.0, 1.0
h, c, L0 = b / n, 2 / (np.pi * E), np.log(b) + 2
C = np.empty((n, n))
for i in range(n):
    for j in range(n):
        C[i, j] = c * (L0 - np.log(h / 2) + 1) if i == j else c * (L0 - np.log(abs(i - j) * h))
K = np.linalg.solve(C, np.eye(n))
K = 0.5 * (K + K.T)
A = np.zeros((2 * n, 2 * n))
A[0::2, 0::2] = K
A[1::2, 1::2] = K
rigid = K @ np.ones(n)
e1, e2 = np.zeros(2 * n), np.zeros(2 * n)
e1[0::2] = rigid / rigid.sum()
e2[1::2] = 1.0 / n
system = {"name": f"flat punch, {n} points (half-plane strips)",
          "A": [[float(f"{x:.15g}") for x in row] for row in A],
          "points": [{"state": "b", "mu": mu, "k_a": k_a} for _ in range(n)],
          "patterns": [[float(f"{x:.15g}") for x in e1], [float(f"{x:.15g}") for x in e2]]}
with open(out, "w") as f:
    json.dump(system, f, indent=1)
    f.write("\n")

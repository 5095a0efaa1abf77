#!/usr/bin/python3
"""Writes the Lemke test problems of two physics engines' own test suites, and classical
cycling examples, as cpkit LCP JSON files (engine_*.json, cycling_*.json) in this directory.

The data are transcribed from the cited files (row-major, as written there); both engines use
cpkit's convention w = M z + q. Each file's "expected" holds the answer of exact (rational)
lexicographic Lemke, exact_lemke.py (status, pivots counted as cpkit counts them, z as
the doubles nearest to the exact fractions), and, where the source states one, the source's
own expected z (exact, as strings "p/q"; for TestProblem2 Drake's Lemke finds (1, 0), the
textbook lexicographic rule (0, 1): both solve it). Siconos' lexicolemke on the same files: siconos_reference.py.
Usage: engine_lcps.py  (rewrites the files)
"""
import json
import os
from fractions import Fraction as F

import exact_lemke

here = os.path.dirname(os.path.abspath(__file__))
DART = ("dartsim/dart, unittests/integration/test_Lemke.cpp, "
        "commit 2fa2e16a05c76426fde16ec8816534e3ceb41ab5")
DRAKE = ("RobotLocomotion/drake, solvers/test/unrevised_lemke_solver_test.cc, "
         "commit be259df724b3b1e206dea95055f0537eae6ad8b9")


def rows(flat, n):
    assert len(flat) == n * n
    return [flat[i * n:(i + 1) * n] for i in range(n)]


problems = []  # (file stem, test name in the source, source, M, q, note, source's expected z)

problems.append(("engine_dart_lemke_1d", "Lemke_1D", DART, [[1]], [-1.5], "", None))
problems.append(("engine_dart_lemke_2d", "Lemke_2D", DART,
                 rows([3.12, 0.1877, 0.1877, 3.254], 2), [-0.00662, -0.006711], "", None))
problems.append(("engine_dart_lemke_4d", "Lemke_4D", DART,
                 rows([3.999, 0.9985, 1.001, -2, 0.9985, 3.998, -2, 0.9995, 1.001, -2, 4.002,
                       1.001, -2, 0.9995, 1.001, 4.001], 4),
                 [-0.01008, -0.009494, -0.07234, -0.07177], "", None))
problems.append(("engine_dart_lemke_6d", "Lemke_6D", DART,
                 rows([3.1360, -2.0370, 0.9723, 0.1096, -2.0370, 0.9723, -2.0370, 3.7820,
                       0.8302, -0.0257, 2.4730, 0.0105, 0.9723, 0.8302, 5.1250, -2.2390, -1.9120,
                       3.4080, 0.1096, -0.0257, -2.2390, 3.1010, -0.0257, -2.2390, -2.0370,
                       2.4730, -1.9120, -0.0257, 5.4870, -0.0242, 0.9723, 0.0105, 3.4080,
                       -2.2390, -0.0242, 3.3860], 6),
                 [0.1649, -0.0025, -0.0904, -0.0093, -0.0000, -0.0889], "q_5 = -0.0000", None))
problems.append(("engine_dart_lemke_12d", "Lemke_12D", DART,
                 rows([4.03, -1.014, -1.898, 1.03, -1.014, -1.898, 1, -1.014, -1.898, -2,
                       -1.014, -1.898, -1.014, 4.885, -1.259, 1.888, 3.81, 2.345, -1.879, 1.281,
                       -2.334, 1.022, 0.206, 1.27, -1.898, -1.259, 3.2, -1.032, -0.6849, 1.275,
                       1.003, 0.6657, 3.774, 1.869, 1.24, 1.85, 1.03, 1.888, -1.032, 4.03, 1.888,
                       -1.032, -2, 1.888, -1.032, 1, 1.888, -1.032, -1.014, 3.81, -0.6849, 1.888,
                       3.225, 1.275, -1.879, 1.85, -1.27, 1.022, 1.265, 0.6907, -1.898, 2.345,
                       1.275, -1.032, 1.275, 4.86, 1.003, -1.24, 0.2059, 1.869, -2.309, 3.791, 1,
                       -1.879, 1.003, -2, -1.879, 1.003, 3.97, -1.879, 1.003, 0.9703, -1.879,
                       1.003, -1.014, 1.281, 0.6657, 1.888, 1.85, -1.24, -1.879, 3.187, 1.234,
                       1.022, 3.755, -0.6714, -1.898, -2.334, 3.774, -1.032, -1.27, 0.2059,
                       1.003, 1.234, 4.839, 1.869, 2.299, 1.27, -2, 1.022, 1.869, 1, 1.022,
                       1.869, 0.9703, 1.022, 1.869, 3.97, 1.022, 1.869, -1.014, 0.206, 1.24,
                       1.888, 1.265, -2.309, -1.879, 3.755, 2.299, 1.022, 4.814, -1.25, -1.898,
                       1.27, 1.85, -1.032, 0.6907, 3.791, 1.003, -0.6714, 1.27, 1.869, -1.25,
                       3.212], 12),
                 [-0.00981, -1.458e-10, 5.357e-10, -0.0098, -1.44e-10, 5.298e-10,
                  -0.009807, -1.399e-10, 5.375e-10, -0.009807, -1.381e-10, 5.316e-10],
                 "a 4-contact LCP, q spans 0.01 and 1e-10 (issue 24, item 7: cpkit's Lemke "
                 "ended in cycle_detected)", None))
problems.append(("engine_drake_cycling", "TestCycling", DRAKE,
                 [[1, 2, 0], [0, 1, 2], [2, 0, 1]], [-1, -1, -1],
                 "known to make Lemke cycle without anti-cycling; every ratio ties",
                 ["1/3", "1/3", "1/3"]))
problems.append(("engine_drake_simple", "TestSimple", DRAKE,
                 [[(i + 1) if i == j else 0 for j in range(9)] for i in range(9)], [-1] * 9, "",
                 ["1", "1/2", "1/3", "1/4", "1/5", "1/6", "1/7", "1/8", "1/9"]))
problems.append(("engine_drake_psd", "TestPSD", DRAKE, [[1, -1], [-1, 1]], [1, -1],
                 "Cottle-Pang-Stone 1992, Example 4.4.16: z0 must leave at the tie", ["0", "1"]))
problems.append(("engine_drake_problem1", "TestProblem1", DRAKE,
                 [[1 if i == j else (2 if j > i else 0) for j in range(16)] for i in range(16)],
                 [-1] * 16, "Handbook of Test Problems in Local and Global Optimization, 10.2.1",
                 ["0"] * 15 + ["1"]))
problems.append(("engine_drake_problem2", "TestProblem2", DRAKE, [[1, 1], [1, 1]], [-1, -1],
                 "Handbook 10.2.2; also solved by (0, 1) and (1/2, 1/2)", ["1", "0"]))
problems.append(("engine_drake_problem3", "TestProblem3", DRAKE,
                 [[0, -1, 2], [2, 0, -2], [-1, 1, 0]], [-3, 6, -1], "Handbook 10.2.3",
                 ["0", "1", "3"]))
problems.append(("engine_drake_problem4", "TestProblem4", DRAKE,
                 [[0, 0, 10, 20], [0, 0, 30, 15], [10, 20, 0, 0], [30, 15, 0, 0]], [-1] * 4,
                 "Handbook 10.2.4; Drake expects Lemke to fail (it has solutions Lemke does "
                 "not reach)", None))
for l in (1, 16, 100):
    z = ([F(l + 16, 13), F(l + 16, 13), F(2 * (23 - l), 13), F(1286 - 9 * l, 13)] if l <= 23
         else [F(3), F(3), F(0), F(83)])
    problems.append((f"engine_drake_problem6_l{l}", "TestProblem6", DRAKE,
                     [[11, 0, 10, -1], [0, 11, 10, -1], [10, 10, 21, -1], [1, 1, 1, 0]],
                     [50, 50, l, -6], f"Handbook 10.2.9 with q_3 = {l}",
                     [str(v) for v in z]))
# Beale's (1955) cycling LP  min -3/4 x1 + 20 x2 - 1/2 x3 + 6 x4  s.t.
# 1/4 x1 - 8 x2 - x3 + 9 x4 <= 0,  1/2 x1 - 12 x2 - 1/2 x3 + 3 x4 <= 0,  x3 <= 1,  x >= 0,
# as the LCP of its optimality conditions: z = (x, y), M = [[0, A^T], [-A, 0]], q = (c, b).
# Optimum x = (1, 0, 1, 0) (value -5/4), duals y = (0, 3/2, 5/4) (by hand: constraint 1 is
# slack, the columns of x1 and x3 are tight).
A = [[F(1, 4), -8, -1, 9], [F(1, 2), -12, F(-1, 2), 3], [0, 0, 1, 0]]
c = [F(-3, 4), 20, F(-1, 2), 6]
b = [0, 0, 1]
Mb = [[0] * 4 + [A[r][j] for r in range(3)] for j in range(4)] + \
     [[-A[i][j] for j in range(4)] + [0] * 3 for i in range(3)]
problems.append(("cycling_beale_lp", "Beale 1955", "E. M. L. Beale, Cycling in the dual simplex "
                 "algorithm, Naval Research Logistics Quarterly 2 (1955) 269-275 (the LP); the "
                 "LCP of its optimality conditions written here",
                 [[float(v) for v in r] for r in Mb], [float(v) for v in c + b],
                 "degenerate (b has zeros); x = z[0:4], y = z[4:7]",
                 ["1", "0", "1", "0", "0", "3/2", "5/4"]))

for stem, test, source, M, q, note, stated in problems:
    status, pivots, z = exact_lemke.lemke(M, q)
    expected = {"exact_lemke": {"status": status, "pivots": pivots,
                                "z": None if z is None else [float(v) for v in z]}}
    if stated is not None:
        expected["source_z"] = stated
    doc = {"name": stem, "source": f"{source}, test {test}" if "commit" in source else source,
           "M": M, "q": q, "expected": expected}
    if note:
        doc["note"] = note
    with open(os.path.join(here, stem + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
    print(stem, status, pivots, None if z is None else [float(v) for v in z][:6])

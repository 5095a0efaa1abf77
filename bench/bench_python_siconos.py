#!/usr/bin/python3
"""Benchmark: cpkit's Python module against Siconos' (siconos.numerics), side by side in one
process (issue 27).

1. Per call: the tiny LCP M = [[2, 1], [1, 2]], q = (-5, -6) through cpkit.solve(M, q,
   solver="lemke") and through Siconos' LCP(M, q) + SolverOptions + lcp_lexicolemke (the
   arrays z, w made per call, as a user's call does). The two are timed in alternating batches
   (a busy machine slows both alike); each figure is the median per-call time over the batches.
   Target: ratio cpkit / Siconos <= 1.
2. Batched: k problems (2x2 and 3x3 SPD, one per contact) by cpkit.solve_batch in one call,
   against a Python loop of Siconos calls and a Python loop of cpkit.solve: problems per second.
Every answer is checked against the other route (same z to 1e-9).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python_siconos.py [--quick]
(exit 77 with the reason when siconos or the module cannot be imported). Numbers: docs/python.md.
"""
import statistics
import sys
import time

import numpy as np

try:
    import siconos.numerics as sn
except ImportError as e:
    print(f"SKIPPED: siconos.numerics is not importable ({e}; Debian: python3-siconos)")
    sys.exit(77)
try:
    import cpkit
except ImportError as e:
    print(f"SKIPPED: cpkit is not importable ({e}; PYTHONPATH=<build>/python)")
    sys.exit(77)

QUICK = "--quick" in sys.argv


def siconos_solve(M, q):
    n = q.size
    problem = sn.LCP(M, q)
    z = np.zeros(n)
    w = np.zeros(n)
    options = sn.SolverOptions(sn.SICONOS_LCP_LEMKE)
    info = sn.lcp_lexicolemke(problem, z, w, options)
    return info, z


def per_call(fn, calls):
    t0 = time.perf_counter()
    for _ in range(calls):
        fn()
    return (time.perf_counter() - t0) / calls


def main():
    M = np.array([[2.0, 1.0], [1.0, 2.0]])
    q = np.array([-5.0, -6.0])
    r = cpkit.solve(M, q, solver="lemke")
    info, zs = siconos_solve(M, q)
    assert r.status == "solved" and info == 0 and np.allclose(r.z, zs, rtol=1e-12), (r, zs)

    batches, calls = (7, 2000) if QUICK else (21, 20000)
    sic, cpk, auto = [], [], []
    for _ in range(batches):  # alternating: the load of the machine hits both alike
        sic.append(per_call(lambda: siconos_solve(M, q), calls))
        cpk.append(per_call(lambda: cpkit.solve(M, q, solver="lemke"), calls))
        auto.append(per_call(lambda: cpkit.solve(M, q), calls))
    s, c, a = (statistics.median(x) * 1e6 for x in (sic, cpk, auto))
    print(f"tiny LCP (n = 2, Lemke), median per call over {batches} alternating batches of "
          f"{calls} calls")
    print("| path | per call | vs Siconos |")
    print("|---|---|---|")
    print(f"| Siconos: LCP + SolverOptions + lcp_lexicolemke | {s:.2f} us | 1.00 |")
    print(f"| cpkit.solve(M, q, solver=\"lemke\") | {c:.2f} us | {c / s:.2f} |")
    print(f"| cpkit.solve(M, q) (auto chain) | {a:.2f} us | {a / s:.2f} |")
    print(f"per-call ratio cpkit / Siconos: {c / s:.2f} (target <= 1)")

    k = 2000 if QUICK else 20000
    print(f"\nbatched: {k} SPD problems per size (random, seed 1)")
    print("| n | cpkit.solve_batch | Python loop of Siconos | Python loop of cpkit.solve | "
          "batch / Siconos loop |")
    print("|---|---|---|---|---|")
    rng = np.random.default_rng(1)
    for n in (2, 3):
        A = rng.standard_normal((k, n, n))
        Ms = A @ A.transpose(0, 2, 1) + np.eye(n)
        qs = rng.standard_normal((k, n)) * 3
        best = {}
        for rep in range(3):
            t0 = time.perf_counter()
            b = cpkit.solve_batch(Ms, qs, solver="lemke")
            best["batch"] = min(best.get("batch", 1e9), time.perf_counter() - t0)
            t0 = time.perf_counter()
            zs = [siconos_solve(Ms[i], qs[i])[1] for i in range(k)]
            best["siconos"] = min(best.get("siconos", 1e9), time.perf_counter() - t0)
            t0 = time.perf_counter()
            zc = [cpkit.solve(Ms[i], qs[i], solver="lemke").z for i in range(k)]
            best["loop"] = min(best.get("loop", 1e9), time.perf_counter() - t0)
        assert b.is_solution.all()
        assert np.allclose(b.z, np.array(zs), rtol=1e-9, atol=1e-12)
        assert np.allclose(b.z, np.array(zc), rtol=1e-12, atol=1e-14)
        rate = {key: k / v for key, v in best.items()}
        print(f"| {n} | {rate['batch']:.3g} problems/s | {rate['siconos']:.3g} problems/s | "
              f"{rate['loop']:.3g} problems/s | {rate['batch'] / rate['siconos']:.1f}x |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Benchmark: cpkit's Python module against Siconos' (siconos.numerics), side by side in one
process (issue 27).

1. Per call: the tiny LCP M = [[2, 1], [1, 2]], q = (-5, -6) through cpkit.solve(M, q) (the
   default solver, "auto", as a user calls it; issue 37), through cpkit.solve(M, q,
   solver="lemke"), and through Siconos' LCP(M, q) + SolverOptions + lcp_lexicolemke (the
   arrays z, w made per call, as a user's call does). Trials of `calls` calls each, the three
   interleaved (the order rotates from trial to trial: the load of the machine and the order
   hit all alike); each trial gives a paired ratio cpkit / Siconos per cpkit route.
   Printed: the medians per call, the median paired ratios and their spread (min, quartiles,
   max over the trials), and the verdict per route: ratio <= 1 "beyond the noise" when a sign
   test over the paired trials says so (the chance of as many trials below 1 without a
   difference < 1%).
   Times are the CPU time of the thread (robust to the load). Target: <= 1.
   The load average is printed before and after (numbers in the docs quote it).
2. Batched: k problems (2x2 and 3x3 SPD, one per contact) by cpkit.solve_batch in one call,
   against a Python loop of Siconos calls and a Python loop of cpkit.solve: problems per second.
Every answer is checked against the other route (same z to 1e-9).

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python_siconos.py [--quick]
  [--trials T] [--calls C] [--cpu K] [--wall] [--instructions]
Default 21 trials of 20000 calls (--quick: 7 of 2000). --cpu K: pin the process to CPU K.
--wall: wall-clock time instead of CPU time. --instructions: also the instructions per call
counted by valgrind's callgrind, independent of the load ((count of 2N calls - count of N
calls) / N per route, ~2 min). Exit 77 with the reason when siconos or the module cannot be
imported. Numbers: docs/python.md.
"""
import math
import os
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


def option(name, default):
    if name in sys.argv:
        return int(sys.argv[sys.argv.index(name) + 1])
    return default


# The CPU time of this thread (time.thread_time): a trial that is descheduled by other
# programs is not charged for it (wall time on a loaded machine swung the paired ratios between
# 0.6 and 1.6); --wall: wall-clock time instead.
CLOCK = time.perf_counter if "--wall" in sys.argv else time.thread_time


# Plain loops (no lambda per call): what a user's loop of calls costs, the same loop overhead
# for both routes.
def time_siconos(M, q, calls):
    LCP, SolverOptions, lexicolemke, zeros = sn.LCP, sn.SolverOptions, sn.lcp_lexicolemke, np.zeros
    lemke_id = sn.SICONOS_LCP_LEMKE
    n = q.size
    t0 = CLOCK()
    for _ in range(calls):
        problem = LCP(M, q)
        z = zeros(n)
        w = zeros(n)
        lexicolemke(problem, z, w, SolverOptions(lemke_id))
    return (CLOCK() - t0) / calls


def time_cpkit(M, q, calls, solver=None):
    """cpkit.solve per call; solver None: the default, called as a user calls it."""
    solve = cpkit.solve
    t0 = CLOCK()
    if solver is None:
        for _ in range(calls):
            solve(M, q)
    else:
        for _ in range(calls):
            solve(M, q, solver)
    return (CLOCK() - t0) / calls


def quartiles(x):
    """(min, lower quartile, median, upper quartile, max) of x."""
    q1, q2, q3 = statistics.quantiles(x, n=4, method="inclusive")
    return min(x), q1, q2, q3, max(x)


def loop_only(route, calls):
    """--loop ROUTE N: N calls of one route after 200 warm-up calls (run under callgrind)."""
    M = np.array([[2.0, 1.0], [1.0, 2.0]])
    q = np.array([-5.0, -6.0])
    if route == "siconos":
        fn = time_siconos
    else:
        def fn(M, q, n):
            return time_cpkit(M, q, n, None if route == "cpkit" else "lemke")
    fn(M, q, 200)
    fn(M, q, calls)


def instructions_per_call(route, calls=2000):
    """Instructions per call of `route` counted by callgrind: the difference of the counts of
    2 calls and `calls` calls of a whole process (start-up cancels), divided by `calls`.
    None when valgrind is missing or fails."""
    import re
    import shutil
    import subprocess
    if shutil.which("valgrind") is None:
        return None
    env = dict(os.environ, PYTHONHASHSEED="0")
    counts = []
    for n in (calls, 2 * calls):
        p = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                            sys.executable, __file__, "--loop", route, str(n)],
                           env=env, capture_output=True, text=True)
        m = re.search(r"Collected : (\d+)", p.stderr)
        if p.returncode != 0 or m is None:
            return None
        counts.append(int(m.group(1)))
    return (counts[1] - counts[0]) / calls


def print_instructions():
    got = {route: instructions_per_call(route) for route in ("siconos", "cpkit", "cpkit-lemke")}
    if None in got.values():
        print("instructions per call: valgrind not available (Debian: valgrind)")
        return
    print(f"instructions per call (callgrind, 2000 calls beyond 2000): Siconos "
          f"{got['siconos'] / 1e3:.1f}k, cpkit.solve (default) {got['cpkit'] / 1e3:.1f}k "
          f"(ratio {got['cpkit'] / got['siconos']:.3f}), cpkit.solve(solver=\"lemke\") "
          f"{got['cpkit-lemke'] / 1e3:.1f}k (ratio {got['cpkit-lemke'] / got['siconos']:.3f})")


def main():
    if "--loop" in sys.argv:
        i = sys.argv.index("--loop")
        loop_only(sys.argv[i + 1], int(sys.argv[i + 2]))
        return
    M = np.array([[2.0, 1.0], [1.0, 2.0]])
    q = np.array([-5.0, -6.0])
    info, zs = siconos_solve(M, q)
    # Every route against the closed form: 2 z1 + z2 = 5, z1 + 2 z2 = 6 -> z = (4/3, 7/3), w = 0.
    assert info == 0 and np.allclose(zs, [4 / 3, 7 / 3]), (info, zs)
    for r in (cpkit.solve(M, q), cpkit.solve(M, q, solver="lemke")):
        assert r.status == "solved" and np.allclose(r.z, [4 / 3, 7 / 3], rtol=1e-14), r

    cpu = option("--cpu", -1)
    if cpu >= 0 and hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {cpu})
    trials = option("--trials", 7 if QUICK else 21)
    calls = option("--calls", 2000 if QUICK else 20000)
    load0 = os.getloadavg()[0]
    routes = {"siconos": lambda n: time_siconos(M, q, n),
              "default": lambda n: time_cpkit(M, q, n),
              "lemke": lambda n: time_cpkit(M, q, n, "lemke")}
    for run in routes.values():
        run(calls // 10)  # warm-up
    times = {name: [] for name in routes}
    order = list(routes)
    for t in range(trials):
        for name in order[t % 3:] + order[:t % 3]:  # the order rotates trial by trial
            times[name].append(routes[name](calls))
    load1 = os.getloadavg()[0]
    med = {name: statistics.median(x) * 1e6 for name, x in times.items()}
    clock = "wall-clock time" if CLOCK is time.perf_counter else "CPU time of the thread"
    print(f"tiny LCP (n = 2): {trials} interleaved trials of {calls} calls, one process, "
          f"{clock}"
          f"{f', pinned to CPU {cpu}' if cpu >= 0 else ''}; load average {load0:.2f} before, "
          f"{load1:.2f} after")
    print("| path | median per call | spread over the trials (min - max) | paired ratio vs Siconos |")
    print("|---|---|---|---|")
    labels = {"siconos": "Siconos: LCP + SolverOptions + lcp_lexicolemke",
              "default": "cpkit.solve(M, q) (default solver, auto)",
              "lemke": "cpkit.solve(M, q, \"lemke\")"}
    ratios = {name: [c / s for c, s in zip(times[name], times["siconos"])]
              for name in ("default", "lemke")}
    for name in routes:
        r = "1.00" if name == "siconos" else f"{statistics.median(ratios[name]):.2f}"
        print(f"| {labels[name]} | {med[name]:.2f} us | {min(times[name]) * 1e6:.2f} - "
              f"{max(times[name]) * 1e6:.2f} us | {r} |")
    # Sign test over the paired trials: under "no difference" each trial is below 1 with
    # probability 1/2; "beyond the noise" when the chance of as many trials below 1 is < 1%.
    for name in ("default", "lemke"):
        rq = quartiles(ratios[name])
        below = sum(x < 1 for x in ratios[name])
        p_value = sum(math.comb(trials, j) for j in range(below, trials + 1)) / 2**trials
        verdict = ("<= 1 beyond the noise" if p_value < 0.01 else "not shown beyond the noise")
        print(f"per-call ratio {labels[name]} / Siconos: median {rq[2]:.3f} over {trials} paired "
              f"trials (min {rq[0]:.3f}, quartiles {rq[1]:.3f} - {rq[3]:.3f}, max {rq[4]:.3f}); "
              f"{below} of {trials} trials below 1 (sign test p = {p_value:.2g}): {verdict}")
    if "--instructions" in sys.argv:
        print_instructions()

    k = 2000 if QUICK else 20000
    print(f"\nbatched: {k} SPD problems per size (random, seed 1), best of 3, {clock}")
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
            t0 = CLOCK()
            b = cpkit.solve_batch(Ms, qs, solver="lemke")
            best["batch"] = min(best.get("batch", 1e9), CLOCK() - t0)
            t0 = CLOCK()
            zs = [siconos_solve(Ms[i], qs[i])[1] for i in range(k)]
            best["siconos"] = min(best.get("siconos", 1e9), CLOCK() - t0)
            t0 = CLOCK()
            zc = [cpkit.solve(Ms[i], qs[i], solver="lemke").z for i in range(k)]
            best["loop"] = min(best.get("loop", 1e9), CLOCK() - t0)
        assert b.is_solution.all()
        assert np.allclose(b.z, np.array(zs), rtol=1e-9, atol=1e-12)
        assert np.allclose(b.z, np.array(zc), rtol=1e-12, atol=1e-14)
        rate = {key: k / v for key, v in best.items()}
        print(f"| {n} | {rate['batch']:.3g} problems/s | {rate['siconos']:.3g} problems/s | "
              f"{rate['loop']:.3g} problems/s | {rate['batch'] / rate['siconos']:.1f}x |")


if __name__ == "__main__":
    main()

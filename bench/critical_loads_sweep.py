#!/usr/bin/python3
"""Exit codes of `cpkit rate` (enumeration cross-checked against analytic) at 400 critical loads.

Issue 24: contacts with cond(A) from 1e2 to 1e12 (log-uniform), states b and d, loads within
1e-16..1e-12 relative of a critical direction (N = a11 dF_N - a12 dF_T = 0 or
L_s = (s + mu a12 C_T) dF_T - mu (1 + a11 C_T) dF_N = 0, docs/model.md). Exit 3 means the two
routes of `cpkit rate` disagree on a complete answer: one of them is wrong.

Usage: bench/critical_loads_sweep.py CPKIT [CPKIT_OTHER]   (fixed seed: the same 400 loads)
"""
import collections
import random
import subprocess
import sys


def cases(n=400, seed=24):
    rng = random.Random(seed)
    for _ in range(n):
        cond = 10 ** rng.uniform(2, 12)
        # A = R diag(l1, l1/cond) R^T, entries of order 1
        import math
        th = rng.uniform(0, math.pi)
        l1 = 10 ** rng.uniform(-1, 1)
        l2 = l1 / cond
        c, s = math.cos(th), math.sin(th)
        a11 = c * c * l1 + s * s * l2
        a22 = s * s * l1 + c * c * l2
        a12 = c * s * (l1 - l2)
        mu = 10 ** rng.uniform(-1, 0.5)
        CT = 0.0 if rng.random() < 0.4 else 10 ** rng.uniform(-2, 1)
        sg = rng.choice([1, -1])
        state = rng.choice("bd")
        eps = rng.choice([-1, 1]) * 10 ** rng.uniform(-16, -12)
        if state == "b" and rng.random() < 0.5:
            dFT, dFN = a11, a12 * (1 + eps)          # N ~ 0
        else:
            dFN = 1.0
            dFT = mu * (1 + a11 * CT) / (sg + mu * a12 * CT) * (1 + eps)  # L_s ~ 0
        args = ["--state", state, "--a11", repr(a11), "--a12", repr(a12), "--a22", repr(a22),
                "--mu", repr(mu), "--C_T", repr(CT), "--dF", repr(dFT), repr(dFN)]
        if state == "d":
            args += ["--P_N", "1", "--sgnPT", str(sg)]
        yield args


def run(prog):
    codes = collections.Counter()
    for args in cases():
        rc = subprocess.run([prog, "rate", *args], capture_output=True).returncode
        codes[rc] += 1
    return codes


if __name__ == "__main__":
    for prog in sys.argv[1:]:
        c = run(prog)
        print(f"{prog}: " + ", ".join(f"exit {k}: {v}" for k, v in sorted(c.items())))

"""Shared helpers of the Python tests: the cpkit CLI of the same build (an independent route to
the same C++ answers), scratch files, and a brute-force LCP enumerator written here."""
import itertools
import json
import os
import subprocess

import numpy as np
import pytest

CLI = os.environ.get("CPKIT_CLI", "")
SOURCE_DIR = os.environ.get("CPKIT_SOURCE_DIR",
                            os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DATA_DIR = os.path.join(SOURCE_DIR, "tests", "data")


def run_cli(*args, expect=(0,)):
    """Runs the cpkit program of this build; returns (exit code, parsed JSON stdout or text)."""
    if not CLI or not os.path.exists(CLI):
        pytest.skip("the cpkit command-line program is not built (CPKIT_CLI unset)")
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=120)
    assert p.returncode in expect, f"cpkit {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}"
    out = p.stdout
    if "--json" in args:
        out = json.loads(out)
    return p.returncode, out


def brute_force_lcp(M, q, tol=1e-9):
    """Every basic solution of LCP(M, q) for nondegenerate data: for each support S solve
    M_SS z_S = -q_S and keep z >= 0, w >= 0. Independent of cpkit (numpy only)."""
    M = np.asarray(M, float)
    q = np.asarray(q, float)
    n = q.size
    sols = []
    for k in range(n + 1):
        for S in itertools.combinations(range(n), k):
            z = np.zeros(n)
            if S:
                idx = list(S)
                try:
                    z[idx] = np.linalg.solve(M[np.ix_(idx, idx)], -q[idx])
                except np.linalg.LinAlgError:
                    continue
            w = M @ z + q
            scale = 1 + np.abs(q).max() + np.abs(M).max() * np.abs(z).max()
            if z.min() >= -tol * scale and w.min() >= -tol * scale:
                if not any(np.allclose(z, s, atol=1e-9 * scale) for s in sols):
                    sols.append(z)
    return sols

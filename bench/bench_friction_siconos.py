#!/usr/bin/python3
"""Benchmark: `cpkit fc solve` against Siconos' fc3d solvers on real 3-D frictional contact
problems (issue 26, "Benchmark against Siconos").

For every problem file (default: tests/data/fclib/local, Siconos .dat and FCLIB local .hdf5):
- cpkit: `cpkit fc solve FILE --solver S --json --tol T` for S in auto, fb-soc, nsgs, prox,
  each solve its own process (`--time-limit` and the subprocess timeout cap it);
- Siconos 4.4 (python3-siconos): fc3d NSGS, NSN_AC, NSN_FB, PROX, ADMM through fc3d_driver,
  each solve in its OWN Python subprocess (this script with --child: some Siconos solvers abort
  the process on hard files), SolverOptions(id) with the same tolerance T, an iteration cap and
  a wall-clock timeout on the subprocess.
Every answer, cpkit's and Siconos', is judged by the SAME independent check, computed here with
numpy from the file's data as read by Siconos' reader (.dat: frictionContact_new_from_filename;
.hdf5: libfclib's fclib_read_local through ctypes): u = W r + q recomputed (the solver's u is not
used), u_hat_i = u_i + (mu_i |u_T,i|, 0, 0), and the natural map
    E = || r - P_K(r - u_hat) ||_2,    relative_q = E / ||q||_2
(Acary, Bremond, Huber, INRIA RR-9118, 2018). A solve "succeeds" when relative_q <= T and r is
finite, whatever the solver's own flag says. Also printed: Siconos' own normalisation
E / max(||q||, ||r||, ||u||) (fc3d_compute_error) and, for cpkit answers, cpkit's unit-free error.

Times: "process" is the wall time of the whole subprocess as a user times it (for Siconos this
includes starting Python and importing siconos.numerics, and reading the file); "solve" is the
inner time: cpkit's `seconds` field, Siconos' time around fc3d_driver inside the subprocess.
Per file: ratio best cpkit / best Siconos (successful solves only) for both times; files of 50
contacts or more are flagged (issue 26's target: ratio <= 1 on those, whole process).

Usage: /usr/bin/python3 bench/bench_friction_siconos.py [--cpkit build/apps/cpkit] [--tol 1e-8]
       [--timeout 20] [--repeat 3] [--out PREFIX] [FILE...]
--out PREFIX writes PREFIX.csv (one row per file and solver) and, when matplotlib is there,
PREFIX_profile.png (Dolan-More profile of the whole-process times). Exit 77 when siconos is
not importable. Numbers: docs/benchmarks.md ("3-D frictional contact against Siconos").
"""
import argparse
import csv
import ctypes
import glob
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.coo  # noqa: F401  (siconos' NM_csc typemap wants these imported)
import scipy.sparse.csc  # noqa: F401

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CPKIT_SOLVERS = ["auto", "fb-soc", "nsgs", "prox"]
SICONOS_SOLVERS = ["NSGS", "NSN_AC", "NSN_FB", "PROX", "ADMM"]
# Iteration caps for Siconos (its defaults are 1000 for NSGS / PROX, 100 for the Newtons and
# 20000 for ADMM); the subprocess timeout bounds them in time anyway.
SICONOS_MAX_ITER = {"NSGS": 10000, "NSN_AC": 1000, "NSN_FB": 1000, "PROX": 10000, "ADMM": 20000}


# ---------------------------------------------------------------------------------------------
# Reading the data, independently of cpkit
class _FclibMatrix(ctypes.Structure):
    _fields_ = [("nzmax", ctypes.c_int), ("m", ctypes.c_int), ("n", ctypes.c_int),
                ("p", ctypes.POINTER(ctypes.c_int)), ("i", ctypes.POINTER(ctypes.c_int)),
                ("x", ctypes.POINTER(ctypes.c_double)), ("nz", ctypes.c_int),
                ("info", ctypes.c_void_p)]


class _FclibLocal(ctypes.Structure):
    _fields_ = [("W", ctypes.POINTER(_FclibMatrix)), ("V", ctypes.POINTER(_FclibMatrix)),
                ("R", ctypes.POINTER(_FclibMatrix)), ("mu", ctypes.POINTER(ctypes.c_double)),
                ("q", ctypes.POINTER(ctypes.c_double)), ("s", ctypes.POINTER(ctypes.c_double)),
                ("spacedim", ctypes.c_int), ("info", ctypes.c_void_p)]


def read_fclib_local(path):
    """W (CSR), q, mu of an FCLIB local problem through libfclib (Debian libfclib0)."""
    lib = ctypes.CDLL("libfclib.so.0")
    lib.fclib_read_local.restype = ctypes.POINTER(_FclibLocal)
    lib.fclib_read_local.argtypes = [ctypes.c_char_p]
    ptr = lib.fclib_read_local(path.encode())
    if not ptr:
        raise ValueError(f"{path}: libfclib cannot read a local problem")
    prob = ptr.contents
    if prob.spacedim != 3:
        raise ValueError(f"{path}: spacedim {prob.spacedim}, only 3-D problems are benchmarked")
    W = prob.W.contents
    m, n, nz = W.m, W.n, W.nz
    if nz >= 0:  # triplet: nz entries, i rows, p columns
        rows = np.ctypeslib.as_array(W.i, (nz,)).copy()
        cols = np.ctypeslib.as_array(W.p, (nz,)).copy()
        vals = np.ctypeslib.as_array(W.x, (nz,)).copy()
        Wm = sp.coo_matrix((vals, (rows, cols)), shape=(m, n)).tocsr()
    elif nz == -1:  # compressed columns
        p = np.ctypeslib.as_array(W.p, (n + 1,)).copy()
        k = p[-1]
        Wm = sp.csc_matrix((np.ctypeslib.as_array(W.x, (k,)).copy(),
                            np.ctypeslib.as_array(W.i, (k,)).copy(), p), shape=(m, n)).tocsr()
    elif nz == -2:  # compressed rows
        p = np.ctypeslib.as_array(W.p, (m + 1,)).copy()
        k = p[-1]
        Wm = sp.csr_matrix((np.ctypeslib.as_array(W.x, (k,)).copy(),
                            np.ctypeslib.as_array(W.i, (k,)).copy(), p), shape=(m, n))
    else:
        raise ValueError(f"{path}: W storage nz = {nz} unknown")
    q = np.ctypeslib.as_array(prob.q, (m,)).copy()
    mu = np.ctypeslib.as_array(prob.mu, (m // 3,)).copy()
    return Wm, q, mu  # the problem is leaked: one per file, in a short process


def siconos_problem(path):
    """The Siconos FrictionContactProblem of a file, as a Siconos user builds it."""
    import siconos.numerics as sn
    if path.endswith(".hdf5"):
        W, q, mu = read_fclib_local(path)
        W = W.tocsc()
        W.indices, W.indptr = W.indices.astype(np.int64), W.indptr.astype(np.int64)
        return sn.FrictionContactProblem(3, W, q, mu)  # int64 indices: Siconos' own width
    return sn.frictionContact_new_from_filename(path)


def read_data(path):
    """W (CSR), q, mu of a file through Siconos' reader or libfclib (never through cpkit)."""
    if path.endswith(".hdf5"):
        return read_fclib_local(path)
    import siconos.numerics as sn
    p = sn.frictionContact_new_from_filename(path)
    W = sn.NM_csc(p.M).tocsr()
    return W, np.array(p.q, dtype=float), np.array(p.mu, dtype=float)


# ---------------------------------------------------------------------------------------------
# The independent check
def project_cone(z, mu):
    """Rows of z (n_c x 3, normal first) projected onto K_mu = {|z_T| <= mu z_N}."""
    zn, zt = z[:, 0], z[:, 1:]
    nt = np.linalg.norm(zt, axis=1)
    out = np.zeros_like(z)
    inside = nt <= mu * zn
    out[inside] = z[inside]
    polar = (~inside) & (mu * nt <= -zn)  # the polar cone -K* = {mu |z_T| <= -z_N} goes to 0
    side = ~(inside | polar)
    a = (zn[side] + mu[side] * nt[side]) / (1.0 + mu[side] ** 2)
    out[side, 0] = a
    out[side, 1:] = (mu[side] * a / nt[side])[:, None] * zt[side]
    return out


def self_check_projection():
    """Moreau's decomposition on random points: P idempotent, z - P(z) orthogonal to P(z) and
    in the polar cone {mu |d_T| <= -d_N}. Guards the one formula every verdict here rests on."""
    rng = np.random.default_rng(1)
    z, mu = rng.normal(size=(2000, 3)), rng.uniform(0.05, 3.0, 2000)
    P = project_cone(z, mu)
    d = z - P
    assert np.abs(project_cone(P, mu) - P).max() < 1e-12
    assert np.abs((d * P).sum(axis=1)).max() < 1e-12
    assert (mu * np.linalg.norm(d[:, 1:], axis=1) + d[:, 0]).max() < 1e-12


def check(W, q, mu, r):
    """(relative_q, relative_max) of r; inf when r is missing or not finite."""
    if r is None or r.shape != q.shape or not np.all(np.isfinite(r)):
        return math.inf, math.inf
    u = W @ r + q
    nc = q.size // 3
    R, U = r.reshape(nc, 3), u.reshape(nc, 3)
    uhat = U.copy()
    uhat[:, 0] += mu * np.linalg.norm(U[:, 1:], axis=1)
    E = float(np.linalg.norm(R - project_cone(R - uhat, mu)))
    nq = float(np.linalg.norm(q))
    eps = np.finfo(float).eps
    rel_q = E / nq if nq > eps else E
    big = max(nq, float(np.linalg.norm(r)), float(np.linalg.norm(u)))
    return rel_q, (E / big if big > eps else E)


# ---------------------------------------------------------------------------------------------
# The Siconos child process
def child(solver, path, tol, max_iter):
    """Solve once with Siconos, print one JSON line (r, info, iterations, seconds)."""
    import siconos.numerics as sn
    problem = siconos_problem(path)
    n = 3 * problem.numberOfContacts
    r, u = np.zeros(n), np.zeros(n)
    options = sn.SolverOptions(getattr(sn, "SICONOS_FRICTION_3D_" + solver))
    options.iparam[sn.SICONOS_IPARAM_MAX_ITER] = max_iter
    options.dparam[sn.SICONOS_DPARAM_TOL] = tol
    t0 = time.perf_counter()
    info = sn.fc3d_driver(problem, r, u, options)
    seconds = time.perf_counter() - t0
    print(json.dumps({"info": int(info), "iterations": int(options.iparam[sn.SICONOS_IPARAM_ITER_DONE]),
                      "error": float(options.dparam[sn.SICONOS_DPARAM_RESIDU]),
                      "seconds": seconds, "r": r.tolist()}))
    sys.stdout.flush()
    os._exit(0)  # skip Siconos' teardown (not part of the solve)


# ---------------------------------------------------------------------------------------------
def run(cmd, timeout):
    """(stdout, exit code, wall seconds); exit code None on timeout."""
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.stdout, p.returncode, time.perf_counter() - t0, p.stderr
    except subprocess.TimeoutExpired:
        return "", None, time.perf_counter() - t0, "timeout"


def run_cpkit(cpkit, path, solver, tol, timeout):
    cmd = [cpkit, "fc", "solve", path, "--solver", solver, "--json", "--tol", repr(tol),
           "--time-limit", repr(0.9 * timeout)]
    out, code, wall, err = run(cmd, timeout)
    res = {"exit": code, "process": wall, "solve": math.nan, "claim": "", "iterations": "",
           "unit_free": math.nan, "r": None, "note": ""}
    try:
        j = json.loads(out)
        res.update(claim=j["status"], iterations=j.get("iterations", ""),
                   solve=float(j.get("seconds", math.nan)),
                   unit_free=float(j["errors"]["unit_free"]) if j["errors"]["unit_free"] is not None
                   else math.inf,
                   r=np.array(j["r"], dtype=float) if j.get("r") else None)
    except (ValueError, KeyError, TypeError):
        res["claim"] = "timeout" if code is None else f"exit {code}"
        res["note"] = err.strip().splitlines()[-1][:80] if err.strip() else ""
    return res


def run_siconos(path, solver, tol, timeout):
    cmd = [sys.executable, os.path.abspath(__file__), "--child", solver, path, repr(tol),
           str(SICONOS_MAX_ITER[solver])]
    out, code, wall, err = run(cmd, timeout)
    res = {"exit": code, "process": wall, "solve": math.nan, "claim": "", "iterations": "",
           "unit_free": math.nan, "r": None, "note": ""}
    lines = [x for x in out.splitlines() if x.startswith("{")]
    if lines:
        j = json.loads(lines[-1])
        res.update(claim="info 0" if j["info"] == 0 else f"info {j['info']}",
                   iterations=j["iterations"], solve=j["seconds"], r=np.array(j["r"]),
                   note=f"own error {j['error']:.1e}")
    else:
        res["claim"] = "timeout" if code is None else (f"killed {-code}" if code < 0
                                                       else f"exit {code}")
    return res


def repeated(solve, k):
    """The last of k runs (the solvers are deterministic) with the median process and solve
    times: on a shared machine one sample can be off by 2x. A timeout is not repeated."""
    runs = [solve()]
    while len(runs) < k and runs[-1]["exit"] is not None:
        runs.append(solve())
    res = dict(runs[-1])
    res["process"] = float(np.median([r["process"] for r in runs]))
    res["solve"] = float(np.median([r["solve"] for r in runs]))
    return res


def fmt_t(x):
    if x is None or not math.isfinite(x):
        return "-"
    return f"{x * 1e3:.1f} ms" if x < 1 else f"{x:.2f} s"


def fmt_e(x):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else (
        "inf" if math.isinf(x) else f"{x:.1e}")


def profile_ratios(rows, key):
    """Per solver, its time / the best time on each file (inf on failure): Dolan-More."""
    files = sorted({r["file"] for r in rows})
    solvers = list(dict.fromkeys(f"{r['code']}:{r['solver']}" for r in rows))
    t = {(r["file"], f"{r['code']}:{r['solver']}"):
         (max(r[key], 1e-7) if r["success"] and math.isfinite(r[key]) else math.inf) for r in rows}
    ratios = {s: [] for s in solvers}
    for f in files:
        best = min(t[(f, s)] for s in solvers)
        for s in solvers:
            ratios[s].append(t[(f, s)] / best if math.isfinite(best) else math.inf)
    return files, solvers, ratios


def profile_table(rows, key):
    files, solvers, ratios = profile_ratios(rows, key)
    taus = [1, 1.5, 2, 5, 10, 100]
    print(f"\n## Dolan-More profile of the {key} time: fraction of the {len(files)} files solved "
          "within tau x the best")
    print("| solver | " + " | ".join(f"tau = {t:g}" for t in taus) + " |")
    print("|---|" + "---|" * len(taus))
    for s in solvers:
        print(f"| {s} | " + " | ".join(
            f"{sum(1 for x in ratios[s] if x <= t * (1 + 1e-12)) / len(files):.2f}" for t in taus)
            + " |")


def profile_png(rows, prefix):
    """Dolan-More profile of whole-process times (failures never count)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(no matplotlib: profile PNG not written)")
        return
    files, solvers, ratios = profile_ratios(rows, "process")
    finite = [x for v in ratios.values() for x in v if math.isfinite(x)]
    tau_max = max(finite + [2.0]) * 1.1
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for s in solvers:
        xs = sorted(x for x in ratios[s] if math.isfinite(x))
        taus = [1.0] + xs + [tau_max]
        frac = [sum(1 for x in xs if x <= tau) / len(files) for tau in taus]
        ax.step(taus, frac, where="post", label=s,
                linestyle="-" if s.startswith("cpkit") else "--")
    ax.set_xscale("log")
    ax.set_xlabel("tau (whole-process time / best on the file; solved: |q|-relative natural map <= T)")
    ax.set_ylabel(f"fraction of the {len(files)} files solved")
    ax.set_ylim(0, 1.02)
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_profile.png", dpi=110)
    print(f"wrote {prefix}_profile.png")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        child(sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5]))
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--cpkit", default=os.path.join(ROOT, "build", "apps", "cpkit"))
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per solve (process)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per solve (median times)")
    ap.add_argument("--out", default="", help="PREFIX for PREFIX.csv and PREFIX_profile.png")
    a = ap.parse_args()
    try:
        import siconos.numerics  # noqa: F401
    except ImportError as e:
        print(f"SKIPPED: siconos.numerics is not importable ({e}; Debian: python3-siconos)")
        return 77
    if not os.access(a.cpkit, os.X_OK):
        print(f"SKIPPED: no cpkit program at {a.cpkit} (build cpkit_cli or pass --cpkit)")
        return 77
    files = a.files or sorted(glob.glob(os.path.join(ROOT, "tests", "data", "fclib", "local", "*")))
    missing = [f for f in files if not os.path.isfile(f)]
    if missing:
        print(f"bench_friction_siconos: no such file: {', '.join(missing)}", file=sys.stderr)
        return 2
    files = [f for f in files if f.endswith((".dat", ".hdf5"))]
    T = a.tol
    self_check_projection()
    print(f"tolerance T = {T:g} on |r - P_K(r - u_hat)| / |q| (checked here with numpy); "
          f"timeout {a.timeout:g} s per solve; median of {a.repeat} runs; load {os.getloadavg()[0]:.1f}")
    # Fixed start-up costs, for reading the process times: an empty Siconos child (Python,
    # numpy, scipy, siconos.numerics imported) and `cpkit --version`.
    base_s = sorted(run([sys.executable, "-c", "import numpy, scipy.sparse, siconos.numerics"],
                        a.timeout)[2] for _ in range(3))[1]
    base_c = sorted(run([a.cpkit, "--version"], a.timeout)[2] for _ in range(3))[1]
    print(f"start-up alone (median of 3): Python + siconos.numerics import {fmt_t(base_s)}, "
          f"`cpkit --version` {fmt_t(base_c)}")
    rows, per_file = [], []
    for path in files:
        name = os.path.basename(path)
        W, q, mu = read_data(path)
        nc = q.size // 3
        print(f"\n## {name}: {nc} contacts, W {W.shape[0]} x {W.shape[1]}, {W.nnz} nonzeros"
              + ("  [>= 50 contacts]" if nc >= 50 else ""))
        print("| code | solver | claim | check: rel. to |q| | rel. to max | cpkit unit-free | "
              "success | iterations | process | solve | note |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        runs = [("cpkit", s, repeated(lambda: run_cpkit(a.cpkit, path, s, T, a.timeout), a.repeat))
                for s in CPKIT_SOLVERS]
        runs += [("siconos", s, repeated(lambda: run_siconos(path, s, T, a.timeout), a.repeat))
                 for s in SICONOS_SOLVERS]
        for code, s, res in runs:
            rq, rm = check(W, q, mu, res["r"])
            ok = rq <= T
            claimed = res["claim"] in ("solved", "info 0")
            note = res["note"]
            if claimed and not ok:
                note = (note + "; " if note else "") + "CLAIMED SUCCESS, CHECK REFUSES" + (
                    " (passes relative to max(|q|,|r|,|u|): |q| is the stricter unit here)"
                    if rm <= T else "")
            print(f"| {code} | {s} | {res['claim']} | {fmt_e(rq)} | {fmt_e(rm)} | "
                  f"{fmt_e(res['unit_free']) if code == 'cpkit' else ''} | "
                  f"{'yes' if ok else 'NO'} | {res['iterations']} | {fmt_t(res['process'])} | "
                  f"{fmt_t(res['solve'])} | {note} |")
            rows.append({"file": name, "contacts": nc, "code": code, "solver": s,
                         "claim": res["claim"], "claimed": int(claimed), "relative_q": rq,
                         "relative_max": rm, "unit_free": res["unit_free"], "success": int(ok),
                         "iterations": res["iterations"], "process": res["process"],
                         "solve": res["solve"], "note": note})
        sys.stdout.flush()
        per_file.append((name, nc, rows[-len(runs):]))

    print("\n## success counts (independent check, T = %g), over %d files" % (T, len(files)))
    print("| code | solver | successes | claimed | claimed but refused | median process | "
          "median solve (successes) |")
    print("|---|---|---|---|---|---|---|")
    for code, solvers in (("cpkit", CPKIT_SOLVERS), ("siconos", SICONOS_SOLVERS)):
        for s in solvers:
            mine = [r for r in rows if r["code"] == code and r["solver"] == s]
            ok = [r for r in mine if r["success"]]
            wrong = sum(1 for r in mine if r["claimed"] and not r["success"])
            print(f"| {code} | {s} | {len(ok)}/{len(mine)} | {sum(r['claimed'] for r in mine)} | "
                  f"{wrong} | {fmt_t(float(np.median([r['process'] for r in mine])))} | "
                  f"{fmt_t(float(np.median([r['solve'] for r in ok]))) if ok else '-'} |")

    print("\n## per file: best successful cpkit / best successful Siconos")
    print("| file | contacts | best cpkit (process, solve) | best Siconos (process, solve) | "
          "ratio process | ratio solve |")
    print("|---|---|---|---|---|---|")
    for name, nc, rs in per_file:
        def best(code, key):
            ok = [r for r in rs if r["code"] == code and r["success"] and math.isfinite(r[key])]
            return min(ok, key=lambda r: r[key]) if ok else None
        cp, sp_, cs, ss = best("cpkit", "process"), best("siconos", "process"), \
            best("cpkit", "solve"), best("siconos", "solve")

        def desc(p, s):
            return (f"{p['solver']} {fmt_t(p['process'])}, {s['solver']} {fmt_t(s['solve'])}"
                    if p else "none")
        rp = f"{cp['process'] / sp_['process']:.2f}" if cp and sp_ else "-"
        rsv = f"{cs['solve'] / ss['solve']:.2f}" if cs and ss and ss["solve"] > 0 else "-"
        flag = " **(>= 50)**" if nc >= 50 else ""
        print(f"| {name} | {nc}{flag} | {desc(cp, cs)} | {desc(sp_, ss)} | {rp} | {rsv} |")

    profile_table(rows, "process")
    profile_table(rows, "solve")

    if a.out:
        with open(a.out + ".csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        print(f"\nwrote {a.out}.csv")
        profile_png(rows, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

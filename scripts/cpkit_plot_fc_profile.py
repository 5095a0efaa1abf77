#!/usr/bin/python3
"""Draw a Dolan-More performance profile from `cpkit fc bench`'s CSV.

Usage: /usr/bin/python3 cpkit_plot_fc_profile.py --csv PREFIX.csv --out PREFIX.png
A (file, solver) counts as solved only when its status is solved or solved_inaccurate (cpkit's
unit-free verdict); its time is `seconds` (floored at 1e-7 s). For each file the ratio is the
solver's time over the fastest solver's; files no solver solved are left out (and counted in the
title). Exit 5 when matplotlib is missing, 2 on bad arguments or an unreadable CSV.
"""
import argparse
import csv
import sys


def ratios(path):
    """{solver: [ratio per file]}, the solvers in CSV order, and the files no solver solved."""
    times, solvers = {}, []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["solver"] not in solvers:
                solvers.append(row["solver"])
            ok = row["status"] in ("solved", "solved_inaccurate")
            t = max(float(row["seconds"]), 1e-7) if ok else float("inf")
            times.setdefault(row["file"], {})[row["solver"]] = t
    out = {s: [] for s in solvers}
    unsolved = 0
    for row in times.values():
        best = min(row.values())
        if best == float("inf"):
            unsolved += 1
            continue
        for s in solvers:
            out[s].append(row.get(s, float("inf")) / best)
    return out, solvers, unsolved, len(times)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--csv", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
        return 5
    try:
        rat, solvers, unsolved, files = ratios(a.csv)
    except (OSError, KeyError, ValueError) as e:
        print(f"cannot read {a.csv}: {e}", file=sys.stderr)
        return 2
    counted = files - unsolved
    finite = [x for v in rat.values() for x in v if x < float("inf")]
    top = max(max(finite) * 1.5, 2.0) if finite else 10.0
    taus, t = [], 1.0
    while t <= top:
        taus.append(t)
        t *= 10 ** 0.02
    taus.append(top)
    fig, ax = plt.subplots(figsize=(8, 5))
    for s in solvers:
        frac = [sum(1 for x in rat[s] if x <= tau) / counted if counted else 0.0 for tau in taus]
        ax.step(taus, frac, where="post", linewidth=2.5 if s == "auto" else 1.5, label=s)
    ax.set_xscale("log")
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("tau (time relative to the fastest solver on each problem)")
    ax.set_ylabel("fraction of problems solved within tau")
    ax.set_title(f"Dolan-More performance profile, {counted} problems"
                 + (f" ({unsolved} solved by no solver, left out)" if unsolved else ""), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

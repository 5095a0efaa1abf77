#!/usr/bin/python3
"""Draw a Dolan-More performance profile from `cpkit fc bench`'s CSV.

Usage: /usr/bin/python3 cpkit_plot_fc_profile.py --csv PREFIX.csv --out PREFIX.png
                                                 [--tol T] [--time-limit S]
A (file, solver) counts as solved only when its status is `solved`: within the bench's --tol in
the measure named by the CSV's `measure` column (`relative_q`, |F_nat|/|q|, by default; the
unit-free verdict must accept the answer in every measure). `solved_inaccurate` (within the looser acceptable tolerance only) is
not counted, as every other status; the title says how many such rows there were. Its time is
`seconds` (floored at 1e-7 s). For each file the ratio is the solver's time over the fastest
solver's; files no solver solved are left out (and counted in the title). --tol and
--time-limit (given by `cpkit fc bench`) are written in the title. Exit 5 when matplotlib is
missing, 2 on bad arguments or an unreadable CSV.
"""
import argparse
import csv
import os
import sys

# The script's own folder (share/cpkit when installed): the one palette of every picture.
sys.path.insert(0, os.path.dirname(os.path.abspath(globals().get("__file__") or sys.argv[0])))
import cpkit_plot_colours as pc  # noqa: E402

COUNTED = ("solved",)


def ratios(path):
    """{solver: [ratio per file]}, the solvers in CSV order, the files no solver solved, the
    number of files and {status: rows} of the statuses not counted."""
    times, solvers, other = {}, [], {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["solver"] not in solvers:
                solvers.append(row["solver"])
            ok = row["status"] in COUNTED
            if not ok:
                other[row["status"]] = other.get(row["status"], 0) + 1
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
    return out, solvers, unsolved, len(times), other


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--csv", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--tol", help="the bench's --tol (for the title)")
    ap.add_argument("--time-limit", help="the bench's --time-limit in seconds (for the title)")
    a = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is missing (apt-get install python3-matplotlib)", file=sys.stderr)
        return 5
    try:
        rat, solvers, unsolved, files, other = ratios(a.csv)
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
    fig, ax = plt.subplots(figsize=(9, 5))
    for k, s in enumerate(solvers):
        frac = [sum(1 for x in rat[s] if x <= tau) / counted if counted else 0.0 for tau in taus]
        ax.step(taus, frac, where="post", linewidth=2.5 if s == "auto" else 1.5, label=s,
                color=pc.series_colour(k), linestyle="-" if k < len(pc.SERIES) else "--")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("tau (time relative to the fastest solver on each problem)")
    ax.set_ylabel("fraction of problems solved within tau")
    setting = ", ".join(x for x in (f"tol {a.tol}" if a.tol else "",
                                    f"time limit {a.time_limit} s per solve"
                                    if a.time_limit else "") if x)
    try:
        with open(a.csv, newline="") as f:
            measures = sorted({row.get("measure") or "" for row in csv.DictReader(f)} - {""})
    except OSError:
        measures = []
    decided_by = (f"{' / '.join(measures)} <= tol, accepted by the unit-free verdict" if measures
                  else "unit-free verdict <= tol")
    solved_means = (f"solved = status 'solved' ({decided_by})"
                    + (f"; not counted: {', '.join(f'{n} {s}' for s, n in sorted(other.items()))}"
                       if other else ""))
    ax.set_title(f"Dolan-More performance profile, {counted} problems"
                 + (f" ({unsolved} solved by no solver, left out)" if unsolved else "")
                 + (f"\n{setting}" if setting else "") + f"\n{solved_means}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    # Outside the axes, so that it never covers a curve.
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, title="solver",
              title_fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110, bbox_inches="tight")
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Draw a Dolan-More performance profile from bench_robustness's output.

Usage: /usr/bin/python3 scripts/plot_profiles.py DIR
Reads DIR/results.csv (recomputing DIR/profile.csv with tau up to the largest finite ratio;
failures never count) or, without it, DIR/profile.csv; writes DIR/profile.png.
Debian's matplotlib is seen by /usr/bin/python3.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The script's own folder: the one palette of every picture.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cpkit_plot_colours as pc  # noqa: E402


def profile(directory):
    """The profile from results.csv (tau up to the largest finite ratio), else profile.csv."""
    results = os.path.join(directory, "results.csv")
    if not os.path.exists(results):
        with open(os.path.join(directory, "profile.csv"), newline="") as f:
            rows = list(csv.reader(f))
        return rows[0], [[float(v) for v in r] for r in rows[1:] if r]
    times, solvers = {}, []
    with open(results, newline="") as f:
        for r in csv.DictReader(f):
            if r["solvable"] != "1":
                continue
            if r["solver"] not in solvers:
                solvers.append(r["solver"])
            t = max(float(r["seconds"]), 1e-7) if r["verified"] == "1" else float("inf")
            times.setdefault(r["problem"], {})[r["solver"]] = t
    ratios = {s: [] for s in solvers}
    for row in times.values():
        best = min(row.values())
        for s in solvers:
            ratios[s].append(row.get(s, float("inf")) / best if best < float("inf") else float("inf"))
    finite = [x for v in ratios.values() for x in v if x < float("inf")]
    top = max(finite) * 1.5 if finite else 10.0
    taus, t = [], 1.0
    while t <= top:
        taus.append(t)
        t *= 10 ** 0.05
    taus.append(top)
    data = [[tau] + [sum(1 for x in ratios[s] if x <= tau) / len(times) for s in solvers]
            for tau in taus]
    with open(os.path.join(directory, "profile.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["tau"] + solvers)
        w.writerows(data)
    return ["tau"] + solvers, data


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    directory = sys.argv[1]
    header, data = profile(directory)
    tau = [r[0] for r in data]
    fig, ax = plt.subplots(figsize=(8, 5))
    for c, name in enumerate(header[1:], start=1):
        style = "-" if not name.startswith("siconos") else "--"
        width = 2.5 if name == "auto" else 1.5
        ax.step(tau, [r[c] for r in data], where="post", linestyle=style, linewidth=width,
                label=name, color=pc.series_colour(c - 1))
    ax.set_xscale("log")
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("tau (time relative to the fastest solver on each problem)")
    ax.set_ylabel("fraction of solvable problems solved within tau")
    title = "Dolan-More performance profile (cpkit verification)"
    machine = os.path.join(directory, "machine.txt")
    if os.path.exists(machine):
        with open(machine) as f:
            cpu = f.readline().strip()
        title += "\n" + cpu
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    # Outside the axes, so that it never covers a curve.
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    fig.tight_layout()
    out = os.path.join(directory, "profile.png")
    fig.savefig(out, dpi=110, bbox_inches="tight")
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

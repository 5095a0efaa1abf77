#!/usr/bin/python3
"""Figures of an N-point `cpkit simulate` run (docs/simulation.md, "N points").

usage: cpkit_plot_system_simulation.py --csv RUN.csv --summary RUN.json --out PREFIX
Writes PREFIX_wear.png/.svg (wear depth over the points after every cycle, with the Archard
integral of the summary as markers) and PREFIX_slip.png/.svg (the solution type of every point
over the steps: stick zone and slip zones).
"""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

# The script's own folder (share/cpkit when installed); sys.argv[0] when run without __file__.
sys.path.insert(0, os.path.dirname(os.path.abspath(globals().get("__file__") or sys.argv[0])))
from cpkit_plot_colours import NO_SOLUTION, TYPE_COLOURS  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--csv", required=True)
ap.add_argument("--summary", required=True)
ap.add_argument("--out", required=True)
a = ap.parse_args()

with open(a.summary) as f:
    summary = json.load(f)
n = summary["n_points"]
rows = list(csv.DictReader(open(a.csv)))
points = list(range(1, n + 1))

fig, ax = plt.subplots(figsize=(6, 4))
cum = [0.0] * n
for c, w in enumerate(summary["wear_per_cycle"]):
    cum = [x + y for x, y in zip(cum, w)]
    ax.plot(points, cum, "-o", ms=3, label=f"after cycle {c + 1}")
ax.plot(points, summary["wear_integral"], "kx", ms=8, label="Archard integral (end)")
ax.set_xlabel("contact point")
ax.set_ylabel("wear depth $w^w$")
ax.set_title(summary["input"].get("name", "") or "wear profile")
ax.legend(fontsize=7)
fig.tight_layout()
for ext in ("png", "svg"):
    fig.savefig(f"{a.out}_wear.{ext}", dpi=120)

# Categories, so a categorical legend (not a colour bar), in the map pictures' fixed colours.
order = ["open", "separation", "stick", "slip+", "slip-"]
steps = [int(r["step"]) for r in rows]
types = [[r[f"type_{i}"] for r in rows] for i in points]
present = [t for t in order if any(t in row for row in types)]
if any(t not in order for row in types for t in row):
    present.append("other")
code = {t: k for k, t in enumerate(present)}
grid = [[code.get(t, code.get("other", 0)) for t in row] for row in types]
cols = [TYPE_COLOURS.get(t, NO_SOLUTION) for t in present]
fig, ax = plt.subplots(figsize=(7, 3))
ax.imshow(grid, aspect="auto", interpolation="nearest", cmap=ListedColormap(cols),
          norm=BoundaryNorm([k - 0.5 for k in range(len(cols) + 1)], len(cols)),
          extent=[steps[0] - 0.5, steps[-1] + 0.5, n + 0.5, 0.5])
ax.legend(handles=[Patch(facecolor=c, edgecolor="#999999",
                         label=t if t != "other" else "other (no solution)")
                   for t, c in zip(present, cols)],
          loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False,
          title="solution type", title_fontsize=8)
ax.set_yticks(points)
ax.set_xlabel("step")
ax.set_ylabel("contact point")
ax.set_title("solution type per point: stick in the middle, slip at the edges")
fig.tight_layout()
for ext in ("png", "svg"):
    fig.savefig(f"{a.out}_slip.{ext}", dpi=120, bbox_inches="tight")

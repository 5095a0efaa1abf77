#!/usr/bin/python3
"""Figures of an N-point `cpkit simulate` run (docs/simulation.md, "N points").

usage: cpkit_plot_system_simulation.py --csv RUN.csv --summary RUN.json --out PREFIX
Writes PREFIX_wear.png/.svg (wear depth over the points after every cycle, with the Archard
integral of the summary as markers) and PREFIX_slip.png/.svg (the solution type of every point
over the steps: stick zone and slip zones). Both say what the run was computed at: the points'
parameters (mu, k_a, ... from the system file the summary names) and the load (the summary's
echo of its input).
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
import cpkit_plot_colours as pc  # noqa: E402
from cpkit_plot import system_parameters  # noqa: E402

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


def load_text(inp):
    """The load of the run from the summary's echo of its input."""
    f = inp.get("fretting")
    if f:
        return ("fretting load: F_N = %g, F_T amplitude %g, period %g, %g cycles of %g steps" %
                (f.get("F_N"), f.get("amplitude"), f.get("period"), f.get("cycles"),
                 f.get("steps_per_cycle")))
    return "load from %s" % os.path.basename(inp["file"]) if inp.get("file") else ""


inp = summary["input"]
params = system_parameters(inp)
try:  # the size of A, to say which A (the file holds it)
    with open(inp["system"]) as f:
        A = json.load(f)["A"]
    params += " (%d x %d)" % (len(A), len(A[0]))
except (OSError, ValueError, KeyError, TypeError, IndexError):
    pass
caption = "\n".join(x for x in (params, load_text(inp)) if x)
name = inp.get("name", "")

fig, ax = plt.subplots(figsize=(6, 4))
cum = [0.0] * n
cycles = len(summary["wear_per_cycle"])
time_colour = plt.get_cmap(pc.TIME_CMAP)  # cycles are time: later cycles further along the map
for c, w in enumerate(summary["wear_per_cycle"]):
    cum = [x + y for x, y in zip(cum, w)]
    ax.plot(points, cum, "-o", ms=3, color=time_colour(c / max(1, cycles - 1) * 0.9),
            label=f"after cycle {c + 1}")
ax.plot(points, summary["wear_integral"], "x", color=pc.INK, ms=8, label="Archard integral (end)")
ax.set_xlabel("contact point")
ax.set_ylabel("wear depth $w^w$")
ax.set_title(((name or "wear profile") + ("\n" + caption if caption else "")), fontsize=8)
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
cols = [pc.TYPE_COLOURS.get(t, pc.NO_SOLUTION) for t in present]
fig, ax = plt.subplots(figsize=(7, 3))
ax.imshow(grid, aspect="auto", interpolation="nearest", cmap=ListedColormap(cols),
          norm=BoundaryNorm([k - 0.5 for k in range(len(cols) + 1)], len(cols)),
          extent=[steps[0] - 0.5, steps[-1] + 0.5, n + 0.5, 0.5])
ax.legend(handles=[Patch(facecolor=c, edgecolor=pc.EDGE,
                         label=t if t != "other" else "other (no solution)")
                   for t, c in zip(present, cols)],
          loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False,
          title="solution type", title_fontsize=8)
ax.set_yticks(points)
ax.set_xlabel("step")
ax.set_ylabel("contact point")
ax.set_title("solution type per point over the steps" + ("\n" + caption if caption else ""),
             fontsize=8)
fig.tight_layout()
for ext in ("png", "svg"):
    fig.savefig(f"{a.out}_slip.{ext}", dpi=120, bbox_inches="tight")

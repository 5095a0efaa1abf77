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

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

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

codes = {"open": 0, "separation": 0, "stick": 1, "slip+": 2, "slip-": 3}
steps = [int(r["step"]) for r in rows]
grid = [[codes.get(r[f"type_{i}"], 0) for r in rows] for i in points]
fig, ax = plt.subplots(figsize=(7, 3))
im = ax.imshow(grid, aspect="auto", interpolation="nearest", cmap="viridis", vmin=0, vmax=3,
               extent=[steps[0], steps[-1], n + 0.5, 0.5])
cb = fig.colorbar(im, ticks=[0, 1, 2, 3])
cb.ax.set_yticklabels(["open/sep.", "stick", "slip+", "slip-"])
ax.set_xlabel("step")
ax.set_ylabel("contact point")
ax.set_title("solution type per point: stick in the middle, slip at the edges")
fig.tight_layout()
for ext in ("png", "svg"):
    fig.savefig(f"{a.out}_slip.{ext}", dpi=120)

#!/usr/bin/python3
"""Draws the maps written by `cpkit map --out PREFIX` (docs/maps.md).

usage: cpkit_plot.py PREFIX.json [--out PREFIX2] [--formats png,svg]

Reads the JSON summary and the CSV files it names (paths relative to the JSON file) and writes
PREFIX.png and PREFIX.svg:
  direction        a polar figure in the style of Fig. 5 of Stromberg, Johansson & Klarbring
                   (1996): one coloured ring per solution type over the directions where that
                   type exists, the number of solutions per sector, the critical directions;
  param-direction  the parameter x direction map coloured by the solution count (left) and by
                   the combination of solution types (right), with the analytic critical values
                   (a11 = mu|a12| in state b, Lambda = 0 in state d) and the exact critical
                   directions drawn over it;
  param-param      unique / non-unique / no-solution / none-and-several classes with the analytic critical curve;
  N-point maps     (`cpkit map --system`) param-direction: the count per cell (left) and the
                   point-type pattern, the type tuples present (right); param-param: the class
                   over all directions (left) and the union of the patterns (right);
  3-D maps         (`cpkit map --system` with "dim": 3) sphere, param-direction, param-param:
                   the count per cell (left) and the solution types (right), cells not proved
                   complete marked.
Exit codes: 0 ok, 2 bad input, 5 matplotlib is not available (the data is unaffected).
Run it with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import csv
import json
import math
import os
import sys

EXIT_BAD_INPUT = 2
EXIT_NO_MATPLOTLIB = 5

# The script's own folder (share/cpkit when installed); sys.argv[0] when run without __file__.
sys.path.insert(0, os.path.dirname(os.path.abspath(globals().get("__file__") or sys.argv[0])))
import cpkit_plot_colours as pc  # noqa: E402  (the one palette of every picture)

TYPE_ORDER = ["separation", "stick", "slip+", "slip-", "open"]  # rings of the direction map


def fail(msg, code=EXIT_BAD_INPUT):
    sys.stderr.write("cpkit_plot.py: %s\n" % msg)
    sys.exit(code)


def model_title(summary):
    """The model parameters, without the ones that vary along an axis."""
    m = summary.get("model", {})
    axes = {summary.get(k, {}).get("param") for k in ("axis", "axis2")}
    if "kappa" in axes or "P_N" in axes or "k_a" in axes or "P_s" in axes:
        axes |= {"kappa"}
    if "a12/a11" in axes:
        axes |= {"a12"}
    parts = ["%s=%g" % (k, m[k]) for k in ("a11", "a12", "a22", "C_T", "mu")
             if k not in axes and k in m]
    if m.get("state") in ("c", "d"):
        parts += ["%s=%g" % (k, m[k]) for k in ("P_N", "kappa") if k not in axes]
        if m.get("state") == "d":
            parts.append("sgn P_T=%+d" % m.get("sgnPT"))
    if m.get("criterion") == "softening":
        parts.append("criterion (35)")
    return "state %s: %s" % (m.get("state"), ", ".join(parts))


def lambda_label(summary):
    """Legend text of the Lambda = 0 curve; with the softening criterion (35) Lambda is eqn (51)
    with mu replaced by mu_eff = mu - 2 kappa (as computed by cpkit)."""
    if summary.get("model", {}).get("criterion") == "softening":
        return r"$\Lambda=0$ (eqn 51, $\mu_{eff}=\mu-2\kappa$)"
    return r"$\Lambda=0$ (eqn 51)"


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


MAX_PIXELS = 2000  # grids larger than this per axis are drawn from every k-th row/column


def stride(n):
    return max(1, (n + MAX_PIXELS - 1) // MAX_PIXELS)


def type_names(summary):
    """Type mask -> "stick|slip+" (the CSV spelling), from the summary's type_bits."""
    bits = sorted(summary.get("type_bits", {}).items(), key=lambda kv: kv[1])

    def name(mask):
        s = "|".join(n for n, b in bits if int(mask) & b)
        return s if s else "none"
    return name


def load_param_direction(summary, base, n, tn):
    """(x, theta, counts (-1 = continuum), type names) of a param-direction map, [n, tn]."""
    import numpy as np
    files = summary["files"]
    if "count" in files:
        cnt = np.load(os.path.join(base, files["count"]), mmap_mode="r")
        typ = np.load(os.path.join(base, files["types"]), mmap_mode="r")
        xs = np.load(os.path.join(base, files["x"]))
        th = np.load(os.path.join(base, files["theta"]))
        if cnt.shape != (n, tn) or typ.shape != (n, tn):
            fail("%s has shape %s, the summary says (%d, %d)" % (files["count"], cnt.shape, n, tn))
        si, sj = stride(n), stride(tn)
        typ = np.asarray(typ[::si, ::sj])
        name = type_names(summary)
        names = np.vectorize(name, otypes=[object])(typ)
        return xs[::si], th[::sj], np.asarray(cnt[::si, ::sj]).astype(int), names
    rows = read_csv(os.path.join(base, files["csv"]))[1:]
    if len(rows) != n * tn:
        fail("CSV has %d cells, the summary says %d" % (len(rows), n * tn))
    xs = np.array([float(rows[i * tn][0]) for i in range(n)])
    th = np.array([float(rows[j][1]) for j in range(tn)])
    cnt = np.array([-1 if r[2] == "inf" else int(r[2]) for r in rows]).reshape(n, tn)
    names = np.array([r[3] for r in rows], dtype=object).reshape(n, tn)
    return xs, th, cnt, names


def load_param_param(summary, base, n1, n2, classes):
    """(x, y, class index) of a param-param map, [n1, n2]."""
    import numpy as np
    files = summary["files"]
    if "class" in files:
        cls = np.load(os.path.join(base, files["class"]), mmap_mode="r")
        if cls.shape != (n1, n2):
            fail("%s has shape %s, the summary says (%d, %d)" % (files["class"], cls.shape, n1, n2))
        si, sj = stride(n1), stride(n2)
        xs = np.load(os.path.join(base, files["x"]))[::si]
        ys = np.load(os.path.join(base, files["y"]))[::sj]
        return xs, ys, np.asarray(cls[::si, ::sj]).astype(int)
    rows = read_csv(os.path.join(base, files["csv"]))[1:]
    if len(rows) != n1 * n2:
        fail("CSV has %d cells, the summary says %d" % (len(rows), n1 * n2))
    cls = np.array([classes.index(r[2]) for r in rows]).reshape(n1, n2)
    xs = np.array([float(rows[i * n2][0]) for i in range(n1)])
    ys = np.array([float(rows[j][1]) for j in range(n2)])
    return xs, ys, cls


def cell_edges(v, lo=None, hi=None):
    """Cell boundaries around the centres v (midpoints; the ends mirrored, or lo and hi)."""
    import numpy as np
    if len(v) == 1:
        return np.array([v[0] - 0.5, v[0] + 0.5])
    mid = 0.5 * (v[1:] + v[:-1])
    e = np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])
    if lo is not None:
        e[0], e[-1] = lo, hi
    return e


count_key = pc.count_key


def theta_window(lo, hi):
    """'' for the full circle, else ' in [lo, hi] rad (a to b degrees)', written after
    "theta": a zoomed map says which directions it shows."""
    if lo == 0 and abs(hi - 2 * math.pi) < 1e-12:
        return ""
    return " in [%.4g, %.4g] rad (%.4g to %.4g degrees)" % (lo, hi, math.degrees(lo),
                                                            math.degrees(hi))


def legend_below(ax, handles, ncol=1, title=None, fontsize=8):
    """A legend under the axes, below their tick labels and axis label (never over the data).
    Placed by place_legends() once the layout is final; savefig(bbox_inches="tight") then grows
    the picture to keep it whole, however long its labels."""
    if handles:
        pending = getattr(ax.figure, "_cpkit_legends", [])
        pending.append((ax, handles, dict(ncol=ncol, fontsize=fontsize, title=title,
                                          title_fontsize=fontsize, frameon=False)))
        ax.figure._cpkit_legends = pending


def place_legends(fig):
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax, handles, kw in getattr(fig, "_cpkit_legends", []):
        box = ax.get_tightbbox(renderer).transformed(fig.transFigure.inverted())
        pos = ax.get_position()
        ax.legend(handles=handles, loc="upper center",
                  bbox_to_anchor=(0.5 * (pos.x0 + pos.x1), box.y0 - 0.01),
                  bbox_transform=fig.transFigure, **kw)


def wrap(text, width=60):
    import textwrap
    return "\n".join(textwrap.wrap(text, width)) or text


def system_parameters(inp, varying=()):
    """The fixed parameters of a --system map, read from its system file (what the picture was
    computed at), without the swept ones; '' if the file cannot be read."""
    try:
        with open(inp["system"]) as f:
            sysf = json.load(f)
    except (OSError, ValueError, KeyError, TypeError):
        return ""
    varying = {str(v).split("_")[0] for v in varying if v}
    per_point = []
    for p in sysf.get("points", []):
        kv = ["state %s" % p["state"]] if "state" in p else []
        for k in ("mu", "C_T", "alpha", "k_a", "P_N", "kappa"):
            if k in p and k not in varying:
                v = p[k]
                kv.append("%s=%s" % (k, ("(" + ", ".join("%g" % x for x in v) + ")")
                                     if isinstance(v, list) else "%g" % v))
        per_point.append(", ".join(kv))
    if not per_point:
        return ""
    if len(set(per_point)) == 1:
        text = ("every point: " if len(per_point) > 1 else "") + per_point[0]
    else:
        text = "; ".join("point %d: %s" % (i + 1, t) for i, t in enumerate(per_point))
    if "coupling" in varying:
        text += " (coupling swept)"
    return text + "; A from " + os.path.basename(inp["system"])


NARROW_SECTOR_DEG = 15.0  # a sector with several solutions narrower than this gets a zoomed inset


def zoom_narrow_sector(fig, ax, summary, present, r_out):
    """An inset that unrolls the narrowest sector with several solutions (Fig. 5(b): 6.4 degrees
    wide) and its neighbours on a linear angle axis: one row per solution type, the critical
    directions as vertical lines; the zoomed range is outlined on the disc."""
    from matplotlib.patches import Wedge
    multi = [s for s in summary["sectors"] if (s["count"] == "inf" or s["count"] >= 2) and
             math.degrees(s["theta_to"] - s["theta_from"]) < NARROW_SECTOR_DEG]
    if not multi:
        return
    z = min(multi, key=lambda s: s["theta_to"] - s["theta_from"])
    d0, d1 = math.degrees(z["theta_from"]), math.degrees(z["theta_to"])
    pad = 0.6 * (d1 - d0)
    lo, hi = d0 - pad, d1 + pad
    ax.add_patch(Wedge((0, 0), r_out + 0.02, lo, hi, width=r_out - 0.3, facecolor="none",
                       edgecolor=pc.INK, linestyle="--", linewidth=0.8))
    ins = fig.add_axes([0.07, 0.70, 0.34, 0.15])
    rows = {t: k for k, t in enumerate(reversed(present))}
    full = 2 * math.pi
    for s in summary["sectors"]:
        a0, a1 = math.degrees(s["theta_from"]), math.degrees(s["theta_to"])
        for shift in (-360.0, 0.0, 360.0):  # sectors are given modulo 2 pi
            b0, b1 = max(a0 + shift, lo), min(a1 + shift, hi)
            if b1 <= b0:
                continue
            for t in s["types"]:
                ins.broken_barh([(b0, b1 - b0)], (rows[t] + 0.1, 0.8),
                                facecolors=pc.TYPE_COLOURS[t], edgecolor=pc.PAPER, linewidth=0.5)
    for c in summary["critical"]:
        th = math.degrees(c["theta"] % full)
        for v in (th - 360.0, th, th + 360.0):
            if lo <= v <= hi:
                ins.axvline(v, color=pc.INK, lw=0.8)
    ins.set_xlim(lo, hi)
    ins.set_ylim(0, len(present))
    ins.set_yticks([rows[t] + 0.5 for t in present])
    ins.set_yticklabels(present, fontsize=7)
    ins.tick_params(axis="x", labelsize=7)
    ins.set_xlabel("load direction theta (degrees)", fontsize=7, labelpad=1)
    ins.set_title("zoom (dashed on the disc): %s solutions for theta in\n(%.2f, %.2f) degrees, "
                  "a sector %.1f degrees wide" % (count_key(z["count"]), d0, d1, d1 - d0),
                  fontsize=7.5)


def plot_direction(summary, base, plt):
    from matplotlib.patches import Patch, Wedge
    fig = plt.figure(figsize=(7.2, 7.6))
    ax = fig.add_axes([0.08, 0.13, 0.84, 0.75])
    ax.set_aspect("equal")
    ax.set_xlim(-1.55, 1.55)
    ax.set_ylim(-1.55, 1.55)
    ax.axis("off")
    present = [t for t in TYPE_ORDER
               if any(t in s["types"] for s in summary["sectors"])
               or any(t in c["types"] for c in summary["critical"])]
    r0, width = 0.35, 0.16
    ring = {t: r0 + k * (width + 0.02) for k, t in enumerate(present)}
    r_out = r0 + len(present) * (width + 0.02)
    # Faint guide circles and the load axes.
    for t in present:
        ax.add_patch(Wedge((0, 0), ring[t] + width, 0, 360, width=width, facecolor=pc.FAINT,
                           edgecolor="none"))
    ax.annotate("", xy=(1.45, 0), xytext=(-1.45, 0),
                arrowprops=dict(arrowstyle="->", color=pc.AXIS, lw=0.8))
    ax.annotate("", xy=(0, 1.45), xytext=(0, -1.45),
                arrowprops=dict(arrowstyle="->", color=pc.AXIS, lw=0.8))
    ax.text(1.47, -0.08, r"$\dot F_T$", fontsize=12, ha="left")
    ax.text(0.04, 1.47, r"$\dot F_N$", fontsize=12, va="bottom")
    for s in summary["sectors"]:
        a0, a1 = math.degrees(s["theta_from"]), math.degrees(s["theta_to"])
        for t in s["types"]:
            ax.add_patch(Wedge((0, 0), ring[t] + width, a0, a1, width=width,
                               facecolor=pc.TYPE_COLOURS[t], edgecolor=pc.PAPER, linewidth=0.5))
        mid = 0.5 * (s["theta_from"] + s["theta_to"])
        n = s["count"]
        # The circle is filled with the count's colour (as in the count maps), its text in
        # white where that colour is dark.
        face = pc.count_colour(n)
        dark = pc.count_key(n) in ("0", "3", "4", "inf")
        label = "inf" if n == "inf" else str(n)
        ax.text((r_out + 0.12) * math.cos(mid), (r_out + 0.12) * math.sin(mid), label,
                ha="center", va="center", fontsize=13, fontweight="bold",
                color=pc.PAPER if dark else pc.INK,
                bbox=dict(boxstyle="circle,pad=0.25", facecolor=face, edgecolor=pc.INK,
                          linewidth=0.8))
    for c in summary["critical"]:
        th = c["theta"]
        ax.plot([0, 1.35 * math.cos(th)], [0, 1.35 * math.sin(th)], color=pc.INK, lw=1.0)
        # Types present on the critical direction itself: dots on the rings.
        for t in c["types"]:
            rr = ring[t] + 0.5 * width
            ax.plot([rr * math.cos(th)], [rr * math.sin(th)], "o", ms=5,
                    markerfacecolor=pc.TYPE_COLOURS[t], markeredgecolor=pc.INK, markeredgewidth=0.6)
        lab = "%s\n%.4f (%s)" % (", ".join(c["conditions"]), th, count_key(c["count"]))
        ha = "left" if math.cos(th) >= 0 else "right"
        ax.text(1.37 * math.cos(th), 1.37 * math.sin(th), lab, fontsize=7.5, ha=ha,
                va="center")
    zoom_narrow_sector(fig, ax, summary, present, r_out)
    handles = [Patch(facecolor=pc.TYPE_COLOURS[t], label=t) for t in present]
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.045), fontsize=9,
               title="solution types (one ring each, inner to outer)", title_fontsize=9,
               frameon=False, ncol=len(handles))
    fig.suptitle("Rate problem: solutions per load direction\n" + model_title(summary),
                 fontsize=10.5)
    fig.text(0.5, 0.015, "circled numbers: solutions per sector (filled in the count colours); "
             "rays: critical directions "
             "(theta in rad, count on the ray in brackets)", ha="center", fontsize=8)
    return fig


def plot_param_direction(summary, base, plt):
    import numpy as np
    from matplotlib.colors import ListedColormap, BoundaryNorm
    from matplotlib.patches import Patch
    ax_info = summary["axis"]
    n, tn = ax_info["n"], summary["theta_n"]
    xs, th, cnt_raw, typ_raw = load_param_direction(summary, base, n, tn)
    n, tn = len(xs), len(th)
    keys = sorted({str(c) if c >= 0 else "inf" for c in np.unique(cnt_raw)},
                  key=lambda k: (k == "inf", int(k) if k != "inf" else 0))
    kidx = {k: i for i, k in enumerate(keys)}
    cnt = np.vectorize(lambda c: kidx[str(c) if c >= 0 else "inf"])(cnt_raw).T
    combos = sorted({str(t) for t in np.unique(typ_raw)})
    cidx = {c: i for i, c in enumerate(combos)}
    typ = np.vectorize(lambda t: cidx[str(t)])(typ_raw).T
    edges = cell_edges
    t_lo, t_hi = summary.get("theta_from", 0.0), summary.get("theta_to", 2 * math.pi)
    xe, te = edges(xs), edges(th, t_lo, t_hi)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.6), sharey=True)
    cmap = ListedColormap([pc.count_colour(k) for k in keys])
    norm = BoundaryNorm(np.arange(len(keys) + 1) - 0.5, len(keys))
    axes[0].pcolormesh(xe, te, cnt, cmap=cmap, norm=norm, shading="flat", rasterized=True)
    tcols = [pc.combination_colour(c) for c in combos]  # fixed per combination (all pictures)
    axes[1].pcolormesh(xe, te, typ, cmap=ListedColormap(tcols),
                       norm=BoundaryNorm(np.arange(len(combos) + 1) - 0.5, len(combos)),
                       shading="flat", rasterized=True)
    crit_pts = []
    crit_vals = summary.get("critical_values", [])
    if "critical_csv" in summary.get("files", {}):
        for r in read_csv(os.path.join(base, summary["files"]["critical_csv"]))[1:]:
            if r[0] == "direction":
                crit_pts.append((float(r[1]), float(r[2])))
    names = {"D+=0": r"$a_{11}=\mu a_{12}$ ($D_+=0$)", "D-=0": r"$a_{11}=-\mu a_{12}$ ($D_-=0$)",
             "Lambda=0": lambda_label(summary)}
    for a in axes:
        if crit_pts:
            a.plot([p[0] for p in crit_pts], [p[1] for p in crit_pts], ".", ms=1.2,
                   color=pc.INK, label="critical directions (exact)")
        for k, cv in enumerate(crit_vals):
            a.axvline(cv["x"], color=pc.INK, lw=1.4, ls="--",
                      label=names.get(cv["name"], cv["name"]) + " at %s = %.6g" %
                      (ax_info["param"], cv["x"]) if k < 4 else None)
        a.set_xlabel(ax_info["param"])
        a.set_xlim(xe[0], xe[-1])
        a.set_ylim(t_lo, t_hi)
        if t_lo == 0 and abs(t_hi - 2 * math.pi) < 1e-12:
            a.set_yticks([0, math.pi / 2, math.pi, 1.5 * math.pi, 2 * math.pi])
            a.set_yticklabels(["0", r"$\pi/2$", r"$\pi$", r"$3\pi/2$", r"$2\pi$"])
    axes[0].set_ylabel(r"load direction $\theta$ ($\dot F_T=\cos\theta$, $\dot F_N=\sin\theta$)")
    axes[0].set_title("number of solutions")
    axes[1].set_title("solution types")
    h0 = [Patch(facecolor=pc.count_colour(k), edgecolor=pc.EDGE, label=pc.count_label(k))
          for k in keys]
    l0, lab0 = axes[0].get_legend_handles_labels()
    legend_below(axes[0], h0 + l0, ncol=2)
    h1 = [Patch(facecolor=tcols[i], edgecolor=pc.EDGE, label=pc.combination_label(c))
          for i, c in enumerate(combos)]
    legend_below(axes[1], h1, ncol=2)
    fig.suptitle("Rate problem: %s x load direction (%d x %d cells, %s route), each cell at "
                 "one load direction theta%s\n%s" %
                 (ax_info["param"], n, tn, summary.get("method", "enumerate"),
                  theta_window(t_lo, t_hi), model_title(summary)), fontsize=10.5)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    return fig


def plot_param_param(summary, base, plt):
    import numpy as np
    from matplotlib.colors import ListedColormap, BoundaryNorm
    from matplotlib.patches import Patch
    a1, a2 = summary["axis"], summary["axis2"]
    classes = pc.CLASS_ORDER
    xs, ys, cls = load_param_param(summary, base, a1["n"], a2["n"], classes)
    n1, n2 = len(xs), len(ys)
    cls = cls.T
    edges = cell_edges
    fig, ax = plt.subplots(figsize=(7.5, 6))
    ax.pcolormesh(edges(xs), edges(ys), cls,
                  cmap=ListedColormap([pc.CLASS_COLOURS[c] for c in classes]),
                  norm=BoundaryNorm([k - 0.5 for k in range(len(classes) + 1)], len(classes)), shading="flat", rasterized=True)
    handles = [Patch(facecolor=pc.CLASS_COLOURS[c], edgecolor=pc.EDGE, label=pc.CLASS_LABELS[c])
               for c in classes if (cls == classes.index(c)).any()]
    if "critical_csv" in summary.get("files", {}):
        pts = [r for r in read_csv(os.path.join(base, summary["files"]["critical_csv"]))[1:]]
        for name in sorted({p[0] for p in pts}):
            q = [(float(p[1]), float(p[2])) for p in pts if p[0] == name]
            lab = {"Lambda=0": lambda_label(summary), "D+=0": r"$a_{11} = \mu a_{12}$",
                   "D-=0": r"$a_{11} = -\mu a_{12}$"}.get(name, name)
            ax.plot([p[0] for p in q], [p[1] for p in q], ".", ms=1.5, color=pc.INK)
            handles.append(plt.Line2D([], [], color=pc.INK, marker=".", ls="", label=lab))
    ax.set_xlim(edges(xs)[0], edges(xs)[-1])
    ax.set_ylim(edges(ys)[0], edges(ys)[-1])
    ax.set_xlabel(a1["param"])
    ax.set_ylabel(a2["param"])
    legend_below(ax, handles, ncol=1)
    ax.set_title("Rate problem, each cell classified over ALL load directions theta in "
                 "[0, 2pi) (%d x %d cells)\n%s" % (n1, n2, model_title(summary)), fontsize=10)
    fig.tight_layout()
    return fig


def load_system_grid(summary, base):
    """(x, y, first array (count or class code), pattern id) of an N-point grid map, [n, m]."""
    import numpy as np
    files, inp = summary["files"], summary["input"]
    pd = summary["kind"] == "param-direction"
    n, m = inp["n"], inp["theta_n"] if pd else inp["n2"]
    first = "count" if pd else "class"
    if first in files:
        a = np.load(os.path.join(base, files[first]), mmap_mode="r")
        pat = np.load(os.path.join(base, files["pattern"]), mmap_mode="r")
        if a.shape != (n, m) or pat.shape != (n, m):
            fail("%s has shape %s, the summary says (%d, %d)" % (files[first], a.shape, n, m))
        si, sj = stride(n), stride(m)
        xs = np.load(os.path.join(base, files["x"]))[::si]
        ys = np.load(os.path.join(base, files["theta" if pd else "y"]))[::sj]
        return xs, ys, np.asarray(a[::si, ::sj]).astype(int), np.asarray(pat[::si, ::sj]).astype(int)
    rows = read_csv(os.path.join(base, files["csv"]))[1:]
    if len(rows) != n * m:
        fail("CSV has %d cells, the summary says %d" % (len(rows), n * m))
    classes = pc.CLASS_ORDER
    xs = np.array([float(rows[i * m][0]) for i in range(n)])
    ys = np.array([float(rows[j][1]) for j in range(m)])
    if pd:
        a = np.array([-1 if r[2] == "inf" else int(r[2]) for r in rows])
    else:
        a = np.array([classes.index(r[2]) for r in rows])
    pat = np.array([int(r[-1]) for r in rows])
    return xs, ys, a.reshape(n, m), pat.reshape(n, m)


def plot_system_grid(summary, base, plt):
    """N points: the count (param-direction) or class (param-param) per cell, left, and the
    point-type pattern per cell (the type tuples present), right."""
    import numpy as np
    from matplotlib.colors import ListedColormap, BoundaryNorm
    from matplotlib.patches import Patch
    inp = summary["input"]
    pd = summary["kind"] == "param-direction"
    xs, ys, a, pat = load_system_grid(summary, base)
    edges = cell_edges
    if pd:
        y_lo, y_hi = inp.get("theta_from", 0.0), inp.get("theta_to", 2 * math.pi)
        xe, ye = edges(xs), edges(ys, y_lo, y_hi)
    else:
        xe, ye = edges(xs), edges(ys)
    fig, axes = plt.subplots(1, 2, figsize=(14, 6), sharey=True)
    if pd:
        keys = sorted({count_key(int(c)) for c in np.unique(a)},
                      key=lambda k: (k == "inf", int(k) if k != "inf" else 0))
        kidx = {k: i for i, k in enumerate(keys)}
        left = np.vectorize(lambda c: kidx[count_key(int(c))])(a).T
        cols = [pc.count_colour(k) for k in keys]
        h0 = [Patch(facecolor=cols[i], edgecolor=pc.EDGE, label=pc.count_label(k))
              for i, k in enumerate(keys)]
        axes[0].set_title("number of solutions")
    else:
        classes = pc.CLASS_ORDER
        present = sorted({int(c) for c in np.unique(a)})
        kidx = {c: i for i, c in enumerate(present)}
        left = np.vectorize(lambda c: kidx[int(c)])(a).T
        cols = [pc.CLASS_COLOURS[classes[c]] for c in present]
        h0 = [Patch(facecolor=cols[i], edgecolor=pc.EDGE, label=pc.CLASS_LABELS[classes[c]])
              for i, c in enumerate(present)]
        axes[0].set_title("over all load directions")
    axes[0].pcolormesh(xe, ye, left, cmap=ListedColormap(cols),
                       norm=BoundaryNorm(np.arange(len(cols) + 1) - 0.5, len(cols)),
                       shading="flat", rasterized=True)
    legend_below(axes[0], h0, ncol=1)
    # Patterns: each its own colour, fixed by the pattern itself (cpkit_plot_colours.py), so the
    # same pattern has the same colour in every picture; every label in full.
    table = {p["id"]: p for p in summary["patterns"]}
    shown_ids = sorted({int(p) for p in np.unique(pat)},
                       key=lambda i: pc.pattern_key(table[i]["types"] if i in table else []))
    by_key = pc.pattern_colours([table[i]["types"] if i in table else [] for i in shown_ids])
    colour, labels = {}, {}
    for i in shown_ids:
        types = table[i]["types"] if i in table else []
        colour[i] = by_key[pc.pattern_key(types)]
        labels[i] = "no solution" if not types else wrap(", ".join(pc.pattern_key(types)), 75)
    order = {i: n for n, i in enumerate(shown_ids)}
    right = np.vectorize(lambda p: order[int(p)])(pat).T
    axes[1].pcolormesh(xe, ye, right, cmap=ListedColormap([colour[i] for i in shown_ids]),
                       norm=BoundaryNorm(np.arange(len(shown_ids) + 1) - 0.5, len(shown_ids)),
                       shading="flat", rasterized=True)
    seen, h1 = set(), []
    for i in shown_ids:
        if labels[i] in seen:
            continue
        seen.add(labels[i])
        h1.append(Patch(facecolor=colour[i], edgecolor=pc.EDGE, label=labels[i]))
    legend_below(axes[1], h1, ncol=1, fontsize=7,
                 title="type tuples present in a cell (point 1/point 2/...)")
    axes[1].set_title("point-type pattern" + ("" if pd else " (union over directions)"))
    for ax in axes:
        ax.set_xlabel(inp["param"])
        ax.set_xlim(xe[0], xe[-1])
        ax.set_ylim(ye[0], ye[-1])
    if pd:
        axes[0].set_ylabel(r"load direction $\theta$ ($\dot F = \cos\theta\, e_1 + \sin\theta\, e_2$)")
        if y_lo == 0 and abs(y_hi - 2 * math.pi) < 1e-12:
            axes[0].set_yticks([0, math.pi / 2, math.pi, 1.5 * math.pi, 2 * math.pi])
            axes[0].set_yticklabels(["0", r"$\pi/2$", r"$\pi$", r"$3\pi/2$", r"$2\pi$"])
    else:
        axes[0].set_ylabel(inp["param2"])
    e = inp.get("patterns") or []
    load = (r"load $\dot F = \cos\theta\, e_1 + \sin\theta\, e_2$" +
            (", e1 = (%s), e2 = (%s)" % tuple(", ".join("%g" % v for v in ei) for ei in e[:2])
             if len(e) >= 2 else ""))
    load += (": each cell at one direction theta" + theta_window(y_lo, y_hi) if pd else
             ": each cell classified over ALL directions theta in [0, 2pi)")
    fixed = system_parameters(inp, (inp.get("param"), inp.get("param2")))
    fig.suptitle("%s: %d points, %s (%d x %d cells%s)\n%s%s" %
                 (inp.get("name") or os.path.basename(inp["system"]), inp["n_points"],
                  "parameter x load direction" if pd else "parameter x parameter",
                  a.shape[0], a.shape[1], "" if summary.get("complete", True)
                  else "; NOT proved complete", load, ("\n" + fixed) if fixed else ""),
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    return fig


def plot_map_3d(summary, base, plt):
    """3-D systems ("dim": 3): the count per cell (left) and the solution types of the loaded
    point (right); cells not proved complete are marked with black dots. Sphere maps: the
    azimuth g horizontally, the polar angle b from +N vertically (+N at the top)."""
    import numpy as np
    from matplotlib.colors import ListedColormap, BoundaryNorm
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D
    files, inp, kind = summary["files"], summary["input"], summary["kind"]
    load = lambda k: np.load(os.path.join(base, files[k]))
    xs, ys = load("x"), load("y")
    cnt, typ, comp = load("count"), load("types"), load("complete")
    if cnt.shape != (len(xs), len(ys)):
        fail("the arrays of %s do not match its axes" % files["json"])
    if kind == "sphere":
        xe = cell_edges(xs, inp.get("beta_from", 0.0), inp.get("beta_to", math.pi))
        ye = cell_edges(ys)
    elif kind == "param-direction":
        xe = cell_edges(xs)
        ye = cell_edges(ys, inp.get("theta_from", 0.0), inp.get("theta_to", 2 * math.pi))
    else:
        xe, ye = cell_edges(xs), cell_edges(ys)
    fig, axes = plt.subplots(1, 2, figsize=(14, 6), sharey=True)
    # sphere: rows b drawn vertically (+N at the top), columns g horizontally
    def mesh(ax, values, cols):
        norm = BoundaryNorm(np.arange(len(cols) + 1) - 0.5, len(cols))
        if kind == "sphere":
            ax.pcolormesh(ye, xe, values, cmap=ListedColormap(cols), norm=norm, shading="flat",
                          rasterized=True)
        else:
            ax.pcolormesh(xe, ye, values.T, cmap=ListedColormap(cols), norm=norm,
                          shading="flat", rasterized=True)
    keys = sorted({count_key(int(c)) for c in np.unique(cnt)},
                  key=lambda k: (k == "inf", int(k) if k != "inf" else 0))
    kidx = {k: i for i, k in enumerate(keys)}
    cols = [pc.count_colour(k) for k in keys]
    mesh(axes[0], np.vectorize(lambda c: kidx[count_key(int(c))])(cnt), cols)
    h0 = [Patch(facecolor=cols[i], edgecolor=pc.EDGE, label=pc.count_label(k))
          for i, k in enumerate(keys)]
    names = ["open", "separation", "stick", "slip"]
    masks = sorted(int(m) for m in np.unique(typ))
    members = lambda m: [n for b, n in enumerate(names) if m & (1 << b)]
    # fixed per combination, the same colours and labels as the 2-D maps' (cpkit_plot_colours.py)
    tcols = [pc.combination_colour(members(m)) for m in masks]
    midx = {m: i for i, m in enumerate(masks)}
    mesh(axes[1], np.vectorize(lambda m: midx[int(m)])(typ), tcols)
    h1 = [Patch(facecolor=tcols[i], edgecolor=pc.EDGE, label=pc.combination_label(members(m)))
          for i, m in enumerate(masks)]
    bad = np.argwhere(comp == 0)
    if len(bad):
        for ax in axes:
            if kind == "sphere":
                ax.plot(ys[bad[:, 1]], xs[bad[:, 0]], ".", color=pc.INK, ms=3)
            else:
                ax.plot(xs[bad[:, 0]], ys[bad[:, 1]], ".", color=pc.INK, ms=3)
        for h in (h0, h1):
            h.append(Line2D([], [], color=pc.INK, marker=".", ls="",
                            label="not proved complete (%d cells)" % len(bad)))
    legend_below(axes[0], h0, ncol=2)
    legend_below(axes[1], h1, ncol=2, title="types at point %d" % inp.get("point", 1))
    axes[0].set_title("number of solutions")
    axes[1].set_title("solution types")
    for ax in axes:
        if kind == "sphere":
            ax.set_xlim(ye[0], ye[-1])
            ax.set_ylim(xe[-1], xe[0])  # +N (b = 0) at the top
            ax.set_xlabel(r"azimuth $g$ from $+T_X$ towards $+T_Y$ (rad)")
            ax.set_xticks([-math.pi, -math.pi / 2, 0, math.pi / 2, math.pi])
            ax.set_xticklabels([r"$-\pi$", r"$-\pi/2$", "0", r"$\pi/2$", r"$\pi$"])
        else:
            ax.set_xlim(xe[0], xe[-1])
            ax.set_ylim(ye[0], ye[-1])
            ax.set_xlabel(inp["param"])
    if kind == "sphere":
        axes[0].set_ylabel(r"polar angle $b$ from $+N$ (rad)")
        axes[0].text(0.99, 0.01, r"$\dot F = (\sin b\cos g, \sin b\sin g, \cos b)$",
                     transform=axes[0].transAxes, ha="right", va="bottom", fontsize=9)
    elif kind == "param-direction":
        axes[0].set_ylabel(r"$\theta$: $\dot F = (\cos\theta\cos G, \cos\theta\sin G, "
                           r"\sin\theta)$, G = %.4g" % inp.get("gamma", 0.0))
    else:
        axes[0].set_ylabel(inp["param2"])
    route = ("faceted, %d facets" % inp["facets"]) if inp.get("facets") else "exact"
    if kind == "param-param":
        load = ("each cell at ONE load direction dF = (%s) (not over all directions)" %
                ", ".join("%g" % v for v in inp.get("dF", [])))
    elif kind == "param-direction":
        load = "each cell at one load direction theta, in the plane of azimuth G = %.4g%s" % (
            inp.get("gamma", 0.0), theta_window(inp.get("theta_from", 0.0),
                                                inp.get("theta_to", 2 * math.pi)))
    else:
        load = "each cell at one load direction (b, g)"
    fixed = system_parameters(inp, (inp.get("param"), inp.get("param2")))
    fig.suptitle("%s: %s map of %d 3-D point%s, %s (%d x %d cells%s)\n%s%s" %
                 (inp.get("name") or os.path.basename(inp["system"]), kind, inp["n_points"],
                  "" if inp["n_points"] == 1 else "s", route, cnt.shape[0], cnt.shape[1],
                  "" if summary.get("complete", True)
                  else "; %d NOT proved complete" % summary.get("incomplete_cells", 0),
                  load, ("\n" + fixed) if fixed else ""), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.9))
    return fig


def main(argv):
    args = argv[1:]
    if not args or args[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if args else EXIT_BAD_INPUT
    src = args[0]
    out, formats = None, ["png", "svg"]
    i = 1
    while i < len(args):
        if args[i] == "--out" and i + 1 < len(args):
            out = args[i + 1]
            i += 2
        elif args[i] == "--formats" and i + 1 < len(args):
            formats = [f for f in args[i + 1].split(",") if f]
            i += 2
        else:
            fail("unknown argument '%s'" % args[i])
    try:
        with open(src) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read %s: %s" % (src, e))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy  # noqa: F401
    except ImportError as e:
        sys.stderr.write("cpkit_plot.py: matplotlib/numpy not available to %s (%s); install "
                         "python3-matplotlib (Debian) and run with /usr/bin/python3\n" %
                         (sys.executable, e))
        return EXIT_NO_MATPLOTLIB
    base = os.path.dirname(os.path.abspath(src))
    if out is None:
        out = src[:-5] if src.endswith(".json") else src
    kind = summary.get("kind")
    if summary.get("dim") == 3:
        fig = plot_map_3d(summary, base, plt)
    elif isinstance(summary.get("input"), dict) and "system" in summary["input"] and \
            kind in ("param-direction", "param-param"):
        fig = plot_system_grid(summary, base, plt)
    elif kind == "direction":
        fig = plot_direction(summary, base, plt)
    elif kind == "param-direction":
        fig = plot_param_direction(summary, base, plt)
    elif kind == "param-param":
        fig = plot_param_param(summary, base, plt)
    else:
        fail("unknown map kind %r in %s" % (kind, src))
    place_legends(fig)
    for fmt in formats:
        fig.savefig("%s.%s" % (out, fmt), dpi=110, bbox_inches="tight")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

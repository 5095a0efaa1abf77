#!/usr/bin/python3
"""Draws the figures of a 3-D fretting run written by `cpkit simulate --system FILE` with a
"dim": 3 file (docs/contact_3d.md, "Fretting with an elliptic load orbit").

usage: cpkit_plot_fretting_3d.py --csv SERIES.csv [--summary SUMMARY.json] --out PREFIX
                                 [--formats png,svg]

Writes, for each format:
  PREFIX_orbit.*  three views of the tangential plane: the load orbit F_T; the traction path
                  P_T with the friction ellipse ||P_T|| = mu P_N (half-axes mu P_N alpha_X,
                  mu P_N alpha_Y, at the largest and the last P_N; needs the summary); the slip
                  path w_T^i (coloured by time; segments without slip, if any, grey);
  PREFIX_wear.*   the wear depth against cycles, and the wear per cycle split into the parts
                  due to slip in X and in Y (wear_X_per_cycle, wear_Y_per_cycle of the summary).
Exit codes: 0 ok, 2 bad input, 5 matplotlib is not available (the data is unaffected).
Run it with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import math
import sys

import cpkit_plot_colours as pc
import cpkit_plot_series as series

NUMERIC = ["step", "t", "F_TX", "F_TY", "F_N", "P_TX", "P_TY", "P_N", "w_TiX", "w_TiY",
           "lambda", "w_w", "cycle"]


SCRIPT = "cpkit_plot_fretting_3d.py"


def main(argv):
    args = series.parse_args(SCRIPT, argv, __doc__)
    s = series.read_series(SCRIPT, args["csv"], NUMERIC, ["type"])
    summary = series.read_summary(SCRIPT, args["summary"])
    plt = series.pyplot(SCRIPT)
    if plt is None:
        return series.EXIT_NO_MATPLOTLIB
    out = args["out"]
    inp = summary.get("input", {})
    point = inp.get("point", {})
    alpha = point.get("alpha", [1.0, 1.0])
    mu = point.get("mu")
    law = inp.get("wear", {}).get("law", "?")
    # The parameters the run was computed at, from the summary's echo of its input.
    params = ", ".join("%s = %g" % (k, point[k]) for k in ("mu", "C_T", "k_a", "P_s") if k in point)
    title = "cpkit simulate, 3-D point: %s, alpha = (%g, %g), %s wear" % (params, alpha[0],
                                                                         alpha[1], law)
    if "A" in point:
        title += ", A = " + series.matrix_text(point["A"])
    orbit = inp.get("orbit")
    if orbit:
        title += ("\nload orbit (3D.40): F_T = R(%g rad) (%g cos 2 pi s/T, %g sin 2 pi s/T), "
                  "T = %g, F_N = %g; %g cycles of %g steps" %
                  (orbit.get("angle", 0.0), orbit.get("a_X"), orbit.get("a_Y"),
                   orbit.get("period", 1.0), orbit.get("F_N"), orbit.get("cycles"),
                   orbit.get("steps_per_cycle")))
    outcome = summary.get("outcome")
    if outcome and outcome != "completed":
        title += " (stopped: %s)" % outcome
    t = s["t"]
    n = len(t)
    cmap = plt.get_cmap(pc.TIME_CMAP)

    def path(ax, xs, ys, slip_only=False):
        """Draws the path; returns how many grey segments (no slip in them) have a visible
        length (a stick step leaves w_T^i where it is: a grey point, not a line)."""
        seg = max(1, n // 600)
        grey = 0
        for i in range(0, n - 1, seg):
            j = min(n - 1, i + seg)
            slipping = any(s["type"][k] == "slip" for k in range(i + 1, j + 1))
            colour = cmap(i / max(1, n - 1)) if (slipping or not slip_only) else pc.NO_SLIP
            grey += colour == pc.NO_SLIP and (xs[j] != xs[i] or ys[j] != ys[i])
            ax.plot(xs[i:j + 1], ys[i:j + 1], color=colour, lw=1.0)
        ax.set_aspect("equal", adjustable="datalim")
        ax.axhline(0, color=pc.GUIDE, lw=0.6, zorder=0)
        ax.axvline(0, color=pc.GUIDE, lw=0.6, zorder=0)
        return grey

    # 1. Load orbit, traction path with the friction ellipse, slip path. Constrained layout
    # keeps every panel's labels clear of its neighbour.
    fig = plt.figure(figsize=(14.5, 5.4), constrained_layout=True)
    fig.set_constrained_layout_pads(w_pad=0.15, wspace=0.08)
    axes = fig.subplots(1, 3)
    path(axes[0], s["F_TX"], s["F_TY"])
    axes[0].set_xlabel("$F_{TX}$")
    axes[0].set_ylabel("$F_{TY}$")
    axes[0].set_title("load orbit $F_T$")
    path(axes[1], s["P_TX"], s["P_TY"])
    if mu is not None:
        th = [2 * math.pi * k / 240 for k in range(241)]
        for PN, style, which in ((max(s["P_N"]), ":", "largest"), (s["P_N"][-1], "--", "last")):
            axes[1].plot([mu * PN * alpha[0] * math.cos(a) for a in th],
                         [mu * PN * alpha[1] * math.sin(a) for a in th], style, color=pc.INK,
                         lw=1.0, label="friction ellipse $\\|P_T\\| = \\mu P_N$ (%s $P_N$)" % which)
        axes[1].legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=7,
                       frameon=False)  # under the panel, never over the path
    axes[1].set_xlabel("$P_{TX}$")
    axes[1].set_ylabel("$P_{TY}$")
    axes[1].set_title("traction path $P_T$")
    grey = path(axes[2], s["w_TiX"], s["w_TiY"], slip_only=True)
    axes[2].set_xlabel("$w^i_{TX}$")
    axes[2].set_ylabel("$w^i_{TY}$")
    # Say "grey" only when grey is drawn (the title used to promise it regardless).
    axes[2].set_title("slip path $w_T^i$" + (" (grey: no slip)" if grey else
                                             " (stick steps do not move it)"))
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(t[0], t[-1]))
    fig.colorbar(sm, ax=list(axes), label="t", shrink=0.8, pad=0.01)
    fig.suptitle(title, fontsize=11)
    series.save(plt, fig, out + "_orbit", args["formats"], 100, bbox_inches="tight")

    # 2. Wear growth and its split by slip direction.
    fig, ax = plt.subplots(figsize=(6.8, 4.8))
    wpc = summary.get("wear_per_cycle") or []
    wx = summary.get("wear_X_per_cycle") or []
    wy = summary.get("wear_Y_per_cycle") or []
    if wpc:
        series.plot_wear_over_cycles(ax, wpc, "wear depth $w^w$ (orbit)")
        ax.set_ylabel("wear depth $w^w$ accumulated over the cycles")
        ax2 = ax.twinx()
        xs = [i + 0.5 for i in range(len(wpc))]
        if len(wx) == len(wpc) and len(wy) == len(wpc):
            ax2.bar(xs, wx, width=0.8, color=pc.series_colour(1), alpha=0.5,
                    label="per cycle, by X slip")
            ax2.bar(xs, wy, width=0.8, bottom=wx, color=pc.series_colour(4), alpha=0.5,
                    label="per cycle, by Y slip")
        else:
            ax2.bar(xs, wpc, width=0.8, color=pc.series_colour(1), alpha=0.4,
                    label="wear per cycle")
        ax2.set_ylabel("wear per cycle")
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = ax2.get_legend_handles_labels()
        ax.legend(h1 + h2, l1 + l2, loc="upper left", fontsize=7)
    else:
        ax.plot(t, s["w_w"], color=pc.series_colour(0), label="wear depth $w^w$")
        ax.set_xlabel("t")
        ax.set_ylabel("wear depth $w^w$")
    ax.set_title("wear (final %.6g)\n%s" % (s["w_w"][-1], title), fontsize=9)
    fig.tight_layout()
    series.save(plt, fig, out + "_wear", args["formats"], 100)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

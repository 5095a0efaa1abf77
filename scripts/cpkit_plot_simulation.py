#!/usr/bin/python3
"""Draws the figures of a fretting simulation written by `cpkit simulate` (docs/simulation.md).

usage: cpkit_plot_simulation.py --csv SERIES.csv [--summary SUMMARY.json] --out PREFIX
                                [--formats png,svg]

Writes, for each format:
  PREFIX_loop.*   the fretting loop: tangential force P_T against tangential displacement w_T,
                  coloured by time;
  PREFIX_wear.*   wear depth w^w against cycles (and wear per cycle when the summary has it);
  PREFIX_state.*  the contact state (a open, b grazing, c stick, d sliding) and the step's
                  solution type over time, with the number of step solutions (branch points)
                  and the interface temperature when heat was computed.
Exit codes: 0 ok, 2 bad input, 5 matplotlib is not available (the data is unaffected).
Run it with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import sys

import cpkit_plot_colours as pc
import cpkit_plot_series as series

TYPE_ORDER = ["separation", "stick", "slip+", "slip-", "open"]  # the rows of the type panel
NUMERIC = ["step", "t", "F_T", "F_N", "P_T", "P_N", "w_T", "w_N", "w_w", "w_Ti", "g", "count",
           "dissipation", "dissipation_total", "work_total", "stored", "temperature"]


SCRIPT = "cpkit_plot_simulation.py"


def main(argv):
    args = series.parse_args(SCRIPT, argv, __doc__)
    s = series.read_series(SCRIPT, args["csv"], NUMERIC, ["state", "type"])
    summary = series.read_summary(SCRIPT, args["summary"])
    plt = series.pyplot(SCRIPT)
    if plt is None:
        return series.EXIT_NO_MATPLOTLIB
    out = args["out"]
    title = "cpkit simulate (%s, %s wear)" % (summary.get("criterion", "?"),
                                               summary.get("wear_law", "?"))
    # The parameters and the load the run was computed at (the summary's "settings").
    settings = summary.get("settings", {})
    par = settings.get("parameters", {})
    if par:
        title += "\n" + ", ".join("%s = %g" % (k, par[k])
                                  for k in ("a11", "a12", "a22", "mu", "C_T", "k_a", "P_s")
                                  if k in par)
    load = settings.get("load", {})
    if load.get("type") == "fretting":
        title += "\nfretting load: F_N = %g, F_T amplitude %g, period %g, %g cycles" % (
            load.get("F_N"), load.get("amplitude"), load.get("period"), load.get("cycles"))
    elif load.get("type") == "ramp":
        title += "\nramp load: F from (%g, %g) to (%g, %g) in %g steps" % (
            load.get("F_T0"), load.get("F_N0"), load.get("F_T1"), load.get("F_N1"),
            load.get("steps"))
    outcome = summary.get("outcome")
    if outcome and outcome != "completed":
        title += " (stopped: %s)" % outcome

    # 1. Fretting loop.
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    t = s["t"]
    n = len(t)
    cmap = plt.get_cmap(pc.TIME_CMAP)
    seg = max(1, n // 400)
    for i in range(0, n - 1, seg):
        j = min(n - 1, i + seg)
        ax.plot(s["w_T"][i:j + 1], s["P_T"][i:j + 1], color=cmap(i / max(1, n - 1)), lw=1.0)
    ax.axhline(0, color=pc.GUIDE, lw=0.6)
    ax.set_xlabel("tangential displacement $w_T$")
    ax.set_ylabel("tangential contact force $P_T$")
    ax.set_title("fretting loop (colour: time)\n" + title, fontsize=9)
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(t[0], t[-1]))
    fig.colorbar(sm, ax=ax, label="t")
    fig.tight_layout()
    series.save(plt, fig, out + "_loop", args["formats"], 110, bbox_inches="tight")

    # 2. Wear depth against cycles (or time when the run has no period).
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    wpc = summary.get("wear_per_cycle") or []
    if wpc:
        series.plot_wear_over_cycles(ax, wpc, "wear depth $w^w$")
        ax2 = ax.twinx()
        ax2.bar([i + 0.5 for i in range(len(wpc))], wpc, width=0.8, color=pc.series_colour(1),
                alpha=0.35, label="wear per cycle")
        ax2.set_ylabel("wear per cycle", color=pc.series_colour(1))
    else:
        ax.plot(t, s["w_w"], color=pc.series_colour(0), label="wear depth $w^w$")
        ax.set_xlabel("t")
    ax.set_ylabel("wear depth $w^w$")
    ax.set_title("wear (final %.6g)\n%s" % (s["w_w"][-1], title), fontsize=9)
    fig.tight_layout()
    series.save(plt, fig, out + "_wear", args["formats"], 110, bbox_inches="tight")

    # 3. Contact state and solution type over time.
    heat = "temperature" in summary
    rows = 3 if heat else 2
    fig, axes = plt.subplots(rows, 1, figsize=(7.5, 2.2 * rows + 1), sharex=True)
    ax = axes[0]
    for k, lab in enumerate(pc.STATE_ORDER):
        xs = [t[i] for i in range(n) if s["state"][i] == lab]
        ax.scatter(xs, [k] * len(xs), s=4, color=pc.STATE_COLOURS[lab])
    ax.set_yticks(range(4))
    ax.set_yticklabels([pc.STATE_LABELS[k] for k in pc.STATE_ORDER])
    ax.set_title("contact state and step solutions over time\n" + title, fontsize=9)
    ax = axes[1]
    for k, typ in enumerate(TYPE_ORDER):
        xs = [t[i] for i in range(n) if s["type"][i] == typ]
        ax.scatter(xs, [k] * len(xs), s=4, color=pc.TYPE_COLOURS[typ])
    ax.set_yticks(range(len(TYPE_ORDER)))
    ax.set_yticklabels(TYPE_ORDER)
    branch = [t[i] for i in range(n) if s["count"][i] > 1]
    if branch:
        ax.scatter(branch, [len(TYPE_ORDER) - 0.5] * len(branch), marker="v", s=10,
                   color=pc.count_colour(3), label="branch point (several solutions)")
        ax.legend(loc="upper right", fontsize=7)
    if heat:
        axes[2].plot(t, s["temperature"], color=pc.INK)
        axes[2].set_ylabel("interface T")
    axes[-1].set_xlabel("t")
    fig.tight_layout()
    series.save(plt, fig, out + "_state", args["formats"], 110, bbox_inches="tight")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

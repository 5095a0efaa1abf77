"""Shared by the simulation plotting scripts (cpkit_plot_simulation.py, cpkit_plot_fretting_3d.py):
their command line (--csv SERIES.csv [--summary SUMMARY.json] --out PREFIX [--formats png,svg]),
the time-series CSV and the summary JSON written by `cpkit simulate`, and matplotlib.
Installed next to them (share/cpkit); a script's own directory is first on sys.path."""
import csv
import json
import sys

import cpkit_plot_colours as pc

EXIT_BAD_INPUT = 2
EXIT_NO_MATPLOTLIB = 5


def fail(script, msg, code=EXIT_BAD_INPUT):
    sys.stderr.write("%s: %s\n" % (script, msg))
    sys.exit(code)


def read_series(script, path, numeric, text):
    """The CSV's columns: `numeric` as floats, `text` as strings (exit 2 naming the row)."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(script, "cannot read %s: %s" % (path, e))
    if not rows:
        fail(script, "%s has no rows" % path)
    cols = {k: [] for k in list(numeric) + list(text)}
    for i, r in enumerate(rows):
        try:
            for k in numeric:
                cols[k].append(float(r[k]))
            for k in text:
                cols[k].append(r[k])
        except (KeyError, ValueError, TypeError) as e:
            fail(script, "%s row %d: %s" % (path, i + 2, e))
    return cols


def parse_args(script, argv, doc):
    args = {"csv": None, "summary": None, "out": None, "formats": ["png", "svg"]}
    i = 1
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(doc)
            sys.exit(0)
        if a not in ("--csv", "--summary", "--out", "--formats") or i + 1 >= len(argv):
            fail(script, "unknown or incomplete option %r (see --help)" % a)
        v = argv[i + 1]
        args[a[2:]] = v.split(",") if a == "--formats" else v
        i += 2
    if not args["csv"] or not args["out"]:
        fail(script, "--csv and --out are required (see --help)")
    return args


def read_summary(script, path):
    """The summary JSON, or {} without one."""
    if not path:
        return {}
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(script, "cannot read summary %s: %s" % (path, e))


def pyplot(script):
    """matplotlib.pyplot with the Agg backend, or None after a message (exit code 5 then)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError as e:
        sys.stderr.write("%s: matplotlib not available to %s (%s); install python3-matplotlib "
                         "(Debian) and run with /usr/bin/python3\n" % (script, sys.executable, e))
        return None


def plot_wear_over_cycles(ax, wear_per_cycle, label):
    """The wear depth accumulated over the cycles (0 before the first, then the running sum of
    wear_per_cycle) against the cycle count, as the wear figures of the simulation scripts draw
    it."""
    cum = [0.0]
    for w in wear_per_cycle:
        cum.append(cum[-1] + w)
    ax.plot(range(len(cum)), cum, "o-", color=pc.series_colour(0), ms=3, label=label)
    ax.set_xlabel("cycles")


def matrix_text(rows):
    """A small matrix on one line: [[2, 0.2], [0.2, 1.5]]."""
    return "[" + ", ".join("[" + ", ".join("%g" % v for v in r) + "]" for r in rows) + "]"


def save(plt, fig, prefix, formats, dpi, **kw):
    """Writes fig as prefix.FMT for every format, then closes it."""
    for fmt in formats:
        fig.savefig("%s.%s" % (prefix, fmt), dpi=dpi, **kw)
    plt.close(fig)

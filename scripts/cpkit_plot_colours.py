"""The one palette of every cpkit picture (scripts/cpkit_plot*.py, scripts/plot_profiles.py):
one fixed colour and one label per class -- solution count, class over all directions, solution
type, combination of types, contact state, N-point pattern -- whatever picture it appears in.
No other script defines a colour (tests/scripts/test_plot_colours.py checks it, and measures
the distances below).

How the colours were chosen (issue 37): the single types are the Okabe-Ito colour-blind-safe
palette; counts and the classes over all directions are greys, purples and reds ("how many":
grey one, purples several, red none); every combination of types and every N-point pattern
colour was picked greedily to be as far as possible, in the DIN99o colour space and under
simulated deuteranopia and protanopia (Machado 2009), from every colour before it. No colour
means two things: any two classes are at least 11 DIN99o units apart, any two colours of the
type panels (2-D and 3-D) at least 16, any two that one picture can show together at least 13
(7 under deuteranopia or protanopia); the old clashes were 7.4 (the blues of "3 solutions" and
separation, 1.5 under deuteranopia) and 14.6 (the two yellows). An N-point pattern's colour
is fixed for that pattern, but patterns are unbounded: two patterns in two pictures may share
one of the 16 palette colours (never two in one picture); read them by their legend.

Pure Python (no matplotlib), so it can be tested alone. Installed next to the scripts
(share/cpkit)."""
import zlib

NO_SOLUTION = "#d62728"  # a cell or point with no solution: count 0 and type "no solution"

# Solution counts per cell ("inf": a continuum of solutions).
COUNT_COLOURS = {"0": NO_SOLUTION, "1": "#dcdcdc", "2": "#ffbbff", "3": "#663399",
                 "4": "#3f007d", "inf": "#000000"}
COUNT_OTHER = "#808080"  # 5 solutions or more (never seen in a map so far)

# Param-param maps: each cell classified over all load directions.
CLASS_ORDER = ["unique", "non-unique", "no-solution", "none-and-several"]
CLASS_COLOURS = {"unique": "#f6f3df", "non-unique": "#bb66dd", "no-solution": "#f4a582",
                 "none-and-several": "#a6216f"}
CLASS_LABELS = {"unique": "unique for every direction",
                "non-unique": "several solutions for some directions",
                "no-solution": "no solution for some directions, one for the others",
                "none-and-several": "no solution for some directions, several for others"}

# One type: 2-D types (separation, stick, slip+, slip-, open) and the 3-D "slip" (any direction).
TYPE_ORDER = ["open", "separation", "stick", "slip+", "slip-", "slip"]
TYPE_COLOURS = {"separation": "#0072b2", "stick": "#009e73", "slip+": "#e69f00",
                "slip-": "#cc79a7", "open": "#56b4e9", "slip": "#f0e442"}

# Contact states of `cpkit simulate` (a open, b grazing, c stick, d sliding): a state that is a
# solution type has that type's colour (same meaning); grazing has its own.
STATE_ORDER = ["a", "b", "c", "d"]
STATE_LABELS = {"a": "a open", "b": "b grazing", "c": "c stick", "d": "d sliding"}
GRAZING = "#a0785a"
STATE_COLOURS = {"a": TYPE_COLOURS["open"], "b": GRAZING, "c": TYPE_COLOURS["stick"],
                 "d": TYPE_COLOURS["slip"]}

# Combinations of two or more types that one point can have at one load (so several
# solutions): the subsets of the 2-D types {separation, stick, slip+, slip-} and of the 3-D
# types {open, separation, stick, slip} (separation + stick is common to both).
COMBO_COLOURS = {
    ("separation", "stick", "slip+"): "#664444",
    ("stick", "slip+"): "#88ffaa",
    ("separation", "stick", "slip"): "#aabb99",
    ("separation", "slip"): "#336666",
    ("stick", "slip"): "#667744",
    ("separation", "stick"): "#6677ff",
    ("stick", "slip-"): "#776688",
    ("separation", "stick", "slip-"): "#55cccc",
    ("separation", "stick", "slip+", "slip-"): "#882200",
    ("open", "separation", "stick", "slip"): "#bbaaaa",
    ("separation", "slip+", "slip-"): "#ff6677",
    ("stick", "slip+", "slip-"): "#dd6611",
    ("open", "separation", "stick"): "#ffddcc",
    ("open", "separation", "slip"): "#77cc55",
    ("open", "stick", "slip"): "#880077",
    ("separation", "slip+"): "#aa0044",
    ("separation", "slip-"): "#776611",
    ("slip+", "slip-"): "#0055bb",
    ("open", "separation"): "#ddbb88",
    ("open", "stick"): "#999944",
    ("open", "slip"): "#6699ee",
}

# N-point patterns (the type tuples present in a cell, "stick/slip+"): a pattern of one tuple
# whose points all have one type ("stick/stick": every point sticks) has that type's colour;
# any other pattern a colour of this palette chosen by a checksum of its canonical name, fixed
# for that pattern in every picture.
PATTERN_PALETTE = ["#555544", "#007711", "#ccee99", "#00ddaa", "#445566", "#99bbbb", "#669955",
                   "#cc8888", "#664400", "#bbaacc", "#229999", "#886666", "#994499", "#aa8800",
                   "#557788", "#ffbbbb"]

# Lines and marks that are not classes (axes, guides, cell edges in legends, curves).
INK = "#000000"            # critical directions and values, the friction limit, data curves
PAPER = "#ffffff"          # gaps between rings, text on dark fills
EDGE = "#999999"           # legend patch edges
GUIDE = "#dddddd"          # zero lines, guide rings
FAINT = "#f2f2f2"          # empty rings of the direction map
AXIS = "#888888"           # the load axes of the direction map
NO_SLIP = "#bbbbbb"        # a slip path segment without slip
# Time and its order (steps, cycles): this colour map, in every picture.
TIME_CMAP = "viridis"
# Curves of one picture told apart by colour (solvers of a profile, cycles of a wear profile):
# Okabe-Ito's order; past its length the colours repeat with another line style.
SERIES = ["#0072b2", "#e69f00", "#009e73", "#cc79a7", "#56b4e9", "#d55e00", "#f0e442",
          "#000000"]


def series_colour(i):
    return SERIES[i % len(SERIES)]


def count_key(c):
    """'0', '1', ... or 'inf' for a count given as an int (-1 = continuum), str or 'inf'."""
    if c == "inf" or c == -1:
        return "inf"
    return str(int(c))


def count_colour(c):
    return COUNT_COLOURS.get(count_key(c), COUNT_OTHER)


def count_label(c):
    k = count_key(c)
    if k == "0":
        return "no solution"
    if k == "inf":
        return "infinitely many (a continuum)"
    return "%s solution%s" % (k, "" if k == "1" else "s")


def canonical_types(types):
    """A combination as a tuple in TYPE_ORDER: "stick|separation", "separation, stick",
    ["stick", "separation"] all give ("separation", "stick"). Empty, "none" or "no solution": ()."""
    if isinstance(types, str):
        sep = "|" if "|" in types else ","
        types = [t.strip() for t in types.split(sep)]
    names = {t for t in types if t and t not in ("none", "no solution")}
    unknown = sorted(names - set(TYPE_ORDER))
    return tuple(t for t in TYPE_ORDER if t in names) + tuple(unknown)


def combination_colour(types):
    """The colour of one point's combination of solution types (one type included)."""
    key = canonical_types(types)
    if not key:
        return NO_SOLUTION
    if len(key) == 1 and key[0] in TYPE_COLOURS:
        return TYPE_COLOURS[key[0]]
    if key in COMBO_COLOURS:
        return COMBO_COLOURS[key]
    return hashed_colour("|".join(key))


def combination_label(types):
    """The one spelling of a combination in every legend: "separation, stick, slip+"."""
    key = canonical_types(types)
    return ", ".join(key) if key else "no solution"


def pattern_key(tuples):
    """An N-point pattern (the set of type tuples "stick/slip+" present in a cell) in canonical
    form: the tuples sorted, so that the order a map lists them in does not matter."""
    return tuple(sorted(str(t) for t in tuples))


def pattern_colour(tuples):
    """The colour of an N-point pattern: no solution red; one tuple of one type that type's
    colour; otherwise fixed by its canonical form."""
    key = pattern_key(tuples)
    if not key:
        return NO_SOLUTION
    if len(key) == 1:
        kinds = set(key[0].split("/"))
        if len(kinds) == 1 and next(iter(kinds)) in TYPE_COLOURS:
            return TYPE_COLOURS[next(iter(kinds))]
    return hashed_colour(";".join(key))


def pattern_colours(patterns):
    """{pattern key: colour} for the patterns of one map. Each gets pattern_colour(); should two
    of them share a palette colour, the one later in canonical order takes the next free palette
    colour (PATTERN_PALETTE has 16), so that one picture never shows two patterns in one
    colour."""
    out, used = {}, set()
    for key in sorted(pattern_key(p) for p in patterns):
        c = pattern_colour(key)
        if c in used and c in PATTERN_PALETTE:
            i = PATTERN_PALETTE.index(c)
            for k in range(1, len(PATTERN_PALETTE) + 1):
                c = PATTERN_PALETTE[(i + k) % len(PATTERN_PALETTE)]
                if c not in used:
                    break
        out[key] = c
        used.add(c)
    return out


def hashed_colour(name):
    return PATTERN_PALETTE[zlib.crc32(name.encode("utf-8")) % len(PATTERN_PALETTE)]

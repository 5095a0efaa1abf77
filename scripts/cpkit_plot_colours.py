"""The colours of every map picture (cpkit_plot.py): one fixed colour per solution type, per
combination of types and per N-point type pattern, whatever map it appears in and however often.
A colour never depends on which other combinations a map holds or on how many cells they cover,
so two pictures can be compared by colour. Pure Python (no matplotlib), so it can be tested alone
(tests/scripts/test_plot_colours.py). Installed next to cpkit_plot.py (share/cpkit)."""
import zlib

NO_SOLUTION = "#d62728"  # also the colour of the count 0

# One type: 2-D types (separation, stick, slip+, slip-, open) and the 3-D "slip" (any direction).
TYPE_ORDER = ["open", "separation", "stick", "slip+", "slip-", "slip"]
TYPE_COLOURS = {"separation": "#4c72b0", "stick": "#55a868", "slip+": "#dd8452",
                "slip-": "#c44e52", "open": "#8172b3", "slip": "#937860"}

# Combinations of two or more types that one point can have at one load: the subsets of the 2-D
# types {separation, stick, slip+, slip-} and of the 3-D types {open, separation, stick, slip}
# (separation + stick is common to both). Each has its own colour, distinct from the single
# types' colours and from one another.
COMBO_COLOURS = {
    ("separation", "stick"): "#64b5cd",
    ("separation", "slip+"): "#ccb974",
    ("separation", "slip-"): "#da8bc3",
    ("stick", "slip+"): "#bcbd22",
    ("stick", "slip-"): "#8c6d31",
    ("slip+", "slip-"): "#ff9896",
    ("separation", "stick", "slip+"): "#ffd92f",
    ("separation", "stick", "slip-"): "#7b4173",
    ("separation", "slip+", "slip-"): "#393b79",
    ("stick", "slip+", "slip-"): "#637939",
    ("separation", "stick", "slip+", "slip-"): "#444444",
    ("open", "separation"): "#9edae5",
    ("open", "stick"): "#c5b0d5",
    ("open", "slip"): "#c49c94",
    ("separation", "slip"): "#e6ab02",
    ("stick", "slip"): "#80cdc1",
    ("open", "separation", "stick"): "#17becf",
    ("open", "separation", "slip"): "#fdb462",
    ("open", "stick", "slip"): "#b3de69",
    ("separation", "stick", "slip"): "#e7298a",
    ("open", "separation", "stick", "slip"): "#7f7f7f",
}

# Anything else (a combination outside the tables, an N-point pattern): a colour from this
# palette chosen by a checksum of its canonical name -- fixed for that name in every picture.
HASH_PALETTE = ["#1b9e77", "#d95f02", "#7570b3", "#1f78b4", "#b2df8a", "#fb9a99", "#fdbf6f",
                "#6a3d9a", "#b15928", "#8dd3c7", "#bebada", "#80b1d3", "#fccde5", "#bc80bd",
                "#ffed6f", "#e7cb94", "#000080", "#808000", "#00ced1", "#2f4f4f"]


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


def pattern_key(tuples):
    """An N-point pattern (the set of type tuples "stick/slip+" present in a cell) in canonical
    form: the tuples sorted, so that the order a map lists them in does not matter."""
    return tuple(sorted(str(t) for t in tuples))


def pattern_colour(tuples):
    """The colour of an N-point pattern: fixed by its canonical form (no solution: red)."""
    key = pattern_key(tuples)
    if not key:
        return NO_SOLUTION
    return hashed_colour(";".join(key))


def pattern_colours(patterns):
    """{pattern key: colour} for the patterns of one map. Each gets pattern_colour(); should two
    of them share a checksum colour, the one later in canonical order takes the next free palette
    colour (rare: HASH_PALETTE has 20 colours), so that one picture never shows two patterns in
    one colour."""
    out, used = {}, set()
    for key in sorted(pattern_key(p) for p in patterns):
        c = pattern_colour(key)
        if key and c in used:
            i = HASH_PALETTE.index(c)
            for k in range(1, len(HASH_PALETTE) + 1):
                c = HASH_PALETTE[(i + k) % len(HASH_PALETTE)]
                if c not in used:
                    break
        out[key] = c
        used.add(c)
    return out


def hashed_colour(name):
    return HASH_PALETTE[zlib.crc32(name.encode("utf-8")) % len(HASH_PALETTE)]

"""The map pictures' colours (scripts/cpkit_plot_colours.py, issue 27): one fixed colour per
solution type, per combination of types and per N-point pattern, whatever map it is drawn in.
Before, a colour was handed out by frequency within each map, so "separation, stick, slip" was
pink in one sphere map, brown in another and green (the colour of "stick") in a third. The
expectations are the issue's requirements, checked over every combination that can occur.
Run by ctest as scripts.plot_colours (plain python3, no matplotlib needed)."""
import itertools
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import cpkit_plot_colours as pc  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def subsets(types):
    return [c for k in range(1, len(types) + 1) for c in itertools.combinations(types, k)]


# The spellings of the different maps name the same combination: the 2-D CSV/npy type names
# ("stick|separation", any order), the 3-D legend ("separation, stick") and a list.
for combo in subsets(["separation", "stick", "slip+", "slip-"]) + \
        subsets(["open", "separation", "stick", "slip"]):
    two_d = pc.combination_colour("|".join(reversed(combo)))
    three_d = pc.combination_colour(", ".join(combo))
    listed = pc.combination_colour(list(combo))
    check(two_d == three_d == listed, "one colour for %s in every spelling" % "+".join(combo))

# Fixed: the colour of a combination does not depend on which other combinations a map holds
# (the old code numbered them by frequency within the map).
seen_in_map_1 = [pc.combination_colour(c) for c in ["separation", "stick|separation|slip+"]]
seen_in_map_2 = [pc.combination_colour(c) for c in ["slip-", "stick", "separation|slip+|stick"]]
check(seen_in_map_1[1] == seen_in_map_2[2], "separation+stick+slip+ the same in two maps")
check(pc.combination_colour("separation, stick, slip") == "#e7298a",
      "3-D separation+stick+slip keeps its tabulated colour")

# Distinct: within the combinations one point can have (2-D and 3-D), no two share a colour,
# and no combination takes a single type's colour (the old "green = stick" confusion) or the
# no-solution red.
for universe in (["separation", "stick", "slip+", "slip-"], ["open", "separation", "stick", "slip"]):
    colours = [pc.combination_colour(c) for c in subsets(universe)] + [pc.combination_colour([])]
    check(len(set(colours)) == len(colours),
          "%d combinations of %s: all colours distinct" % (len(colours), "/".join(universe)))
singles = set(pc.TYPE_COLOURS.values())
for combo, colour in pc.COMBO_COLOURS.items():
    check(colour not in singles and colour != pc.NO_SOLUTION,
          "%s is not coloured like a single type" % "+".join(combo))
check(pc.combination_colour("none") == pc.combination_colour("no solution") == pc.NO_SOLUTION,
      "no solution is red in every spelling")

# N-point patterns: the same set of type tuples, listed in another order by another map, has
# the same colour; two maps with different other patterns give it the same colour too.
pat = ["separation/separation", "slip+/slip+", "stick/stick"]
a = pc.pattern_colours([pat, ["stick/slip+"]])
b = pc.pattern_colours([list(reversed(pat)), ["separation/slip+"], []])
check(a[pc.pattern_key(pat)] == b[pc.pattern_key(pat)] == pc.pattern_colour(pat),
      "an N-point pattern keeps its colour across maps and orders")
check(b[()] == pc.NO_SOLUTION, "the empty pattern (no solution) is red")
# Within one map, patterns never share a colour, even when their checksums collide.
many = [["p%d/q" % i] for i in range(len(pc.HASH_PALETTE))]
cols = pc.pattern_colours(many)
check(len(set(cols.values())) == len(many),
      "%d patterns in one map: %d colours" % (len(many), len(set(cols.values()))))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)

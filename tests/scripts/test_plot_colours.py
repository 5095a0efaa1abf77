"""The one palette of every cpkit picture (scripts/cpkit_plot_colours.py; issues 27 and 37).

Issue 27: a colour was handed out by frequency within each map, so one combination had three
colours in three sphere maps. Issue 37: yellow meant "separation + stick + slip+" in one picture
and "separation, slip" in another, orange meant "2 solutions" in one and "several for some
directions" in another, "3 solutions" blue sat next to the separation blue, and labels were
spelled "+" in one and "," in the other. The checks: every plotting script takes its colours
from the palette and writes none of its own; every class has one colour and one label
spelling; no two classes share a colour, measured as a perceptual distance (DIN99o, computed
here from the sRGB definition, DIN 6176) under normal vision and, within the classes one
picture can show together, under simulated deuteranopia and protanopia (Machado, Oliveira &
Fernandes 2009, severity 1).
Run by ctest as scripts.plot_colours (plain python3, no matplotlib needed)."""
import glob
import itertools
import math
import os
import re
import sys

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import cpkit_plot_colours as pc  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def subsets(types, smallest=1):
    return [c for k in range(smallest, len(types) + 1) for c in itertools.combinations(types, k)]


T2 = ["separation", "stick", "slip+", "slip-"]
T3 = ["open", "separation", "stick", "slip"]

# --- colour science, independent of the palette module -------------------------------------
MACHADO = {"deuteranopia": [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413],
                            [-0.011820, 0.042940, 0.968881]],
           "protanopia": [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216],
                          [-0.003882, -0.048116, 1.051998]]}


def din99o(hex_colour, vision=None):
    """DIN99o coordinates of an sRGB colour (D65), optionally as seen with a colour-vision
    deficiency (Machado's matrix on linear RGB)."""
    h = hex_colour.lstrip("#")
    rgb = []
    for i in (0, 2, 4):
        c = int(h[i:i + 2], 16) / 255.0
        rgb.append(c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4)
    if vision:
        m = MACHADO[vision]
        rgb = [min(1.0, max(0.0, sum(m[i][j] * rgb[j] for j in range(3)))) for i in range(3)]
    r, g, b = rgb
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    f = lambda t: t ** (1 / 3) if t > 216 / 24389 else (24389 / 27 * t + 16) / 116
    L, a, bb = 116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))
    cos26, sin26 = math.cos(math.radians(26)), math.sin(math.radians(26))
    e = a * cos26 + bb * sin26
    ff = 0.83 * (-a * sin26 + bb * cos26)
    C = math.log(1 + 0.075 * math.hypot(e, ff)) / 0.0435
    hue = math.atan2(ff, e) + math.radians(26)
    return (303.67 * math.log(1 + 0.0039 * L), C * math.cos(hue), C * math.sin(hue))


def distance(c1, c2, vision=None):
    return math.dist(din99o(c1, vision), din99o(c2, vision))


# --- 1. one source: every plotting script imports the palette and names no colour itself ---
scripts = sorted(glob.glob(os.path.join(SCRIPTS, "*.py")))
plotting = [p for p in scripts if "matplotlib" in open(p).read() and
            not p.endswith("cpkit_plot_colours.py")]
check(len(plotting) >= 7, "%d plotting scripts found in scripts/" % len(plotting))
colour_literal = re.compile(
    r"#[0-9a-fA-F]{6}\b|#[0-9a-fA-F]{3}\b|[\"']tab:\w+[\"']|[\"']C\d[\"']"
    r"|\b(?:colou?rs?|facecolou?rs?|edgecolou?rs?|markerfacecolor|markeredgecolor|mfc|mec)"
    r"\s*=\s*[\"'](?!none[\"'])[^\"']*[\"']"
    r"|,\s*[\"'][bgrcmykw][-.oxsv^*+:]+[\"']")
for p in plotting:
    text = open(p).read()
    name = os.path.basename(p)
    check(re.search(r"^\s*(import cpkit_plot_colours|from cpkit_plot_colours import)", text,
                    re.M) is not None, "%s imports cpkit_plot_colours" % name)
    found = [m.group(0) for m in colour_literal.finditer(text)]
    check(not found, "%s names no colour of its own %s" % (name, found if found else ""))
# The check would see a script that does (not a check that cannot fail).
check(colour_literal.search('ax.plot(x, y, color="#1f77b4")') is not None and
      colour_literal.search('ax.plot(x, y, "k.")') is not None and
      colour_literal.search('Patch(facecolor="orange")') is not None and
      colour_literal.search('Patch(facecolor=pc.TYPE_COLOURS[t], edgecolor="none")') is None,
      "the colour-literal check recognises hex, named and format-string colours")

# --- 2. one colour and one label per class, whatever the spelling --------------------------
for combo in subsets(T2) + subsets(T3):
    spellings = ["|".join(reversed(combo)), ", ".join(combo), list(combo), list(reversed(combo))]
    check(len({pc.combination_colour(s) for s in spellings}) == 1,
          "one colour for %s in every spelling" % "+".join(combo))
    check(len({pc.combination_label(s) for s in spellings}) == 1 and
          " + " not in pc.combination_label(spellings[0]),
          "one label for %s: %r" % ("+".join(combo), pc.combination_label(spellings[0])))
check(pc.combination_colour("none") == pc.combination_colour("no solution") ==
      pc.count_colour(0) == pc.NO_SOLUTION, "no solution: one colour as a type and as a count")
check(pc.combination_label("none") == pc.count_label(0) == "no solution",
      "no solution: one label as a type and as a count")
check(pc.count_colour(-1) == pc.count_colour("inf") and pc.count_label(-1) == pc.count_label("inf"),
      "a continuum: one colour and label for -1 and 'inf'")
# Fixed: a combination's colour does not depend on which other combinations a map holds.
check(pc.combination_colour("stick|separation|slip+") ==
      pc.combination_colour("separation|slip+|stick"),
      "separation+stick+slip+ the same in two maps")

# --- 3. no colour means two things ----------------------------------------------------------
classes = {}  # colour -> the classes it means


def add(meaning, colour):
    classes.setdefault(colour.lower(), set()).add(meaning)


for k in ["1", "2", "3", "4", "inf"]:
    add("count " + k, pc.count_colour(k))
add("5 or more solutions", pc.COUNT_OTHER)
add("no solution", pc.NO_SOLUTION)
for c in pc.CLASS_ORDER:
    add("class " + c, pc.CLASS_COLOURS[c])
for t, c in pc.TYPE_COLOURS.items():
    add("type " + t, c)
add("state b grazing", pc.GRAZING)
for combo in subsets(T2, 2) + subsets(T3, 2):
    add("types " + pc.combination_label(combo), pc.combination_colour(combo))
for k, c in enumerate(pc.PATTERN_PALETTE):
    add("N-point pattern colour %d" % k, c)
shared = {c: m for c, m in classes.items() if len(m) > 1}
check(not shared, "every class its own colour %s" % (shared if shared else ""))
# A state that is a solution type keeps that type's colour (same meaning, same colour).
check(pc.STATE_COLOURS["a"] == pc.TYPE_COLOURS["open"] and
      pc.STATE_COLOURS["c"] == pc.TYPE_COLOURS["stick"] and
      pc.STATE_COLOURS["d"] == pc.TYPE_COLOURS["slip"] and pc.STATE_COLOURS["b"] == pc.GRAZING,
      "contact states a, c, d in the colours of open, stick, slip; b its own")

# Perceptual distance. Every class against every other, in any two pictures: at least
# ALL_PICTURES (normal vision). Within the classes one picture shows together (its count panel
# and its type panel; a class panel and its pattern panel): at least ONE_PICTURE under normal
# vision and CVD under deuteranopia and protanopia. For scale: a DIN99o distance of 1 is about
# a just-noticeable difference; the old palette had the yellows of "separation, stick, slip+"
# and "separation, slip" 14.6 apart and the blues of "3 solutions" and separation 7.4 apart
# (1.5 under deuteranopia).
ALL_PICTURES, TYPE_PANELS, ONE_PICTURE, CVD = 11.0, 16.0, 13.0, 7.0
everything = sorted(classes)
worst = min((distance(a, b), classes[a], classes[b])
            for a, b in itertools.combinations(everything, 2))
check(worst[0] >= ALL_PICTURES, "any two classes at least %g apart (closest %.1f: %s / %s)" %
      (ALL_PICTURES, worst[0], sorted(worst[1]), sorted(worst[2])))
# The type panels of all maps (2-D and 3-D, singles and combinations): further apart still, so
# that a colour seen in one type panel is never taken for another class in another.
type_panels = sorted({pc.combination_colour(c) for c in subsets(T2) + subsets(T3)})
d, a, b = min((distance(a, b), a, b) for a, b in itertools.combinations(type_panels, 2))
check(d >= TYPE_PANELS, "%d type-panel colours of all maps at least %g apart "
      "(closest %.1f: %s / %s)" % (len(type_panels), TYPE_PANELS, d, a, b))
counts = [pc.count_colour(k) for k in ["0", "1", "2", "3", "4", "inf"]]
pictures = {
    "2-D count and type panels": counts + [pc.combination_colour(c) for c in subsets(T2)],
    "3-D count and type panels": counts + [pc.combination_colour(c) for c in subsets(T3)],
    "N-point class and pattern panels": [pc.CLASS_COLOURS[c] for c in pc.CLASS_ORDER] +
    list(pc.TYPE_COLOURS.values()) + pc.PATTERN_PALETTE + [pc.NO_SOLUTION],
    "N-point count and pattern panels": counts + list(pc.TYPE_COLOURS.values()) +
    pc.PATTERN_PALETTE,
    "simulation state and type panels": list(pc.STATE_COLOURS.values()) +
    [pc.TYPE_COLOURS[t] for t in ["separation", "stick", "slip+", "slip-", "open"]],
}
for name, colours in pictures.items():
    colours = sorted(set(colours))
    for vision, least in ((None, ONE_PICTURE), ("deuteranopia", CVD), ("protanopia", CVD)):
        d, a, b = min((distance(a, b, vision), a, b) for a, b in itertools.combinations(colours, 2))
        check(d >= least, "%s, %s: any two at least %g apart (closest %.1f: %s / %s)" %
              (name, vision or "normal vision", least, d, a, b))
# The measure is a real one: the old clashes of issue 37 fail it.
check(distance("#ffd92f", "#e6ab02") < TYPE_PANELS and
      distance("#1f77b4", "#4c72b0") < ONE_PICTURE and
      distance("#1f77b4", "#4c72b0", "deuteranopia") < CVD,
      "the distance check would have caught the old yellow/yellow and blue/blue clashes")

# --- 4. N-point patterns -------------------------------------------------------------------
pat = ["separation/separation", "slip+/slip+", "stick/stick"]
a = pc.pattern_colours([pat, ["stick/slip+"]])
b = pc.pattern_colours([list(reversed(pat)), ["separation/slip+"], []])
check(a[pc.pattern_key(pat)] == b[pc.pattern_key(pat)] == pc.pattern_colour(pat),
      "an N-point pattern keeps its colour across maps and orders")
check(b[()] == pc.NO_SOLUTION, "the empty pattern (no solution) is red")
check(pc.pattern_colour(["stick/stick/stick"]) == pc.TYPE_COLOURS["stick"] and
      pc.pattern_colour(["separation/separation"]) == pc.TYPE_COLOURS["separation"],
      "a pattern where every point has one type has that type's colour")
check(pc.pattern_colour(["stick/slip+"]) in pc.PATTERN_PALETTE, "a mixed pattern a palette colour")
many = [["p%d/q" % i] for i in range(len(pc.PATTERN_PALETTE))]
cols = pc.pattern_colours(many)
check(len(set(cols.values())) == len(many),
      "%d patterns in one map: %d colours" % (len(many), len(set(cols.values()))))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)

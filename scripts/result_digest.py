#!/usr/bin/python3
"""The result digest of issue 36: one SHA-256 over every result of a fixed set of `cpkit` runs.

A refactor of rate_problem/ must not change any result. This script runs a fixed list of
`cpkit` commands (rate, step, map, simulate; one point and N points; 2-D and 3-D) on the test
suite's problems, the docs' examples and seeded random families it generates itself, and hashes
everything they produce: the exit code, stdout (JSON and text), stderr and every file written
(--out, --csv, --summary). Timings and the version are masked (the keys in MASKED_KEYS, and
"<number> s" in text); the scratch directory is written as $WORK. Doubles are printed by cpkit in
shortest round-trip form, so equal digests mean bit-identical results. The checkout's own path is
written as $ROOT, so that the digest does not depend on where the repository is.

    scripts/result_digest.py [--cpkit build/apps/cpkit] [--write FILE] [--check FILE] [--only NAME]

prints one line per command, "<sha256>  <name>", then "total <sha256>". --write FILE stores
these lines; --check FILE compares with a stored file and names the commands that differ (exit 1).
docs/architecture.md ("The result digest") says how to use it. Uses only the standard library.
"""
import argparse
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EX = "docs/examples"
SYS = "tests/data/systems"

# JSON keys whose values depend on the machine or the moment, not on the results.
MASKED_KEYS = {"seconds", "elapsed", "elapsed_seconds", "wall_seconds", "cpu_seconds",
               "estimate", "threads", "cpkit_version", "version", "commit", "date", "time_s"}
# Text: a duration such as "0.25 s", "12 ms", "(3.1 s)".
TEXT_TIME = re.compile(r"\b\d+(\.\d+)?(e[+-]?\d+)? ?(s|ms|us|seconds)\b")
# Lines `cpkit map` writes to stderr only when the map takes more than a second by the clock
# (its estimate, then its progress; report/map_text.cpp, requests/map_request_run.cpp): whether
# they appear depends on the machine's load, not on the results, so they are left out (a
# record without them is unchanged: the reference was written where no map took a second).
CLOCK_LINES = re.compile(r"cpkit map: [^\n]*\(estimate\)\n\n?|(\rcpkit map: (chunks|cells) +\d+% \([^)]*\)( stopped)?)+\n?")


def mask_json(x):
    if isinstance(x, dict):
        return {k: ("<masked>" if k in MASKED_KEYS else mask_json(v)) for k, v in x.items()}
    if isinstance(x, list):
        return [mask_json(v) for v in x]
    return x


def masked_text(data, work):
    """Bytes of one output, masked: JSON re-serialised with the timing keys masked (key order
    and float text kept: json keeps the parsed float's repr, which round-trips)."""
    text = data.decode("utf-8", errors="replace").replace(work, "$WORK").replace(ROOT, "$ROOT")
    stripped = text.strip()
    if stripped.startswith("{") or stripped.startswith("["):
        try:
            return json.dumps(mask_json(json.loads(stripped)), sort_keys=True, indent=0)
        except ValueError:
            pass
    return TEXT_TIME.sub("<t>", CLOCK_LINES.sub("", text))


# ---------------------------------------------------------------------------------------------
# Seeded random families (Python's Mersenne Twister: the same numbers on every platform).


def r4(x):
    return round(x, 4)


def spd(rng, n):
    """A random symmetric positive definite n x n matrix B B^T + 0.5 I, entries to 4 decimals."""
    b = [[r4(rng.uniform(-1, 1)) for _ in range(n)] for _ in range(n)]
    a = [[r4(sum(b[i][k] * b[j][k] for k in range(n)) + (0.5 if i == j else 0.0))
          for j in range(n)] for i in range(n)]
    return a


def write_json(path, obj):
    with open(path, "w") as f:
        json.dump(obj, f)
    return path


def random_families(work):
    """Returns (name, argv) pairs for the seeded families; writes their input files in work."""
    rng = random.Random(36)
    cmds = []
    num = lambda x: repr(r4(x))
    # One 2-D point: rate in every state, step, a small map and a short simulation.
    for i in range(6):
        a = spd(rng, 2)
        mu = r4(rng.uniform(0.2, 4))
        ct = r4(rng.choice([0.0, rng.uniform(0, 0.5)]))
        ka = r4(rng.choice([0.0, rng.uniform(0, 0.2)]))
        state = "abcd"[i % 4]
        model = ["--a11", num(a[0][0]), "--a12", num(a[0][1]), "--a22", num(a[1][1]),
                 "--mu", repr(mu), "--C_T", repr(ct), "--k_a", repr(ka)]
        st = ["--state", state]
        if state in "cd":
            st += ["--P_N", num(rng.uniform(0.5, 2))]
        if state == "d":
            st += ["--sgnPT", rng.choice(["1", "-1"])]
        df = [num(rng.uniform(-1, 1)), num(rng.uniform(-1, 1))]
        cmds.append((f"rand2d_rate_{i}", ["rate"] + st + model + ["--dF"] + df + ["--json"]))
        pn0 = r4(rng.uniform(0, 2))
        pt0 = r4(rng.uniform(-0.99, 0.99) * mu * pn0)
        step = ["step"] + model + ["--P_T0", repr(pt0), "--P_N0", repr(pn0), "--g0", "0",
                                   "--dF", num(rng.uniform(-1, 1)), num(rng.uniform(-1, 1))]
        cmds.append((f"rand2d_step_all_{i}", step + ["--all", "--json"]))
        cmds.append((f"rand2d_step_chain_{i}", step + ["--json"]))
        if i < 3:
            no_mu = model[:6] + model[8:]  # mu is the map's axis
            cmds.append((f"rand2d_map_pd_{i}", ["map"] + st + no_mu +
                         ["--kind", "param-direction", "--param", "mu", "--from", "0.1", "--to",
                          "4", "--n", "20", "--theta-n", "36", "--threads", "1", "--json",
                          "--out", f"{work}/out/rand2d_map_pd_{i}/m"]))
            cmds.append((f"rand2d_sim_{i}", ["simulate"] + model +
                         ["--load", "fretting", "--F_N", num(rng.uniform(0.5, 2)),
                          "--amplitude", num(rng.uniform(0.1, 2)), "--cycles", "2",
                          "--steps-per-cycle", "20", "--json",
                          "--csv", f"{work}/out/rand2d_sim_{i}/s.csv"]))
    # N 2-D points (N = 2, 3): rate, step --all, a direction map, a fretting simulation.
    for i, n in enumerate([2, 2, 3]):
        pts = []
        for k in range(n):
            p = {"mu": r4(rng.uniform(0.3, 3)), "C_T": r4(rng.uniform(0, 0.3))}
            if k % 2 == 0:
                p["state"] = "b"
            else:
                p["state"] = "c"
                p["P_N"] = r4(rng.uniform(0.5, 2))
            pts.append(p)
        e1 = [1.0 if j % 2 == 0 else 0.0 for j in range(2 * n)]
        e2 = [0.0 if j % 2 == 0 else 1.0 for j in range(2 * n)]
        sysf = write_json(f"{work}/in/rand2d_sys_{i}.json",
                          {"name": f"random {n} points {i}", "A": spd(rng, 2 * n), "points": pts,
                           "dF": [r4(rng.uniform(-1, 1)) for _ in range(2 * n)],
                           "patterns": [e1, e2]})
        cmds.append((f"rand2d_sys_rate_{i}", ["rate", "--system", sysf, "--json"]))
        df = [num(rng.uniform(-0.3, 0.3)) for _ in range(2 * n)]
        cmds.append((f"rand2d_sys_step_{i}", ["step", "--system", sysf, "--dF"] + df +
                     ["--all", "--json"]))
        cmds.append((f"rand2d_sys_map_{i}", ["map", "--system", sysf, "--threads", "1",
                                             "--json", "--out",
                                             f"{work}/out/rand2d_sys_map_{i}/m"]))
        cfg = write_json(f"{work}/in/rand2d_sim_{i}.json",
                         {"system": f"rand2d_sys_{i}.json",
                          "load": {"type": "fretting", "F_N": 1, "amplitude": 0.3, "period": 1,
                                   "cycles": 2, "steps_per_cycle": 12, "ramp_steps": 3}})
        cmds.append((f"rand2d_sys_sim_{i}", ["simulate", "--config", cfg, "--json", "--csv",
                                             f"{work}/out/rand2d_sys_sim_{i}/s.csv"]))
    # One 3-D point: rate, step (--all, --facets, the default chain), a sphere map, fretting.
    for i in range(4):
        p = {"state": "b", "mu": r4(rng.uniform(0.3, 4)), "C_T": r4(rng.uniform(0, 0.3)),
             "k_a": r4(rng.uniform(0, 0.1)) if i % 2 else 0.0, "P_s": 1,
             "alpha": [r4(rng.uniform(0.4, 1.2)), r4(rng.uniform(0.4, 1.2))]}
        df = [r4(rng.uniform(-1, 1)) for _ in range(3)]
        sysf = write_json(f"{work}/in/rand3d_pt_{i}.json",
                          {"name": f"random 3-D point {i}", "dim": 3, "A": spd(rng, 3),
                           "points": [p], "dF": df})
        dfa = [repr(x) for x in df]
        cmds.append((f"rand3d_rate_{i}", ["rate", "--system", sysf, "--json"]))
        cmds.append((f"rand3d_step_all_{i}", ["step", "--system", sysf, "--dF"] + dfa +
                     ["--all", "--json"]))
        cmds.append((f"rand3d_step_{i}", ["step", "--system", sysf, "--dF"] + dfa + ["--json"]))
        if i % 2 == 0:  # the faceted step is the LCP without wear
            cmds.append((f"rand3d_step_facets_{i}", ["step", "--system", sysf, "--dF"] + dfa +
                         ["--facets", "12", "--json"]))
        if i < 2:
            cmds.append((f"rand3d_sphere_{i}", ["map", "--system", sysf, "--kind", "sphere",
                                                "--n", "9", "--n2", "16", "--threads", "1",
                                                "--json", "--out",
                                                f"{work}/out/rand3d_sphere_{i}/m"]))
            cmds.append((f"rand3d_fretting_{i}", ["simulate", "--system", sysf, "--orbit",
                                                  num(rng.uniform(0.2, 1)),
                                                  num(rng.uniform(-1, 1)), "--cycles", "2",
                                                  "--steps-per-cycle", "24", "--json", "--csv",
                                                  f"{work}/out/rand3d_fretting_{i}/s.csv"]))
    # Two 3-D points: the faceted rate problem and a faceted sphere map.
    for i in range(2):
        pts = [{"state": "b", "mu": r4(rng.uniform(0.5, 3)), "C_T": r4(rng.uniform(0, 0.3)),
                "alpha": [r4(rng.uniform(0.5, 1.2)), r4(rng.uniform(0.5, 1.2))]}
               for _ in range(2)]
        sysf = write_json(f"{work}/in/rand3d_sys_{i}.json",
                          {"name": f"random two 3-D points {i}", "dim": 3, "A": spd(rng, 6),
                           "points": pts, "dF": [r4(rng.uniform(-1, 1)) for _ in range(6)]})
        cmds.append((f"rand3d_sys_rate_{i}", ["rate", "--system", sysf, "--facets", "6",
                                              "--json"]))
        if i == 0:
            cmds.append((f"rand3d_sys_sphere_{i}", ["map", "--system", sysf, "--kind", "sphere",
                                                    "--facets", "6", "--n", "5", "--n2", "8",
                                                    "--threads", "1", "--json", "--out",
                                                    f"{work}/out/rand3d_sys_sphere_{i}/m"]))
    return cmds


def fixed_commands(work):
    """The docs' examples and the test suite's problems (inputs from the repository)."""
    o = lambda name: f"{work}/out/{name}/m"
    c = [
        # rate, one 2-D point (docs/model.md), every method
        ("rate_b", ["rate", "--state", "b", "--a11", "1", "--a12", "2", "--a22", "5", "--mu", "1",
                    "--dF", "1", "1.2", "--json"]),
        ("rate_b_text", ["rate", "--state", "b", "--a11", "1", "--a12", "2", "--a22", "5",
                         "--mu", "1", "--dF", "1", "1.2"]),
        ("rate_b_lemke", ["rate", "--state", "b", "--a11", "1", "--a12", "2", "--a22", "5",
                          "--mu", "1", "--dF", "1", "1.2", "--method", "lemke", "--json"]),
        ("rate_b_fbnewton", ["rate", "--state", "b", "--a11", "1", "--a12", "2", "--a22", "5",
                             "--mu", "1", "--dF", "1", "1.2", "--method", "fb-newton", "--json"]),
        ("rate_d", ["rate", "--state", "d", "--a11", "1", "--a12", "0.5", "--a22", "1", "--mu",
                    "1.5", "--C_T", "0.25", "--P_N", "1", "--sgnPT", "1", "--dF", "0.3", "1",
                    "--json"]),
        ("rate_d_softening", ["rate", "--state", "d", "--a11", "1", "--a12", "0.5", "--a22", "1",
                              "--mu", "1.5", "--k_a", "0.1", "--criterion", "35", "--P_N", "1",
                              "--sgnPT", "-1", "--dF", "-0.3", "1", "--json"]),
        # rate, N points and 3-D (docs/model.md, docs/contact_3d.md, tests/data/systems)
        ("rate_sys_two_point", ["rate", "--system", f"{EX}/two_point_system.json", "--json"]),
        ("rate_sys_two_point_text", ["rate", "--system", f"{EX}/two_point_system.json"]),
        ("rate_sys_two_point_lemke", ["rate", "--system", f"{EX}/two_point_system.json",
                                      "--method", "lemke", "--json"]),
        ("rate_sys_three_point", ["rate", "--system", f"{SYS}/three_point_punch.json",
                                  "--json"]),
        ("rate_sys_coupled", ["rate", "--system", f"{EX}/coupled_grazing_points.json", "--dF",
                              "1", "0.2", "-0.5", "1", "--json"]),
        ("rate_3d_elliptic", ["rate", "--system", f"{EX}/elliptic_point_3d.json", "--json"]),
        ("rate_3d_elliptic_text", ["rate", "--system", f"{EX}/elliptic_point_3d.json"]),
        ("rate_3d_elliptic_facets", ["rate", "--system", f"{EX}/elliptic_point_3d.json",
                                     "--facets", "16", "--json"]),
        ("rate_3d_sphere_point", ["rate", "--system", f"{EX}/sphere_point_3d.json", "--json"]),
        ("rate_3d_two_point", ["rate", "--system", f"{EX}/two_point_system_3d.json", "--facets",
                               "8", "--json"]),
        ("rate_3d_two_point_text", ["rate", "--system", f"{EX}/two_point_system_3d.json",
                                    "--facets", "8"]),
        # step (docs/simulation.md, docs/contact_3d.md)
        ("step_2d_all", ["step", "--a11", "1", "--a12", "0.9", "--a22", "1", "--mu", "2",
                         "--P_T0", "2", "--P_N0", "1", "--g0", "0", "--dF", "-0.01", "0", "--all",
                         "--json"]),
        ("step_2d_all_text", ["step", "--a11", "1", "--a12", "0.9", "--a22", "1", "--mu", "2",
                              "--P_T0", "2", "--P_N0", "1", "--g0", "0", "--dF", "-0.01", "0",
                              "--all"]),
        ("step_2d_chain", ["step", "--a11", "1", "--a12", "0.9", "--a22", "1", "--mu", "2",
                           "--P_T0", "2", "--P_N0", "1", "--g0", "0", "--dF", "-0.01", "0",
                           "--json"]),
        ("step_2d_chain_lemke", ["step", "--a11", "1", "--a12", "0.3", "--a22", "1.5", "--mu",
                                 "0.5", "--P_T0", "0.2", "--P_N0", "1", "--g0",
                                 "0", "--dF", "0.5", "0.1", "--chain", "lemke", "--json"]),
        ("step_2d_chain_fb", ["step", "--a11", "1", "--a12", "0.3", "--a22", "1.5", "--mu",
                              "0.5", "--k_a", "0.01", "--P_T0", "0.2", "--P_N0", "1", "--g0",
                              "0", "--dF", "0.5", "0.1", "--chain", "fb-newton", "--json"]),
        ("step_2d_mroz", ["step", "--a11", "2", "--a12", "0.3", "--a22", "1.5", "--mu", "0.5",
                          "--wear-law", "mroz", "--k_M", "0.05", "--P_T0", "0.4", "--P_N0", "1",
                          "--g0", "0", "--dF", "0.3", "0.1", "--all", "--json"]),
        ("step_2d_softening", ["step", "--a11", "2", "--a12", "0.3", "--a22", "1.5", "--mu",
                               "0.5", "--k_a", "0.05", "--criterion", "35", "--P_T0", "0.2",
                               "--P_N0", "1", "--g0", "0", "--dF", "0.3", "0.1", "--all",
                               "--json"]),
        ("step_sys_three_point", ["step", "--system", f"{EX}/three_point_punch.json", "--dF",
                                  "0.2", "0.1", "0", "0.1", "-0.2", "0.1", "--all", "--json"]),
        ("step_sys_three_point_text", ["step", "--system", f"{EX}/three_point_punch.json", "--dF",
                                       "0.2", "0.1", "0", "0.1", "-0.2", "0.1", "--all"]),
        ("step_sys_two_point", ["step", "--system", f"{SYS}/two_point_system.json", "--dF",
                                "0.3", "0.2", "-0.1", "0.4", "--all", "--json"]),
        ("step_3d_all", ["step", "--system", f"{EX}/elliptic_point_3d.json", "--dF", "1.0", "0.5",
                         "0.9", "--all", "--json"]),
        ("step_3d_all_text", ["step", "--system", f"{EX}/elliptic_point_3d.json", "--dF", "1.0",
                              "0.5", "0.9", "--all"]),
        ("step_3d_facets", ["step", "--system", f"{EX}/elliptic_point_3d.json", "--dF", "1.0",
                            "0.5", "0.9", "--facets", "32", "--json"]),
        ("step_3d_chain", ["step", "--system", f"{EX}/elliptic_point_3d.json", "--dF", "1.0",
                           "0.5", "0.9", "--json"]),
        ("step_3d_multistart", ["step", "--system", f"{EX}/elliptic_point_3d.json", "--dF",
                                "1.0", "0.5", "0.9", "--multistart", "4", "--json"]),
        ("step_3d_sphere_point", ["step", "--system", f"{EX}/sphere_point_3d.json", "--dF", "1.0",
                                  "0.3", "0.8", "--all", "--json"]),
        # maps of every kind (docs/maps.md, docs/contact_3d.md)
        ("map_fig5b", ["map", "--preset", "fig5b", "--json", "--out", o("map_fig5b")]),
        ("map_fig5b_text", ["map", "--preset", "fig5b"]),
        ("map_fig5a", ["map", "--preset", "fig5a", "--json"]),
        ("map_state_d", ["map", "--preset", "state-d", "--n", "40", "--theta-n", "72",
                         "--threads", "1", "--json", "--out", o("map_state_d")]),
        ("map_mu_kappa", ["map", "--preset", "state-d-mu-kappa", "--n", "30", "--n2", "20",
                          "--threads", "1", "--json", "--out", o("map_mu_kappa")]),
        ("map_mu_kappa_csv", ["map", "--preset", "state-d-mu-kappa", "--n", "12", "--n2", "8",
                              "--format", "csv", "--threads", "1", "--json", "--out",
                              o("map_mu_kappa_csv")]),
        ("map_pd_analytic", ["map", "--preset", "fig5b", "--kind", "param-direction", "--param",
                             "mu", "--from", "0.1", "--to", "4", "--n", "40", "--theta-n", "72",
                             "--method", "analytic", "--threads", "1", "--json", "--out",
                             o("map_pd_analytic")]),
        ("map_sys_direction", ["map", "--system", f"{EX}/two_point_system.json", "--json",
                               "--out", o("map_sys_direction")]),
        ("map_sys_direction_text", ["map", "--system", f"{EX}/two_point_system.json"]),
        ("map_sys_punch", ["map", "--system", f"{EX}/three_point_punch_sliding.json", "--json", "--out", o("map_sys_punch")]),
        ("map_sys_pd", ["map", "--system", f"{EX}/coupled_grazing_points.json", "--kind",
                        "param-direction", "--param", "coupling", "--from", "0", "--to", "1",
                        "--n", "11", "--theta-n", "90", "--threads", "1", "--json", "--out",
                        o("map_sys_pd")]),
        ("map_sys_pp", ["map", "--system", f"{EX}/coupled_grazing_points.json", "--kind",
                        "param-param", "--param", "coupling", "--from", "0", "--to", "1", "--n",
                        "6", "--param2", "mu", "--from2", "0.5", "--to2", "2", "--n2", "4",
                        "--threads", "1", "--json", "--out", o("map_sys_pp")]),
        ("map_sys_pp_point", ["map", "--system", f"{EX}/two_point_system.json", "--kind",
                              "param-param", "--param", "mu@2", "--from", "0.5", "--to", "4",
                              "--n", "5", "--param2", "C_T", "--from2", "0", "--to2", "0.5",
                              "--n2", "4", "--threads", "1", "--json", "--out",
                              o("map_sys_pp_point")]),
        ("map_3d_sphere", ["map", "--system", f"{EX}/sphere_point_3d.json", "--kind", "sphere",
                           "--n", "31", "--n2", "60", "--threads", "1", "--json", "--out",
                           o("map_3d_sphere")]),
        ("map_3d_sphere_text", ["map", "--system", f"{EX}/sphere_point_3d.json", "--kind",
                                "sphere", "--n", "11", "--n2", "20", "--threads", "1"]),
        ("map_3d_pd", ["map", "--system", f"{EX}/sphere_point_3d.json", "--kind",
                       "param-direction", "--param", "alpha_X", "--from", "0.2", "--to", "0.9",
                       "--n", "10", "--theta-n", "36", "--gamma", "0.3", "--threads", "1",
                       "--json", "--out", o("map_3d_pd")]),
        ("map_3d_pp", ["map", "--system", f"{EX}/sphere_point_3d.json", "--kind", "param-param",
                       "--param", "alpha_X", "--from", "0.2", "--to", "0.9", "--n", "8",
                       "--param2", "mu", "--from2", "1", "--to2", "6", "--n2", "6", "--threads",
                       "1", "--json", "--out", o("map_3d_pp")]),
        ("map_3d_sys_sphere", ["map", "--system", f"{EX}/two_point_system_3d.json", "--kind",
                               "sphere", "--facets", "16", "--point", "2", "--n", "11", "--n2",
                               "20", "--threads", "1", "--json", "--out",
                               o("map_3d_sys_sphere")]),
        ("map_3d_sys_pp", ["map", "--system", f"{EX}/two_point_system_3d.json", "--kind",
                           "param-param", "--facets", "8", "--param", "mu@1", "--from", "1",
                           "--to", "4", "--n", "4", "--param2", "C_T", "--from2", "0", "--to2",
                           "0.5", "--n2", "3", "--threads", "1", "--json", "--out",
                           o("map_3d_sys_pp")]),
        # simulation (docs/simulation.md, docs/contact_3d.md)
        ("sim_fretting", ["simulate", "--config", f"{EX}/fretting.json", "--json", "--csv",
                          f"{work}/out/sim_fretting/s.csv", "--summary",
                          f"{work}/out/sim_fretting/s.json"]),
        ("sim_fretting_text", ["simulate", "--config", f"{EX}/fretting.json", "--csv",
                               f"{work}/out/sim_fretting_text/s.csv", "--summary",
                               f"{work}/out/sim_fretting_text/s.json"]),
        ("sim_ramp_softening", ["simulate", "--a11", "1", "--a12", "0", "--a22", "1", "--mu",
                                "0.5", "--k_a", "0.3", "--criterion", "35", "--load", "ramp",
                                "--F_N1", "10", "--steps", "100", "--json", "--csv",
                                f"{work}/out/sim_ramp_softening/s.csv"]),
        ("sim_mroz_heat", ["simulate", "--a11", "2", "--a12", "0.3", "--a22", "1.5", "--mu",
                           "0.5", "--C_T", "0.4", "--wear-law", "mroz", "--k_M", "0.01",
                           "--load", "fretting", "--F_N", "1", "--amplitude", "1.2", "--cycles",
                           "3", "--steps-per-cycle", "40", "--heat", "--heat-capacity", "0.05",
                           "--T-body", "293", "300", "--conductance", "0.02", "0.03", "--json",
                           "--csv", f"{work}/out/sim_mroz_heat/s.csv"]),
        ("sim_stop_rule", ["simulate", "--config", f"{EX}/fretting.json", "--branch-rule", "stop",
                           "--json", "--csv", f"{work}/out/sim_stop_rule/s.csv", "--summary",
                           f"{work}/out/sim_stop_rule/s.json"]),
        ("sim_sys_two_point", ["simulate", "--config", f"{work}/in/sim_two_point.json", "--json",
                               "--csv", f"{work}/out/sim_sys_two_point/s.csv"]),
        ("sim_3d_fretting", ["simulate", "--system", f"{EX}/fretting_point_3d.json", "--orbit",
                             "0.9", "0.5", "--cycles", "5", "--steps-per-cycle", "60", "--json",
                             "--csv", f"{work}/out/sim_3d_fretting/s.csv", "--summary",
                             f"{work}/out/sim_3d_fretting/s.json"]),
        ("sim_3d_fretting_text", ["simulate", "--system", f"{EX}/fretting_point_3d.json",
                                  "--orbit", "0.9", "0.5", "--cycles", "5", "--steps-per-cycle",
                                  "60"]),
        ("sim_3d_fretting_mroz", ["simulate", "--system", f"{work}/in/fretting_point_3d_mroz.json",
                                  "--orbit", "0.7", "-0.4", "--orbit-angle", "0.5",
                                  "--wear-law", "mroz", "--k_M", "0.02", "--cycles", "2",
                                  "--steps-per-cycle", "30", "--json", "--csv",
                                  f"{work}/out/sim_3d_fretting_mroz/s.csv"]),
        # bad input: the message and exit code are part of the output
        ("step_3d_two_point_chain", ["step", "--system", f"{EX}/two_point_system_3d.json",
                                     "--dF", "1", "0", "-1", "0.5", "0", "1", "--json"]),
        ("step_3d_two_point_multistart", ["step", "--system", f"{EX}/two_point_system_3d.json",
                                          "--dF", "1", "0", "-1", "0.5", "0", "1",
                                          "--multistart", "3", "--json"]),
        ("bad_step_3d_two_points", ["step", "--system", f"{EX}/two_point_system_3d.json", "--dF",
                                    "1", "0", "-1", "0.5", "0", "1", "--all"]),
    ]
    return c


def test_suite_rows(work):
    """Loads from the test suite's exact tables: every 8th row of the one-point critical loads
    (tests/rate_problem/rate_boundary_rows.inc) and every 3rd knife-edge load of the two-point
    problem (tests/rate_problem/knife_edge_rows.inc, system of tests/data/system_rate_knife_edges.py)."""
    cmds = []
    hexnum = r"(-?0x[0-9a-fA-F.]+p[+-]\d+)"
    row = re.compile(r"^\s*\{'([abcd])', " + ", ".join([hexnum] * 8) + r", (-?1), " + hexnum +
                     ", " + hexnum + ",")
    rows = []
    with open(os.path.join(ROOT, "tests/rate_problem/rate_boundary_rows.inc")) as f:
        for line in f:
            m = row.match(line)
            if m:
                rows.append(m.groups())
    assert len(rows) > 400, "rate_boundary_rows.inc: rows not found"
    for k, g in enumerate(rows[::8]):
        v = [repr(float.fromhex(x)) for x in g[1:9]]
        argv = ["rate", "--state", g[0], "--a11", v[0], "--a12", v[1], "--a22", v[2], "--mu",
                v[3], "--C_T", v[4], "--k_a", v[5], "--P_s", v[6]]
        if g[0] in "cd":
            argv += ["--P_N", v[7]]
        if g[0] == "d":
            argv += ["--sgnPT", g[9]]
        argv += ["--dF", repr(float.fromhex(g[10])), repr(float.fromhex(g[11])), "--json"]
        cmds.append((f"boundary_row_{8 * k}", argv))
    knife = write_json(f"{work}/in/knife_edge_system.json",
                       {"A": [[1, 2, 0.25, 0.1], [2, 5, 0.1, 0.5], [0.25, 0.1, 1, 0.3],
                              [0.1, 0.5, 0.3, 2]],
                        "points": [{"state": "b", "mu": 1.0, "C_T": 0.0},
                                   {"state": "b", "mu": 0.5, "C_T": 0.25}]})
    edges = []
    with open(os.path.join(ROOT, "tests/rate_problem/knife_edge_rows.inc")) as f:
        for line in f:
            m = re.match(r"^\s*\{" + hexnum + ", " + hexnum + ",", line)
            if m:
                edges.append(m.groups())
    assert len(edges) > 50, "knife_edge_rows.inc: rows not found"
    for k, (t, n) in enumerate(edges[::3]):
        cmds.append((f"knife_edge_row_{3 * k}",
                     ["rate", "--system", knife, "--dF", repr(float.fromhex(t)),
                      repr(float.fromhex(n)), "0.3", "-0.2", "--json"]))
    return cmds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cpkit", default=os.path.join(ROOT, "build", "apps", "cpkit"))
    ap.add_argument("--write", help="store the per-command lines and the total in this file")
    ap.add_argument("--check", help="compare with a stored file; exit 1 naming the differences")
    ap.add_argument("--only", action="append", help="run only the commands with this name")
    ap.add_argument("--show", action="store_true", help="print each command's masked output")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="cpkit-digest-")
    try:
        os.makedirs(f"{work}/in")
        os.makedirs(f"{work}/out")
        write_json(f"{work}/in/sim_two_point.json",
                   {"system": os.path.join(ROOT, SYS, "two_point_system.json"),
                    "load": {"type": "fretting", "F_N": 1, "amplitude": 0.8, "period": 1,
                             "cycles": 2, "steps_per_cycle": 16, "ramp_steps": 4}})
        with open(os.path.join(ROOT, EX, "fretting_point_3d.json")) as f:
            point = json.load(f)
        point["points"][0]["k_a"] = 0  # the Mroz law takes its constant from --k_M
        write_json(f"{work}/in/fretting_point_3d_mroz.json", point)
        cmds = fixed_commands(work) + test_suite_rows(work) + random_families(work)
        names = [n for n, _ in cmds]
        assert len(names) == len(set(names)), "duplicate command names"
        lines = []
        total = hashlib.sha256()
        for name, argv in cmds:
            if args.only and name not in args.only:
                continue
            outdir = f"{work}/out/{name}"
            os.makedirs(outdir, exist_ok=True)
            p = subprocess.run([args.cpkit] + argv, cwd=ROOT, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
            parts = [f"command: cpkit {' '.join(argv)}".replace(work, "$WORK").replace(ROOT, "$ROOT"),
                     f"exit: {p.returncode}",
                     "stdout:\n" + masked_text(p.stdout, work),
                     "stderr:\n" + masked_text(p.stderr, work)]
            for f in sorted(os.listdir(outdir)):
                with open(os.path.join(outdir, f), "rb") as fh:
                    data = fh.read()
                body = data.hex() if f.endswith(".npy") else masked_text(data, work)
                parts.append(f"file {f}:\n{body}")
            record = "\n".join(parts).encode()
            if args.show:
                print(record.decode())
            h = hashlib.sha256(record).hexdigest()
            total.update(f"{h}  {name}\n".encode())
            lines.append(f"{h}  {name}")
            print(lines[-1], flush=True)
        lines.append(f"total {total.hexdigest()}")
        print(lines[-1])
        if args.write:
            with open(args.write, "w") as f:
                f.write("\n".join(lines) + "\n")
        if args.check:
            with open(args.check) as f:
                want = [l.rstrip("\n") for l in f if l.strip() and not l.startswith("#")]
            want_map = {l.split("  ", 1)[1]: l.split("  ", 1)[0] for l in want if "  " in l}
            got_map = {l.split("  ", 1)[1]: l.split("  ", 1)[0] for l in lines if "  " in l}
            names_checked = set(got_map) if args.only else set(want_map) | set(got_map)
            diff = sorted(n for n in names_checked if want_map.get(n) != got_map.get(n))
            if diff:
                print("result digest DIFFERS for: " + ", ".join(diff))
                return 1
            print("result digest equal to " + args.check)
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())

"""3-D contact points from Python (docs/contact_3d.md) against independent answers:
the 2-D one-point rate problem and the 2-D step enumeration for an isotropic point whose Y
direction is decoupled and unloaded (Y-slip is impossible there), the 2-D N-point solver for the
two-point example embedded in 3-D, the C++ command line on the same file, and bad input."""
import json
import math
import os

import numpy as np
import pytest

import cpkit
from conftest import SOURCE_DIR, run_cli


def decoupled(rng):
    a11, a22 = rng.uniform(0.3, 2, 2)
    a12 = rng.uniform(-0.95, 0.95) * math.sqrt(a11 * a22)
    aYY = rng.uniform(0.3, 2)
    mu = rng.uniform(0.2, 3)
    C_T = float(rng.choice([0.0, rng.uniform(0, 1)]))
    p2 = cpkit.ContactParameters(a11=a11, a12=a12, a22=a22, mu=mu, C_T=C_T)
    p3 = cpkit.Point3d(A=[[a11, 0, a12], [0, aYY, 0], [a12, 0, a22]], mu=mu, C_T=C_T)
    return p2, p3


def type3(t2):
    return {"slip+": "slip", "slip-": "slip"}.get(t2, t2)


def test_rate_3d_decoupled_is_the_2d_problem():
    rng = np.random.default_rng(31)
    several = 0
    for _ in range(300):
        p2, p3 = decoupled(rng)
        th = rng.uniform(0, 2 * math.pi)
        dFT, dFN = math.cos(th), math.sin(th)
        two = cpkit.solve_rate_problem(p2, "b", (dFT, dFN))
        three = cpkit.solve_rate_3d(p3, "b", (dFT, 0.0, dFN))
        assert three.complete, three.message
        assert sorted(three.types) == sorted(type3(s.type) for s in two.solutions)
        for s in two.solutions:
            hits = [x for x in three.solutions if abs(x["at"]["dP_N"] - s.start["dP_N"]) < 1e-9 * (1 + abs(s.start["dP_N"]))
                    and abs(x["at"]["dP_T"][0] - s.start["dP_T"]) < 1e-9 * (1 + abs(s.start["dP_T"]))]
            assert hits, (s, three.solutions)
            if s.type == "slip+":
                assert abs(hits[0]["slip_angle"]) < 1e-9
            if s.type == "slip-":
                assert abs(abs(hits[0]["slip_angle"]) - math.pi) < 1e-9
        several += two.count > 1
    assert several >= 3


def test_step_3d_decoupled_is_the_2d_step():
    rng = np.random.default_rng(32)
    compared = 0
    for i in range(300):
        p2, p3 = decoupled(rng)
        p2.k_a = p3.k_a = float(rng.uniform(0, 0.5))
        P_N0 = float(rng.uniform(0.1, 1)) if i % 2 else 0.0
        P_T0 = float(rng.uniform(-1, 1)) * p2.mu * P_N0
        DF = rng.uniform(-1, 1, 2)
        two = cpkit.enumerate_step(p2, P_T0, P_N0, 0.0, DF, detect_jumps=False)
        if two.count < 0:
            continue
        three = cpkit.enumerate_step_3d(p3, (DF[0], 0.0, DF[1]), P_T0=(P_T0, 0.0), P_N0=P_N0)
        assert three.complete, three.message
        assert sorted(three.types) == sorted(type3(s.type) for s in two.solutions)
        for s in two.solutions:
            assert any(abs(x["values"]["P_N1"] - s.start["P_N1"]) < 1e-8 * (1 + abs(s.start["P_N1"]))
                       and abs(x["values"]["P_T1"][0] - s.start["P_T1"]) < 1e-8 * (1 + abs(s.start["P_T1"]))
                       for x in three.solutions)
        compared += 1
    assert compared > 250


def test_faceted_agrees_with_exact_for_many_facets():
    rng = np.random.default_rng(33)
    agree = 0
    for _ in range(60):
        L = rng.uniform(-1, 1, (3, 3))
        A = L @ L.T + 0.3 * np.eye(3)
        p = cpkit.Point3d(A=A, mu=float(rng.uniform(0.3, 2)), alpha=rng.uniform(0.4, 1.2, 2))
        dF = rng.uniform(-1, 1, 3)
        exact = cpkit.solve_rate_3d(p, "b", dF)
        faceted = cpkit.solve_rate_3d(p, "b", dF, facets=64)
        agree += exact.complete and exact.count == faceted.count
    assert agree >= 57


def test_two_point_system_3d_matches_the_2d_system_and_the_cli():
    path = os.path.join(SOURCE_DIR, "docs", "examples", "two_point_system_3d.json")
    three = cpkit.solve_system_rate_3d(path, facets=8)
    with open(path) as f:
        doc = json.load(f)
    # The same system in 2-D: drop the Y DOFs (decoupled, unloaded).
    keep = [i for i in range(3 * len(doc["points"])) if i % 3 != 1]
    A2 = np.asarray(doc["A"])[np.ix_(keep, keep)]
    pts2 = []
    for p in doc["points"]:
        q = {k: v for k, v in p.items() if k not in ("alpha", "P_T")}
        if "P_T" in p:  # state d: the 2-D file gives the sliding direction as sgnPT
            q["sgnPT"] = 1 if p["P_T"][0] > 0 else -1
        pts2.append(q)
    sys2 = cpkit.ContactSystem(A2, pts2)
    two = cpkit.solve_system_rate(sys2, np.asarray(doc["dF"])[keep])
    assert three.count == two.count
    assert sorted("/".join(type3(t) for t in s["types"]) for s in three.solutions) == \
        sorted("/".join(type3(t) for t in s.types) for s in two.solutions)
    _, cli = run_cli("rate", "--system", path, "--facets", "8", "--json")
    assert cli["count"] == three.count


def test_bad_input_is_a_value_error():
    p = cpkit.Point3d(A=np.eye(3), mu=0.5)
    with pytest.raises(ValueError, match="dF"):
        cpkit.solve_rate_3d(p, "b", (1, 0))
    with pytest.raises(ValueError, match="state"):
        cpkit.solve_rate_3d(p, "x", (1, 0, 0))
    with pytest.raises(ValueError, match="alpha"):
        cpkit.solve_rate_3d(cpkit.Point3d(alpha=(0, 1)), "b", (1, 0, 0))
    with pytest.raises(ValueError, match="NaN"):
        cpkit.enumerate_step_3d(p, (math.nan, 0, 1))
    with pytest.raises(ValueError, match="g0"):
        cpkit.enumerate_step_3d(p, (1, 0, 1), g0=1.0)
    with pytest.raises(ValueError, match="facets"):
        cpkit.solve_rate_3d(p, "b", (1, 0, 1), facets=0)
    with pytest.raises(ValueError, match="state b"):
        cpkit.solve_rate_3d(p, "a", (1, 0, 1), facets=8)


def test_multistart_count_is_capped():
    # issue 24, item 16: n_starts = 10**9 ran for days; refused up front, naming the cap
    p = cpkit.Point3d(A=np.eye(3), mu=0.5)
    with pytest.raises(ValueError, match="exceeds the cap of 10000"):
        cpkit.multistart_step_3d(p, (1, 0, 1), n_starts=10**9)
    with pytest.raises(ValueError, match="exceeds the cap of 10000"):
        cpkit.solve_step_3d_faceted(p, (1, 0, 1), facets=8, k_M=0.0, n_starts=10**9)

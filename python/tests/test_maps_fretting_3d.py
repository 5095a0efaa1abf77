"""The rest of the 3-D API from Python (maps, step solvers, fretting) against independent
answers: every map cell against cpkit.solve_rate_3d / solve_system_rate_3d at the cell's load
and parameters, the sphere map against the command line's .npy files, the step solvers against
the exact enumeration, the fretting wear against the wear law (40) summed from the returned
series, the decoupled isotropic back-and-forth orbit against the 2-D cpkit.simulate of the X-N
problem, the fretting run against `cpkit simulate --system --json`, and bad input."""
import json
import math
import os

import numpy as np
import pytest

import cpkit
from conftest import SOURCE_DIR, run_cli

EXAMPLES = os.path.join(SOURCE_DIR, "docs", "examples")
SPHERE = os.path.join(EXAMPLES, "sphere_point_3d.json")
TWO = os.path.join(EXAMPLES, "two_point_system_3d.json")
BITS = {"open": 1, "separation": 2, "stick": 4, "slip": 8}


def cos_sin_exact(a):
    """As sphere_map_3d.cpp: exact zeros at 0, +-pi/2, +-pi."""
    table = {0.0: (1.0, 0.0), math.pi: (-1.0, 0.0), -math.pi: (-1.0, 0.0),
             math.pi / 2: (0.0, 1.0), -math.pi / 2: (0.0, -1.0)}
    return table.get(a, (math.cos(a), math.sin(a)))


def point_of(system, **changes):
    """The Point3d of a one-point system dict (with changed fields)."""
    pt = dict(system["points"][0])
    pt.update(changes)
    return cpkit.Point3d(A=system["A"], mu=pt["mu"], C_T=pt.get("C_T", 0.0), k_a=pt.get("k_a", 0.0),
                         P_s=pt.get("P_s", 1.0), alpha=pt.get("alpha", (1.0, 1.0)))


def cell_of(s):
    """(count, type mask, complete) of a one-point Rate3dSolutionSet, as a map cell."""
    count = -1 if any(x["kind"] == "ray" for x in s.solutions) else s.count
    mask = 0
    for t in s.types:
        mask |= BITS[t]
    return count, mask, s.complete


def check_map_cells(m, solve, cells):
    for i, j in cells:
        count, mask, complete = solve(m.x[i], m.y[j])
        assert (m.count[i, j], m.types[i, j], m.complete[i, j]) == (count, mask, complete), (i, j)


def load(path):
    with open(path) as f:
        return json.load(f)


def test_sphere_map_cells_are_the_one_point_rate_problem():
    sys = load(SPHERE)
    p = point_of(sys)
    m = cpkit.sphere_map_3d(SPHERE, n_beta=7, n_gamma=12)
    assert m.count.shape == m.types.shape == m.complete.shape == (7, 12)
    assert m.count.dtype == np.int8 and m.types.dtype == np.uint8 and m.complete.dtype == bool
    assert np.allclose(m.x, math.pi * (np.arange(7) + 0.5) / 7)
    assert np.allclose(m.y, math.pi * (2 * (np.arange(12) + 1) - 12) / 12)
    assert m.route == "exact" and m.incomplete_cells == int((~m.complete).sum())
    assert sum(m.count_cells.values()) == 84 and sum(m.type_cells.values()) == 84
    assert (m.count == 3).any() and (m.count == 1).any()  # the map is not trivial

    def solve(b, g):
        (cb, sb), (cg, sg) = cos_sin_exact(b), cos_sin_exact(g)
        return cell_of(cpkit.solve_rate_3d(p, "b", (sb * cg, sb * sg, cb)))
    check_map_cells(m, solve, [(i, j) for i in range(7) for j in range(12)])
    # the same map from a dict and from JSON text, on 2 threads
    assert np.array_equal(cpkit.sphere_map_3d(sys, 7, 12, threads=2).count, m.count)
    assert np.array_equal(cpkit.sphere_map_3d(json.dumps(sys), 7, 12).types, m.types)


def test_sphere_map_is_the_command_lines(tmp_path):
    prefix = str(tmp_path / "sph")
    code, _ = run_cli("map", "--system", SPHERE, "--kind", "sphere", "--n", 9, "--n2", 16,
                      "--from", 0.2, "--to", 2.9, "--out", prefix, expect=(0, 5))
    m = cpkit.sphere_map_3d(SPHERE, n_beta=9, n_gamma=16, beta_range=(0.2, 2.9))
    assert np.array_equal(np.load(prefix + "_count.npy"), m.count)
    assert np.array_equal(np.load(prefix + "_types.npy"), m.types)
    assert np.array_equal(np.load(prefix + "_complete.npy").astype(bool), m.complete)
    assert np.array_equal(np.load(prefix + "_x.npy"), m.x)
    assert np.array_equal(np.load(prefix + "_y.npy"), m.y)
    assert (code == 0) == (m.incomplete_cells == 0)


def test_faceted_sphere_map_of_two_points_is_the_system_rate_problem():
    sys = load(TWO)
    m = cpkit.sphere_map_3d(TWO, n_beta=3, n_gamma=4, facets=8)
    assert m.route == "faceted" and m.others == "file" and m.point == 1

    def solve(b, g):
        (cb, sb), (cg, sg) = cos_sin_exact(b), cos_sin_exact(g)
        s = dict(sys)
        s["dF"] = [sb * cg, sb * sg, cb] + list(sys["dF"][3:])
        r = cpkit.solve_system_rate_3d(s, facets=8)
        mask = 0
        for x in r.solutions:
            mask |= BITS[x["types"][0]]
        return min(r.count, 127), mask, r.complete
    check_map_cells(m, solve, [(0, 0), (1, 1), (1, 3), (2, 2)])


def test_param_direction_and_param_param_maps_cell_by_cell():
    sys = load(SPHERE)
    G = 0.3
    m = cpkit.param_direction_map_3d(SPHERE, "mu", 1.0, 5.0, n=3, theta_n=8, gamma=G)
    assert m.count.shape == (3, 8) and m.param == "mu"
    assert np.allclose(m.x, [1.0, 3.0, 5.0])
    assert np.allclose(m.y, 2 * math.pi * (np.arange(8) + 0.5) / 8)

    def solve_pd(mu, th):
        c, s = cos_sin_exact(th)
        cg, sg = cos_sin_exact(G)
        return cell_of(cpkit.solve_rate_3d(point_of(sys, mu=mu), "b", (c * cg, c * sg, s)))
    check_map_cells(m, solve_pd, [(i, j) for i in range(3) for j in range(0, 8, 3)])

    q = cpkit.param_param_map_3d(SPHERE, "alpha_X", 0.3, 1.2, 3, "mu", 0.5, 4.0, 4)
    assert q.count.shape == (3, 4) and (q.param1, q.param2) == ("alpha_X", "mu")

    def solve_pp(ax, mu):
        p = point_of(sys, mu=mu, alpha=[ax, sys["points"][0]["alpha"][1]])
        return cell_of(cpkit.solve_rate_3d(p, "b", sys["dF"]))
    check_map_cells(q, solve_pp, [(0, 0), (1, 2), (2, 3), (2, 1)])


def random_point(rng, wear=True):
    B = rng.uniform(-1, 1, (3, 3))
    A = B @ B.T + rng.uniform(0.3, 1.0) * np.eye(3)
    return cpkit.Point3d(A=A, mu=float(rng.uniform(0.2, 2.5)), C_T=float(rng.uniform(0, 0.5)),
                         k_a=float(rng.uniform(0, 0.3)) if wear else 0.0,
                         alpha=tuple(rng.uniform(0.4, 1.2, 2)))


def random_step(rng, p, i):
    P_N0 = float(rng.uniform(0.2, 1.5)) if i % 3 else 0.0
    phi = rng.uniform(-math.pi, math.pi)
    r = float(rng.uniform(0, 0.95)) * p.mu * P_N0
    P_T0 = (r * p.alpha[0] * math.cos(phi), r * p.alpha[1] * math.sin(phi))
    return dict(DF=rng.uniform(-1, 1, 3), P_T0=P_T0, P_N0=P_N0)


def in_set(sol, exact):
    v = sol["values"]
    scale = 1 + abs(v["P_N1"]) + np.abs(v["P_T1"]).max()
    return any(abs(x["values"]["P_N1"] - v["P_N1"]) < 1e-7 * scale
               and np.abs(x["values"]["P_T1"] - v["P_T1"]).max() < 1e-7 * scale
               and x["type"] == sol["type"] for x in exact.solutions)


def test_step_chain_and_multistart_against_the_enumeration():
    rng = np.random.default_rng(41)
    checked = 0
    for i in range(40):
        p = random_point(rng)
        st = random_step(rng, p, i)
        exact = cpkit.enumerate_step_3d(p, **st)
        if not exact.complete:
            continue
        for chain in (("exact", "fb-soc", "ipopt"), ("fb-soc",)):
            r = cpkit.solve_step_3d(p, chain=chain, **st)
            if chain == ("fb-soc",) and not r.solved:
                continue  # a local method may fail; it must not invent
            assert r.solved, r.message
            assert r.solution["residual"] <= 1e-9
            assert r.attempts[-1]["solver"] == r.solver and r.attempts[-1]["solved"]
            assert in_set(r.solution, exact), (st, r.solution, exact.solutions)
        if i < 12:
            ms = cpkit.multistart_step_3d(p, n_starts=8, **st)
            assert not ms.complete and ms.message
            assert all(in_set(s, exact) for s in ms.solutions)
        checked += 1
    assert checked >= 30


def test_faceted_step_approaches_the_exact_one():
    """Without wear: a complete LCP enumeration of the inscribed 64-gon, whose solutions are
    those of the ellipse within the polygon's gap (1 - cos(pi/64) ~ 1.2e-3)."""
    rng = np.random.default_rng(42)
    compared = 0
    for i in range(12):
        p = random_point(rng, wear=False)
        st = random_step(rng, p, i)
        f = cpkit.solve_step_3d_faceted(p, facets=64, **st)
        assert f.lcp and f.facets == 64 and f.nodes > 0
        exact = cpkit.enumerate_step_3d(p, **st)
        if not (f.complete and exact.complete and exact.count == 1):
            continue
        assert f.types == exact.types
        a, b = f.solutions[0]["values"], exact.solutions[0]["values"]
        scale = 1 + abs(b["P_N1"]) + np.abs(b["P_T1"]).max()
        assert abs(a["P_N1"] - b["P_N1"]) < 5e-3 * scale
        assert np.abs(a["P_T1"] - b["P_T1"]).max() < 5e-3 * scale
        compared += 1
    assert compared >= 8
    worn = random_point(rng, wear=True)
    worn.k_a = 0.2
    f = cpkit.solve_step_3d_faceted(worn, (0.5, 0.2, 0.8), facets=16, n_starts=4)
    assert not f.lcp and not f.complete


FRETTING = cpkit.Point3d(A=[[2.0, 0.2, 0.3], [0.2, 1.5, -0.1], [0.3, -0.1, 1.5]], mu=0.5,
                         C_T=0.2, k_a=0.03, P_s=1.0, alpha=(0.6, 1.0))


def test_fretting_wear_is_the_integral_of_the_wear_law():
    r = cpkit.simulate_fretting_3d(FRETTING, (0.9, 0.5), angle=0.4, cycles=3, steps_per_cycle=40)
    assert r.outcome == "completed", r.message
    s = r.series
    n = r.steps + 1
    assert s["P_T"].shape == (n, 2) and s["P_N"].shape == (n,) and len(s["type"]) == n
    assert r.total_slip > 0 and r.wear_depth > 0
    k = FRETTING.k_a / (3 * FRETTING.P_s)
    D = np.asarray(FRETTING.alpha)
    per_step = k * s["P_N"] * np.linalg.norm(s["Dw_Ti"] * D, axis=1)  # (40) k P_N |D Dw_T^i|
    assert np.allclose(per_step, s["Dw_w"], rtol=1e-9, atol=1e-15)
    assert per_step.sum() == pytest.approx(r.wear_depth, rel=1e-9)
    assert per_step.sum() == pytest.approx(r.wear_integral, rel=1e-9)
    assert np.cumsum(s["Dw_w"])[-1] == pytest.approx(s["w_w"][-1], rel=1e-9)
    assert s["lambda"] == pytest.approx(np.linalg.norm(s["Dw_Ti"] * D, axis=1), rel=1e-9, abs=1e-15)
    assert r.total_slip == pytest.approx(np.linalg.norm(s["Dw_Ti"], axis=1).sum(), rel=1e-9)
    assert len(r.wear_per_cycle) == 3
    for c in range(3):
        sel = s["cycle"] == c
        assert per_step[sel].sum() == pytest.approx(r.wear_per_cycle[c], rel=1e-9)
    assert np.allclose(r.wear_X_per_cycle + r.wear_Y_per_cycle, r.wear_per_cycle, rtol=1e-9)
    # the load is the orbit (3D.40)
    sel = s["cycle"] >= 0
    ph = 2 * math.pi * (s["t"][sel] - r.cycle_start) / r.period
    R = np.array([[math.cos(0.4), -math.sin(0.4)], [math.sin(0.4), math.cos(0.4)]])
    want = (R @ np.vstack([0.9 * np.cos(ph), 0.5 * np.sin(ph)])).T
    assert np.allclose(s["F_T"][sel], want, atol=1e-12)


def test_decoupled_back_and_forth_orbit_is_the_2d_simulation():
    a11, a12, a22, aYY, mu, C_T, k_a = 1.3, 0.4, 1.1, 0.9, 0.6, 0.15, 0.05
    p3 = cpkit.Point3d(A=[[a11, 0, a12], [0, aYY, 0], [a12, 0, a22]], mu=mu, C_T=C_T, k_a=k_a)
    p2 = cpkit.ContactParameters(a11=a11, a12=a12, a22=a22, mu=mu, C_T=C_T, k_a=k_a)
    r3 = cpkit.simulate_fretting_3d(p3, (1.5, 0.0), F_N=1.2, cycles=3, steps_per_cycle=40,
                                    ramp_steps=5)
    assert r3.outcome == "completed", r3.message
    s3 = r3.series
    assert np.all(s3["F_T"][:, 1] == 0) and np.abs(s3["P_T"][:, 1]).max() < 1e-12
    assert np.abs(s3["w_Ti"][:, 1]).max() < 1e-12
    # the 2-D history is the 3-D load without the start point: the same steps
    h = {"t": s3["t"][1:], "F_T": s3["F_T"][1:, 0], "F_N": s3["F_N"][1:],
         "period": r3.period, "cycle_start": r3.cycle_start}
    r2 = cpkit.simulate(p2, h)
    assert r2.outcome == "completed"
    s2 = r2.series
    assert len(s2["t"]) == len(s3["t"])
    for k3, k2 in (("P_T", "P_T"), ("w_T", "w_T"), ("w_Ti", "w_Ti")):
        assert np.allclose(s3[k3][:, 0], s2[k2], rtol=1e-8, atol=1e-10), k3
    for k in ("P_N", "w_N", "w_w", "g"):
        assert np.allclose(s3[k], s2[k], rtol=1e-8, atol=1e-10), k
    assert r3.wear_depth == pytest.approx(r2.wear_depth, rel=1e-8)
    assert r3.total_slip == pytest.approx(r2.total_slip, rel=1e-8)
    assert r3.total_slip > 0.5
    assert np.allclose(r3.slip_per_cycle, r2.slip_per_cycle, rtol=1e-8)
    assert np.allclose(r3.wear_per_cycle, r2.wear_per_cycle, rtol=1e-8)


def test_fretting_is_the_command_lines(tmp_path):
    f = tmp_path / "point.json"
    pt = {"state": "b", "mu": FRETTING.mu, "C_T": FRETTING.C_T, "k_a": FRETTING.k_a,
          "P_s": FRETTING.P_s, "alpha": FRETTING.alpha}
    f.write_text(json.dumps({"dim": 3, "A": FRETTING.A, "points": [pt]}))
    _, j = run_cli("simulate", "--system", f, "--orbit", 0.9, -0.5, "--orbit-angle", 0.2,
                   "--cycles", 2, "--steps-per-cycle", 30, "--lead-steps", 5, "--json")
    r = cpkit.simulate_fretting_3d(FRETTING, (0.9, -0.5), angle=0.2, cycles=2,
                                   steps_per_cycle=30, lead_steps=5, record_every=0)
    assert len(r.series["t"]) == 0 and r.final_state["step"] == r.steps
    assert j["outcome"] == r.outcome and j["steps"] == r.steps
    for key, mine in (("final_wear_depth", r.wear_depth), ("wear_integral", r.wear_integral),
                      ("total_slip", r.total_slip), ("dissipation", r.dissipation)):
        assert j[key] == pytest.approx(mine, rel=1e-12), key
    assert np.allclose(j["wear_per_cycle"], r.wear_per_cycle, rtol=1e-12)
    assert np.allclose(j["final"]["P_T"], r.final_state["P_T"], rtol=1e-12)


@pytest.mark.parametrize("call, field", [
    (lambda: cpkit.sphere_map_3d(SPHERE, facets=0), "facets"),
    (lambda: cpkit.sphere_map_3d(SPHERE, point=2), "point"),
    (lambda: cpkit.sphere_map_3d(SPHERE, n_beta=0), "n_beta"),
    (lambda: cpkit.sphere_map_3d(SPHERE, beta_range=(0, 1, 2)), "beta_range"),
    (lambda: cpkit.sphere_map_3d(SPHERE, others="all"), "others"),
    (lambda: cpkit.sphere_map_3d(TWO), "facets"),
    (lambda: cpkit.sphere_map_3d({"dim": 3, "A": [[1]], "points": []}), "points"),
    (lambda: cpkit.param_direction_map_3d(SPHERE, "nu", 0, 1), "mu"),
    (lambda: cpkit.param_direction_map_3d(SPHERE, "alpha_X", -1, 1, n=3), "alpha"),
    (lambda: cpkit.param_direction_map_3d(SPHERE, "mu", 1, 2, theta_range=(0, 7)), "theta"),
    (lambda: cpkit.param_param_map_3d(SPHERE, "mu", 1, 2, 2, "mu", 1, 3, 2), "same"),
    (lambda: cpkit.solve_step_3d(FRETTING, (1, 2)), "DF"),
    (lambda: cpkit.solve_step_3d(FRETTING, (1, 2, 3), chain=["newton"]), "newton"),
    (lambda: cpkit.solve_step_3d(FRETTING, (1, 2, 3), P_N0=-1), "P_N0"),
    (lambda: cpkit.multistart_step_3d(FRETTING, (1, 2, 3), n_starts=-1), "n_starts"),
    (lambda: cpkit.solve_step_3d_faceted(FRETTING, (1, 2, 3), facets=2), "facets"),
    (lambda: cpkit.solve_step_3d_faceted(FRETTING, (1, 2, 3), 8, wear_law="x"), "wear_law"),
    (lambda: cpkit.simulate_fretting_3d(FRETTING, (1, 2, 3)), "orbit"),
    (lambda: cpkit.simulate_fretting_3d(FRETTING, (1, 0), period=0), "period"),
    (lambda: cpkit.simulate_fretting_3d(FRETTING, (1, 0), cycles=0), "cycles"),
    (lambda: cpkit.simulate_fretting_3d(FRETTING, (1, 0), branch_rule="any"), "branch_rule"),
    (lambda: cpkit.simulate_fretting_3d(FRETTING, (1, 0), record_every=-1), "record_every"),
    (lambda: cpkit.simulate_fretting_3d(cpkit.Point3d(mu=-1), (1, 0)), "mu"),
])
def test_bad_input_raises_value_error_naming_the_field(call, field):
    with pytest.raises(ValueError, match=field):
        call()


def test_memory_bound_refuses_a_huge_run():
    with pytest.raises(ValueError, match="memory|GiB|too"):
        cpkit.simulate_fretting_3d(FRETTING, (1, 0), cycles=10**6, steps_per_cycle=10**4)

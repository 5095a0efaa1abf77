"""The contact model from Python: the rate problem against the paper's state-b conditions
(written out here from docs/contact_model.md) and against the cpkit CLI, maps against the same
conditions cell by cell, the step against the hand case of docs/simulation.md, the simulation
against the CLI on the same configuration."""
import json
import math
import os
import pickle

import numpy as np
import pytest

import cpkit
from conftest import SOURCE_DIR, run_cli


def state_b_types(p, dFT, dFN, eps=1e-9):
    """Solution types of state b by the paper's sign conditions (docs/contact_model.md, Sec. 3):
    separation iff N < 0; stick iff L+ <= 0 and L- <= 0; slip s iff N/D_s >= 0, L_s/D_s > 0.
    None when some quantity is within eps of zero (a boundary: not decided here)."""
    N = p.a11 * dFN - p.a12 * dFT
    L = {s: (s + p.mu * p.a12 * p.C_T) * dFT - p.mu * (1 + p.a11 * p.C_T) * dFN for s in (1, -1)}
    D = {s: p.a11 - s * p.mu * p.a12 for s in (1, -1)}
    if min(abs(N), abs(L[1]), abs(L[-1]), abs(D[1]), abs(D[-1])) < eps:
        return None
    types = set()
    if N < 0:
        types.add("separation")
    if L[1] <= 0 and L[-1] <= 0:
        types.add("stick")
    for s, name in ((1, "slip+"), (-1, "slip-")):
        if N / D[s] >= 0 and L[s] / D[s] > 0:
            types.add(name)
    return types


def test_rate_problem_matches_the_paper_conditions():
    rng = np.random.default_rng(11)
    checked = 0
    while checked < 300:
        a11, a22 = rng.uniform(0.2, 3, 2)
        a12 = rng.uniform(-0.95, 0.95) * math.sqrt(a11 * a22)
        p = cpkit.ContactParameters(a11=a11, a12=a12, a22=a22, mu=rng.uniform(0.1, 4),
                                    C_T=rng.choice([0.0, rng.uniform(0, 2)]))
        th = rng.uniform(0, 2 * math.pi)
        dF = (math.cos(th), math.sin(th))
        expected = state_b_types(p, *dF)
        if expected is None:
            continue
        for method in ("enumerate", "analytic"):
            r = cpkit.solve_rate_problem(p, "b", dF, method=method)
            assert set(r.types) == expected and r.count == len(expected), (p, dF, method)
        assert r.unique_for_all_directions == (p.a11 > p.mu * abs(p.a12))
        checked += 1


@pytest.mark.parametrize("args", [
    dict(a11=1, a12=2, a22=5, mu=1, dF=(1, 1.2)),
    dict(a11=1, a12=2, a22=5, mu=0.5, dF=(1, 2)),  # degenerate a11 = mu |a12|: a segment
    dict(a11=2, a12=-0.3, a22=1, mu=0.4, C_T=0.5, dF=(-0.3, 1)),
])
def test_rate_problem_agrees_with_the_cli(args):
    args = dict(args)
    dF = args.pop("dF")
    p = cpkit.ContactParameters(**args)
    cli_args = ["rate", "--state", "b", "--dF", dF[0], dF[1], "--json"]
    for k, v in args.items():
        cli_args += [f"--{k}", v]
    _, cli = run_cli(*cli_args)
    r = cpkit.solve_rate_problem(p, "b", dF)
    assert (r.count if r.count >= 0 else "inf") == cli["count"]
    assert sorted(r.types) == sorted(cli["types"])
    assert len(r.solutions) == len(cli["solutions"])
    for mine, theirs in zip(r.solutions, cli["solutions"]):
        assert mine.type == theirs["type"] and mine.kind == theirs["kind"]
        start = theirs["rates"] if theirs["kind"] == "point" else theirs["start"]
        for key, value in start.items():
            assert mine.start[key] == pytest.approx(value, abs=1e-12)
    pickle.loads(pickle.dumps(r))


def test_states_c_and_d_and_single_solvers():
    p = cpkit.ContactParameters(a11=1, a12=0.5, a22=1, mu=0.6, k_a=0.3)
    c = cpkit.solve_rate_problem(p, cpkit.ContactState("c", P_N=1.0), (0.2, 1.0))
    assert c.count == 1 and c.types == ["stick"]  # state c: always unique stick
    # Stick rates of state c: dw = 0, so dP = dF (equilibrium dF - dP = A dw).
    assert c.solutions[0].start["dP_T"] == pytest.approx(0.2)
    assert c.solutions[0].start["dP_N"] == pytest.approx(1.0)
    one = cpkit.solve_rate_problem(p, "b", (1.0, 1.0), method="lemke")
    assert not one.complete and len(one.solutions) == 1
    ind = cpkit.rate_indicators(p, cpkit.ContactState("d", P_N=1.0, sgn_PT=1))
    assert ind["kappa"] == pytest.approx(0.3 / 3)  # k_a P_N / (3 P_s)


def test_bad_contact_input():
    with pytest.raises(ValueError, match="positive definite"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(a11=1, a12=2, a22=1), "b", (1, 0))
    with pytest.raises(ValueError, match="P_N > 0"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(), cpkit.ContactState("d"), (1, 0))
    with pytest.raises(ValueError, match="state must be"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(), "e", (1, 0))
    with pytest.raises(ValueError, match="mu"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(mu=-1), "b", (1, 0))
    with pytest.raises(ValueError, match="dF"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(), "b", (1, 0, 3))
    with pytest.raises(ValueError, match="method"):
        cpkit.solve_rate_problem(cpkit.ContactParameters(), "b", (1, 0), method="guess")
    with pytest.raises(ValueError, match="param must be"):
        cpkit.param_direction_map(cpkit.ContactParameters(), "b", "nu")


FIG5 = dict(a11=1.0, a12=0.5, a22=1.0, C_T=0.25)  # the paper's Fig. 5 (docs/maps.md)


def test_param_direction_map_cell_by_cell():
    p = cpkit.ContactParameters(mu=1.0, **FIG5)
    m = cpkit.param_direction_map(p, "b", "mu", 0.1, 4.0, 40, 72)
    assert m.count.shape == (40, 72) and m.types.shape == (40, 72)
    np.testing.assert_allclose(m.x, np.linspace(0.1, 4.0, 40))
    np.testing.assert_allclose(m.theta, (np.arange(72) + 0.5) * 2 * math.pi / 72)
    # The analytic criterion: D+ = a11 - mu a12 = 0 at mu = a11 / a12 = 2.
    assert [c["name"] for c in m.critical_values] == ["D+=0"]
    assert m.critical_values[0]["x"] == pytest.approx(2.0)
    cells = 0
    for i, mu in enumerate(m.x):
        q = cpkit.ContactParameters(mu=mu, **FIG5)
        for j, th in enumerate(m.theta):
            expected = state_b_types(q, math.cos(th), math.sin(th))
            if expected is None:
                continue
            got = {name for name in cpkit.TYPE_BITS if m.types[i, j] & cpkit.TYPE_BITS[name]}
            assert got == expected and m.count[i, j] == len(expected), (mu, th)
            assert m.has_type("stick")[i, j] == ("stick" in expected)
            cells += 1
    assert cells > 2500
    # Non-uniqueness only above the critical value; just above it the wedge of three
    # solutions is narrower than a grid cell, but the exact direction map has it.
    assert m.count[m.x < 2.0].max() == 1 and m.count[m.x > 2.0].max() == 3
    for mu in (1.99, 2.01):
        exact = cpkit.direction_map(cpkit.ContactParameters(mu=mu, **FIG5), "b")
        assert exact.counts.max() == (1 if mu < 2 else 3)
    pickle.loads(pickle.dumps(m))


def test_direction_map_sectors_and_critical_directions():
    p = cpkit.ContactParameters(mu=3.0, **FIG5)
    dm = cpkit.direction_map(p, "b")
    # Every critical direction is a zero of one of the linear forms N, S, L+, L- (by hand).
    forms = [(-p.a12, p.a11), (-p.a12 * p.C_T, 1 + p.a11 * p.C_T)]
    forms += [(s + p.mu * p.a12 * p.C_T, -p.mu * (1 + p.a11 * p.C_T)) for s in (1, -1)]
    for c in dm.critical:
        th = c["theta"]
        assert min(abs(cT * math.cos(th) + cN * math.sin(th)) for cT, cN in forms) < 1e-12
    for s in dm.sectors:
        mid = 0.5 * (s["theta_from"] + s["theta_to"])
        assert s["count"] == len(state_b_types(p, math.cos(mid), math.sin(mid)))
    assert dm.counts.max() == 3  # Fig. 5(b): three solutions in one sector


def test_param_param_map_classes():
    p = cpkit.ContactParameters(mu=1.0, **FIG5)
    m = cpkit.param_param_map(p, "b", "mu", 0.1, 4, 12, "a12", -0.9, 0.9, 10)
    assert m.cls.shape == (12, 10)
    for i, mu in enumerate(m.x):
        for j, a12 in enumerate(m.y):
            if abs(1.0 - mu * abs(a12)) < 1e-9:
                continue
            # state b: unique for every direction iff a11 > mu |a12|, else non-unique for some
            expected = "unique" if 1.0 > mu * abs(a12) else "non-unique"
            assert cpkit.UNIQUENESS_CLASSES[m.cls[i, j]] == expected, (mu, a12)


def test_step_hand_case():
    # docs/simulation.md: from state b with a11 = a12 = mu = 1, a22 = 2, DF = (0.5, 0.5): the
    # stick point DP = (0.5, 0.5) and the slip+ segment DP_T = DP_N = x, Dw_T^i = 0.5 - x,
    # closed at x = 0 (zero-force slip), open at the stick end x = 0.5.
    p = cpkit.ContactParameters(a11=1, a12=1, a22=2, mu=1)
    s = cpkit.enumerate_step(p, 0, 0, 0, (0.5, 0.5))
    assert s.count == -1 and sorted(s.types) == ["slip+", "stick"]
    assert s.complete and s.message == ""  # a well-conditioned step is proved complete
    stick = [x for x in s.solutions if x.type == "stick"][0]
    assert stick.start["DP_T"] == pytest.approx(0.5) and stick.start["DP_N"] == pytest.approx(0.5)
    seg = [x for x in s.solutions if x.type == "slip+"][0]
    ends = {(round(e["DP_N"], 12), round(e["Dw_Ti"], 12), closed)
            for e, closed in ((seg.start, seg.start_closed), (seg.end, seg.end_closed))}
    assert ends == {(0.0, 0.5, True), (0.5, 0.0, False)}
    one = cpkit.solve_step(p, 0, 0, 0, (0.5, 0.5))
    assert one["result"].is_solution


def test_simulation_agrees_with_the_cli():
    path = os.path.join(SOURCE_DIR, "docs", "examples", "fretting.json")
    with open(path) as f:
        cfg = json.load(f)
    _, cli = run_cli("simulate", "--config", path, "--json")
    h = cfg["heat"]
    params = cpkit.ContactParameters(**cfg["parameters"])
    load = {k: v for k, v in cfg["load"].items() if k != "type"}
    history = cpkit.fretting_history(**load)
    heat = {k: h[k] for k in ("heat_capacity", "T_ref", "T_initial", "T_body", "conductance")}
    r = cpkit.simulate(params, history, heat=heat)
    assert r.outcome == cli["outcome"] == "completed"
    assert r.steps == cli["steps"]
    assert r.wear_depth == pytest.approx(cli["final_wear_depth"], rel=1e-12)
    np.testing.assert_allclose(r.slip_per_cycle, cli["slip_per_cycle"], rtol=1e-12)
    assert r.series["P_T"][-1] == pytest.approx(cli["final"]["P_T"], rel=1e-12)
    assert r.max_temperature == pytest.approx(cli["temperature"]["max"], rel=1e-12)
    # Coulomb's law holds along the whole series (|P_T| <= mu P_N).
    assert (np.abs(r.series["P_T"]) <= params.mu * r.series["P_N"] * (1 + 1e-12) + 1e-15).all()
    pickle.loads(pickle.dumps(r))


def test_oversized_requests_are_refused_up_front():
    with pytest.raises(ValueError, match="100000 x 100000 .*limit is 1 GiB"):
        cpkit.param_direction_map(cpkit.ContactParameters(), "b", "mu", 0.1, 1, 100000, 100000)
    with pytest.raises(ValueError, match="limit is 1 GiB"):
        cpkit.param_param_map(cpkit.ContactParameters(), "b", "mu", 0.1, 1, 100000, "a22", 1, 2,
                              100000)
    with pytest.raises(ValueError, match="limit is 1 GiB"):
        cpkit.fretting_history(cycles=10**6, steps_per_cycle=10**6)

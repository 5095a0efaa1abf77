"""LCP: solve / enumerate / cross_verify against closed forms, a brute force written here and
the cpkit CLI on the same files."""
import json
import os
import pickle

import numpy as np
import pytest

import cpkit
from conftest import DATA_DIR, brute_force_lcp, run_cli

M2 = np.array([[2.0, 1.0], [1.0, 2.0]])
q2 = np.array([-5.0, -6.0])
Z2 = np.array([4.0 / 3.0, 7.0 / 3.0])  # by hand: M z = -q, both positive


@pytest.mark.parametrize("solver", cpkit.solvers("lcp"))
def test_every_solver_matches_the_closed_form(solver):
    r = cpkit.solve(M2, q2, solver=solver)
    assert r.is_solution, r
    np.testing.assert_allclose(r.z, Z2, rtol=1e-8)
    np.testing.assert_allclose(r.w, M2 @ r.z + q2, atol=1e-12)
    assert r.residuals.natural <= 1e-10


def test_one_default_solver_for_python_and_the_command_line():
    # Issue 37: the command line defaulted to Lemke (ray_termination, exit 1, on a game with three
    # equilibria), Python to auto. One default, defined once in the library.
    import inspect
    assert inspect.signature(cpkit.solve).parameters["solver"].default == "auto"
    path = os.path.join(DATA_DIR, "lcp", "battle_of_the_sexes.json")
    with open(path) as f:
        doc = json.load(f)
    M, q = np.array(doc["M"], float), np.array(doc["q"], float)
    r = cpkit.solve(M, q)
    assert r.is_solution
    _, out = run_cli("lcp", "solve", path, "--json")
    assert out["run"]["options"]["solver"] == "auto"
    # Both answers are among the three equilibria the file lists (bimatrix_examples, by hand).
    for z in (r.z, np.array(out["z"])):
        assert min(np.abs(z - np.array(s)).max() for s in doc["expected"]["solutions"]) < 1e-9


def test_result_fields_repr_and_pickle():
    r = cpkit.solve(M2, q2)  # auto: every attempt reported
    assert r.status == "solved" and r.attempts and r.attempts[-1].status == "solved"
    assert isinstance(r.z, np.ndarray) and isinstance(r.w, np.ndarray)
    text = repr(r)
    assert "status='solved'" in text and "1.333333" in text
    back = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(back.z, r.z)
    assert back.status == r.status and back.residuals == r.residuals


def test_sparse_input_gives_the_linear_solution():
    # Tridiagonal M (P-matrix) with q < 0 chosen so that the solution is z = 1: then w = 0 and
    # z solves the linear system; the answer is known before solving.
    import scipy.sparse as sp
    n = 50
    M = sp.diags([-1.0, 4.0, -1.0], [-1, 0, 1], shape=(n, n), format="csr")
    q = -(M @ np.ones(n))
    for solver in ("fb-newton", "auto"):
        r = cpkit.solve(M, q, solver=solver)
        assert r.is_solution, r
        np.testing.assert_allclose(r.z, np.ones(n), rtol=1e-8)


def test_infeasible_lcp_has_a_checked_certificate():
    M = np.array([[1.0, -1.0], [-1.0, 1.0]])
    q = np.array([-1.0, -1.0])  # w1 + w2 = -2 < 0 for every z: infeasible
    r = cpkit.solve(M, q, solver="lemke")
    assert r.status == "infeasible"
    y = r.certificate.y
    assert (y >= 0).all() and (M.T @ y <= 1e-12).all() and q @ y < 0  # checked here, in numpy


def test_enumerate_matches_brute_force_on_random_problems():
    rng = np.random.default_rng(7)
    for _ in range(40):
        n = int(rng.integers(1, 6))
        M = rng.normal(size=(n, n))
        q = rng.normal(size=n)
        s = cpkit.enumerate(M, q)
        assert s.complete
        expected = brute_force_lcp(M, q)
        assert s.count == len(expected), (M, q)
        for z in expected:
            assert any(np.allclose(z, e.z, atol=1e-8 * (1 + np.abs(z).max())) for e in s.solutions)


def test_enumerate_reports_a_continuum():
    # M = 0, q = 0: every z >= 0 solves it (one piece, rays e1, e2).
    s = cpkit.enumerate(np.zeros((2, 2)), np.zeros(2))
    assert s.infinite and s.complete and s.pieces


@pytest.mark.parametrize("name", ["cps_example_4_4_7", "battle_of_the_sexes", "murty_exp_6",
                                  "pang_isolated"])
def test_enumerate_agrees_with_the_cli(name):
    path = os.path.join(DATA_DIR, "lcp", name + ".json")
    with open(path) as f:
        data = json.load(f)
    _, cli = run_cli("lcp", "enumerate", path, "--json", expect=(0, 1))
    s = cpkit.enumerate(data["M"], data["q"])
    assert s.complete == cli["complete"]
    assert s.count == cli["num_extreme"]
    for sol in cli["solutions"]:
        assert any(np.allclose(np.array(sol["z"], float), e.z, atol=1e-9) for e in s.solutions)


def test_cross_verify_is_consistent():
    rep = cpkit.cross_verify(M2, q2, skip=["ipopt", "nlopt"])
    assert rep.consistent and rep.set.count == 1
    assert {c.solver for c in rep.checks} >= {"lemke", "fb-newton"}
    assert all(c.verdict == "consistent" for c in rep.checks)
    pickle.loads(pickle.dumps(rep))


@pytest.mark.parametrize("M, q, exc, words", [
    ([[1.0, 2.0]], [1.0], ValueError, "square"),
    ([[1.0, 2.0], [3.0, 4.0]], [1.0], ValueError, "size mismatch"),
    ([[1.0, np.nan], [3.0, 4.0]], [1.0, 2.0], ValueError, "non-finite"),
    ([1.0, 2.0], [1.0, 2.0], ValueError, "2-D"),
    ("abc", [1.0], TypeError, "matrix of numbers"),
    ([[1.0]], [[1.0]], ValueError, "1-D"),
])
def test_bad_input_raises_with_the_message(M, q, exc, words):
    with pytest.raises(exc, match=words):
        cpkit.solve(M, q)


def test_unknown_solver_lists_the_valid_ones():
    with pytest.raises(ValueError, match="unknown solver 'simplex'.*lemke"):
        cpkit.solve(M2, q2, solver="simplex")


def test_enumeration_beyond_max_size_is_incomplete_not_wrong():
    # n = 31 > max_size = 30: the general engine does not attempt it and says so.
    s = cpkit.enumerate(np.eye(31), -np.ones(31), max_size=30)
    assert not s.complete and "max_size" in s.message


def test_enumeration_max_size_out_of_range_is_an_error():
    with pytest.raises(ValueError):
        cpkit.enumerate(np.eye(2), -np.ones(2), max_size=65)

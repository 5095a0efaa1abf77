"""solve_batch (many small LCPs in one call) and the quick route of solve() (issue 27): every
answer checked by this file's own complementarity test, against single calls, against a
closed form, and bad input (shapes, NaN/Inf, unknown solver) refused with a clear ValueError."""
import pickle

import numpy as np
import pytest

import cpkit
from cpkit import _cpkit


def is_lcp_solution(M, q, z, tol=1e-9):
    """z >= 0, w = M z + q >= 0, z.w = 0, each to tol relative to the data's scale (written
    here, independently of cpkit's residuals)."""
    w = M @ z + q
    scale = max(1.0, np.abs(q).max(), np.abs(M).max() * max(1.0, np.abs(z).max()))
    return (z.min() >= -tol * scale and w.min() >= -tol * scale
            and abs(z @ w) <= tol * scale * max(1.0, np.abs(z).sum()))


def spd_batch(k, n, seed):
    """k random SPD (hence P-matrix: exactly one solution each) problems of size n."""
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((k, n, n))
    Ms = A @ A.transpose(0, 2, 1) + np.eye(n)
    qs = rng.standard_normal((k, n)) * 3
    return Ms, qs


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_batch_answers_are_solutions_and_equal_single_calls(n):
    Ms, qs = spd_batch(300, n, seed=n)
    b = cpkit.solve_batch(Ms, qs, solver="lemke")
    assert len(b) == 300 and b.z.shape == (300, n) and b.w.shape == (300, n)
    assert b.is_solution.all(), b.status[~b.is_solution]
    for i in range(300):
        assert is_lcp_solution(Ms[i], qs[i], b.z[i]), i
        one = cpkit.solve(Ms[i], qs[i], solver="lemke")
        assert one.status == b.status[i]
        np.testing.assert_allclose(b.z[i], one.z, rtol=1e-12, atol=1e-14)
        np.testing.assert_allclose(b.w[i], one.w, rtol=1e-12, atol=1e-14)
        assert b.residual[i] == one.residuals.natural


def test_batch_closed_form_and_other_solvers():
    # M = [[2, 1], [1, 2]], q = (-5, -6): w = 0, z = M^-1 (5, 6) = (4/3, 7/3) by hand.
    Ms = np.tile([[2.0, 1.0], [1.0, 2.0]], (4, 1, 1))
    qs = np.tile([-5.0, -6.0], (4, 1))
    for solver in ("lemke", "fb-newton", "auto"):
        b = cpkit.solve_batch(Ms, qs, solver=solver)
        assert (b.status == "solved").all()
        np.testing.assert_allclose(b.z, np.tile([4 / 3, 7 / 3], (4, 1)), rtol=1e-9)
    # Lists convert; the default solver is solve()'s ("auto"); an empty batch gives empty arrays.
    b = cpkit.solve_batch(Ms.tolist(), qs.tolist())
    assert b.solver == "auto" and (b.status == "solved").all()
    e = cpkit.solve_batch(np.zeros((0, 3, 3)), np.zeros((0, 3)))
    assert len(e) == 0 and e.z.shape == (0, 3)


def test_batch_mixed_outcomes_keep_their_rows():
    # Row 1 has no solution: M = [[-1]] (w = -z - 1 < 0 for every z >= 0). The batch's
    # default is solve()'s: each row's status is that of solve() with its default.
    Ms = np.array([[[1.0]], [[-1.0]], [[2.0]]])
    qs = np.array([[-1.0], [-1.0], [4.0]])
    b = cpkit.solve_batch(Ms, qs)
    assert list(b.is_solution) == [True, False, True]
    assert b.status[1] == cpkit.solve(Ms[1], qs[1]).status
    np.testing.assert_allclose(b.z[[0, 2], 0], [1.0, 0.0])  # z = 1 (w = 0); z = 0 (w = 4)
    assert "3 problems" in repr(b) and "2 solved" in repr(b)


def test_batch_bad_input_is_named():
    Ms, qs = spd_batch(5, 2, seed=7)
    cases = [
        ((Ms[:, :, :1], qs), "shape (k, n, n)"),
        ((Ms[0], qs[0]), "shape (k, n, n)"),
        ((Ms, qs[:4]), "qs must have shape (k, n) = (5, 2)"),
        ((Ms, qs[:, :1]), "qs must have shape"),
    ]
    for (m, q), text in cases:
        with pytest.raises(ValueError, match=text.replace("(", r"\(").replace(")", r"\)")):
            cpkit.solve_batch(m, q)
    bad = Ms.copy()
    bad[3, 1, 0] = np.nan
    with pytest.raises(ValueError, match=r"Ms\[3\] has a non-finite entry .* at \(1, 0\)"):
        cpkit.solve_batch(bad, qs)
    badq = qs.copy()
    badq[2, 1] = np.inf
    with pytest.raises(ValueError, match=r"qs\[2\] has a non-finite entry"):
        cpkit.solve_batch(Ms, badq)
    with pytest.raises(ValueError, match="unknown solver 'lemk'"):
        cpkit.solve_batch(Ms, qs, solver="lemk")
    with pytest.raises(ValueError, match="tol"):
        cpkit.solve_batch(Ms, qs, tol=-1.0)
    with pytest.raises(TypeError):
        cpkit.solve_batch([["a"]], [[1.0]])


def test_quick_route_gives_the_general_routes_result():
    # The quick route (float64 numpy arrays) and the general one (lists) return equal objects.
    M = np.array([[2.0, 1.0], [1.0, 2.0]])
    q = np.array([-5.0, -6.0])
    quick = cpkit.solve(M, q, solver="lemke")
    general = cpkit.solve(M.tolist(), q.tolist(), solver="lemke")
    assert type(quick) is type(general) is cpkit.SolveResult
    for f in ("status", "solver", "iterations", "basis", "message", "certificate", "ray"):
        assert getattr(quick, f) == getattr(general, f), f
    assert quick.residuals == general.residuals
    np.testing.assert_array_equal(quick.z, general.z)
    np.testing.assert_array_equal(quick.w, general.w)
    assert is_lcp_solution(M, q, quick.z)
    back = pickle.loads(pickle.dumps(quick))
    assert back.status == "solved" and back.residuals == quick.residuals
    # "auto" reports its attempts as Attempt objects on the quick route too.
    auto = cpkit.solve(M, q)
    assert auto.attempts and isinstance(auto.attempts[0], cpkit.results.Attempt)
    # Arrays the extension cannot read in place (non-contiguous, big-endian) give the same z.
    Mt = np.asfortranarray(M)
    np.testing.assert_array_equal(cpkit.solve(Mt, q, solver="lemke").z, quick.z)
    np.testing.assert_array_equal(
        cpkit.solve(M.astype(">f8"), q.astype(">f8"), solver="lemke").z, quick.z)
    # An infeasible problem keeps its certificate on the quick route.
    inf = cpkit.solve(np.array([[-1.0]]), np.array([-1.0]), solver="lemke")
    assert not inf.is_solution


def test_quick_route_bad_input_messages():
    M = np.array([[2.0, 1.0], [1.0, 2.0]])
    with pytest.raises(ValueError, match=r"M must be a 2-D array, got shape \(3,\)"):
        cpkit.solve(np.ones(3), np.ones(3), solver="lemke")
    with pytest.raises(ValueError, match=r"q must be a 1-D array"):
        cpkit.solve(M, np.ones((2, 1)), solver="lemke")
    with pytest.raises(ValueError, match=r"M is not square \(2 x 3\)"):
        cpkit.solve(np.ones((2, 3)), np.ones(2), solver="lemke")
    with pytest.raises(ValueError, match=r"non-finite entry at \(0, 1\)"):
        cpkit.solve(np.array([[1.0, np.nan], [0.0, 1.0]]), np.ones(2), solver="lemke")
    with pytest.raises(ValueError, match="unknown solver"):
        cpkit.solve(M, np.ones(2), solver="nope")
    assert _cpkit.STATUS_NAMES[1] == "solved"

"""NCP/MCP with Python callables: closed-form solutions, exceptions raised inside F or J come
back unchanged (never a crash), bad shapes are ValueErrors, and solves run without the GIL."""
import pickle
import threading

import numpy as np
import pytest

import cpkit


def F_quad(x):  # NCP x >= 0, F >= 0, x.F = 0 with F_i = x_i^2 - c_i: x_i = sqrt(c_i) for c_i > 0
    return x * x - np.array([4.0, 0.25, -1.0])


def J_quad(x):
    return np.diag(2.0 * x)


# Solution by hand: x = (2, 0.5, 0) with F = (0, 0, 1).
X_QUAD = np.array([2.0, 0.5, 0.0])


@pytest.mark.parametrize("solver", ["fb-newton", "ipopt", "nlopt", "auto"])
def test_ncp_closed_form(solver):
    r = cpkit.solve_mcp(F_quad, J_quad, [1.0, 1.0, 1.0], solver=solver)
    assert r.is_solution, r
    np.testing.assert_allclose(r.z, X_QUAD, atol=1e-7)
    np.testing.assert_allclose(r.w, F_quad(r.z), atol=1e-12)
    pickle.loads(pickle.dumps(r))


def test_finite_differences_and_sparse_jacobian():
    import scipy.sparse as sp
    for J in (None, lambda x: sp.diags(2.0 * x)):
        r = cpkit.solve_mcp(F_quad, J, [1.0, 1.0, 1.0])
        assert r.is_solution, r
        np.testing.assert_allclose(r.z, X_QUAD, atol=1e-8)


def test_box_mcp_closed_form():
    # F(x) = x - c on [l, u]: the solution is the projection mid(l, u, c).
    c = np.array([-2.0, 0.3, 5.0, 1.0])
    lower = np.array([-1.0, 0.0, -np.inf, -np.inf])
    upper = np.array([1.0, 1.0, 2.0, np.inf])
    r = cpkit.solve_mcp(lambda x: x - c, lambda x: np.eye(4), np.zeros(4), lower, upper)
    assert r.is_solution, r
    np.testing.assert_allclose(r.z, [-1.0, 0.3, 2.0, 1.0], atol=1e-10)


class Boom(Exception):
    pass


@pytest.mark.parametrize("solver", ["fb-newton", "ipopt", "nlopt", "auto"])
@pytest.mark.parametrize("where", ["F", "J"])
def test_exception_inside_a_callback_comes_back(solver, where):
    calls = {"n": 0}

    def F(x):
        calls["n"] += 1
        if where == "F" and calls["n"] > 2:
            raise Boom("from F")
        return F_quad(x)

    def J(x):
        if where == "J":
            raise Boom("from J")
        return J_quad(x)

    with pytest.raises(Boom, match="from " + where):
        cpkit.solve_mcp(F, J, [1.0, 1.0, 1.0], solver=solver)


def test_wrong_shapes_are_value_errors():
    with pytest.raises(ValueError, match="length 3"):
        cpkit.solve_mcp(lambda x: np.zeros(2), None, np.ones(3))
    with pytest.raises(ValueError, match="n x n"):
        cpkit.solve_mcp(F_quad, lambda x: np.eye(2), np.ones(3))
    with pytest.raises(TypeError):
        cpkit.solve_mcp("not callable", None, np.ones(3))
    with pytest.raises(ValueError, match="unknown MCP solver"):
        cpkit.solve_mcp(F_quad, J_quad, np.ones(3), solver="lemke")


def test_none_means_outside_the_domain():
    # F(x) = sqrt(x) - 1 is undefined for x < 0; the solution is x = 1.
    def F(x):
        return None if (x < 0).any() else np.sqrt(x) - 1.0
    r = cpkit.solve_mcp(F, None, [4.0])
    assert r.is_solution and abs(r.z[0] - 1.0) < 1e-8


def test_long_computations_release_the_gil():
    # While a worker thread is inside one long C++ call (a parameter x parameter map, ~0.2 s),
    # the main thread keeps running Python: it records time stamps, some of which must fall
    # strictly inside the call. With the GIL held there would be none (at most one at a switch).
    import time
    params = cpkit.ContactParameters(a11=1, a12=0.5, a22=1, C_T=0.25, mu=3)
    span = {}

    def work():
        span["enter"] = time.perf_counter()
        cpkit.param_param_map(params, "b", "mu", 0.1, 4, 100, "a12", -0.9, 0.9, 100, threads=1)
        span["exit"] = time.perf_counter()

    t = threading.Thread(target=work)
    stamps = []
    t.start()
    while t.is_alive():
        stamps.append(time.perf_counter())
        time.sleep(0.001)
    t.join()
    inside = [s for s in stamps if span["enter"] < s < span["exit"]]
    assert len(inside) >= 5, (len(inside), span)


def test_callbacks_from_two_threads():
    # Two MCP solves at once, each calling back into Python: no deadlock, both correct.
    results = [None, None]

    def work(k):
        results[k] = cpkit.solve_mcp(F_quad, J_quad, [1.0 + k, 1.0, 1.0])

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=60)
    for r in results:
        assert r is not None and r.is_solution
        np.testing.assert_allclose(r.z, X_QUAD, atol=1e-8)

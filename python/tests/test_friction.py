"""Friction problems from FCLIB / Siconos files (cpkit.read_fclib, cpkit.solve_friction): the
reader against Siconos' own (python3-siconos; skipped without it) and numbers read by eye; the
solver's r re-checked here with numpy (cone, dual cone, complementarity on u = W r + q)."""
import os

import numpy as np
import pytest

import cpkit
from conftest import DATA_DIR

FCLIB = os.path.join(DATA_DIR, "fclib", "local")
DAT_FILES = sorted(f for f in os.listdir(FCLIB) if f.endswith(".dat"))


def test_numbers_read_by_eye():
    p = cpkit.read_fclib(os.path.join(FCLIB, "FrictionContact3D_1c.dat"))
    np.testing.assert_array_equal(p.W.toarray(), [[15, -1, -2], [-1, 14, 1], [-2, 1, 16]])
    np.testing.assert_array_equal(p.q, [-1, 2, 3])
    np.testing.assert_array_equal(p.mu, [0.1])
    assert p.contacts == 1 and p.name == "FrictionContact3D_1c"


@pytest.mark.parametrize("name", DAT_FILES)
def test_dat_files_read_as_siconos_reads_them(name):
    sn = pytest.importorskip("siconos.numerics", reason="python3-siconos is not installed")
    path = os.path.join(FCLIB, name)
    s = sn.frictionContact_new_from_filename(path)
    M = s.M
    W = np.array([[sn.NM_get_value(M, i, j) for j in range(M.size1)] for i in range(M.size0)])
    p = cpkit.read_fclib(path)
    assert p.contacts == s.numberOfContacts
    np.testing.assert_array_equal(p.W.toarray(), W)
    np.testing.assert_array_equal(p.q, np.asarray(s.q))
    np.testing.assert_array_equal(p.mu, np.asarray(s.mu))


def check_solution(W, q, mu, r, tol=1e-8):
    u = W @ r + q
    rs, us = max(abs(r).max(), 1e-300), abs(u).max() + abs(q).max()
    for i, m in enumerate(mu):
        rn, rt = r[3 * i], np.hypot(*r[3 * i + 1:3 * i + 3])
        ut = np.hypot(*u[3 * i + 1:3 * i + 3])
        hn = u[3 * i] + m * ut  # De Saxce's u_hat
        assert rt <= m * rn + tol * rs
        assert m * ut <= hn + tol * us
        assert abs(rn * hn + r[3 * i + 1:3 * i + 3] @ u[3 * i + 1:3 * i + 3]) <= tol * rs * us


@pytest.mark.parametrize("name", ["FrictionContact3D_1c.dat", "Rover4396.dat",
                                  "fclib_local_problem_test.hdf5"])
def test_solve_friction_gives_a_checked_solution(name):
    p = cpkit.read_fclib(os.path.join(FCLIB, name))
    res = cpkit.solve_friction(p)
    assert res.solved and res.status == "solved", res
    assert res.errors["unit_free"] <= 1e-10
    check_solution(p.W, p.q, p.mu, res.r)
    # W, q, mu given directly (a dense W is accepted too)
    res2 = cpkit.solve_friction(p.W.toarray(), p.q, p.mu, solver="fb-soc")
    if res2.solved:
        check_solution(p.W, p.q, p.mu, res2.r)


def test_bad_files_and_solvers_are_value_errors(tmp_path):
    bad = tmp_path / "bad.dat"
    bad.write_text("3 1 0 3 3 3 3 1 2 3")
    with pytest.raises(ValueError, match="bad.dat"):
        cpkit.read_fclib(bad)
    p = cpkit.read_fclib(os.path.join(FCLIB, "Rover4396.dat"))
    with pytest.raises(ValueError, match="nope"):
        cpkit.solve_friction(p, solver="nope")

"""Hostile input to the Python API (issue 34; ../shared/problems/hostile-friction/F4-06): a
scipy.sparse matrix whose indices are out of range, negative, or whose indptr is not a valid
column pointer crashed the interpreter or was "solved" for another matrix. Each such case runs in
a CHILD interpreter, so that a crash is a failed test here and not the end of pytest, and must
raise ValueError naming the bad entry. Also: complex and string data (TypeError), integer
options beyond a C++ int (ValueError naming the option and its range), bytes and os.PathLike
paths, a missing file (FileNotFoundError), and the friction calls taking a problem object.

Oracles: the hand solution of W = diag(2, 1, 1), q = (-2, 3, 4), mu = 1/2 (slip: u_N = 0 gives
r_N = 1; r_T = -mu r_N (3, 4)/5 = (-0.3, -0.4), u_T = (2.7, 3.6) along (3, 4)), which every
valid way of writing W (CSC, CSR, COO, unsorted, duplicates summed) must give; the messages
name the entry as the FCLIB reader does ("W: entry (7, 2) outside its 3 x 3 size")."""
import json
import os
import pathlib
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import scipy.sparse as sp

import cpkit
from conftest import DATA_DIR

# ---- malformed sparse matrices, each in a child interpreter ----------------------------------

CHILD = textwrap.dedent("""\
    import json, numpy as np, scipy.sparse as sp, cpkit
    def bad(last, fmt=sp.csc_matrix):
        return fmt((np.array([2., 1, 1]), np.array([0, 1, last]), np.array([0, 1, 2, 3])),
                   shape=(3, 3))
    def bad_indptr(indptr):  # scipy's constructor checks indptr: replaced after construction
        W = sp.csc_matrix(np.diag([2., 1, 1]))
        W.indptr = np.array(indptr, dtype=np.int32)
        return W
    try:
        r = {call}
        print(json.dumps({{"returned": str(getattr(r, "status", r))}}))
    except Exception as e:
        print(json.dumps({{"type": type(e).__name__, "message": str(e)}}))
    """)

Q, MU = "[-2., 3, 4]", "[0.5]"
GLOBAL = ("cpkit.solve_friction_global(cpkit.GlobalFrictionProblem(M={M}, H={H}, "
          "f=np.array([-1., 0, 0]), w=np.zeros(3), mu=np.array([0.5])))")
EYE = "sp.identity(3, format='csc')"

# (call, the words the ValueError must contain)
CASES = {
    # F4-06's own cases (its README: CRASH signal 11 / 6, or "solved" for index -5)
    "solve_friction, row 7": (f"cpkit.solve_friction(bad(7), {Q}, {MU})",
                              "W: entry (7, 2) outside its 3 x 3 size"),
    "solve_friction, row 1e8": (f"cpkit.solve_friction(bad(100000000), {Q}, {MU})",
                                "W: entry (100000000, 2) outside its 3 x 3 size"),
    "solve_friction, row -5": (f"cpkit.solve_friction(bad(-5), {Q}, {MU})",
                               "W: entry (-5, 2) outside its 3 x 3 size"),
    "friction_errors, row 1e8": (f"cpkit.friction_errors(bad(100000000), {Q}, {MU}, [1, 0, 0])",
                                 "W: entry (100000000, 2) outside"),
    "friction_solutions, row 7": (f"cpkit.friction_solutions(bad(7), {Q}, {MU}, starts=1)",
                                  "W: entry (7, 2) outside"),
    "solve_friction_global, M row 5e7": (GLOBAL.format(M="bad(50000000)", H=EYE),
                                         "M: entry (50000000, 2) outside its 3 x 3 size"),
    "lcp solve (sparse M), row 1e8": ("cpkit.solve(bad(100000000), [-1., -1, -1])",
                                      "M: entry (100000000, 2) outside"),
    # the same check on every other route that takes a sparse matrix
    "solve_friction_global, H row -1": (GLOBAL.format(M=EYE, H="bad(-1)"),
                                        "H: entry (-1, 2) outside its 3 x 3 size"),
    "lcp enumerate (sparse M), row 3": ("cpkit.enumerate(bad(3), [-1., -1, -1])",
                                        "M: entry (3, 2) outside its 3 x 3 size"),
    "lcp cross_verify (sparse M), row -5": ("cpkit.cross_verify(bad(-5), [-1., -1, -1])",
                                            "M: entry (-5, 2) outside"),
    "mcp sparse J(x), row 9": ("cpkit.solve_mcp(lambda x: x - 1, lambda x: bad(9), np.zeros(3))",
                               "J(x): entry (9, 2) outside its 3 x 3 size"),
    "CSR column index 7": (f"cpkit.solve_friction(bad(7, fmt=sp.csr_matrix), {Q}, {MU})",
                           "W: entry (2, 7) outside its 3 x 3 size"),
    # scipy's COO constructor checks bounds: the row array is replaced after construction
    "COO row index 7": (f"(lambda W: (setattr(W, 'row', np.array([0, 1, 7], dtype=np.int32)), "
                        f"cpkit.solve_friction(W, {Q}, {MU}))[1])(sp.coo_matrix(np.eye(3)))",
                        "W: entry (7, 2) outside its 3 x 3 size"),
    "a huge declared size, no entries": ("cpkit.solve(sp.coo_matrix((2**31 - 1, 2**31 - 1)), [1.0])",
                                         "M: 2147483647 x 2147483647 declares more than"),
    "indptr decreasing": (f"cpkit.solve_friction(bad_indptr((0, 2, 1, 3)), {Q}, {MU})",
                          "W: indptr decreases: indptr[2] = 1 < indptr[1] = 2"),
    "indptr not starting at 0": (f"cpkit.solve_friction(bad_indptr((1, 1, 2, 3)), {Q}, {MU})",
                                 "W: indptr[0] = 1, must be 0"),
    "indptr past the entries": (f"cpkit.solve_friction(bad_indptr((0, 1, 2, 90000000)), {Q}, "
                                f"{MU})",
                                "W: indptr ends at 90000000 but 3 entries are stored"),
    "indptr of the wrong size": (f"cpkit.solve_friction(bad_indptr((0, 1, 3)), {Q}, {MU})",
                                 "W: indptr has 3 entries; a 3 x 3 CSC matrix needs 4"),
}


@pytest.fixture(scope="module")
def child_outcomes():
    """{case: (exit code, its last JSON line, stderr)}, every case in its own child interpreter,
    all started at once (each spends most of its time importing numpy, scipy and cpkit)."""
    children = {name: subprocess.Popen([sys.executable, "-c", CHILD.format(call=call)],
                                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                for name, (call, _) in CASES.items()}
    outcomes = {}
    for name, p in children.items():
        out, err = p.communicate(timeout=300)
        lines = out.strip().splitlines()
        outcomes[name] = (p.returncode, json.loads(lines[-1]) if lines else {}, err)
    return outcomes


def test_the_hostile_cases_are_all_here():
    assert len(CASES) >= 18  # the 7 of F4-06's README and the other routes: none left out


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_malformed_sparse_matrix_raises_value_error_naming_the_entry(name, child_outcomes):
    words = CASES[name][1]
    rc, out, err = child_outcomes[name]
    assert rc == 0, f"{name}: the interpreter died (exit {rc})\n{err[-2000:]}"
    assert out.get("type") == "ValueError", (name, out)
    assert words in out["message"], (name, out["message"])


def test_the_malformed_matrices_are_accepted_by_scipy_itself():
    # the hostile input is real: scipy's constructor lets each index through unchecked
    for last in (7, 100000000, -5):
        W = sp.csc_matrix((np.array([2., 1, 1]), np.array([0, 1, last]), np.array([0, 1, 2, 3])),
                          shape=(3, 3))
        assert W.indices[2] == last and W.has_canonical_format


# ---- every valid way of writing one W gives the hand answer ----------------------------------

R_HAND = np.array([1.0, -0.3, -0.4])
Q_HAND, MU_HAND = np.array([-2.0, 3.0, 4.0]), np.array([0.5])
W_DENSE = np.diag([2.0, 1.0, 1.0])


def unsorted_csc_with_duplicates():
    # column 0 holds (0, 0) twice (1.5 + 0.5) and an explicit zero at (2, 0), rows unsorted
    data = np.array([0.0, 1.5, 0.5, 1.0, 1.0])
    rows = np.array([2, 0, 0, 1, 2])
    W = sp.csc_matrix((data, rows, np.array([0, 3, 4, 5])), shape=(3, 3))
    assert not W.has_canonical_format
    return W


@pytest.mark.parametrize("form", ["dense", "csc", "csr", "coo", "lil", "csc_array",
                                  "unsorted_duplicates"])
def test_every_valid_form_of_w_gives_the_hand_answer(form):
    W = {"dense": W_DENSE, "csc": sp.csc_matrix(W_DENSE), "csr": sp.csr_matrix(W_DENSE),
         "coo": sp.coo_matrix(W_DENSE), "lil": sp.lil_matrix(W_DENSE),
         "csc_array": sp.csc_array(W_DENSE),
         "unsorted_duplicates": unsorted_csc_with_duplicates()}[form]
    res = cpkit.solve_friction(W, Q_HAND, MU_HAND)
    assert res.status == "solved"
    np.testing.assert_allclose(res.r, R_HAND, atol=1e-9)
    np.testing.assert_allclose(res.u, W_DENSE @ R_HAND + Q_HAND, atol=1e-9)


def test_the_sparse_lcp_reads_csr_and_coo_as_the_dense_one():
    # LCP(diag(2, 1, 1), (-2, 3, -4)) has the one solution z = (1, 0, 4) (w = 0, 3, 0)
    q = np.array([-2.0, 3.0, -4.0])
    for M in (sp.csr_matrix(W_DENSE), sp.coo_matrix(W_DENSE), sp.csc_matrix(W_DENSE)):
        np.testing.assert_allclose(cpkit.solve(M, q).z, [1.0, 0.0, 4.0], atol=1e-12)


# ---- complex and string data: TypeError --------------------------------------------------------

TYPE_ERRORS = {
    "complex q": lambda: cpkit.solve_friction(W_DENSE, Q_HAND + 1e-3j, MU_HAND),
    "complex dense W": lambda: cpkit.solve_friction(W_DENSE + 0j, Q_HAND, MU_HAND),
    "complex sparse W": lambda: cpkit.solve_friction(sp.csc_matrix(W_DENSE + 1j), Q_HAND, MU_HAND),
    "numeric strings in mu": lambda: cpkit.solve_friction(W_DENSE, Q_HAND, ["0.5"]),
    "numeric string tol": lambda: cpkit.solve_friction(W_DENSE, Q_HAND, MU_HAND, tol="1e-8"),
    "complex LCP M": lambda: cpkit.solve(np.array([[2, 1], [1, 2]], dtype=complex), [-5, -6]),
    "string LCP q": lambda: cpkit.solve([[2, 1], [1, 2]], ["-5", "-6"]),
    "complex sparse LCP M": lambda: cpkit.solve(sp.csc_matrix(np.eye(2) * 1j), [-1, -1]),
    "complex batch": lambda: cpkit.solve_batch(np.eye(2)[None] + 0j, [[-1.0, -1.0]]),
    "string enumerate q": lambda: cpkit.enumerate(np.eye(2), "12"),
    "complex friction_errors r": lambda: cpkit.friction_errors(W_DENSE, Q_HAND, MU_HAND,
                                                               R_HAND + 0j),
    "complex 3-D point A": lambda: cpkit.Point3d(A=np.eye(3) + 0j),
    "string alpha": lambda: cpkit.Point3d(alpha=["1", "1"]),
    "complex step load": lambda: cpkit.enumerate_step(cpkit.ContactParameters(a11=1, a12=0.5, a22=1,
                                                                              mu=0.5),
                                                      0.0, 0.0, 0.0, [1j, -1]),
    "None in q": lambda: cpkit.solve([[1.0]], [None]),
}


@pytest.mark.parametrize("name", sorted(TYPE_ERRORS))
def test_complex_and_string_data_raise_type_error(name):
    with pytest.raises(TypeError):
        TYPE_ERRORS[name]()


def test_the_type_error_says_why():
    with pytest.raises(TypeError, match="q must .*complex entries"):
        cpkit.solve_friction(W_DENSE, Q_HAND + 1e-3j, MU_HAND)
    with pytest.raises(TypeError, match="W has complex entries"):
        cpkit.solve_friction(sp.csc_matrix(W_DENSE + 1j), Q_HAND, MU_HAND)
    with pytest.raises(TypeError, match="mu must .*dtype <U3 \\(strings are not converted\\)"):
        cpkit.solve_friction(W_DENSE, Q_HAND, ["0.5"])


# ---- integer options beyond a C++ int: ValueError naming the option and its range ------------

INT_OPTIONS = {
    "solve max_iterations": (lambda v: cpkit.solve([[2.0, 1], [1, 2]], [-5.0, -6],
                                                   max_iterations=v), "max_iterations"),
    "solve_friction max_iterations": (lambda v: cpkit.solve_friction(
        W_DENSE, Q_HAND, MU_HAND, max_iterations=v), "max_iterations"),
    "solve_friction_global max_iterations": (lambda v: cpkit.solve_friction_global(
        cpkit.GlobalFrictionProblem(M=np.eye(3), H=np.eye(3), f=-Q_HAND, w=np.zeros(3),
                                    mu=MU_HAND), max_iterations=v), "max_iterations"),
    "solve_batch max_iterations": (lambda v: cpkit.solve_batch(
        np.eye(2)[None], [[-1.0, -1.0]], max_iterations=v), "max_iterations"),
    "solve_mcp max_iterations": (lambda v: cpkit.solve_mcp(
        lambda x: x - 1, None, np.zeros(2), max_iterations=v), "max_iterations"),
    "friction_solutions starts": (lambda v: cpkit.friction_solutions(
        W_DENSE, Q_HAND, MU_HAND, starts=v), "starts"),
    "enumerate max_size": (lambda v: cpkit.enumerate(np.eye(2), [-1.0, -1], max_size=v),
                           "max_size"),
    "param_direction_map n": (lambda v: cpkit.param_direction_map(
        cpkit.ContactParameters(a11=1, a12=0.5, a22=1), "b", "mu", 0.1, 4.0, n=v), "n"),
    "fretting_history cycles": (lambda v: cpkit.fretting_history(cycles=v), "cycles"),
}


@pytest.mark.parametrize("name", sorted(INT_OPTIONS))
def test_a_huge_integer_option_raises_value_error_naming_it(name):
    call, option = INT_OPTIONS[name]
    with pytest.raises(ValueError, match=rf"^{option} must be an integer in \[.*2147483647\], "
                                         rf"got 1099511627776$"):
        call(2**40)


def test_the_seed_range_is_that_of_an_unsigned_32_bit_integer():
    with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 4294967295\]"):
        cpkit.friction_solutions(W_DENSE, Q_HAND, MU_HAND, starts=1, seed=2**32)
    with pytest.raises(TypeError, match="max_iterations must be an integer, got str"):
        cpkit.solve([[1.0]], [-1.0], max_iterations="10")


# ---- paths: str, bytes, os.PathLike; a missing file is FileNotFoundError ----------------------

LOCAL_DAT = os.path.join(DATA_DIR, "fclib", "local", "FC3D_Example1.dat")
GLOBAL_DAT = os.path.join(DATA_DIR, "fclib", "global", "GFC3D_TwoRods1.dat")


def test_bytes_and_pathlike_paths_read_the_same_problem():
    by_str = cpkit.read_fclib(LOCAL_DAT)
    for path in (os.fsencode(LOCAL_DAT), pathlib.Path(LOCAL_DAT)):
        p = cpkit.read_fclib(path)
        assert (p.W != by_str.W).nnz == 0
        np.testing.assert_array_equal(p.q, by_str.q)
        np.testing.assert_array_equal(p.mu, by_str.mu)
    g = cpkit.read_fclib_global(os.fsencode(GLOBAL_DAT))
    np.testing.assert_array_equal(g.f, cpkit.read_fclib_global(GLOBAL_DAT).f)


@pytest.mark.parametrize("reader", ["read_fclib", "read_fclib_global", "ContactSystem.from_file",
                                    "ContactSystem3d.from_file", "ContactSystem3d"])
@pytest.mark.parametrize("kind", [str, os.fsencode, pathlib.Path])
def test_a_missing_file_raises_file_not_found_error(tmp_path, reader, kind):
    missing = kind(str(tmp_path / "missing.dat"))
    read = {"read_fclib": cpkit.read_fclib, "read_fclib_global": cpkit.read_fclib_global,
            "ContactSystem.from_file": cpkit.ContactSystem.from_file,
            "ContactSystem3d.from_file": cpkit.ContactSystem3d.from_file,
            "ContactSystem3d": cpkit.ContactSystem3d}[reader]
    with pytest.raises(FileNotFoundError, match="missing.dat") as e:
        read(missing)
    assert os.fsdecode(e.value.filename) == str(tmp_path / "missing.dat")


def test_a_path_of_another_type_raises_type_error():
    with pytest.raises(TypeError, match="path must be a str, bytes or os.PathLike"):
        cpkit.read_fclib(3)


# ---- the friction calls take the problem object ------------------------------------------------

def test_solve_friction_takes_the_problem_as_read_fclib_returns_it():
    p = cpkit.FrictionProblem(W=sp.csc_matrix(W_DENSE), q=Q_HAND, mu=MU_HAND)
    res = cpkit.solve_friction(p, solver="auto", tol=1e-10)
    assert res.status == "solved"
    np.testing.assert_allclose(res.r, R_HAND, atol=1e-9)
    e = cpkit.friction_errors(p, R_HAND)
    assert e == cpkit.friction_errors(p.W, p.q, p.mu, R_HAND) == cpkit.friction_errors(p, r=R_HAND)
    assert e.unit_free < 1e-15  # the hand answer is exact in binary except -0.3, -0.4
    s = cpkit.friction_solutions(p, starts=3)
    assert len(s) == 1  # slip, the only solution (W positive definite: unique)
    np.testing.assert_allclose(s.solutions[0].r, R_HAND, atol=1e-9)


def test_a_real_file_solves_the_same_through_the_problem_and_its_arrays():
    p = cpkit.read_fclib(LOCAL_DAT)
    a = cpkit.solve_friction(p, solver="nsgs")
    b = cpkit.solve_friction(p.W, p.q, p.mu, solver="nsgs")
    assert a.status == b.status
    np.testing.assert_array_equal(a.r, b.r)


def test_a_problem_with_extra_arrays_or_a_global_problem_is_refused():
    p = cpkit.FrictionProblem(W=sp.csc_matrix(W_DENSE), q=Q_HAND, mu=MU_HAND)
    with pytest.raises(TypeError, match="solver=..."):
        cpkit.solve_friction(p, "nsgs")
    g = cpkit.GlobalFrictionProblem(M=np.eye(3), H=np.eye(3), f=-Q_HAND, w=np.zeros(3),
                                    mu=MU_HAND)
    with pytest.raises(TypeError, match="solve_friction_global"):
        cpkit.solve_friction(g)
    with pytest.raises(TypeError, match="needs r"):
        cpkit.friction_errors(p)
    with pytest.raises(TypeError, match="W, q and mu"):
        cpkit.solve_friction(W_DENSE, Q_HAND)

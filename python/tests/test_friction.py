"""3-D frictional contact from Python (issue 26): read_fclib against Siconos' own reader (.dat)
and libfclib read here through ctypes (HDF5), solve_friction against hand-derived one-contact
answers, and real files solved with r re-checked by this file's own numpy code."""
import ctypes
import ctypes.util
import os
import pickle
import threading
import time

import numpy as np
import pytest
import scipy.sparse

import cpkit
from conftest import DATA_DIR

LOCAL = os.path.join(DATA_DIR, "fclib", "local")
FILES = sorted(os.listdir(LOCAL))
DAT = [f for f in FILES if f.endswith(".dat")]
HDF5 = [f for f in FILES if f.endswith(".hdf5")]


def test_the_data_directory_has_both_formats():
    assert len(DAT) >= 10 and len(HDF5) >= 2, FILES  # nothing below is vacuous


# ---- reading: Siconos' reader (.dat) ---------------------------------------------------------

def siconos_numerics():
    try:
        import siconos.numerics as sn
    except Exception as e:  # noqa: BLE001 -- any failure means: no peer here
        pytest.skip(f"python3-siconos (siconos.numerics) not importable: {e}")
    return sn


def siconos_dense(sn, M):
    if M.storageType == 1:  # NM_SPARSE_BLOCK
        return np.asarray(sn.SBM_to_dense(M.matrix1), dtype=float)
    D = np.zeros((M.size0, M.size1))  # dense storage (small files here): entry by entry
    for i in range(M.size0):
        for j in range(M.size1):
            D[i, j] = sn.NM_get_value(M, i, j)
    return D


@pytest.mark.parametrize("name", DAT)
def test_dat_files_read_as_siconos_reads_them(name):
    sn = siconos_numerics()
    path = os.path.join(LOCAL, name)
    ref = sn.frictionContact_new_from_filename(path)
    p = cpkit.read_fclib(path)
    assert ref.dimension == 3
    assert isinstance(p.W, scipy.sparse.csc_matrix)
    n = 3 * ref.numberOfContacts
    assert p.W.shape == (n, n) and p.q.shape == (n,) and p.mu.shape == (ref.numberOfContacts,)
    assert p.contacts == ref.numberOfContacts
    # Both parse the same decimal text: the same doubles, bit for bit.
    np.testing.assert_array_equal(p.W.toarray(), siconos_dense(sn, ref.M))
    np.testing.assert_array_equal(p.q, np.asarray(ref.q, dtype=float))
    np.testing.assert_array_equal(p.mu, np.asarray(ref.mu, dtype=float))
    assert p.name


# ---- reading: HDF5 through libfclib called here with ctypes ----------------------------------
# Siconos 4.4 as packaged cannot read HDF5 ("fclib interface is not active") and h5py is not a
# dependency (scripts/setup-deps.sh): the second route is libfclib's fclib_read_local called from
# ctypes, with the matrix decoded here (compressed rows, columns or triplets), not by cpkit's C++
# conversion.

class _FclibMatrix(ctypes.Structure):
    _fields_ = [("nzmax", ctypes.c_int), ("m", ctypes.c_int), ("n", ctypes.c_int),
                ("p", ctypes.POINTER(ctypes.c_int)), ("i", ctypes.POINTER(ctypes.c_int)),
                ("x", ctypes.POINTER(ctypes.c_double)), ("nz", ctypes.c_int),
                ("info", ctypes.c_void_p)]


class _FclibLocal(ctypes.Structure):
    _fields_ = [("W", ctypes.POINTER(_FclibMatrix)), ("V", ctypes.POINTER(_FclibMatrix)),
                ("R", ctypes.POINTER(_FclibMatrix)), ("mu", ctypes.POINTER(ctypes.c_double)),
                ("q", ctypes.POINTER(ctypes.c_double)), ("s", ctypes.POINTER(ctypes.c_double)),
                ("spacedim", ctypes.c_int), ("info", ctypes.c_void_p)]


def fclib_by_ctypes(path):
    lib_name = ctypes.util.find_library("fclib")
    if lib_name is None:
        pytest.skip("libfclib (Debian libfclib0/libfclib-dev) not found by ctypes")
    lib = ctypes.CDLL(lib_name)
    lib.fclib_read_local.restype = ctypes.POINTER(_FclibLocal)
    lib.fclib_read_local.argtypes = [ctypes.c_char_p]
    lib.fclib_delete_local.argtypes = [ctypes.POINTER(_FclibLocal)]
    ptr = lib.fclib_read_local(path.encode())
    assert ptr, f"libfclib could not read {path}"
    try:
        loc = ptr.contents
        assert loc.spacedim == 3
        w = loc.W.contents
        m, n, nz = w.m, w.n, w.nz
        if nz == -1:  # compressed columns
            indptr = np.ctypeslib.as_array(w.p, (n + 1,)).copy()
            nnz = int(indptr[-1])
            W = scipy.sparse.csc_matrix((np.ctypeslib.as_array(w.x, (nnz,)).copy(),
                                         np.ctypeslib.as_array(w.i, (nnz,)).copy(), indptr),
                                        shape=(m, n))
        elif nz == -2:  # compressed rows
            indptr = np.ctypeslib.as_array(w.p, (m + 1,)).copy()
            nnz = int(indptr[-1])
            W = scipy.sparse.csr_matrix((np.ctypeslib.as_array(w.x, (nnz,)).copy(),
                                         np.ctypeslib.as_array(w.i, (nnz,)).copy(), indptr),
                                        shape=(m, n))
        else:  # triplets: p = rows, i = columns (duplicates add up)
            W = scipy.sparse.coo_matrix((np.ctypeslib.as_array(w.x, (nz,)).copy(),
                                         (np.ctypeslib.as_array(w.p, (nz,)).copy(),
                                          np.ctypeslib.as_array(w.i, (nz,)).copy())),
                                        shape=(m, n))
        q = np.ctypeslib.as_array(loc.q, (m,)).copy()
        mu = np.ctypeslib.as_array(loc.mu, (m // 3,)).copy()
        has_vr = bool(loc.V) or bool(loc.R)
    finally:
        lib.fclib_delete_local(ptr)
    return W.toarray(), q, mu, has_vr


@pytest.mark.parametrize("name", HDF5)
def test_hdf5_files_read_as_libfclib_reads_them(name):
    path = os.path.join(LOCAL, name)
    W, q, mu, has_vr = fclib_by_ctypes(path)
    assert not has_vr
    p = cpkit.read_fclib(path)
    np.testing.assert_array_equal(p.W.toarray(), W)
    np.testing.assert_array_equal(p.q, q)
    np.testing.assert_array_equal(p.mu, mu)


# ---- the test's own verdict ------------------------------------------------------------------

def project_cone(x, mu):
    """Euclidean projection of x = (x_N, x_T) onto K_mu = {|x_T| <= mu x_N}."""
    xn, xt = x[0], x[1:]
    t = np.linalg.norm(xt)
    if t <= mu * xn:
        return x.copy()
    if mu * t <= -xn:
        return np.zeros(3)
    a = (xn + mu * t) / (1.0 + mu * mu)
    return np.concatenate(([a], mu * a * xt / t))


def natural_map(W, q, mu, r):
    """Per contact r_i - P_K(r_i - u_hat_i), with u = W r + q and De Saxce's u_hat."""
    u = W @ r + q
    out = np.zeros_like(r)
    for i, m in enumerate(mu):
        ri, ui = r[3 * i:3 * i + 3], u[3 * i:3 * i + 3]
        uhat = ui + np.array([m * np.linalg.norm(ui[1:]), 0.0, 0.0])
        out[3 * i:3 * i + 3] = ri - project_cone(ri - uhat, m)
    return out


def assert_is_solution(W, q, mu, r, u, rel=1e-6):
    """r solves the problem, judged here: u = W r + q, r_i in K, u_hat_i in K*, r_i . u_hat_i = 0
    and the natural map, each relative to r's and u's own sizes."""
    Wd = W.toarray() if scipy.sparse.issparse(W) else np.asarray(W)
    u_here = Wd @ r + q
    R = max(np.abs(r).max(), 1e-300)
    S = np.abs(q).max() + np.abs(Wd).max() * R
    np.testing.assert_allclose(u, u_here, rtol=0, atol=1e-12 * S)
    for i, m in enumerate(mu):
        ri, ui = r[3 * i:3 * i + 3], u_here[3 * i:3 * i + 3]
        uhat = ui + np.array([m * np.linalg.norm(ui[1:]), 0.0, 0.0])
        assert np.linalg.norm(ri[1:]) <= m * ri[0] + rel * R, (i, ri)       # r_i in K_mu
        assert m * np.linalg.norm(uhat[1:]) <= uhat[0] + rel * S, (i, uhat)  # u_hat_i in K*_mu
        assert abs(ri @ uhat) <= rel * R * S, (i, ri @ uhat)                # r_i . u_hat_i = 0
    # natural map in unit-free variables (r / R, u / S)
    assert np.abs(natural_map(Wd / S * R, q / S, mu, r / R)).max() <= rel


# ---- one contact, answers derived by hand ----------------------------------------------------
# W = diag(2, 1, 1) (no normal-tangential coupling), mu = 0.5. r_N follows from Signorini alone
# (u_N = 2 r_N + q_N), then the tangential part is a projection: each answer is unique.
W1 = np.diag([2.0, 1.0, 1.0])
MU1 = np.array([0.5])
HAND = {
    # q_N > 0: separation, r = 0, u = q
    "separation": (np.array([1.0, 0.3, -0.2]), np.zeros(3), np.array([1.0, 0.3, -0.2])),
    # q_N = -2: r_N = 1; r_T = -q_T = (-0.1, 0) has |r_T| = 0.1 <= mu r_N = 0.5: stick, u = 0
    "stick": (np.array([-2.0, 0.1, 0.0]), np.array([1.0, -0.1, 0.0]), np.zeros(3)),
    # q_N = -2: r_N = 1; |q_T| = 5 > 0.5: slip, r_T = -0.5 q_T/5 = (-0.3, -0.4),
    # u_T = q_T + r_T = (2.7, 3.6), u_N = 0
    "slip": (np.array([-2.0, 3.0, 4.0]), np.array([1.0, -0.3, -0.4]), np.array([0.0, 2.7, 3.6])),
}


@pytest.mark.parametrize("case", sorted(HAND))
@pytest.mark.parametrize("solver", ["auto", "nsgs", "fb-soc", "prox"])
def test_one_contact_matches_the_hand_answer(case, solver):
    q, r_hand, u_hand = HAND[case]
    res = cpkit.solve_friction(W1, q, MU1, solver=solver)
    assert res.status == "solved", res
    np.testing.assert_allclose(res.r, r_hand, rtol=0, atol=1e-8)
    np.testing.assert_allclose(res.u, u_hand, rtol=0, atol=1e-8)
    assert res.errors.unit_free <= 1e-10
    assert res.iterations >= 0 and res.seconds >= 0


def test_a_problem_without_solution_is_never_solved():
    # W = 0 and q_N = -1: u_N = -1 whatever r is, so u_hat_N = -1 + mu |u_T| < 0 = never in K*.
    for solver in ("auto", "nsgs", "fb-soc", "prox"):
        res = cpkit.solve_friction(np.zeros((3, 3)), [-1.0, 0.0, 0.0], [0.5], solver=solver,
                                   max_iterations=200, time_limit=10)
        assert not res.is_solution, (solver, res)
        assert res.errors.unit_free > 1e-3, (solver, res.errors)


def test_stick_with_a_coupled_W_is_the_linear_solution():
    # A full SPD W: stick means u = 0, so r solves W r = -q; q chosen so that r = (1, 0.1, -0.2)
    # (|r_T| = 0.224 <= mu r_N = 0.6). numpy's solve is the second route.
    W = np.array([[3.0, 0.5, -0.2], [0.5, 2.0, 0.3], [-0.2, 0.3, 1.5]])
    r_true = np.array([1.0, 0.1, -0.2])
    q = -W @ r_true
    res = cpkit.solve_friction(scipy.sparse.coo_matrix(W), q, [0.6])
    assert res.is_solution, res
    np.testing.assert_allclose(res.r, np.linalg.solve(W, -q), rtol=0, atol=1e-8)
    assert_is_solution(W, q, [0.6], res.r, res.u)


def test_any_sparse_format_and_dense_give_the_same_answer():
    q = HAND["slip"][0]
    answers = [cpkit.solve_friction(M, q, MU1, solver="fb-soc").r
               for M in (W1, scipy.sparse.csr_matrix(W1), scipy.sparse.coo_matrix(W1),
                         scipy.sparse.lil_matrix(W1), scipy.sparse.csc_array(W1))]
    for a in answers:
        np.testing.assert_array_equal(a, answers[0])


def test_unsorted_and_duplicate_csc_entries_are_summed_and_the_callers_matrix_kept():
    # W1 with each diagonal entry stored as two halves, row indices in reverse order: scipy's
    # meaning is the sum; the answer must be the slip answer derived by hand above.
    data = np.array([1.0, 1.0, 0.5, 0.5, 0.5, 0.5])
    indices = np.array([0, 0, 1, 1, 2, 2])
    W = scipy.sparse.csc_matrix((data, indices, np.array([0, 2, 4, 6])), shape=(3, 3))
    order = np.array([1, 0, 3, 2, 5, 4])
    W.data, W.indices = W.data[order], W.indices[order]
    W.has_canonical_format = False
    kept = (W.data.copy(), W.indices.copy())
    q, r_hand, _ = HAND["slip"]
    res = cpkit.solve_friction(W, q, MU1)
    np.testing.assert_allclose(res.r, r_hand, atol=1e-8)
    np.testing.assert_array_equal(W.data, kept[0])
    np.testing.assert_array_equal(W.indices, kept[1])


@pytest.mark.parametrize("scale", [1e-12, 1e-6, 1e6, 1e12])
def test_verdict_and_answer_follow_any_scaling(scale):
    # q -> a q scales r by a (u = W r + q is linear, the cones are cones); (W, q) -> b (W, q)
    # leaves r unchanged. The verdict is unit-free: "solved" either way.
    q, r_hand, u_hand = HAND["slip"]
    a = cpkit.solve_friction(W1, scale * q, MU1)
    assert a.status == "solved", a
    np.testing.assert_allclose(a.r, scale * r_hand, rtol=0, atol=1e-8 * scale)
    b = cpkit.solve_friction(scipy.sparse.csc_matrix(scale * W1), scale * q, MU1)
    assert b.status == "solved", b
    np.testing.assert_allclose(b.r, r_hand, rtol=0, atol=1e-8)
    np.testing.assert_allclose(b.u, scale * u_hand, rtol=0, atol=1e-8 * scale)


def test_errors_of_a_wrong_r_match_this_files_natural_map():
    # r = 0 on the slip problem: u = q, natural map = -P_K(-u_hat), computed here.
    q = HAND["slip"][0]
    e = cpkit.friction_errors(W1, q, MU1, np.zeros(3))
    E = np.linalg.norm(natural_map(W1, q, MU1, np.zeros(3)))
    assert E > 0.1
    np.testing.assert_allclose(e.relative_q, E / np.linalg.norm(q), rtol=1e-12)
    np.testing.assert_allclose(e.relative_max, E / np.linalg.norm(q), rtol=1e-12)  # |u| = |q|
    assert e.unit_free > 0.1


def test_result_repr_and_pickle():
    res = cpkit.solve_friction(W1, HAND["stick"][0], MU1)
    back = pickle.loads(pickle.dumps(res))
    np.testing.assert_array_equal(back.r, res.r)
    assert back.errors == res.errors and back.status == "solved"
    assert "status='solved'" in repr(res)
    assert "nsgs" in cpkit.friction_solvers() and "auto" in cpkit.friction_solvers()


# ---- real files, r re-checked here -----------------------------------------------------------

@pytest.mark.parametrize("name", ["FC3D_Example1.dat", "Confeti-ex03-Fc3D-SBM.dat",
                                  "fclib_local_problem_test.hdf5"])
def test_real_files_solve_and_recheck(name):
    p = cpkit.read_fclib(os.path.join(LOCAL, name))
    res = cpkit.solve_friction(p.W, p.q, p.mu, tol=1e-8)
    assert res.is_solution, res
    assert_is_solution(p.W, p.q, p.mu, res.r, res.u)
    # The published normalisation recomputed here: |natural map| / |q|.
    E = np.linalg.norm(natural_map(p.W.toarray(), p.q, p.mu, res.r))
    np.testing.assert_allclose(res.errors.relative_q, E / np.linalg.norm(p.q),
                               rtol=1e-6, atol=1e-14)


def test_solutions_are_each_verified_here():
    p = cpkit.read_fclib(os.path.join(LOCAL, "FC3D_Example1.dat"))
    s = cpkit.friction_solutions(p.W, p.q, p.mu, starts=3, seed=1)
    assert len(s) >= 1 and s.complete is False and s.message
    for res in s.solutions:
        assert res.status == "solved"
        assert_is_solution(p.W, p.q, p.mu, res.r, res.u)
    # distinct, as the documented rule says
    for a in range(len(s)):
        for b in range(a):
            ra, rb = s.solutions[a].r, s.solutions[b].r
            assert np.abs(ra - rb).max() > 1e-7 * max(np.abs(ra).max(), np.abs(rb).max())


def test_the_one_contact_solution_set_has_the_hand_answer():
    q, r_hand, _ = HAND["slip"]
    s = cpkit.friction_solutions(W1, q, MU1, starts=2)
    assert len(s) == 1  # unique (see HAND), so distinct solutions cannot be more than one
    np.testing.assert_allclose(s.solutions[0].r, r_hand, atol=1e-8)


def test_solves_release_the_gil():
    # While a worker thread is inside one friction solve (NSGS on a 48-contact FCLIB file, about
    # 0.3 s), the main thread keeps running Python: some of its time stamps fall strictly inside
    # the call. With the GIL held there would be none (at most one at a switch).
    p = cpkit.read_fclib(os.path.join(LOCAL, "fclib_local_problem_test.hdf5"))
    span = {}

    def work():
        span["enter"] = time.perf_counter()
        span["result"] = cpkit.solve_friction(p.W, p.q, p.mu, solver="nsgs")
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
    assert span["result"].r.shape == (3 * p.contacts,)


# ---- bad input -------------------------------------------------------------------------------

@pytest.mark.parametrize("W, q, mu, solver, words", [
    (np.eye(3), [1.0, 0.0, 0.0], [-0.5], "auto", "mu"),
    (np.eye(3), [np.nan, 0.0, 0.0], [0.5], "auto", ""),
    (np.array([[np.nan, 0, 0], [0, 1, 0], [0, 0, 1]]), [1.0, 0.0, 0.0], [0.5], "auto", ""),
    (np.eye(3), [1.0, 0.0], [0.5], "auto", "sizes"),
    (np.eye(6), [1.0] * 6, [0.5], "auto", "sizes"),
    (np.ones((3, 4)), [1.0, 0.0, 0.0], [0.5], "auto", "square"),
    (np.eye(3), [1.0, 0.0, 0.0], [0.5], "no-such-solver", "no-such-solver"),
    (np.eye(3), [1.0, 0.0, 0.0], [0.5], "fb-newton", "valid"),  # an LCP/MCP solver only
])
def test_bad_problems_raise_value_error(W, q, mu, solver, words):
    with pytest.raises(ValueError, match=words):
        cpkit.solve_friction(W, q, mu, solver=solver)


def test_bad_options_raise_value_error():
    with pytest.raises(ValueError, match="tol"):
        cpkit.solve_friction(W1, HAND["stick"][0], MU1, tol=0.5)
    with pytest.raises(ValueError, match="starts"):
        cpkit.friction_solutions(W1, HAND["stick"][0], MU1, starts=0)
    with pytest.raises(TypeError):
        cpkit.solve_friction(W1, ["a", "b", "c"], MU1)


def test_bad_files_raise_value_error_naming_the_file(tmp_path):
    missing = tmp_path / "missing.dat"
    with pytest.raises(FileNotFoundError, match="missing.dat"):  # as open() says it
        cpkit.read_fclib(missing)
    junk = tmp_path / "junk.hdf5"
    junk.write_text("3\n1\nnot a number\n")
    with pytest.raises(ValueError, match="junk.hdf5"):
        cpkit.read_fclib(junk)
    truncated = tmp_path / "truncated.dat"
    with open(os.path.join(LOCAL, "FC3D_Example1.dat")) as f:
        truncated.write_text(f.read()[:200])
    with pytest.raises(ValueError, match="truncated.dat"):
        cpkit.read_fclib(truncated)


# ---- per_contact: the state of each contact --------------------------------------------------

@pytest.mark.parametrize("case, state", [("separation", "separated"), ("stick", "stick"),
                                         ("slip", "slip")])
def test_per_contact_state_is_the_hand_answers(case, state):
    q = HAND[case][0]
    res = cpkit.solve_friction(W1, q, MU1, solver="fb-soc")
    assert res.status == "solved", res
    assert [c.state for c in res.per_contact] == [state]
    assert 0 <= res.per_contact[0].error <= res.errors.unit_free


def numpy_states(r, u, mu, margin=1e-6):
    """Each contact's state judged here from (r, u), or None where it is within `margin` (relative
    to the largest |r_i| and |u_i|) of two states: separated when r_i = 0 and u_N > 0, stick when
    u_i = 0 and r_i strictly inside K (on its boundary with u_T = 0 it is both stick and slip),
    slip when u_T != 0 (and r_T = -mu r_N u_T / |u_T|)."""
    R = max(np.abs(r).max(), 1e-300)
    S = max(np.abs(u).max(), 1e-300)
    out = []
    for i, m in enumerate(mu):
        ri, ui = r[3 * i:3 * i + 3] / R, u[3 * i:3 * i + 3] / S
        if np.linalg.norm(ri) <= margin * 1e-3 and ui[0] > margin:
            out.append("separated")
        elif np.linalg.norm(ui) <= margin * 1e-3 and m * ri[0] - np.linalg.norm(ri[1:]) > margin:
            out.append("stick")
        elif np.linalg.norm(ui[1:]) > margin and ri[0] > margin:
            out.append("slip")
        else:
            out.append(None)
    return out


# ---- global problems: the condensation route of `fc solve` -----------------------------------
# The files are the byte copies of ../shared/problems/fclib/global (checksums in MANIFEST.txt).
GLOBAL = os.path.join(DATA_DIR, "fclib", "global")


@pytest.mark.parametrize("name", ["Box_Stacks-i0122-82-5.hdf5", "GFC3D_TwoRods1.dat",
                                  "GFC3D_Example1.dat"])
def test_global_files_solve_and_recheck_in_numpy(name):
    g = cpkit.read_fclib_global(os.path.join(GLOBAL, name))
    assert g.M.shape == (g.dofs, g.dofs) and g.H.shape == (g.dofs, 3 * g.contacts)
    res = cpkit.solve_friction_global(g, tol=1e-10)
    assert res.status == "solved" and res.condensed, res
    assert res.dofs == g.dofs and res.v.shape == (g.dofs,) and len(res.per_contact) == g.contacts
    M, H = g.M.toarray(), g.H.toarray()
    # Balance in the global variables, row by row relative to the row's own terms.
    resid = M @ res.v - H @ res.r - g.f
    scale = np.abs(M) @ np.abs(res.v) + np.abs(H) @ np.abs(res.r) + np.abs(g.f)
    assert np.all(np.abs(resid) <= 1e-12 * np.maximum(scale, 1e-300)), np.abs(resid).max()
    # u = H^T v + w, and the local problem condensed a second way (numpy's dense solve).
    np.testing.assert_allclose(res.u, H.T @ res.v + g.w, rtol=0,
                               atol=1e-12 * (np.abs(H.T) @ np.abs(res.v) + np.abs(g.w)).max())
    W = H.T @ np.linalg.solve(M, H)
    q = H.T @ np.linalg.solve(M, g.f) + g.w
    assert_is_solution(W, q, g.mu, res.r, res.u, rel=1e-7)
    # Per contact: where this file's own classification is unambiguous, the same state.
    here = numpy_states(res.r, res.u, g.mu)
    judged = [(a, b.state) for a, b in zip(here, res.per_contact) if a is not None]
    assert judged, "no contact could be classified here: the test would be vacuous"
    assert all(a == b for a, b in judged), judged


def test_global_singular_m_is_not_run_with_the_reason():
    # M = 0: nothing to factorize; said, not solved.
    g = cpkit.GlobalFrictionProblem(M=np.zeros((3, 3)), H=np.eye(3), f=np.zeros(3),
                                    w=np.array([-1.0, 0.0, 0.0]), mu=np.array([0.5]))
    res = cpkit.solve_friction_global(g)
    assert res.status == "not_run" and not res.condensed, res
    assert not res.is_solution and res.per_contact == []
    assert res.message
    # Nothing was judged: the global numbers are None, never 0 (which would read as perfect).
    assert res.global_errors == {"balance": None, "local": None}, res.global_errors


def test_global_bad_input_raises_value_error(tmp_path):
    g = cpkit.GlobalFrictionProblem(M=np.eye(4), H=np.eye(3), f=np.zeros(4), w=np.zeros(3),
                                    mu=np.array([0.5]))
    with pytest.raises(ValueError, match="H"):
        cpkit.solve_friction_global(g)
    with pytest.raises(ValueError, match="local"):  # a local file is not a global one
        cpkit.read_fclib_global(os.path.join(LOCAL, "Capsules-i125-1213.hdf5"))
    with pytest.raises(FileNotFoundError, match="missing.dat"):
        cpkit.read_fclib_global(tmp_path / "missing.dat")


def test_global_proximal_solves_a_massless_degree_of_freedom_as_by_hand():
    # M = diag(1, 1, 0), H = I, w = 0, mu = 0.5, f = (-4, 3, 1). By hand (row 3: r_2 = -f_2;
    # contact closed: r_N = 4; stick would need |r_T| = sqrt(10) > 2: slip with r_2 = -1 on the
    # cone's edge): r = (4, -sqrt 3, -1), v = (0, 3 - sqrt 3, (3 - sqrt 3) / sqrt 3).
    g = cpkit.GlobalFrictionProblem(M=np.diag([1.0, 1.0, 0.0]), H=np.eye(3),
                                    f=np.array([-4.0, 3.0, 1.0]), w=np.zeros(3),
                                    mu=np.array([0.5]))
    assert cpkit.solve_friction_global(g).status == "not_run"
    res = cpkit.solve_friction_global(g, proximal=True)
    assert res.status == "solved", res
    s3 = np.sqrt(3.0)
    np.testing.assert_allclose(res.r, [4.0, -s3, -1.0], rtol=0, atol=1e-7)
    np.testing.assert_allclose(res.v, [0.0, 3 - s3, (3 - s3) / s3], rtol=0, atol=1e-7)
    # balance and the contact law recomputed here
    np.testing.assert_allclose(np.diag([1.0, 1.0, 0.0]) @ res.v, res.r + g.f, rtol=0, atol=1e-9)
    u = res.v + g.w
    uhat = u + np.array([0.5 * np.linalg.norm(u[1:]), 0.0, 0.0])
    assert abs(res.r @ uhat) <= 1e-8 and np.linalg.norm(res.r[1:]) <= 0.5 * res.r[0] + 1e-9
    assert [c.state for c in res.per_contact] == ["slip"]


# ---- the field's measure (issue 35) -----------------------------------------------------------
# W = I, q = (-1, 0.3, 0.4), mu = 0.5 sticks at the cone's edge: r = -q = (1, -0.3, -0.4).

@pytest.mark.parametrize("measure", ["unit_free", "relative_q", "relative_max"])
def test_measure_decides_solved_and_the_hand_answer_is_reached(measure):
    W, q, mu = np.eye(3), np.array([-1.0, 0.3, 0.4]), np.array([0.5])
    res = cpkit.solve_friction(W, q, mu, tol=1e-10, measure=measure)
    assert res.status == "solved", res.message
    assert np.allclose(res.r, [1.0, -0.3, -0.4], atol=1e-9)
    # relative_q recomputed here: |F_nat| / |q|
    assert np.linalg.norm(natural_map(W, q, mu, res.r)) / np.linalg.norm(q) <= 1e-9
    s = cpkit.friction_solutions(W, q, mu, starts=2, tol=1e-10, measure=measure)
    assert any(x.status == "solved" for x in s.solutions)


def test_an_unknown_measure_is_a_value_error_naming_the_three():
    with pytest.raises(ValueError, match=r"unknown measure 'relative'.*unit_free, relative_q, relative_max"):
        cpkit.solve_friction(np.eye(3), [-1.0, 0.0, 0.0], [0.5], measure="relative")
    with pytest.raises(ValueError, match="unknown measure"):
        cpkit.friction_solutions(np.eye(3), [-1.0, 0.0, 0.0], [0.5], measure="")
    with pytest.raises(TypeError, match="measure must be a str"):
        cpkit.solve_friction(np.eye(3), [-1.0, 0.0, 0.0], [0.5], measure=1)


def test_a_sparse_dat_file_reads_as_its_dense_original_printed_with_g():
    # tests/data/fclib/sparse: Siconos' own writer, entries printed with %g (6 digits)
    sparse = cpkit.read_fclib(os.path.join(DATA_DIR, "fclib", "sparse", "FC3D_Example1_csc.dat"))
    dense = cpkit.read_fclib(os.path.join(LOCAL, "FC3D_Example1.dat"))
    rounded = np.vectorize(lambda x: float("%g" % x))(dense.W.toarray())
    assert np.array_equal(sparse.W.toarray(), rounded)
    assert np.array_equal(sparse.q, dense.q) and np.array_equal(sparse.mu, dense.mu)

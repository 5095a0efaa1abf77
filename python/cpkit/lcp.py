"""LCPs (z >= 0, w = M z + q >= 0, z.w = 0) and NCP/MCPs with Python callables."""
from __future__ import annotations

import math
from typing import Callable, Iterable, Optional

import numpy as np

from . import _cpkit
from ._checks import integer, is_sparse as _is_sparse, number, numbers, real, sparse_matrix
from ._checks import vector as _vector
from .results import (Attempt, BatchResult, Certificate, CrossVerifyReport, Residuals,
                      SolutionSet, SolveResult)

__all__ = ["solve", "solve_batch", "enumerate", "cross_verify", "solve_mcp", "solvers"]

_INF = math.inf
# The extension builds these result objects itself on the quick route of solve().
_cpkit._set_result_classes(SolveResult, Residuals, Attempt, Certificate)
_quick_solve = _cpkit.solve_dense_fast


def _lcp_data(M, q):
    """(is_sparse, M, q) with M as a float64 array or a scipy.sparse matrix whose indices the
    compiled part checks (sparse_from.hpp), and q 1-D; shapes checked here, values (NaN/Inf,
    size agreement) by the C++ validator."""
    q = _vector(q, "q")
    if _is_sparse(M):
        M = sparse_matrix(M)
        if M.ndim != 2 or M.shape[0] != M.shape[1]:
            raise ValueError(f"M must be square, got shape {M.shape}")
        return True, M, q
    return False, numbers(M, "M", 2, "be a matrix of numbers (numpy array or scipy.sparse)"), q


def _options(tol, tol_acceptable, max_iterations, time_limit):
    """The common options checked: (tol, tol_acceptable, max_iterations, time_limit)."""
    return (real(tol, "tol"), real(tol_acceptable, "tol_acceptable"),
            integer(max_iterations, "max_iterations", 0),
            number(time_limit, "time_limit"))


def solvers(kind: str = "lcp"):
    """Registered solver names ("lcp" or "mcp"), in the order of the automatic chain."""
    return _cpkit.solvers(kind)


def solve(M, q, solver: str = _cpkit.DEFAULT_SOLVER, *, tol: float = 1e-10,
          tol_acceptable: float = 1e-6, max_iterations: int = 0,
          time_limit: float = _INF) -> SolveResult:
    """One solution of LCP(M, q), verified from the data: z >= 0, w = M z + q >= 0, z.w = 0.

    M: square numpy array (or anything np.asarray accepts) or scipy.sparse matrix; q: 1-D.
    solver: "auto", the default of Python and the command line alike (Lemke, FB Newton,
    enumeration, Farkas search, Ipopt, NLopt, every attempt in `attempts`) or one of
    solvers("lcp"). tol / tol_acceptable bound the unit-free residual
    for "solved" / "solved_inaccurate" (docs/conventions.md); max_iterations 0 is the solver's
    default; time_limit in seconds. Outcomes are statuses; bad input raises ValueError/TypeError.
    """
    # Quick route (issue 27: a tiny LCP costs no more than Siconos' call): float64 numpy
    # arrays readable in place and plain option types are solved by the extension directly;
    # anything else comes back as NotImplemented and takes the general route below.
    r = _quick_solve(M, q, solver, tol, tol_acceptable, max_iterations, time_limit)
    if r is not NotImplemented:
        return r
    sparse, M, q = _lcp_data(M, q)
    fn = _cpkit.solve_sparse if sparse else _cpkit.solve_dense
    return SolveResult._from(fn(M, q, str(solver), *_options(tol, tol_acceptable, max_iterations,
                                                             time_limit)))


def solve_batch(Ms, qs, solver: str = _cpkit.DEFAULT_SOLVER, *, tol: float = 1e-10,
                tol_acceptable: float = 1e-6, max_iterations: int = 0,
                time_limit: float = _INF) -> BatchResult:
    """One solution of each of k LCPs (Ms[i], qs[i]) in one call: Ms of shape (k, n, n), qs of
    shape (k, n) (dense, float64 or convertible). The problems are solved in C++ one after the
    other without the GIL and without Python objects per problem, each answer decided from its
    data as by solve() (same solver names, default "auto", and tolerances; time_limit is per
    problem).

    Returns a BatchResult of arrays: z and w (k, n), status (k,) names, residual (k,), and
    is_solution (k,) booleans. A bad shape or a non-finite entry raises ValueError naming the
    first bad problem, before any problem is solved.
    """
    Ms = np.ascontiguousarray(numbers(Ms, "Ms", what="be an array of numbers"))
    qs = np.ascontiguousarray(numbers(qs, "qs", what="be an array of numbers"))
    d = _cpkit.solve_batch(Ms, qs, str(solver), *_options(tol, tol_acceptable, max_iterations,
                                                          time_limit))
    return BatchResult._from(d)


def enumerate(M, q, *, max_size: int = 64, time_limit: float = 60.0) -> SolutionSet:
    """Every solution of LCP(M, q) (general engine: n <= max_size <= 64; bimatrix games of any size): all extreme solutions, the pieces of
    positive dimension with their rays, and whether the enumeration is `complete`."""
    sparse, M, q = _lcp_data(M, q)
    fn = _cpkit.enumerate_sparse if sparse else _cpkit.enumerate_dense
    return SolutionSet._from(fn(M, q, integer(max_size, "max_size", 1),
                                number(time_limit, "time_limit")))


def cross_verify(M, q, *, skip: Iterable[str] = (), max_size: int = 64,
                 time_limit: float = 60.0) -> CrossVerifyReport:
    """Every registered solver's answer checked against the complete enumeration;
    `consistent` is False when some solver's claim contradicts it (`disagreements`)."""
    sparse, M, q = _lcp_data(M, q)
    fn = _cpkit.cross_verify_sparse if sparse else _cpkit.cross_verify_dense
    return CrossVerifyReport._from(fn(M, q, list(skip), integer(max_size, "max_size", 1),
                                      number(time_limit, "time_limit")))


def solve_mcp(F: Callable, J: Optional[Callable], x0, lower=None, upper=None,
              solver: str = "fb-newton", *, tol: float = 1e-10, tol_acceptable: float = 1e-6,
              max_iterations: int = 0, time_limit: float = _INF) -> SolveResult:
    """One solution of MCP(F, lower, upper) from x0:
    x_i = l_i => F_i(x) >= 0, x_i = u_i => F_i(x) <= 0, l_i < x_i < u_i => F_i(x) = 0.
    lower=None means 0 and upper=None means +inf (the NCP x >= 0, F(x) >= 0, x.F(x) = 0).

    F(x) -> 1-D array of length n (or None when x is outside F's domain); J(x) -> n x n numpy
    array or scipy.sparse matrix (the kind is taken from J(x0)), or J=None for finite
    differences. solver: "fb-newton", "ipopt", "nlopt" or "auto". An exception raised inside F
    or J stops the solve and is re-raised here unchanged.
    """
    if not callable(F):
        raise TypeError("F must be callable: F(x) -> array of length n")
    if J is not None and not callable(J):
        raise TypeError("J must be callable (J(x) -> n x n array or sparse matrix) or None")
    x0 = _vector(x0, "x0")
    n = x0.size
    lower = np.zeros(n) if lower is None else _vector(lower, "lower")
    upper = np.full(n, _INF) if upper is None else _vector(upper, "upper")
    jac, sparse_jac = J, False
    if J is not None and _is_sparse(J(x0.copy())):
        sparse_jac = True

        def jac(x):  # its indices are checked by the compiled part (sparse_from.hpp)
            m = J(x)
            return sparse_matrix(m) if _is_sparse(m) else m  # None: outside the domain
    return SolveResult._from(_cpkit.solve_mcp(F, jac, sparse_jac, x0, lower, upper, str(solver),
                                              *_options(tol, tol_acceptable, max_iterations,
                                                        time_limit)))

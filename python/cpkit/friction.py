"""3-D frictional contact problems (issue 26; docs/python.md, docs/friction_contact.md):
u = W r + q, r_i in K_{mu_i}, u_hat_i = u_i + (mu_i |u_T,i|, 0, 0) in K*_{mu_i}, r_i . u_hat_i = 0,
contact i owning rows 3i..3i+2, normal first (FCLIB's and Siconos' convention).

W is a scipy.sparse matrix (CSC, CSR and COO read as they are, every index checked by the
extension before use; other formats converted to COO) or a dense array. Bad input raises
ValueError (TypeError for things that are not real numbers, FileNotFoundError for a missing
file), with the C++ validator's or reader's message."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional

import numpy as np

from . import _cpkit
from ._checks import (existing_path, integer, is_sparse, number, numbers, real, sparse_matrix,
                      vector)
from .results import Attempt, Residuals, _short

__all__ = ["FrictionProblem", "FrictionErrors", "FrictionResult", "FrictionSolutionSet",
           "ContactReport", "GlobalFrictionProblem", "GlobalFrictionResult",
           "read_fclib", "read_fclib_global", "solve_friction", "solve_friction_global",
           "friction_solutions", "friction_errors", "friction_solvers"]

_INF = math.inf


class _Contacts:
    """What the local and the global problem share: mu holds one coefficient a contact."""

    @property
    def contacts(self) -> int:
        return int(self.mu.size)


@dataclass(repr=False)
class FrictionProblem(_Contacts):
    """A local problem as read from a file: W (scipy.sparse.csc_matrix, 3 n_c square), q (3 n_c),
    mu (n_c), name (file stem or the file's own label), note (free text of the file)."""
    W: Any
    q: np.ndarray
    mu: np.ndarray
    name: str = ""
    note: str = ""

    def __repr__(self):
        return (f"FrictionProblem(name={self.name!r}, contacts={self.contacts}, "
                f"W_nonzeros={self.W.nnz})")


@dataclass
class FrictionErrors:
    """unit_free decides "solved" (<= tol; unchanged when q, or W and q together, are scaled);
    relative_q (natural-map norm / |q|, Acary-Bremond-Huber) and relative_max (/ max(|q|, |r|, |u|),
    Siconos' fc3d_compute_error) are the published normalisations, for comparison."""
    unit_free: float
    relative_q: float
    relative_max: float


@dataclass
class ContactReport:
    """One contact of an answer (`fc solve --json`'s per_contact): state "separated", "stick" or
    "slip" (the two sides of each complementarity compared in unit-free variables, no
    tolerance) and error, the contact's share of the unit-free number."""
    state: str
    error: float


@dataclass(repr=False)
class FrictionResult:
    """What solve_friction returns (the fields of `cpkit fc solve --json`): status ("solved",
    "solved_inaccurate", or why not), r and u = W r + q (recomputed from the data), errors,
    the solver's iterations and seconds, residuals (as SolveResult's), attempts of "auto"."""
    status: str
    solver: str
    r: np.ndarray
    u: np.ndarray
    errors: FrictionErrors
    residuals: Residuals
    iterations: int = 0
    seconds: float = 0.0
    attempts: List[Attempt] = field(default_factory=list)
    message: str = ""
    per_contact: List[ContactReport] = field(default_factory=list)

    @property
    def is_solution(self) -> bool:
        return self.status in ("solved", "solved_inaccurate")

    def __repr__(self):
        s = (f"FrictionResult(status={self.status!r}, solver={self.solver!r}, r={_short(self.r)}, "
             f"unit_free={self.errors.unit_free:.3g}, iterations={self.iterations}")
        if self.message:
            s += f", message={self.message!r}"
        return s + ")"

    @classmethod
    def _from(cls, d: Dict[str, Any]) -> "FrictionResult":
        d = dict(d)
        d["errors"] = FrictionErrors(**d["errors"])
        d["residuals"] = Residuals(**d["residuals"])
        d["attempts"] = [Attempt(**a) for a in d["attempts"]]
        d["per_contact"] = [ContactReport(**c) for c in d["per_contact"]]
        return cls(**d)


@dataclass(repr=False)
class GlobalFrictionProblem(_Contacts):
    """A global problem M v = H r + f, u = H^T v + w as read from a file: M (m x m) and H
    (m x 3 n_c) scipy.sparse.csc_matrix, f (m), w (3 n_c), mu (n_c), name, note."""
    M: Any
    H: Any
    f: np.ndarray
    w: np.ndarray
    mu: np.ndarray
    name: str = ""
    note: str = ""

    @property
    def dofs(self) -> int:
        return int(self.f.size)

    def __repr__(self):
        return (f"GlobalFrictionProblem(name={self.name!r}, contacts={self.contacts}, "
                f"dofs={self.dofs})")


@dataclass(repr=False)
class GlobalFrictionResult(FrictionResult):
    """What solve_friction_global returns (`cpkit fc solve --json` on a global file): the fields
    of FrictionResult for the condensed local problem (r, u = H^T v + w, its errors and
    per_contact), plus v (m), dofs, condensed (False when M could not be factorized: status
    "not_run", nothing solved) and global_errors {"balance", "local"}, the unit-free numbers of
    the verdict in the global variables (lcp/friction/global.hpp)."""
    v: np.ndarray = field(default_factory=lambda: np.zeros(0))
    dofs: int = 0
    condensed: bool = False
    global_errors: Dict[str, float] = field(default_factory=dict)

    def __repr__(self):
        return (f"GlobalFrictionResult(status={self.status!r}, solver={self.solver!r}, "
                f"condensed={self.condensed}, global_errors={self.global_errors}, "
                f"iterations={self.iterations})")


@dataclass(repr=False)
class FrictionSolutionSet:
    """Distinct verified solutions (each a FrictionResult with status "solved") and whether the
    list is proved `complete` (it is not, so far, on any route: message says what ran)."""
    solutions: List[FrictionResult]
    complete: bool
    message: str = ""

    def __len__(self):
        return len(self.solutions)

    def __repr__(self):
        return (f"FrictionSolutionSet({len(self.solutions)} solutions, "
                f"complete={self.complete})")


def _matrix(A, name: str):
    """A as a scipy.sparse matrix whose index arrays the compiled part checks (sparse_from.hpp),
    or, when dense, a float64 CSC matrix built by scipy from its numbers."""
    import scipy.sparse
    if is_sparse(A):
        if A.ndim != 2:
            raise ValueError(f"{name} must be 2-D, got shape {A.shape}")
        return sparse_matrix(A)
    return scipy.sparse.csc_matrix(numbers(A, name, 2, "be a matrix of numbers (numpy array or "
                                                       "scipy.sparse)"))


def _unpack(W, q, mu, call: str):
    """(W, q, mu) from a problem object (anything with W, q, mu: FrictionProblem) given alone,
    or as given. TypeError for a problem given with q or mu, or a global problem."""
    if isinstance(W, GlobalFrictionProblem):
        raise TypeError(f"{call} takes a local problem: use solve_friction_global for a "
                        f"GlobalFrictionProblem")
    if all(hasattr(W, a) for a in ("W", "q", "mu")):
        if q is not None or mu is not None:
            raise TypeError(f"{call}: give a problem alone or W, q, mu (the other arguments "
                            f"by keyword: {call}(problem, solver=..., ...))")
        return W.W, W.q, W.mu
    if q is None or mu is None:
        raise TypeError(f"{call} needs a problem (FrictionProblem) or W, q and mu")
    return W, q, mu


def _data(W, q, mu, call: str):
    """(W, q, mu) ready for the compiled part: shapes checked here, every index of W by
    sparse_from (C++), sizes and values by the C++ validator (FrictionContactProblem::validate),
    each naming what is wrong."""
    W, q, mu = _unpack(W, q, mu, call)
    q = vector(q, "q")
    mu = vector(mu, "mu")
    W = _matrix(W, "W")
    if W.shape[0] != W.shape[1]:
        raise ValueError(f"W must be square (3 n_c x 3 n_c), got shape {W.shape}")
    if W.shape[0] != q.size or q.size != 3 * mu.size:
        raise ValueError(f"sizes disagree: W is {W.shape[0]} x {W.shape[1]}, q has {q.size} "
                         f"entries, mu has {mu.size} (need 3 n_c, 3 n_c, n_c)")
    return W, q, mu


def read_fclib(path) -> FrictionProblem:
    """A local problem from an FCLIB HDF5 file (/fclib_local) or a Siconos FrictionContact .dat
    file (chosen by content); path: str, bytes or os.PathLike. A missing file raises
    FileNotFoundError, an unreadable or malformed one ValueError naming it."""
    d = _cpkit.read_fclib(existing_path(path))
    return FrictionProblem(W=d["W"], q=d["q"], mu=d["mu"], name=d["name"], note=d["note"])


def read_fclib_global(path) -> GlobalFrictionProblem:
    """A global problem from an FCLIB HDF5 file (/fclib_global) or a Siconos
    GlobalFrictionContact .dat file; path as read_fclib's. A missing file raises
    FileNotFoundError, an unreadable or malformed one ValueError."""
    d = _cpkit.read_fclib_global(existing_path(path))
    return GlobalFrictionProblem(M=d["M"], H=d["H"], f=d["f"], w=d["w"], mu=d["mu"],
                                 name=d["name"], note=d["note"])


def _options(tol, tol_acceptable, max_iterations, time_limit):
    """The common options checked: (tol, tol_acceptable, max_iterations, time_limit)."""
    return (1e-10 if tol is None else real(tol, "tol"), real(tol_acceptable, "tol_acceptable"),
            integer(max_iterations, "max_iterations", 0),
            number(time_limit, "time_limit"))


def _measure(measure) -> str:
    """The measure's name (the C++ side checks the word: ValueError listing the valid ones)."""
    if not isinstance(measure, str):
        raise TypeError(f"measure must be a str (unit_free, relative_q, relative_max), "
                        f"got {type(measure).__name__}")
    return measure


def solve_friction(W, q=None, mu=None, solver: str = "auto", tol: Optional[float] = None, *,
                   tol_acceptable: float = 1e-6, max_iterations: int = 0,
                   time_limit: float = _INF, measure: str = "unit_free") -> FrictionResult:
    """One solution of the local problem, judged from the data: solve_friction(problem, ...)
    with a FrictionProblem (as read_fclib returns), or solve_friction(W, q, mu, ...).

    solver: "auto" or one of friction_solvers() (nsgs, fb-soc, prox, lemke on the faceted cone,
    ipopt). tol (default 1e-10, at most 1e-3) bounds the unit-free error for "solved";
    tol_acceptable for "solved_inaccurate". measure decides "solved": "unit_free" (default),
    "relative_q" (|F_nat|/|q|, FCLIB's) or "relative_max" (Siconos'); in a relative measure the
    problem is solved again at lower unit-free tolerances until within tol, and the unit-free
    verdict must still accept the answer (docs/friction_contact.md, "The field's measure").
    An unknown measure raises ValueError. The GIL is released during the solve."""
    W, q, mu = _data(W, q, mu, "solve_friction")
    return FrictionResult._from(_cpkit.solve_friction(
        W, q, mu, str(solver), *_options(tol, tol_acceptable, max_iterations, time_limit),
        _measure(measure)))


def solve_friction_global(problem: GlobalFrictionProblem, solver: str = "auto",
                          tol: Optional[float] = None, *, tol_acceptable: float = 1e-6,
                          max_iterations: int = 0, time_limit: float = _INF,
                          proximal: bool = False) -> GlobalFrictionResult:
    """The global problem solved as `cpkit fc solve` does: condensed to W = H^T M^-1 H,
    q = H^T M^-1 f + w (sparse LDL^T of M), the local problem solved by `solver`, v recovered
    and the answer judged in the global variables ("solved" when global_errors' balance and
    local are both <= tol). A singular M gives status "not_run" with the reason in message,
    unless proximal=True: then the proximal point method in v (M + rho I and f + rho v_k at
    each outer step, each condensed and solved as above; lcp/friction/global.hpp,
    solve_global_proximal) runs instead, and max_iterations bounds its outer iterations.
    Sizes and values are checked by the C++ validator (ValueError naming what is wrong)."""
    p = problem
    d = _cpkit.solve_friction_global(
        _matrix(p.M, "M"), _matrix(p.H, "H"), vector(p.f, "f"), vector(p.w, "w"),
        vector(p.mu, "mu"), str(solver), *_options(tol, tol_acceptable, max_iterations,
                                                   time_limit), bool(proximal))
    return GlobalFrictionResult._from(d)


def friction_solutions(W, q=None, mu=None, starts: int = 20, seed: int = 1, *,
                       tol: Optional[float] = None,
                       time_limit: float = _INF,
                       measure: str = "unit_free") -> FrictionSolutionSet:
    """Distinct verified solutions of a problem (friction_solutions(problem, starts=...)) or
    of (W, q, mu): every solution of the faceted problem checked on the true cone (up to 5
    contacts), then a seeded multistart of `starts` points (deterministic for a seed).
    complete is False unless proved (lcp/friction/solutions.hpp). measure as solve_friction's:
    each solution is polished within tol in it where it can be, and its status decided in it."""
    W, q, mu = _data(W, q, mu, "friction_solutions")
    d = _cpkit.friction_solutions(W, q, mu, integer(starts, "starts", 1),
                                  integer(seed, "seed", 0, 2**32 - 1),
                                  1e-10 if tol is None else real(tol, "tol"),
                                  number(time_limit, "time_limit"), _measure(measure))
    return FrictionSolutionSet([FrictionResult._from(s) for s in d["solutions"]], d["complete"],
                               d["message"])


def friction_errors(W, q=None, mu=None, r=None) -> FrictionErrors:
    """The verdict's errors of a candidate r (3 n_c), whatever produced it:
    friction_errors(problem, r) or friction_errors(W, q, mu, r)."""
    if r is None and mu is None and all(hasattr(W, a) for a in ("W", "q", "mu")):
        q, r = None, q  # friction_errors(problem, r)
    if r is None:
        raise TypeError("friction_errors needs r: friction_errors(problem, r) or "
                        "friction_errors(W, q, mu, r)")
    W, q, mu = _data(W, q, mu, "friction_errors")
    return FrictionErrors(**_cpkit.friction_errors(W, q, mu, vector(r, "r")))


def friction_solvers() -> List[str]:
    """Names of the solvers that accept friction problems ("auto" included)."""
    return list(_cpkit.friction_solvers())

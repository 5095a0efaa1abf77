"""3-D frictional contact problems (docs/friction_contact.md): u = W r + q, r_i in the Coulomb
cone K_{mu_i}, u_hat_i = u_i + (mu_i |u_T,i|, 0, 0) in its dual, r_i . u_hat_i = 0; contact i owns
entries 3i..3i+2, normal first."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from . import _cpkit

__all__ = ["FrictionProblem", "FrictionResult", "read_fclib", "solve_friction"]


@dataclass
class FrictionProblem:
    """W (scipy.sparse CSC, 3 n_c x 3 n_c), q (3 n_c), mu (n_c)."""
    W: object
    q: np.ndarray
    mu: np.ndarray
    name: str = ""
    note: str = ""

    @property
    def contacts(self) -> int:
        return int(self.mu.size)


@dataclass
class FrictionResult:
    status: str
    solved: bool
    solver: str
    r: np.ndarray
    u: np.ndarray
    errors: dict = field(default_factory=dict)  # unit_free, relative_q, relative_max
    iterations: int = 0
    seconds: float = 0.0
    message: str = ""


def read_fclib(path) -> FrictionProblem:
    """A local problem from an FCLIB file (HDF5) or a Siconos FrictionContact .dat file (chosen
    by content). ValueError naming the file and what is wrong for a bad file."""
    d = _cpkit.read_fclib(str(path))
    return FrictionProblem(W=d["W"], q=np.asarray(d["q"]), mu=np.asarray(d["mu"]),
                           name=d["name"], note=d["note"])


def solve_friction(problem_or_W, q=None, mu=None, *, solver: str = "auto", tol: float = 1e-10,
                   time_limit: Optional[float] = None) -> FrictionResult:
    """Solves a FrictionProblem (or W, q, mu; W dense or scipy.sparse) with a registered
    friction solver ("auto", "fb-soc", "nsgs", "prox", ...). `solved` only when cpkit's
    unit-free verdict accepts r."""
    if isinstance(problem_or_W, FrictionProblem):
        W, q, mu = problem_or_W.W, problem_or_W.q, problem_or_W.mu
    else:
        W = problem_or_W
    try:
        import scipy.sparse
        W = scipy.sparse.csc_matrix(W, dtype=float)
    except ImportError:
        raise ImportError("solve_friction needs scipy (python3-scipy) for the sparse W") from None
    d = _cpkit.solve_friction(W, np.asarray(q, dtype=float), np.asarray(mu, dtype=float), solver,
                              float(tol), math.inf if time_limit is None else float(time_limit))
    return FrictionResult(status=d["status"], solved=d["solved"], solver=d["solver"],
                          r=np.asarray(d["r"]), u=np.asarray(d["u"]), errors=d.get("errors", {}),
                          iterations=d["iterations"], seconds=d["seconds"], message=d["message"])

"""N contact points coupled through a condensed stiffness (docs/model.md, "N contact points";
rate_problem/system/contact_system.hpp): what a finite-element code hands over."""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _cpkit
from ._checks import numbers
from .model import ContactParameters
from .results import SystemRateSolutionSet

__all__ = ["ContactSystem", "solve_system_rate", "system_direction_counts"]


def _finite_list(a, name, ndim=None):
    return numbers(a, name, ndim, finite=True).tolist()


@dataclass(repr=False)
class ContactSystem:
    """N contact points in 2-D. A: the 2N x 2N symmetric positive definite stiffness on the DOFs
    (T_1, N_1, T_2, N_2, ...) (N points into the obstacle: w_N > 0 penetrates; P_N >= 0
    compressive; equilibrium F - P = A w). points: one dict per point with the keys of the
    system file (docs/file_formats.md): "mu", "C_T", "k_a", "P_s" and either "state" ("a".."d",
    with "P_N" for c/d and "sgnPT" for d, "g" < 0 for a) or the current values "P_N", "g"
    (and "P_T"). dF: an optional load rate, patterns: optional load patterns (e1, e2) for
    direction maps, both 2N-vectors. Validated on construction (ValueError naming the field and
    the point, 1-based); A is then symmetrised and each point completed with its state."""
    A: Any
    points: List[Dict[str, Any]]
    criterion: str = "38"
    dF: Optional[Any] = None
    patterns: Optional[Tuple[Any, Any]] = None
    name: str = ""

    def __post_init__(self):
        d = _cpkit.system_normalized(self.to_json())
        self.A = d["A"]
        self.points = d["points"]
        self.criterion = d["criterion"]
        self.dF = d["dF"]
        self.patterns = d["patterns"]

    def to_json(self) -> str:
        """The system file's JSON text (docs/file_formats.md)."""
        if not isinstance(self.points, (list, tuple)) or not all(isinstance(p, dict) for p in self.points):
            raise TypeError("points must be a list of dicts (one per contact point)")
        doc = {"A": _finite_list(self.A, "A", 2),
               "points": [{k: (v if isinstance(v, str) else _finite_list(v, f"point {i + 1}: {k}"))
                           for k, v in p.items()} for i, p in enumerate(self.points)],
               "criterion": str(self.criterion)}
        if self.name:
            doc["name"] = str(self.name)
        if self.dF is not None:
            doc["dF"] = _finite_list(self.dF, "dF", 1)
        if self.patterns is not None:
            if len(self.patterns) != 2:
                raise ValueError("patterns must be two load patterns (e1, e2)")
            doc["patterns"] = [_finite_list(e, f"patterns[{k}]", 1)
                               for k, e in enumerate(self.patterns)]
        return json.dumps(doc)

    @classmethod
    def from_file(cls, path: str) -> "ContactSystem":
        """Reads a system file (JSON)."""
        d = _cpkit.system_from_file(str(path))
        return cls(A=d["A"], points=d["points"], criterion=d["criterion"], dF=d["dF"],
                   patterns=d["patterns"], name=d["name"])

    @property
    def n_points(self) -> int:
        return len(self.points)

    def point_parameters(self, i: int) -> ContactParameters:
        """The one-point parameters of point i (0-based): its diagonal 2 x 2 block of A and its
        interface data."""
        p = self.points[i]
        return ContactParameters(a11=float(self.A[2 * i, 2 * i]), a12=float(self.A[2 * i, 2 * i + 1]),
                                 a22=float(self.A[2 * i + 1, 2 * i + 1]), mu=p["mu"], C_T=p["C_T"],
                                 k_a=p["k_a"], P_s=p["P_s"], criterion=self.criterion)

    def __repr__(self):
        states = "".join(p["state"] for p in self.points)
        return f"ContactSystem({self.name!r}, N={self.n_points}, states={states!r})"


def solve_system_rate(system: ContactSystem, dF, method: str = "enumerate"):
    """Every solution of the N-point rate problem for the load rate dF (a 2N-vector,
    interleaved (dF_T1, dF_N1, ...)). method: "enumerate" (every solution) or a single LCP
    solver ("lemke", "fb-newton", "ipopt": one solution, complete=False)."""
    if not isinstance(system, ContactSystem):
        raise TypeError("system must be a cpkit.ContactSystem")
    dF = np.asarray(dF, dtype=float)
    if dF.ndim != 1:
        raise ValueError(f"dF must be a 1-D array of 2N = {2 * system.n_points} entries, got shape {dF.shape}")
    return SystemRateSolutionSet._from(_cpkit.solve_system_rate(system.to_json(), dF, method))


def system_direction_counts(system: ContactSystem, theta, e1=None, e2=None) -> Dict[str, np.ndarray]:
    """For the loads dF = cos(theta) e1 + sin(theta) e2 at every theta (radians): "count"
    (-1: infinitely many), "n_tuples" (distinct type tuples) and "reliable" (False where the
    enumeration could not decide), as numpy arrays. e1, e2 default to the system's patterns."""
    if e1 is None or e2 is None:
        if system.patterns is None:
            raise ValueError("give the load patterns e1, e2 (the system has no patterns)")
        e1, e2 = system.patterns
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    if theta.ndim != 1:
        raise ValueError(f"theta must be 1-D, got shape {theta.shape}")
    d = _cpkit.system_direction_counts(system.to_json(), np.asarray(e1, float),
                                       np.asarray(e2, float), theta)
    return dict(d)

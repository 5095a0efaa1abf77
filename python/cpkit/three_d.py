"""Three-dimensional contact points with the elliptic friction-and-wear law (39)-(41)
(docs/contact_3d.md): DOFs (T_X, T_Y, N), friction norm ||p_T|| = |D^-1 p_T| with
D = diag(alpha_X, alpha_Y)."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from . import _cpkit

__all__ = ["Point3d", "Rate3dSolutionSet", "Step3dSolutionSet", "solve_rate_3d",
           "solve_system_rate_3d", "enumerate_step_3d"]


@dataclass
class Point3d:
    """One 3-D contact point: A the 3 x 3 symmetric positive definite stiffness on
    (T_X, T_Y, N) (force/length), mu > 0, C_T >= 0 (length/force), Archard's k_a >= 0 and the
    hardness P_s > 0 (wear (40): k = k_a / (3 P_s)), alpha = (alpha_X, alpha_Y) > 0 the half-axes
    of the friction ellipse (39) ((1, 1): isotropic). Validated when used (ValueError naming the
    field)."""
    A: Any = field(default_factory=lambda: np.eye(3))
    mu: float = 0.5
    C_T: float = 0.0
    k_a: float = 0.0
    P_s: float = 1.0
    alpha: Sequence[float] = (1.0, 1.0)

    def __post_init__(self):
        self.A = np.asarray(self.A, dtype=float).tolist()
        self.alpha = [float(a) for a in self.alpha]


@dataclass
class Rate3dSolutionSet:
    """Every solution of a 3-D rate problem. solutions: dicts with "type" (open, separation,
    stick, slip), "kind" (point or ray), "at" (rates dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w; 2-vectors
    as arrays), "slip_direction" (unit vector of dw_Ti, None without slip), "slip_angle" (rad).
    For systems: "types" and "rates", one per point. complete: False when the list is not proved
    complete (message says why)."""
    solutions: List[Dict[str, Any]]
    complete: bool
    message: str
    route: str
    facets: int

    @property
    def count(self) -> int:
        return len(self.solutions)

    @property
    def types(self) -> List[str]:
        return [s["type"] if "type" in s else "/".join(s["types"]) for s in self.solutions]


@dataclass
class Step3dSolutionSet:
    """Every solution of one implicit 3-D step (docs/contact_3d.md, "The implicit step").
    solutions: dicts with "type", "values" (P_T1, P_N1, DP_T, DP_N, Dw_T, Dw_N, Dw_Ti, Dw_w, g1,
    lambda), "slip_direction", "slip_angle", "residual"."""
    solutions: List[Dict[str, Any]]
    complete: bool
    message: str

    @property
    def count(self) -> int:
        return len(self.solutions)

    @property
    def types(self) -> List[str]:
        return [s["type"] for s in self.solutions]


def _vec(x, n, name):
    a = np.asarray(x, dtype=float).ravel()
    if a.size != n:
        raise ValueError(f"{name} must hold {n} numbers, got {a.size}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} has a NaN or infinite entry")
    return a.tolist()


def solve_rate_3d(point: Point3d, state: str, dF, P_T=(0.0, 0.0), P_N: float = 0.0,
                  facets: Optional[int] = None) -> Rate3dSolutionSet:
    """Every solution of the rate problem of one 3-D point for the load rate dF = (dF_TX, dF_TY,
    dF_N). state: "a" open, "b" grazing, "c" stick (P_T, P_N inside the ellipse cone), "d" on
    the cone. Exact (slip directions of state b from a quartic with a completeness
    certificate), or with facets=k (state b only) the faceted LCP."""
    k = 0 if facets is None else int(facets)
    if facets is not None and k <= 0:
        raise ValueError(f"facets must be a positive number of facets (3..64), got {facets}")
    d = _cpkit.solve_rate_3d(point, str(state), _vec(P_T, 2, "P_T"), float(P_N),
                             _vec(dF, 3, "dF"), k)
    return Rate3dSolutionSet(**d)


def solve_system_rate_3d(system, facets: int, dF=None) -> Rate3dSolutionSet:
    """Every solution of the faceted rate problem of N coupled 3-D points. system: a path to a
    "dim": 3 system file, its JSON text, or a dict of it (docs/file_formats.md)."""
    if isinstance(system, dict):
        text = json.dumps(system)
    elif isinstance(system, str) and system.lstrip().startswith("{"):
        text = system
    else:
        with open(os.fspath(system), encoding="utf-8") as f:
            text = f.read()
    load = None if dF is None else np.asarray(dF, dtype=float).ravel().tolist()
    return Rate3dSolutionSet(**_cpkit.solve_system_rate_3d(text, load, int(facets)))


def enumerate_step_3d(point: Point3d, DF, P_T0=(0.0, 0.0), P_N0: float = 0.0, g0: float = 0.0,
                      wear_law: str = "archard", k_M: float = 0.0) -> Step3dSolutionSet:
    """Every solution of one implicit step of a 3-D point from the state (P_T0, P_N0, g0) under
    the load increment DF (3 numbers); wear_law "archard" (40) or "mroz" (41) with k_M."""
    d = _cpkit.enumerate_step_3d(point, _vec(P_T0, 2, "P_T0"), float(P_N0), float(g0),
                                 _vec(DF, 3, "DF"), str(wear_law), float(k_M))
    return Step3dSolutionSet(**d)

"""The rate problem (docs/contact_model.md, docs/contact_3d.md): one 2-D point (and N points
through a ContactSystem), its indicators, and the 3-D point and N-point 3-D system."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Optional

import numpy as np

from . import _cpkit
from ._checks import facet_count, integer, load_2d, number, numbers, vec
from .model import ContactParameters, Point3d
from .results import RateSolutionSet
from .system import ContactSystem, solve_system_rate, system_3d

__all__ = ["solve_rate_problem", "rate_indicators", "Rate3dSolutionSet", "solve_rate_3d",
           "solve_system_rate_3d"]


def solve_rate_problem(params, state, dF=None, method: str = "enumerate"):
    """Every solution of a rate problem.

    One point: solve_rate_problem(params, state, dF, method="enumerate") with
    ContactParameters, a ContactState or just its label ("a".."d"), and dF = (dF_T, dF_N);
    method "enumerate" (LCP + complete enumeration, default), "analytic" (the paper's closed
    forms) or a single solver ("lemke", "fb-newton", "ipopt": one solution, complete=False).
    Returns a RateSolutionSet.

    N points: solve_rate_problem(system, dF, method="enumerate") with a ContactSystem and a
    2N-vector dF (see cpkit.system.solve_system_rate). Returns a SystemRateSolutionSet."""
    if isinstance(params, ContactSystem):
        if dF is not None:  # solve_rate_problem(system, dF, method)
            method = dF
        return solve_system_rate(params, state, method)
    if dF is None:
        raise TypeError("solve_rate_problem(params, state, dF): the load rate dF is missing")
    dFT, dFN = load_2d(dF)
    return RateSolutionSet._from(_cpkit.solve_rate_problem(params, state, dFT, dFN, method))


def rate_indicators(params: ContactParameters, state) -> dict:
    """detA, D0, kappa, mu_eff, D_plus, D_minus, Lambda and unique_for_all_directions."""
    return dict(_cpkit.rate_indicators(params, state))


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


def solve_rate_3d(point: Point3d, state: str, dF, P_T=(0.0, 0.0), P_N: float = 0.0,
                  facets: Optional[int] = None) -> Rate3dSolutionSet:
    """Every solution of the rate problem of one 3-D point for the load rate dF = (dF_TX, dF_TY,
    dF_N). state: "a" open, "b" grazing, "c" stick (P_T, P_N inside the ellipse cone), "d" on
    the cone. Exact (slip directions of state b from a quartic with a completeness
    certificate), or with facets=k (state b only) the faceted LCP."""
    k = facet_count(facets)
    d = _cpkit.solve_rate_3d(point, str(state), vec(P_T, 2, "P_T"), number(P_N, "P_N"),
                             vec(dF, 3, "dF"), k)
    return Rate3dSolutionSet(**d)


def solve_system_rate_3d(system, facets: int, dF=None) -> Rate3dSolutionSet:
    """Every solution of the faceted rate problem of N coupled 3-D points. system: a path to a
    "dim": 3 system file, its JSON text, a dict of it (docs/file_formats.md) or a ContactSystem3d."""
    data = system_3d(system)
    load = None if dF is None else numbers(dF, "dF").ravel().tolist()
    return Rate3dSolutionSet(**_cpkit.solve_system_rate_3d(data, load, integer(facets, "facets")))

"""One implicit step (docs/simulation.md, docs/contact_3d.md "The implicit step"): every
solution or one by the solver chain, for a 2-D point and a 3-D point (chain, multistart,
faceted)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence

from . import _cpkit
from ._checks import integer, load_2d, number, real, vec
from .model import ContactParameters, Point3d
from .results import SolveResult, StepSolutionSet

__all__ = ["enumerate_step", "solve_step", "Step3dSolutionSet", "StepChain3dResult",
           "FacetedStep3dSolutionSet", "enumerate_step_3d", "solve_step_3d", "multistart_step_3d",
           "solve_step_3d_faceted"]


def enumerate_step(params: ContactParameters, P_T0: float, P_N0: float, g0: float, DF,
                   wear_law: str = "archard", k_M: float = 0.0,
                   detect_jumps: bool = True) -> StepSolutionSet:
    """All solutions of one implicit step from (P_T0, P_N0, g0) under the load increment
    DF = (DF_T, DF_N) (docs/simulation.md)."""
    dFT, dFN = load_2d(DF)
    return StepSolutionSet._from(_cpkit.enumerate_step(
        params, number(P_T0, "P_T0"), number(P_N0, "P_N0"), number(g0, "g0"), dFT, dFN, wear_law,
        number(k_M, "k_M"),
        bool(detect_jumps)))


def solve_step(params: ContactParameters, P_T0: float, P_N0: float, g0: float, DF,
               wear_law: str = "archard", k_M: float = 0.0,
               chain: Sequence[str] = ()) -> dict:
    """One solution of a step by the solver chain (default active-set, lemke, fb-newton,
    ipopt): {"result": SolveResult (z = (P_N1, l+, l-)), "values": {...}, "type": name}."""
    dFT, dFN = load_2d(DF)
    d = _cpkit.solve_step(params, number(P_T0, "P_T0"), number(P_N0, "P_N0"), number(g0, "g0"),
                          dFT, dFN, wear_law, number(k_M, "k_M"), list(chain))
    d["result"] = SolveResult._from(d["result"])
    return d


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


@dataclass
class StepChain3dResult:
    """One verified solution of a 3-D step by the solver chain: solved, solver (the link that
    succeeded), solution (a dict as enumerate_step_3d's, None when unsolved), attempts (solver,
    solved, residual, iterations, seconds, message), message."""
    solved: bool
    solver: str
    solution: Optional[Dict[str, Any]]
    attempts: List[Dict[str, Any]]
    message: str


@dataclass
class FacetedStep3dSolutionSet(Step3dSolutionSet):
    """The faceted step's solutions (values of the polygonal law; residual against the
    elliptic one). lcp: True without wear (complete LCP enumeration), False with wear (an NCP
    from starts: complete is False)."""
    facets: int = 0
    size: int = 0
    lcp: bool = True
    nodes: int = 0
    seconds: float = 0.0


def enumerate_step_3d(point: Point3d, DF, P_T0=(0.0, 0.0), P_N0: float = 0.0, g0: float = 0.0,
                      wear_law: str = "archard", k_M: float = 0.0) -> Step3dSolutionSet:
    """Every solution of one implicit step of a 3-D point from the state (P_T0, P_N0, g0) under
    the load increment DF (3 numbers); wear_law "archard" (40) or "mroz" (41) with k_M."""
    d = _cpkit.enumerate_step_3d(point, vec(P_T0, 2, "P_T0"), number(P_N0, "P_N0"),
                                 number(g0, "g0"), vec(DF, 3, "DF"), str(wear_law),
                                 number(k_M, "k_M"))
    return Step3dSolutionSet(**d)


def _step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M):
    return (point, vec(P_T0, 2, "P_T0"), real(P_N0, "P_N0"), real(g0, "g0"),
            vec(DF, 3, "DF"), str(wear_law), real(k_M, "k_M"))


def solve_step_3d(point: Point3d, DF, P_T0=(0.0, 0.0), P_N0: float = 0.0, g0: float = 0.0,
                  wear_law: str = "archard", k_M: float = 0.0,
                  chain: Sequence[str] = ("exact", "fb-soc", "ipopt"), max_iterations: int = 100,
                  tol: float = 1e-9, time_limit: float = 10.0) -> StepChain3dResult:
    """One verified solution of a 3-D step by the chain of links tried in order: "exact"
    (enumerate_step_3d, the solution closest to the start), "fb-soc" (SOC Fischer-Burmeister
    Newton), "ipopt" (MPCC). Every answer passes step_3d_residual <= tol."""
    if isinstance(chain, str):
        chain = [chain]
    d = _cpkit.solve_step_3d(*_step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M),
                             [str(c) for c in chain], integer(max_iterations, "max_iterations", 0),
                             real(tol, "tol"), real(time_limit, "time_limit"))
    return StepChain3dResult(**d)


def multistart_step_3d(point: Point3d, DF, P_T0=(0.0, 0.0), P_N0: float = 0.0, g0: float = 0.0,
                       wear_law: str = "archard", k_M: float = 0.0, n_starts: int = 16,
                       seed: int = 1) -> Step3dSolutionSet:
    """Distinct verified solutions of a 3-D step from FB-SOC and Ipopt at seeded starts;
    complete is always False (local solvers cannot prove that no other solution exists)."""
    d = _cpkit.multistart_step_3d(*_step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M),
                                  integer(n_starts, "n_starts", 0), integer(seed, "seed", 0))
    return Step3dSolutionSet(**d)


def solve_step_3d_faceted(point: Point3d, DF, facets: int, P_T0=(0.0, 0.0), P_N0: float = 0.0,
                          g0: float = 0.0, wear_law: str = "archard", k_M: float = 0.0,
                          n_starts: int = 16, seed: int = 1) -> FacetedStep3dSolutionSet:
    """The step with the friction ellipse replaced by its inscribed k-gon (facets in 3..64):
    without wear every solution of an LCP of size 1 + k (complete enumeration); with wear an
    NCP solved from starts (complete False)."""
    d = _cpkit.solve_step_3d_faceted(*_step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M),
                                     integer(facets, "facets"), integer(n_starts, "n_starts", 1),
                                     integer(seed, "seed", 0))
    return FacetedStep3dSolutionSet(**d)

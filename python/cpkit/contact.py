"""The contact, friction and wear model of Stromberg, Johansson & Klarbring (1996): the
one-point rate problem, its maps, one incremental step and the quasi-static simulation
(docs/contact_model.md, docs/maps.md, docs/simulation.md)."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from . import _cpkit
from .results import (DirectionMap, ParamDirectionMap, ParamParamMap, RateSolutionSet,
                      SimulationResult, SolveResult, StepSolutionSet)

__all__ = ["ContactParameters", "ContactState", "solve_rate_problem", "rate_indicators",
           "direction_map", "param_direction_map", "param_param_map", "enumerate_step",
           "solve_step", "simulate", "fretting_history", "ramp_history"]


@dataclass
class ContactParameters:
    """One contact point [Stromberg et al. 1996, Sec. 4]: A = [[a11, a12], [a12, a22]]
    (stiffness, force/length, symmetric positive definite), friction coefficient mu > 0,
    tangential compliance C_T >= 0 (length/force), Archard coefficient k_a >= 0, hardness
    P_s > 0, criterion "38" (Coulomb, default) or "35" (friction softening)."""
    a11: float = 1.0
    a12: float = 0.0
    a22: float = 1.0
    mu: float = 0.5
    C_T: float = 0.0
    k_a: float = 0.0
    P_s: float = 1.0
    criterion: str = "38"


@dataclass
class ContactState:
    """Contact state a (open), b (grazing), c (stick, P_N > 0) or d (sliding, P_N > 0,
    sgn_PT = sign of P_T)."""
    label: str = "b"
    P_N: float = 0.0
    sgn_PT: int = 1


def _load(dF):
    a = np.asarray(dF, dtype=float)
    if a.shape != (2,):
        raise ValueError(f"dF must be (dF_T, dF_N), got shape {a.shape}")
    return float(a[0]), float(a[1])


def solve_rate_problem(params, state, dF=None, method: str = "enumerate"):
    """Every solution of a rate problem.

    One point: solve_rate_problem(params, state, dF, method="enumerate") with
    ContactParameters, a ContactState or just its label ("a".."d"), and dF = (dF_T, dF_N);
    method "enumerate" (LCP + complete enumeration, default), "analytic" (the paper's closed
    forms) or a single solver ("lemke", "fb-newton", "ipopt": one solution, complete=False).
    Returns a RateSolutionSet.

    N points: solve_rate_problem(system, dF, method="enumerate") with a ContactSystem and a
    2N-vector dF (see cpkit.system.solve_system_rate). Returns a SystemRateSolutionSet."""
    from .system import ContactSystem, solve_system_rate
    if isinstance(params, ContactSystem):
        if dF is not None:  # solve_rate_problem(system, dF, method)
            method = dF
        return solve_system_rate(params, state, method)
    if dF is None:
        raise TypeError("solve_rate_problem(params, state, dF): the load rate dF is missing")
    dFT, dFN = _load(dF)
    return RateSolutionSet._from(_cpkit.solve_rate_problem(params, state, dFT, dFN, method))


def rate_indicators(params: ContactParameters, state) -> dict:
    """detA, D0, kappa, mu_eff, D_plus, D_minus, Lambda and unique_for_all_directions."""
    return dict(_cpkit.rate_indicators(params, state))


def direction_map(params: ContactParameters, state, method: str = "enumerate") -> DirectionMap:
    """The exact direction map: sectors of load directions with their solution sets."""
    return DirectionMap(**_cpkit.direction_map(params, state, method))


def param_direction_map(params: ContactParameters, state, param: str = "mu", start: float = 0.1,
                        stop: float = 4.0, n: int = 100, theta_n: int = 360,
                        method: str = "enumerate", threads: int = 0) -> ParamDirectionMap:
    """Grid of solution counts/types over `param` in [start, stop] (n values) x theta_n load
    directions. param: mu, a11, a12, a22, a12/a11, C_T, k_a, P_s, P_N, kappa."""
    return ParamDirectionMap(**_cpkit.param_direction_map(
        params, state, param, float(start), float(stop), int(n), int(theta_n), method,
        int(threads)))


def param_param_map(params: ContactParameters, state, param1: str, start1: float, stop1: float,
                    n1: int, param2: str, start2: float, stop2: float, n2: int,
                    method: str = "enumerate", threads: int = 0) -> ParamParamMap:
    """Every (param1, param2) cell classified from its exact direction map."""
    return ParamParamMap(**_cpkit.param_param_map(
        params, state, param1, float(start1), float(stop1), int(n1), param2, float(start2),
        float(stop2), int(n2), method, int(threads)))


def enumerate_step(params: ContactParameters, P_T0: float, P_N0: float, g0: float, DF,
                   wear_law: str = "archard", k_M: float = 0.0,
                   detect_jumps: bool = True) -> StepSolutionSet:
    """All solutions of one implicit step from (P_T0, P_N0, g0) under the load increment
    DF = (DF_T, DF_N) (docs/simulation.md)."""
    dFT, dFN = _load(DF)
    return StepSolutionSet._from(_cpkit.enumerate_step(
        params, float(P_T0), float(P_N0), float(g0), dFT, dFN, wear_law, float(k_M),
        bool(detect_jumps)))


def solve_step(params: ContactParameters, P_T0: float, P_N0: float, g0: float, DF,
               wear_law: str = "archard", k_M: float = 0.0,
               chain: Sequence[str] = ()) -> dict:
    """One solution of a step by the solver chain (default active-set, lemke, fb-newton,
    ipopt): {"result": SolveResult (z = (P_N1, l+, l-)), "values": {...}, "type": name}."""
    dFT, dFN = _load(DF)
    d = _cpkit.solve_step(params, float(P_T0), float(P_N0), float(g0), dFT, dFN, wear_law,
                          float(k_M), list(chain))
    d["result"] = SolveResult._from(d["result"])
    return d


def fretting_history(F_N=1.0, amplitude=0.1, period=1.0, cycles=10, steps_per_cycle=100,
                     ramp_steps=10) -> dict:
    """A fretting load history: ramp to F_N, then F_T = amplitude sin(2 pi t / period).
    Returns {"t", "F_T", "F_N", "period", "cycle_start"} (arrays and numbers)."""
    return dict(_cpkit.fretting_history(float(F_N), float(amplitude), float(period), int(cycles),
                                        int(steps_per_cycle), int(ramp_steps)))


def ramp_history(F_T0=0.0, F_N0=0.0, F_T1=0.0, F_N1=1.0, duration=1.0, steps=100) -> dict:
    """A linear ramp of the load, as fretting_history()."""
    return dict(_cpkit.ramp_history(float(F_T0), float(F_N0), float(F_T1), float(F_N1),
                                    float(duration), int(steps)))


def simulate(params: ContactParameters, history: dict, wear_law: str = "archard",
             k_M: float = 0.0, heat: Optional[dict] = None, branch_rule: str = "closest",
             tol: float = 1e-9, record_every: int = 1) -> SimulationResult:
    """Quasi-static simulation of the load history {"t", "F_T", "F_N"[, "period",
    "cycle_start"]} from the unloaded grazing state. heat: None (off) or a dict with any of
    heat_capacity, T_ref, T_initial, T_body (2), conductance (2)."""
    def arr(key):
        if key not in history:
            raise ValueError(f"history needs the key {key!r} (t, F_T, F_N)")
        a = np.asarray(history[key], dtype=float)
        if a.ndim != 1:
            raise ValueError(f"history[{key!r}] must be 1-D, got shape {a.shape}")
        return a
    d = _cpkit.simulate(params, arr("t"), arr("F_T"), arr("F_N"),
                        float(history.get("period", 0.0)), float(history.get("cycle_start", 0.0)),
                        wear_law, float(k_M), heat, branch_rule, float(tol), int(record_every))
    return SimulationResult(**d)

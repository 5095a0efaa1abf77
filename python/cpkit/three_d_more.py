"""More of the 3-D API (docs/contact_3d.md): maps of a "dim": 3 system over the sphere of load
directions and over parameters, the solvers of one implicit 3-D step (chain, multistart,
faceted), and fretting of one 3-D point under an elliptic tangential load orbit."""
from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from . import _cpkit
from .three_d import Point3d, Step3dSolutionSet, _vec

__all__ = ["Map3d", "StepChain3dResult", "FacetedStep3dSolutionSet", "Fretting3dResult",
           "sphere_map_3d", "param_direction_map_3d", "param_param_map_3d", "solve_step_3d",
           "multistart_step_3d", "solve_step_3d_faceted", "simulate_fretting_3d"]

#: Bits of a cell's type mask (sphere_map_3d.hpp type_bit).
TYPE_BITS_3D = {"open": 1, "separation": 2, "stick": 4, "slip": 8}


@dataclass
class Map3d:
    """A 3-D map: rows x columns numpy grids `count` (int8, -1: infinitely many), `types`
    (uint8 mask: open 1, separation 2, stick 4, slip 8, of the loaded point) and `complete`
    (bool: the cell's set is proved complete); `x`, `y` the row and column values (sphere: b and
    g; param-direction: the parameter and theta; param-param: the two parameters).
    incomplete_cells counts the cells not proved complete; count_cells {count: cells},
    type_cells {"separation|stick": cells}."""
    kind: str
    x: np.ndarray
    y: np.ndarray
    count: np.ndarray
    types: np.ndarray
    complete: np.ndarray
    incomplete_cells: int
    count_cells: Dict[int, int]
    type_cells: Dict[str, int]
    route: str
    facets: int
    point: int
    others: str
    seconds: float
    threads: int
    param: Optional[str] = None
    gamma: Optional[float] = None
    param1: Optional[str] = None
    param2: Optional[str] = None

    @property
    def shape(self):
        return self.count.shape


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


@dataclass
class Fretting3dResult:
    """A 3-D fretting run. series: numpy columns step, t, F_N, P_N, g, w_N, lambda, Dw_w, w_w,
    count, complete (1/0), dissipation, cycle (-1: ramp or lead-in), 2-vector columns F_T, P_T,
    w_T, w_Ti, Dw_Ti of shape (n, 2), and type (a list of names). outcome "completed" or why it
    stopped (message); wear_depth, wear_integral ((40) or (41) summed), total_slip, total_lambda,
    per-cycle arrays slip_per_cycle, wear_per_cycle, wear_X_per_cycle, wear_Y_per_cycle."""
    series: Dict[str, Any]
    final_state: Dict[str, Any]
    outcome: str
    message: str
    steps: int
    branch_steps: int
    incomplete_steps: int
    local_steps: int
    enumeration_missed: int
    wear_depth: float
    wear_integral: float
    total_slip: float
    total_lambda: float
    slip_per_cycle: np.ndarray
    wear_per_cycle: np.ndarray
    wear_X_per_cycle: np.ndarray
    wear_Y_per_cycle: np.ndarray
    dissipation: float
    min_step_dissipation: float
    max_residual: float
    period: float
    cycle_start: float
    lead_steps: int


def _system_text(system) -> str:
    """A "dim": 3 system given as a path, its JSON text or a dict, as JSON text."""
    if isinstance(system, dict):
        return json.dumps(system)
    if isinstance(system, str) and system.lstrip().startswith("{"):
        return system
    with open(os.fspath(system), encoding="utf-8") as f:
        return f.read()


def _int(x, name, low=None):
    if isinstance(x, bool) or not float(x).is_integer():
        raise ValueError(f"{name} must be an integer, got {x!r}")
    v = int(x)
    if low is not None and v < low:
        raise ValueError(f"{name} must be >= {low}, got {v}")
    return v


def _real(x, name):
    v = float(x)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return v


def _facets(facets):
    if facets is None:
        return 0
    k = _int(facets, "facets")
    if k <= 0:
        raise ValueError(f"facets must be a positive number of facets (3..64), got {facets}")
    return k


def _range(r, name):
    a = _vec(r, 2, name)
    return a[0], a[1]


def sphere_map_3d(system, n_beta: int = 91, n_gamma: int = 180,
                  beta_range: Sequence[float] = (0.0, math.pi), facets: Optional[int] = None,
                  point: int = 1, others: str = "auto", threads: int = 0) -> Map3d:
    """The map over the sphere of load directions dF = (sin b cos g, sin b sin g, cos b) of
    point `point` (1-based): n_beta rows at the cell centres of beta_range (b from +N),
    n_gamma columns g_j = -pi + 2 pi (j + 1) / n_gamma. One point: exact, or faceted with
    facets=K; N > 1 points need facets. others: the other points' load rates, "zero", "file"
    (the system's dF) or "auto" (the file's when N > 1 and it has one; as the CLI)."""
    b0, b1 = _range(beta_range, "beta_range")
    return Map3d(**_cpkit.sphere_map_3d(
        _system_text(system), _int(n_beta, "n_beta", 1), _int(n_gamma, "n_gamma", 1), b0, b1,
        _facets(facets), _int(point, "point"), str(others), _int(threads, "threads", 0)))


def param_direction_map_3d(system, param: str, start: float, stop: float, n: int = 100,
                           theta_n: int = 360, theta_range: Sequence[float] = (0.0, 2 * math.pi),
                           gamma: float = 0.0, facets: Optional[int] = None, point: int = 1,
                           others: str = "auto", threads: int = 0) -> Map3d:
    """Rows: param (alpha_X, alpha_Y, mu, C_T, k_a, P_s, or "NAME@i") in [start, stop], n values;
    columns: theta_n directions dF = (cos t cos gamma, cos t sin gamma, sin t) at the cell
    centres of theta_range (0 < width <= 2 pi)."""
    t0, t1 = _range(theta_range, "theta_range")
    return Map3d(**_cpkit.param_direction_map_3d(
        _system_text(system), str(param), _real(start, "start"), _real(stop, "stop"),
        _int(n, "n", 1), _int(theta_n, "theta_n", 1), t0, t1, _real(gamma, "gamma"),
        _facets(facets), _int(point, "point"), str(others), _int(threads, "threads", 0)))


def param_param_map_3d(system, param1: str, start1: float, stop1: float, n1: int, param2: str,
                       start2: float, stop2: float, n2: int, facets: Optional[int] = None,
                       point: int = 1, others: str = "auto", threads: int = 0) -> Map3d:
    """Two parameters at the system's "dF" (required): rows param1, columns param2; `types`
    of point `point`."""
    return Map3d(**_cpkit.param_param_map_3d(
        _system_text(system), str(param1), _real(start1, "start1"), _real(stop1, "stop1"),
        _int(n1, "n1", 1), str(param2), _real(start2, "start2"), _real(stop2, "stop2"),
        _int(n2, "n2", 1), _facets(facets), _int(point, "point"), str(others),
        _int(threads, "threads", 0)))


def _step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M):
    return (point, _vec(P_T0, 2, "P_T0"), _real(P_N0, "P_N0"), _real(g0, "g0"),
            _vec(DF, 3, "DF"), str(wear_law), _real(k_M, "k_M"))


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
                             [str(c) for c in chain], _int(max_iterations, "max_iterations", 0),
                             _real(tol, "tol"), _real(time_limit, "time_limit"))
    return StepChain3dResult(**d)


def multistart_step_3d(point: Point3d, DF, P_T0=(0.0, 0.0), P_N0: float = 0.0, g0: float = 0.0,
                       wear_law: str = "archard", k_M: float = 0.0, n_starts: int = 16,
                       seed: int = 1) -> Step3dSolutionSet:
    """Distinct verified solutions of a 3-D step from FB-SOC and Ipopt at seeded starts;
    complete is always False (local solvers cannot prove that no other solution exists)."""
    d = _cpkit.multistart_step_3d(*_step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M),
                                  _int(n_starts, "n_starts", 0), _int(seed, "seed", 0))
    return Step3dSolutionSet(**d)


def solve_step_3d_faceted(point: Point3d, DF, facets: int, P_T0=(0.0, 0.0), P_N0: float = 0.0,
                          g0: float = 0.0, wear_law: str = "archard", k_M: float = 0.0,
                          n_starts: int = 16, seed: int = 1) -> FacetedStep3dSolutionSet:
    """The step with the friction ellipse replaced by its inscribed k-gon (facets in 3..64):
    without wear every solution of an LCP of size 1 + k (complete enumeration); with wear an
    NCP solved from starts (complete False)."""
    d = _cpkit.solve_step_3d_faceted(*_step_args(point, DF, P_T0, P_N0, g0, wear_law, k_M),
                                     _int(facets, "facets"), _int(n_starts, "n_starts", 1),
                                     _int(seed, "seed", 0))
    return FacetedStep3dSolutionSet(**d)


def simulate_fretting_3d(point: Point3d, orbit: Sequence[float], F_N: float = 1.0,
                         angle: float = 0.0, period: float = 1.0, cycles: int = 10,
                         steps_per_cycle: int = 100, ramp_steps: int = 10,
                         lead_steps: Optional[int] = None, wear_law: str = "archard",
                         k_M: float = 0.0, branch_rule: str = "closest", record_every: int = 1,
                         local_fallback: bool = True) -> Fretting3dResult:
    """Quasi-static fretting of one 3-D point from the unloaded grazing state: F_N ramps up in
    ramp_steps steps, F_T leads in linearly to the orbit's start in lead_steps steps (None:
    steps_per_cycle / 4), then `cycles` cycles of F_T = R(angle) (a_X cos, a_Y sin)(2 pi s /
    period) with orbit = (a_X, a_Y) (a_Y < 0 clockwise, 0 a straight line). Every step is
    enumerated exactly (enumerate_step_3d); several solutions: branch_rule "closest" or "stop"."""
    a_X, a_Y = _vec(orbit, 2, "orbit")
    lead = -1 if lead_steps is None else _int(lead_steps, "lead_steps", 0)
    d = _cpkit.simulate_fretting_3d(
        point, _real(F_N, "F_N"), a_X, a_Y, _real(angle, "angle"), _real(period, "period"),
        _int(cycles, "cycles", 1), _int(steps_per_cycle, "steps_per_cycle", 1),
        _int(ramp_steps, "ramp_steps", 1), lead, str(wear_law), _real(k_M, "k_M"),
        str(branch_rule), _int(record_every, "record_every", 0), bool(local_fallback))
    return Fretting3dResult(**d)

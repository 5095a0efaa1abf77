"""Quasi-static simulation (docs/simulation.md, docs/contact_3d.md): load histories and the
simulation of one 2-D point; fretting of one 3-D point under an elliptic tangential orbit."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Optional, Sequence

import numpy as np

from . import _cpkit
from ._checks import integer, number, numbers, real, vec
from .model import ContactParameters, Point3d
from .results import SimulationResult

__all__ = ["fretting_history", "ramp_history", "simulate", "Fretting3dResult",
           "simulate_fretting_3d"]


def fretting_history(F_N=1.0, amplitude=0.1, period=1.0, cycles=10, steps_per_cycle=100,
                     ramp_steps=10) -> dict:
    """A fretting load history: ramp to F_N, then F_T = amplitude sin(2 pi t / period).
    Returns {"t", "F_T", "F_N", "period", "cycle_start"} (arrays and numbers)."""
    return dict(_cpkit.fretting_history(
        number(F_N, "F_N"), number(amplitude, "amplitude"), number(period, "period"),
        integer(cycles, "cycles"), integer(steps_per_cycle, "steps_per_cycle"),
        integer(ramp_steps, "ramp_steps")))


def ramp_history(F_T0=0.0, F_N0=0.0, F_T1=0.0, F_N1=1.0, duration=1.0, steps=100) -> dict:
    """A linear ramp of the load, as fretting_history()."""
    return dict(_cpkit.ramp_history(number(F_T0, "F_T0"), number(F_N0, "F_N0"), number(F_T1, "F_T1"),
                                    number(F_N1, "F_N1"), number(duration, "duration"),
                                    integer(steps, "steps")))


def simulate(params: ContactParameters, history: dict, wear_law: str = "archard",
             k_M: float = 0.0, heat: Optional[dict] = None, branch_rule: str = "closest",
             tol: float = 1e-9, record_every: int = 1) -> SimulationResult:
    """Quasi-static simulation of the load history {"t", "F_T", "F_N"[, "period",
    "cycle_start"]} from the unloaded grazing state. heat: None (off) or a dict with any of
    heat_capacity, T_ref, T_initial, T_body (2), conductance (2)."""
    def arr(key):
        if key not in history:
            raise ValueError(f"history needs the key {key!r} (t, F_T, F_N)")
        return numbers(history[key], f"history[{key!r}]", 1)
    d = _cpkit.simulate(params, arr("t"), arr("F_T"), arr("F_N"),
                        number(history.get("period", 0.0), "history['period']"),
                        number(history.get("cycle_start", 0.0), "history['cycle_start']"),
                        wear_law, number(k_M, "k_M"), heat, branch_rule, number(tol, "tol"),
                        integer(record_every, "record_every"))
    return SimulationResult(**d)


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
    a_X, a_Y = vec(orbit, 2, "orbit")
    lead = -1 if lead_steps is None else integer(lead_steps, "lead_steps", 0)
    d = _cpkit.simulate_fretting_3d(
        point, real(F_N, "F_N"), a_X, a_Y, real(angle, "angle"), real(period, "period"),
        integer(cycles, "cycles", 1), integer(steps_per_cycle, "steps_per_cycle", 1),
        integer(ramp_steps, "ramp_steps", 1), lead, str(wear_law), real(k_M, "k_M"),
        str(branch_rule), integer(record_every, "record_every", 0), bool(local_fallback))
    return Fretting3dResult(**d)

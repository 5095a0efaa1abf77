"""Maps of solution counts and types (docs/maps.md, docs/contact_3d.md): the one-point 2-D
direction and parameter maps, and the maps of a "dim": 3 system over the sphere of load
directions and over parameters."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, Optional, Sequence

import numpy as np

from . import _cpkit
from ._checks import facet_count, integer, number, real, vec
from .model import ContactParameters
from .results import DirectionMap, ParamDirectionMap, ParamParamMap
from .system import system_3d

__all__ = ["direction_map", "param_direction_map", "param_param_map", "Map3d", "sphere_map_3d",
           "param_direction_map_3d", "param_param_map_3d"]


def direction_map(params: ContactParameters, state, method: str = "enumerate") -> DirectionMap:
    """The exact direction map: sectors of load directions with their solution sets."""
    return DirectionMap(**_cpkit.direction_map(params, state, method))


def param_direction_map(params: ContactParameters, state, param: str = "mu", start: float = 0.1,
                        stop: float = 4.0, n: int = 100, theta_n: int = 360,
                        method: str = "enumerate", threads: int = 0) -> ParamDirectionMap:
    """Grid of solution counts/types over `param` in [start, stop] (n values) x theta_n load
    directions. param: mu, a11, a12, a22, a12/a11, C_T, k_a, P_s, P_N, kappa."""
    return ParamDirectionMap(**_cpkit.param_direction_map(
        params, state, param, number(start, "start"), number(stop, "stop"), integer(n, "n", 1),
        integer(theta_n, "theta_n", 1), method, integer(threads, "threads", 0)))


def param_param_map(params: ContactParameters, state, param1: str, start1: float, stop1: float,
                    n1: int, param2: str, start2: float, stop2: float, n2: int,
                    method: str = "enumerate", threads: int = 0) -> ParamParamMap:
    """Every (param1, param2) cell classified from its exact direction map."""
    return ParamParamMap(**_cpkit.param_param_map(
        params, state, param1, number(start1, "start1"), number(stop1, "stop1"), integer(n1, "n1", 1),
        param2, number(start2, "start2"), number(stop2, "stop2"), integer(n2, "n2", 1), method,
        integer(threads, "threads", 0)))


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


def _range(r, name):
    a = vec(r, 2, name)
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
        system_3d(system), integer(n_beta, "n_beta", 1), integer(n_gamma, "n_gamma", 1), b0, b1,
        facet_count(facets), integer(point, "point"), str(others), integer(threads, "threads", 0)))


def param_direction_map_3d(system, param: str, start: float, stop: float, n: int = 100,
                           theta_n: int = 360, theta_range: Sequence[float] = (0.0, 2 * math.pi),
                           gamma: float = 0.0, facets: Optional[int] = None, point: int = 1,
                           others: str = "auto", threads: int = 0) -> Map3d:
    """Rows: param (alpha_X, alpha_Y, mu, C_T, k_a, P_s, or "NAME@i") in [start, stop], n values;
    columns: theta_n directions dF = (cos t cos gamma, cos t sin gamma, sin t) at the cell
    centres of theta_range (0 < width <= 2 pi)."""
    t0, t1 = _range(theta_range, "theta_range")
    return Map3d(**_cpkit.param_direction_map_3d(
        system_3d(system), str(param), real(start, "start"), real(stop, "stop"),
        integer(n, "n", 1), integer(theta_n, "theta_n", 1), t0, t1, real(gamma, "gamma"),
        facet_count(facets), integer(point, "point"), str(others), integer(threads, "threads", 0)))


def param_param_map_3d(system, param1: str, start1: float, stop1: float, n1: int, param2: str,
                       start2: float, stop2: float, n2: int, facets: Optional[int] = None,
                       point: int = 1, others: str = "auto", threads: int = 0) -> Map3d:
    """Two parameters at the system's "dF" (required): rows param1, columns param2; `types`
    of point `point`."""
    return Map3d(**_cpkit.param_param_map_3d(
        system_3d(system), str(param1), real(start1, "start1"), real(stop1, "stop1"),
        integer(n1, "n1", 1), str(param2), real(start2, "start2"), real(stop2, "stop2"),
        integer(n2, "n2", 1), facet_count(facets), integer(point, "point"), str(others),
        integer(threads, "threads", 0)))

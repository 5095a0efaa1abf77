"""The argument checks shared by the modules of cpkit: each turns a user's value into what the
compiled part takes, or raises TypeError/ValueError naming the argument."""
from __future__ import annotations

import json
import math
import os

import numpy as np


def numbers(x, name: str, ndim=None, what: str = "hold numbers", finite: bool = False) -> np.ndarray:
    """x as a float64 array. TypeError "<name> must <what> (...)" when it does not convert,
    ValueError for another number of dimensions than ndim or (finite) a NaN/Inf entry."""
    try:
        a = np.asarray(x, dtype=float)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name} must {what} ({e})") from None
    if ndim is not None and a.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-D array, got shape {a.shape}")
    if finite and not np.isfinite(a).all():
        raise ValueError(f"{name} has a NaN or infinite entry")
    return a


def vector(v, name: str) -> np.ndarray:
    """A 1-D float64 array."""
    return numbers(v, name, 1, "be a vector of numbers")


def vec(x, n: int, name: str) -> list:
    """Exactly n finite numbers (any shape), as a list."""
    a = np.asarray(x, dtype=float).ravel()
    if a.size != n:
        raise ValueError(f"{name} must hold {n} numbers, got {a.size}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} has a NaN or infinite entry")
    return a.tolist()


def load_2d(dF):
    """A 2-D load (dF_T, dF_N) as two floats."""
    a = np.asarray(dF, dtype=float)
    if a.shape != (2,):
        raise ValueError(f"dF must be (dF_T, dF_N), got shape {a.shape}")
    return float(a[0]), float(a[1])


def integer(x, name: str, low=None) -> int:
    if isinstance(x, bool) or not float(x).is_integer():
        raise ValueError(f"{name} must be an integer, got {x!r}")
    v = int(x)
    if low is not None and v < low:
        raise ValueError(f"{name} must be >= {low}, got {v}")
    return v


def real(x, name: str) -> float:
    v = float(x)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return v


def facet_count(facets) -> int:
    """None (exact: 0) or a positive number of facets."""
    if facets is None:
        return 0
    k = integer(facets, "facets")
    if k <= 0:
        raise ValueError(f"facets must be a positive number of facets (3..64), got {facets}")
    return k


def system_text(system) -> str:
    """A "dim": 3 system given as a path, its JSON text or a dict, as JSON text."""
    if isinstance(system, dict):
        return json.dumps(system)
    if isinstance(system, str) and system.lstrip().startswith("{"):
        return system
    with open(os.fspath(system), encoding="utf-8") as f:
        return f.read()

"""N contact points coupled through a condensed stiffness (docs/model.md, "N contact points";
rate_problem/system/contact_system.hpp): what a finite-element code hands over. A ContactSystem
(2-D) or ContactSystem3d ("dim": 3) is parsed ONCE by the C++ reader and keeps the parsed object,
which every function that takes a system receives (no JSON text on the call path)."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _cpkit
from ._checks import existing_path, numbers, system_text
from .model import ContactParameters
from .results import SystemRateSolutionSet

__all__ = ["ContactSystem", "ContactSystem3d", "solve_system_rate", "system_direction_counts"]


def _finite_list(a, name, ndim=None):
    return numbers(a, name, ndim, finite=True).tolist()


_FIELDS = ("A", "points", "criterion", "dF", "patterns", "name")


class _ReadOnlyDict(dict):
    """A point of a parsed system: a dict that refuses in-place edits (the parsed C++ system would
    not see them); copy it (dict(p)) and assign system.points = [...] to change a point."""

    def _refuse(self, *args, **kwargs):
        raise TypeError("a ContactSystem's points are read-only once parsed: assign "
                        "system.points = [...] (e.g. with dict(p) copies) to change them")

    __setitem__ = __delitem__ = update = pop = popitem = clear = setdefault = _refuse
    __ior__ = _refuse

    def __reduce__(self):  # copy and pickle without __setitem__
        return (self.__class__, (dict(self),))


class _ReadOnlyList(list):
    """The points of a parsed system (see _ReadOnlyDict)."""
    __setitem__ = __delitem__ = __iadd__ = __imul__ = _ReadOnlyDict._refuse
    append = extend = insert = pop = remove = clear = sort = reverse = _ReadOnlyDict._refuse

    def __reduce__(self):
        return (self.__class__, (list(self),))


def _read_only(a):
    if isinstance(a, np.ndarray):
        a.flags.writeable = False
    return a


@dataclass(repr=False)
class ContactSystem:
    """N contact points in 2-D. A: the 2N x 2N symmetric positive definite stiffness on the DOFs
    (T_1, N_1, T_2, N_2, ...) (N points into the obstacle: w_N > 0 penetrates; P_N >= 0
    compressive; equilibrium F - P = A w). points: one dict per point with the keys of the
    system file (docs/file_formats.md): "mu", "C_T", "k_a", "P_s" and either "state" ("a".."d",
    with "P_N" for c/d and "sgnPT" for d, "g" < 0 for a) or the current values "P_N", "g"
    (and "P_T"). dF: an optional load rate, patterns: optional load patterns (e1, e2) for
    direction maps, both 2N-vectors. Validated on construction (ValueError naming the field and
    the point, 1-based); A is then symmetrised and each point completed with its state. Parsed
    once by the C++ reader: calls receive the parsed system. The fields are read-only in place;
    assigning one (system.points = [...]) has the system parsed and checked at the next call."""
    A: Any
    points: List[Dict[str, Any]]
    criterion: str = "38"
    dF: Optional[Any] = None
    patterns: Optional[Tuple[Any, Any]] = None
    name: str = ""

    def __post_init__(self):
        self._parse()

    def __setattr__(self, key, value):
        # Assigning a field drops the parsed system: the next call parses (and validates) anew,
        # as before. In-place edits are refused instead (read-only arrays, points).
        object.__setattr__(self, key, value)
        if key in _FIELDS:
            object.__setattr__(self, "_data", None)

    def __getstate__(self):  # pickle the fields; the parsed system is rebuilt on loading
        return {k: self.__dict__[k] for k in _FIELDS}

    def __setstate__(self, state):
        for k, v in state.items():
            object.__setattr__(self, k, v)
        self._parse()

    def _adopt(self, data) -> "ContactSystem":
        """Takes the parsed system `data` and shows its normalised fields (A symmetrised, each
        point completed with its state), read-only."""
        d = data.to_dict()
        object.__setattr__(self, "A", _read_only(d["A"]))
        object.__setattr__(self, "points", _ReadOnlyList(_ReadOnlyDict(p) for p in d["points"]))
        object.__setattr__(self, "criterion", d["criterion"])
        object.__setattr__(self, "dF", _read_only(d["dF"]))
        patterns = d["patterns"]
        object.__setattr__(self, "patterns",
                           None if patterns is None else tuple(_read_only(e) for e in patterns))
        object.__setattr__(self, "_data", data)
        return self

    def _parse(self):
        return self._adopt(_cpkit.ContactSystemData.from_json(self.to_json()))._data

    def _system(self):
        """The parsed C++ system (_cpkit.ContactSystemData), parsed again only after a field
        was assigned."""
        data = self.__dict__.get("_data")
        return data if data is not None else self._parse()

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
        data = _cpkit.ContactSystemData.from_file(existing_path(path))
        s = cls.__new__(cls)
        object.__setattr__(s, "name", data.to_dict()["name"])
        return s._adopt(data)

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
    dF = numbers(dF, "dF")
    if dF.ndim != 1:
        raise ValueError(f"dF must be a 1-D array of 2N = {2 * system.n_points} entries, got shape {dF.shape}")
    return SystemRateSolutionSet._from(_cpkit.solve_system_rate(system._system(), dF, method))


def system_direction_counts(system: ContactSystem, theta, e1=None, e2=None) -> Dict[str, np.ndarray]:
    """For the loads dF = cos(theta) e1 + sin(theta) e2 at every theta (radians): "count"
    (-1: infinitely many), "n_tuples" (distinct type tuples) and "reliable" (False where the
    enumeration could not decide), as numpy arrays. e1, e2 default to the system's patterns."""
    if not isinstance(system, ContactSystem):
        raise TypeError("system must be a cpkit.ContactSystem")
    if e1 is None or e2 is None:
        if system.patterns is None:
            raise ValueError("give the load patterns e1, e2 (the system has no patterns)")
        e1, e2 = system.patterns
    theta = np.atleast_1d(numbers(theta, "theta"))
    if theta.ndim != 1:
        raise ValueError(f"theta must be 1-D, got shape {theta.shape}")
    d = _cpkit.system_direction_counts(system._system(), numbers(e1, "e1"), numbers(e2, "e2"),
                                       theta)
    return dict(d)


class ContactSystem3d:
    """A "dim": 3 system (docs/file_formats.md, "System file"; rate_problem/system/
    contact_system.hpp), parsed once: ContactSystem3d(source) with a path, the file's JSON
    text or a dict of it, or ContactSystem3d.from_file(path) (the reader of `cpkit`, messages
    naming the file). ValueError naming the field and the point for bad input. Every function that
    takes a 3-D system accepts one (and a path, JSON text or dict, parsed at the call)."""

    def __init__(self, source):
        self._text = system_text(source)  # kept for pickling (the parsed object is not)
        self._data = _cpkit.ContactSystem3dData.from_json(self._text)

    @classmethod
    def from_file(cls, path) -> "ContactSystem3d":
        s = cls.__new__(cls)
        path = existing_path(path)
        s._data = _cpkit.ContactSystem3dData.from_file(path)  # its messages first
        with open(path, encoding="utf-8") as f:
            s._text = f.read()
        return s

    def __reduce__(self):  # pickled as its text, parsed again on loading
        return (self.__class__, (self._text,))

    @classmethod
    def from_dict(cls, doc: Dict[str, Any]) -> "ContactSystem3d":
        if not isinstance(doc, dict):
            raise TypeError("from_dict takes the system file as a dict")
        return cls(doc)

    @property
    def n_points(self) -> int:
        return self._data.n_points

    @property
    def name(self) -> str:
        return self._data.name

    def __repr__(self):
        return f"ContactSystem3d({self.name!r}, N={self.n_points})"


def system_3d(system):
    """The parsed C++ system of a ContactSystem3d, or of a path, JSON text or dict (parsed now)."""
    if isinstance(system, ContactSystem3d):
        return system._data
    return _cpkit.ContactSystem3dData.from_json(system_text(system))

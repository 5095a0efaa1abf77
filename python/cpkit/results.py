"""Result objects of cpkit: plain data (numbers, strings, lists, numpy arrays) in dataclasses,
so they pickle, compare and print without the compiled module. Field names follow the C++
structs and the CLI's JSON (docs/conventions.md, docs/python.md)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional

import numpy as np

# Solution types of the contact model and their bits in the type masks of maps
# (bit = the C++ enum value of SolutionType).
TYPE_BITS = {"open": 1, "separation": 2, "stick": 4, "slip+": 8, "slip-": 16}


def _short(a, width=6):
    """A numpy vector as a short string (the first `width` entries)."""
    if a is None:
        return "None"
    a = np.asarray(a)
    body = np.array2string(a[:width], precision=6, separator=", ", suppress_small=True)
    return body if a.size <= width else body[:-1] + f", ... ({a.size} entries)]"


@dataclass
class Residuals:
    """Residuals recomputed from the data (core/residuals.hpp). `natural` is the unit-free
    number that decides "solved" (<= tol); the others are information."""
    natural: float = 0.0
    natural_abs: float = 0.0
    complementarity: float = 0.0
    min_z: float = 0.0
    min_w: float = 0.0
    worst_index: int = -1
    scale: float = 0.0
    z_scale: float = 0.0
    rounding: float = 0.0
    finite: bool = True


@dataclass
class Certificate:
    """Farkas proof of infeasibility: y >= 0, M^T y <= 0, q^T y < 0, re-checked from the data."""
    y: np.ndarray
    checked: bool
    exact: bool
    q_dot_y: float
    max_MTy: float


@dataclass
class Attempt:
    """How one solver of a chain ("auto") ended."""
    solver: str
    status: str
    residual: float
    seconds: float
    message: str


@dataclass(repr=False)
class SolveResult:
    """What a solve returns. `status` is one of cpkit's status names ("solved",
    "solved_inaccurate", "infeasible", "ray_termination", ...); only "solved" and
    "solved_inaccurate" are solutions (`is_solution`). `w` = M z + q (F(x) for an MCP) is
    recomputed from your data."""
    status: str
    solver: str
    z: np.ndarray
    w: np.ndarray
    residuals: Residuals
    iterations: int = 0
    function_evals: int = 0
    jacobian_evals: int = 0
    seconds: float = 0.0
    certificate: Optional[Certificate] = None
    ray: Optional[np.ndarray] = None
    basis: List[int] = field(default_factory=list)
    attempts: List[Attempt] = field(default_factory=list)
    message: str = ""

    @property
    def is_solution(self) -> bool:
        return self.status in ("solved", "solved_inaccurate")

    @property
    def residual(self) -> float:
        """The unit-free acceptance residual (residuals.natural)."""
        return self.residuals.natural

    def __repr__(self):
        s = (f"SolveResult(status={self.status!r}, solver={self.solver!r}, z={_short(self.z)}, "
             f"residual={self.residuals.natural:.3g}, iterations={self.iterations}")
        if self.certificate is not None:
            s += f", certificate=y{_short(self.certificate.y)}"
        if self.attempts:
            s += ", attempts=[" + ", ".join(f"{a.solver}: {a.status}" for a in self.attempts) + "]"
        if self.message:
            s += f", message={self.message!r}"
        return s + ")"

    @classmethod
    def _from(cls, d: Dict[str, Any]) -> "SolveResult":
        # The extension's dict has every field: filled in directly, without the generated
        # __init__ (a third of a tiny solve's cost in Python; issue 27). Same object.
        r = object.__new__(cls)
        fields = r.__dict__
        fields.update(d)
        res = object.__new__(Residuals)
        res.__dict__.update(d["residuals"])
        fields["residuals"] = res
        if d["certificate"] is not None:
            fields["certificate"] = Certificate(**d["certificate"])
        attempts = d["attempts"]
        fields["attempts"] = [Attempt(**a) for a in attempts] if attempts else []
        return r


@dataclass(repr=False)
class BatchResult:
    """What solve_batch returns: one row per problem. `status` holds cpkit's status names;
    rows whose status is not a solution have z and w as the solver left them (NaN when it
    returned none)."""
    solver: str
    z: np.ndarray
    w: np.ndarray
    status: np.ndarray
    residual: np.ndarray

    @property
    def is_solution(self) -> np.ndarray:
        return (self.status == "solved") | (self.status == "solved_inaccurate")

    def __len__(self):
        return self.z.shape[0]

    def __repr__(self):
        k = len(self)
        solved = int(self.is_solution.sum())
        return f"BatchResult({k} problems, solver={self.solver!r}, {solved} solved)"

    @classmethod
    def _from(cls, d: Dict[str, Any]) -> "BatchResult":
        from . import _cpkit
        names = np.array(_cpkit.STATUS_NAMES)
        return cls(solver=d["solver"], z=d["z"], w=d["w"],
                   status=names[d["status_code"].astype(np.intp)], residual=d["residual"])


@dataclass
class ExtremeSolution:
    """One extreme solution (a vertex of a piece of the solution set)."""
    z: np.ndarray
    w: np.ndarray
    basis: List[int]


@dataclass
class SolutionPiece:
    """A piece of positive dimension: conv(vertices) + cone(rays); `support` has w_i = 0."""
    support: List[int]
    vertices: List[int]
    rays: List[np.ndarray]


@dataclass(repr=False)
class SolutionSet:
    """Every solution of an LCP (lcp/enumerate.hpp). `complete` is True only when every
    complementary basis was accounted for; otherwise `message` says why not."""
    solutions: List[ExtremeSolution]
    pieces: List[SolutionPiece]
    directions: List[np.ndarray]
    complete: bool
    infinite: bool
    ambiguous: int = 0
    unrepresentable: int = 0
    nodes: int = 0
    leaves: int = 0
    structured: bool = False
    seconds: float = 0.0
    message: str = ""

    @property
    def count(self) -> int:
        """Number of extreme solutions (see `infinite` for continua)."""
        return len(self.solutions)

    @property
    def z(self) -> np.ndarray:
        """The extreme solutions as rows of a (count x n) array."""
        if not self.solutions:
            return np.zeros((0, 0))
        return np.vstack([s.z for s in self.solutions])

    def __repr__(self):
        s = (f"SolutionSet(count={self.count}, infinite={self.infinite}, "
             f"complete={self.complete}, pieces={len(self.pieces)}")
        for k, sol in enumerate(self.solutions[:4]):
            s += f", z{k}={_short(sol.z)}"
        if self.count > 4:
            s += ", ..."
        if self.message:
            s += f", message={self.message!r}"
        return s + ")"

    @classmethod
    def _from(cls, d):
        d = dict(d)
        d["solutions"] = [ExtremeSolution(**s) for s in d["solutions"]]
        d["pieces"] = [SolutionPiece(**p) for p in d["pieces"]]
        return cls(**d)


@dataclass
class SolverCheck:
    """One solver's answer against the complete enumeration (lcp/cross_verify.hpp)."""
    solver: str
    status: str
    residual: float
    data_residual: float
    in_set: bool
    solution_index: int
    verdict: str
    seconds: float
    message: str


@dataclass(repr=False)
class CrossVerifyReport:
    set: SolutionSet
    checks: List[SolverCheck]
    disagreements: List[str]
    consistent: bool

    def __repr__(self):
        v = ", ".join(f"{c.solver}: {c.verdict}" for c in self.checks)
        return (f"CrossVerifyReport(consistent={self.consistent}, count={self.set.count}, "
                f"complete={self.set.complete}, checks=[{v}])")

    @classmethod
    def _from(cls, d):
        return cls(set=SolutionSet._from(d["set"]),
                   checks=[SolverCheck(**c) for c in d["checks"]],
                   disagreements=list(d["disagreements"]), consistent=d["consistent"])


@dataclass
class RateSolution:
    """One connected piece of a rate problem's solution set: a point, a segment or a ray.
    Rates are dicts {dP_T, dP_N, dw_T, dw_N, dw_Ti, dw_w}; `end` (segments) and `direction`
    (rays) are None otherwise."""
    type: str
    kind: str
    start: Dict[str, float]
    start_closed: bool = True
    end: Optional[Dict[str, float]] = None
    end_closed: bool = True
    direction: Optional[Dict[str, float]] = None


@dataclass(repr=False)
class RateSolutionSet:
    """All solutions of a rate problem (point_rate.hpp). `count` is -1 for infinitely many.
    Single solvers (method lemke, fb-newton, ipopt) give complete=False: one solution, not a
    count."""
    solutions: List[RateSolution]
    complete: bool
    infinite: bool
    count: int
    types: List[str]
    Lambda: float
    D_plus: float
    D_minus: float
    unique_for_all_directions: bool
    message: str = ""
    residual: float = 0.0

    def __repr__(self):
        n = "inf" if self.count < 0 else str(self.count)
        if not self.complete:
            return (f"RateSolutionSet(complete=False, found={len(self.solutions)}, "
                    f"types={self.types}, message={self.message!r})")
        return (f"RateSolutionSet(count={n}, types={self.types}, "
                f"unique_for_all_directions={self.unique_for_all_directions})")

    @classmethod
    def _from(cls, d):
        d = dict(d)
        d["solutions"] = [RateSolution(**s) for s in d["solutions"]]
        return cls(**d)


def _mask_has(types: np.ndarray, name: str) -> np.ndarray:
    if name not in TYPE_BITS:
        raise ValueError(f"unknown solution type {name!r} (valid: {', '.join(TYPE_BITS)})")
    return (np.asarray(types) & TYPE_BITS[name]) != 0


@dataclass(repr=False)
class DirectionMap:
    """Exact direction map: open sectors (theta_from, theta_to) with their solution count and
    types, and the critical directions between them (direction_map.hpp). Angles in radians
    from +dF_T towards +dF_N; theta_to > 2 pi marks the sector containing theta = 0."""
    sectors: List[Dict[str, Any]]
    critical: List[Dict[str, Any]]
    evaluations: int
    disagreements: int
    inconsistent_sectors: int
    unreliable: int
    cross_checked: bool

    @property
    def theta_from(self) -> np.ndarray:
        return np.array([s["theta_from"] for s in self.sectors])

    @property
    def theta_to(self) -> np.ndarray:
        return np.array([s["theta_to"] for s in self.sectors])

    @property
    def counts(self) -> np.ndarray:
        """Solution count per sector (-1: infinitely many)."""
        return np.array([s["count"] for s in self.sectors], dtype=np.int8)

    def __repr__(self):
        parts = [f"({s['theta_from']:.4f}, {s['theta_to']:.4f}): {s['count']} {s['types']}"
                 for s in self.sectors]
        return "DirectionMap(" + "; ".join(parts) + ")"


@dataclass(repr=False)
class ParamDirectionMap:
    """Parameter x direction grid: `count[i, j]` and `types[i, j]` (bit mask, TYPE_BITS) at
    parameter value `x[i]` and direction `theta[j]` (cell centres, radians), plus the analytic
    critical values (x where D_+ / D_- / Lambda vanish) and the exact critical directions."""
    param: str
    x: np.ndarray
    theta: np.ndarray
    count: np.ndarray
    types: np.ndarray
    disagree: Optional[np.ndarray]
    disagreements: int
    unreliable: int
    cross_checked: bool
    critical_values: List[Dict[str, Any]]
    critical_directions: List[Dict[str, Any]]
    seconds: float
    threads: int

    def has_type(self, name: str) -> np.ndarray:
        """Boolean grid: cells whose solution set contains a solution of type `name`."""
        return _mask_has(self.types, name)

    def __repr__(self):
        return (f"ParamDirectionMap({self.param} in [{self.x[0]:g}, {self.x[-1]:g}] x "
                f"{self.theta.size} directions, max count {int(self.count.max())}, "
                f"critical values {[(c['name'], round(c['x'], 6)) for c in self.critical_values]})")


@dataclass(repr=False)
class ParamParamMap:
    """Parameter x parameter grid: `cls[i, j]` indexes UNIQUENESS_CLASSES ("unique",
    "non-unique", "no-solution" for some direction) at (x[i], y[j]); min/max counts over all
    directions (-1: infinite) and the union of the types."""
    param1: str
    param2: str
    x: np.ndarray
    y: np.ndarray
    cls: np.ndarray
    min_count: np.ndarray
    max_count: np.ndarray
    types: np.ndarray
    disagreements: int
    inconsistent_sectors: int
    unreliable: int
    cross_checked: bool
    critical_curve: List[Dict[str, Any]]
    seconds: float
    threads: int

    def has_type(self, name: str) -> np.ndarray:
        return _mask_has(self.types, name)

    def __repr__(self):
        return (f"ParamParamMap({self.param1} x {self.param2}, {self.cls.shape[0]} x "
                f"{self.cls.shape[1]} cells)")


@dataclass
class StepSolution:
    """One piece of a step's solution set; values are dicts {DP_T, DP_N, Dw_T, Dw_N, Dw_Ti,
    Dw_w, P_T1, P_N1, g1}."""
    type: str
    kind: str
    start: Dict[str, float]
    start_closed: bool
    residual: float
    jump: bool
    end: Optional[Dict[str, float]] = None
    end_closed: bool = True
    direction: Optional[Dict[str, float]] = None


@dataclass(repr=False)
class StepSolutionSet:
    solutions: List[StepSolution]
    infinite: bool
    count: int
    continuous_count: int
    types: List[str]
    # False when a candidate could be neither accepted nor rejected (`message` says which):
    # the listed solutions are verified, but the set is not proved to hold every solution.
    complete: bool = True
    message: str = ""

    def __repr__(self):
        n = "inf" if self.count < 0 else str(self.count)
        more = "" if self.complete else ", complete=False"
        return (f"StepSolutionSet(count={n}, types={self.types}, "
                f"continuous_count={self.continuous_count}{more})")

    @classmethod
    def _from(cls, d):
        d = dict(d)
        d["solutions"] = [StepSolution(**s) for s in d["solutions"]]
        return cls(**d)


@dataclass(repr=False)
class SimulationResult:
    """A quasi-static simulation: `series` maps column names (t, F_T, F_N, P_T, P_N, w_T, w_N,
    w_w, w_Ti, g, count, dissipation, ..., temperature) to numpy arrays, and `state`/`type`
    to lists of names; `outcome` is "completed" or why the march stopped (`message`)."""
    series: Dict[str, Any]
    outcome: str
    message: str
    steps: int
    branch_steps: int
    wear_depth: float
    wear_integral: float
    total_slip: float
    slip_per_cycle: List[float]
    wear_per_cycle: List[float]
    external_work: float
    stored_energy: float
    dissipation: float
    energy_error: float
    min_step_dissipation: float
    thermal_dissipation: float
    max_temperature: float
    max_residual: float

    def __repr__(self):
        return (f"SimulationResult(outcome={self.outcome!r}, steps={self.steps}, "
                f"wear_depth={self.wear_depth:.6g}, total_slip={self.total_slip:.6g}, "
                f"energy_error={self.energy_error:.3g})")


@dataclass
class SystemRateSolution:
    """One piece of an N-point rate problem's solution set with one type tuple (`types`, one
    name per point). Rates are dicts of numpy arrays (one entry per point): dP_T, dP_N, dw_T,
    dw_N, dw_Ti, dw_w."""
    types: List[str]
    kind: str
    start: Dict[str, np.ndarray]
    start_closed: bool = True
    end: Optional[Dict[str, np.ndarray]] = None
    end_closed: bool = True
    direction: Optional[Dict[str, np.ndarray]] = None


@dataclass(repr=False)
class SystemRateSolutionSet:
    """All solutions of an N-point rate problem (rate/system_rate.hpp); `count` is -1 for
    infinitely many; `complete` False for single solvers or when the enumeration could not
    decide (then `message` says why)."""
    solutions: List[SystemRateSolution]
    infinite: bool
    complete: bool
    count: int
    message: str = ""
    residual: float = 0.0
    disagreement: bool = False

    @property
    def type_tuples(self) -> List[str]:
        """The distinct type tuples present, e.g. ["stick/slip+", "stick/stick"]."""
        return sorted({"/".join(s.types) for s in self.solutions})

    def __repr__(self):
        n = "inf" if self.count < 0 else str(self.count)
        return (f"SystemRateSolutionSet(count={n}, complete={self.complete}, "
                f"types={self.type_tuples})")

    @classmethod
    def _from(cls, d):
        d = dict(d)
        d["solutions"] = [SystemRateSolution(**s) for s in d["solutions"]]
        return cls(**d)

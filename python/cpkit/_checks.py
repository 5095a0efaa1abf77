"""The argument checks shared by the modules of cpkit: each turns a user's value into what the
compiled part takes, or raises TypeError/ValueError naming the argument (FileNotFoundError for a
missing file). Every array, number, integer option, path and sparse matrix a caller hands over
passes through one of these."""
from __future__ import annotations

import decimal
import errno
import json
import math
import numbers as _numbers
import os

import numpy as np

#: numpy dtype kinds taken as real numbers: bool, signed and unsigned integers, floats.
_REAL_KINDS = "biuf"
#: The largest value of a C++ int, the type of the compiled part's integer options.
INT_MAX = 2**31 - 1


def _is_real_scalar(v) -> bool:
    return isinstance(v, (_numbers.Real, decimal.Decimal)) and not isinstance(v, (str, bytes))


def real_array(x, name: str, what: str = "hold numbers") -> np.ndarray:
    """x as a float64 array, refusing what is not a real number: complex entries (their
    imaginary part would be dropped silently), strings (numeric ones included), None, objects.
    TypeError "<name> must <what> (...)"."""
    try:
        a = np.asarray(x)
    except (TypeError, ValueError) as e:  # ragged nesting, a failing __array__
        raise TypeError(f"{name} must {what} ({e})") from None
    kind = a.dtype.kind
    if kind == "c":
        raise TypeError(f"{name} must {what}: it has complex entries (dtype {a.dtype}); cpkit "
                        f"solves real problems (pass x.real if the imaginary part is meant to "
                        f"be dropped)")
    if kind == "O":  # Python objects (mixed types, Fraction, Decimal): each a real number
        bad = [v for v in a.flat if not _is_real_scalar(v)][:1]
        if bad:
            raise TypeError(f"{name} must {what}, got an entry of type {type(bad[0]).__name__}")
    elif kind not in _REAL_KINDS:
        raise TypeError(f"{name} must {what}, got dtype {a.dtype}" +
                        (" (strings are not converted)" if kind in "US" else ""))
    return a.astype(float, copy=False)


def numbers(x, name: str, ndim=None, what: str = "hold numbers", finite: bool = False) -> np.ndarray:
    """x as a float64 array (real_array). ValueError for another number of dimensions than
    ndim or (finite) a NaN/Inf entry."""
    a = real_array(x, name, what)
    if ndim is not None and a.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-D array, got shape {a.shape}")
    if finite and not np.isfinite(a).all():
        raise ValueError(f"{name} has a NaN or infinite entry")
    return a


def vector(v, name: str) -> np.ndarray:
    """A 1-D float64 array, C-contiguous (the compiled part maps it without a copy)."""
    return np.ascontiguousarray(numbers(v, name, 1, "be a vector of numbers"))


def vec(x, n: int, name: str) -> list:
    """Exactly n finite numbers (any shape), as a list."""
    a = numbers(x, name, finite=True).ravel()
    if a.size != n:
        raise ValueError(f"{name} must hold {n} numbers, got {a.size}")
    return a.tolist()


def load_2d(dF):
    """A 2-D load (dF_T, dF_N) as two floats."""
    a = numbers(dF, "dF")
    if a.shape != (2,):
        raise ValueError(f"dF must be (dF_T, dF_N), got shape {a.shape}")
    return float(a[0]), float(a[1])


def integer(x, name: str, low=None, high: int = INT_MAX) -> int:
    """An integer option in [low, high] (by default the range of a C++ int). TypeError for
    what is not a number (a string included), ValueError naming the option and its range for a
    fraction or a value outside it."""
    if isinstance(x, bool) or not _is_real_scalar(x):
        if isinstance(x, (bool, np.bool_)):
            raise ValueError(f"{name} must be an integer, got {x!r}")
        raise TypeError(f"{name} must be an integer, got {type(x).__name__} {x!r}")
    if not (isinstance(x, _numbers.Integral) or float(x).is_integer()):
        raise ValueError(f"{name} must be an integer, got {x!r}")
    v = int(x)
    low = -INT_MAX - 1 if low is None else low
    if not low <= v <= high:
        raise ValueError(f"{name} must be an integer in [{low}, {high}], got {v}")
    return v


def real(x, name: str, finite: bool = True) -> float:
    """A real number (TypeError for a string, a complex or anything else); ValueError when
    finite and x is NaN or infinite."""
    a = real_array(x, name, "be a real number")
    if a.ndim != 0:
        raise TypeError(f"{name} must be a real number, got an array of shape {a.shape}")
    v = float(a)
    if finite and not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return v


def number(x, name: str) -> float:
    """A real number, NaN and infinity passed on (the compiled part's validator judges them)."""
    return real(x, name, finite=False)


def facet_count(facets) -> int:
    """None (exact: 0) or a positive number of facets."""
    if facets is None:
        return 0
    k = integer(facets, "facets")
    if k <= 0:
        raise ValueError(f"facets must be a positive number of facets (3..64), got {facets}")
    return k


def existing_path(path, name: str = "path") -> bytes:
    """A file path given as str, bytes or os.PathLike, as the bytes the compiled part opens
    (any file name the system accepts). FileNotFoundError when nothing is there."""
    try:
        p = os.fsencode(os.fspath(path))
    except TypeError:
        raise TypeError(f"{name} must be a str, bytes or os.PathLike file path, got "
                        f"{type(path).__name__}") from None
    if not os.path.exists(p):
        raise FileNotFoundError(errno.ENOENT, os.strerror(errno.ENOENT), os.fsdecode(p))
    return p


def sparse_matrix(A):
    """A scipy.sparse matrix in a format whose arrays the compiled part reads and checks itself
    (CSC, CSR, COO: python/src/sparse_from.hpp) unchanged: scipy's own conversions between them
    trust the indices and can crash on bad ones. Other formats become COO."""
    return A if A.format in ("csc", "csr", "coo") else A.tocoo()


def is_sparse(A) -> bool:
    try:
        import scipy.sparse
    except ImportError:  # without scipy nothing can be a scipy matrix
        return False
    return scipy.sparse.issparse(A)


def system_text(system) -> str:
    """A "dim": 3 system given as a path, its JSON text or a dict, as JSON text."""
    if isinstance(system, dict):
        return json.dumps(system)
    if isinstance(system, str) and system.lstrip().startswith("{"):
        return system
    with open(existing_path(system, "system"), encoding="utf-8") as f:
        return f.read()

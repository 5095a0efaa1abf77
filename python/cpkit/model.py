"""The model's data (docs/model.md, docs/contact_3d.md): one 2-D contact point and its state,
one 3-D contact point. Plain data, validated where used (ValueError naming the field)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np

from ._checks import numbers

__all__ = ["ContactParameters", "ContactState", "Point3d"]


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


@dataclass
class Point3d:
    """One 3-D contact point: A the 3 x 3 symmetric positive definite stiffness on
    (T_X, T_Y, N) (force/length), mu > 0, C_T >= 0 (length/force), Archard's k_a >= 0 and the
    hardness P_s > 0 (wear (40): k = k_a / (3 P_s)), alpha = (alpha_X, alpha_Y) > 0 the half-axes
    of the friction ellipse (39) ((1, 1): isotropic). Validated when used (ValueError naming the
    field)."""
    A: Any = field(default_factory=lambda: np.eye(3))
    mu: float = 0.5
    C_T: float = 0.0
    k_a: float = 0.0
    P_s: float = 1.0
    alpha: Sequence[float] = (1.0, 1.0)

    def __post_init__(self):
        self.A = numbers(self.A, "A", 2).tolist()
        self.alpha = numbers(self.alpha, "alpha", 1).tolist()

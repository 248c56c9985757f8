"""Kinetostatics at a position: d'Alembert's principle on every body, solved for the reactions.

Each body's free-body diagram holds its given loads, its inertia loads (d'Alembert: the force
Ф = −m·a_S at its centre of mass S and the moment M_Ф = −J·ε) and the reactions of its
neighbours. With the inertia loads added every body is in equilibrium:

    ΣF_x = 0,  ΣF_y = 0,  ΣM_O = 0      (moments about the frame's origin).

The unknowns are the reactions — a joint's force of unknown direction (two components), a
contact's force along a known line (one magnitude), a guide's couple — and a balancing force or
moment. A reaction of body a on body b enters b's equations as itself and a's as its negative
(Newton's third law); the frame (``None``) has no equations. The stacked equations are solved by
least squares; a system whose unknowns are not all determined (a dead position, a load with no
arm) or whose loads cannot be balanced is a :class:`~geomcad.errors.ConstructionError`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from geomcad import tol
from geomcad.errors import ConstructionError, ParameterError
from geomcad.geom import PointLike, Vec, vec

Kind = Literal["given", "inertia", "reaction", "balancing"]


@dataclass(frozen=True)
class Applied:
    """One load on one body's free-body diagram after solving.

    A force ``force`` (N) at ``at``, or a moment ``moment`` (N·m, counter-clockwise positive,
    ``force`` None). ``kind`` says where it comes from; ``of`` names the body that exerts a
    reaction ("0" for the frame).
    """

    name: str
    body: str
    kind: Kind
    force: Vec | None = None
    at: Vec | None = None
    moment: float = 0.0
    of: str = ""


@dataclass
class _Unknown:
    name: str
    a: str | None  # the body that exerts it (None: the frame or the outside)
    b: str  # the body it acts on
    kind: Kind
    columns: int  # 1 (a magnitude along ``direction``, or a couple) or 2 (Fx, Fy)
    at: Vec | None
    direction: Vec | None


@dataclass(repr=False)
class Reactions:
    """The solved unknowns: ``values[name]`` is a Vec for a force, a float for a couple or a
    moment; ``magnitudes[name]`` the signed magnitude along the given direction for a contact
    or a balancing force. ``loads[body]`` is each body's free-body diagram."""

    values: dict[str, Vec | float] = field(default_factory=dict)
    magnitudes: dict[str, float] = field(default_factory=dict)
    loads: dict[str, list[Applied]] = field(default_factory=dict)

    def __str__(self) -> str:
        parts = []
        for name, v in self.values.items():
            if isinstance(v, Vec):
                parts.append(f"{name} = ({v.x + 0.0:.9g}, {v.y + 0.0:.9g})")
            else:
                parts.append(f"{name} = {v + 0.0:.9g}")
        return "; ".join(parts)

    def force(self, name: str) -> Vec:
        v = self.values[name]
        if not isinstance(v, Vec):
            raise KeyError(f"{name} is a moment, not a force")
        return v

    def moment(self, name: str) -> float:
        v = self.values[name]
        if isinstance(v, Vec):
            raise KeyError(f"{name} is a force, not a moment")
        return v


class Kinetostatics:
    """The kinetostatic problem of a mechanism at one position (see the module's docstring)."""

    def __init__(self, title: str) -> None:
        self.title = title
        self.bodies: list[str] = []
        self.known: dict[str, list[Applied]] = {}
        self.unknowns: list[_Unknown] = []

    def body(
        self,
        name: str,
        m: float = 0.0,
        J: float = 0.0,
        centre: PointLike = (0.0, 0.0),
        a: PointLike = (0.0, 0.0),
        eps: float = 0.0,
        inertia_names: tuple[str, str] = ("", ""),
    ) -> None:
        """A body with its d'Alembert loads: Ф = −m·a at ``centre`` and M_Ф = −J·ε.

        ``inertia_names`` names the two loads on the diagram (default Ф_name and M_Ф name).
        """
        if name in self.known:
            raise ValueError(f"body {name!r} is declared twice in {self.title}")
        if not (m >= 0.0 and J >= 0.0):
            raise ParameterError(f"mass of {name}", m if m < 0.0 else J, "cannot be negative")
        self.bodies.append(name)
        self.known[name] = []
        s = vec(centre)
        fname = inertia_names[0] or f"Ф_{{{name}}}"
        mname = inertia_names[1] or f"M_{{Ф{name}}}"
        acc = vec(a)
        if m > 0.0:
            self.known[name].append(Applied(fname, name, "inertia", acc * -m, s))
        if J > 0.0:
            self.known[name].append(Applied(mname, name, "inertia", None, None, -J * eps))

    def force(self, body: str, name: str, F: PointLike, at: PointLike) -> None:
        """A given force ``F`` (N) at ``at`` on ``body``."""
        self.known[body].append(Applied(name, body, "given", vec(F), vec(at)))

    def torque(self, body: str, name: str, M: float) -> None:
        """A given moment ``M`` (N·m, counter-clockwise positive) on ``body``."""
        self.known[body].append(Applied(name, body, "given", None, None, M))

    def joint(self, name: str, a: str | None, b: str, at: PointLike) -> None:
        """A revolute joint at ``at``: the unknown force of ``a`` on ``b`` (two components)."""
        self.unknowns.append(_Unknown(name, a, b, "reaction", 2, vec(at), None))

    def contact(
        self, name: str, a: str | None, b: str, at: PointLike, direction: PointLike
    ) -> None:
        """A contact at ``at`` that transmits force only along ``direction`` (a frictionless slot,
        a rolling contact's friction): the unknown signed magnitude N of a on b."""
        self.unknowns.append(_Unknown(name, a, b, "reaction", 1, vec(at), vec(direction).unit()))

    def couple(self, name: str, a: str | None, b: str) -> None:
        """An unknown reaction couple of ``a`` on ``b`` (a translational guide's moment)."""
        self.unknowns.append(_Unknown(name, a, b, "reaction", 1, None, None))

    def balancing_force(self, name: str, body: str, at: PointLike, direction: PointLike) -> None:
        """An unknown balancing force on ``body`` at ``at`` along ``direction``."""
        self.unknowns.append(
            _Unknown(name, None, body, "balancing", 1, vec(at), vec(direction).unit())
        )

    def balancing_torque(self, name: str, body: str) -> None:
        """An unknown balancing moment on ``body``."""
        self.unknowns.append(_Unknown(name, None, body, "balancing", 1, None, None))

    # -- solving -------------------------------------------------------------------------------
    def _rows(self, body: str) -> int:
        return 3 * self.bodies.index(body)

    def solve(self, step: str = "") -> Reactions:
        """Solve every body's equilibrium for the unknowns.

        Raises :class:`ConstructionError` (named ``step``, default the title) when the unknowns are
        not determined — the equations' matrix, its columns scaled to unit length, has a singular
        value below :data:`geomcad.tol.KINETOSTATIC_RANK` of the largest — or when the loads
        cannot be balanced (the least-squares residual is not zero).
        """
        step = step or self.title
        n_rows = 3 * len(self.bodies)
        cols: list[tuple[_Unknown, int]] = [(u, k) for u in self.unknowns for k in range(u.columns)]
        A = np.zeros((n_rows, len(cols)))
        rhs = np.zeros(n_rows)
        for body, loads in self.known.items():
            r = self._rows(body)
            for ld in loads:
                if ld.force is not None and ld.at is not None:
                    rhs[r] -= ld.force.x
                    rhs[r + 1] -= ld.force.y
                    rhs[r + 2] -= ld.at.cross(ld.force)
                else:
                    rhs[r + 2] -= ld.moment
        for j, (u, k) in enumerate(cols):
            unit = Vec(1.0, 0.0) if k == 0 else Vec(0.0, 1.0)
            d = u.direction if u.columns == 1 else unit
            for who, sign in ((u.b, 1.0), (u.a, -1.0)):
                if who is None:
                    continue
                r = self._rows(who)
                if d is None:  # a couple
                    A[r + 2, j] += sign
                else:
                    assert u.at is not None
                    A[r, j] += sign * d.x
                    A[r + 1, j] += sign * d.y
                    A[r + 2, j] += sign * u.at.cross(d)
        norms = np.linalg.norm(A, axis=0)
        if np.any(norms == 0.0):
            lost = [cols[j][0].name for j in np.nonzero(norms == 0.0)[0]]
            raise ConstructionError(step, f"the unknown {', '.join(lost)} enters no equation")
        An = A / norms
        sv = np.linalg.svd(An, compute_uv=False)
        if len(sv) < len(cols) or sv[-1] <= tol.KINETOSTATIC_RANK * sv[0]:
            raise ConstructionError(
                step,
                "the reactions are not determined by the equilibrium of the bodies (the system "
                "is singular: a dead position, where a reaction has no arm)",
            )
        xn, *_ = np.linalg.lstsq(An, rhs, rcond=None)
        x = xn / norms
        scale = max(
            float(np.max(np.abs(rhs))), float(np.max(np.abs(A * x))), np.finfo(np.float64).tiny
        )
        resid = float(np.max(np.abs(A @ x - rhs)))
        if resid > tol.DERIVED * scale:
            raise ConstructionError(
                step,
                f"the loads cannot be balanced by these reactions (residual {resid:.3g} of "
                f"{scale:.3g}): the accelerations do not satisfy the equation of motion, or a "
                "balancing load is missing",
            )
        out = Reactions(loads={b: list(v) for b, v in self.known.items()})
        j = 0
        for u in self.unknowns:
            if u.columns == 2:
                f = Vec(float(x[j]), float(x[j + 1]))
                out.values[u.name] = f
                self._apply(out, u, f, 0.0)
            elif u.direction is not None:
                n = float(x[j])
                f = u.direction * n
                out.values[u.name] = f
                out.magnitudes[u.name] = n
                self._apply(out, u, f, 0.0)
            else:
                m = float(x[j])
                out.values[u.name] = m
                out.magnitudes[u.name] = m
                self._apply(out, u, None, m)
            j += u.columns
        return out

    def _apply(self, out: Reactions, u: _Unknown, f: Vec | None, m: float) -> None:
        """Put a solved unknown on both bodies' diagrams (the negative on the exerting one)."""
        pairs: Sequence[tuple[str | None, float, str]] = (
            (u.b, 1.0, u.a or "0"),
            (u.a, -1.0, u.b),
        )
        for body, sign, of in pairs:
            if body is None:
                continue
            out.loads[body].append(
                Applied(u.name, body, u.kind, None if f is None else f * sign, u.at, m * sign, of)
            )

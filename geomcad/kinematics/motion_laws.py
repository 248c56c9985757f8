"""Follower motion laws and cam programs (rise, dwell, return), evaluated over arrays of angles.

A cam turns through φ; the follower's displacement S(φ) is given phase by phase. Each law is
written once in normalised form, s(u) for u ∈ [0, 1] with s(0) = 0 and s(1) = 1, and a phase of
angle Φ and stroke H scales it: S = H·s(u), the velocity analogue S′ = dS/dφ = (H/Φ)·s′(u) and
the acceleration analogue S″ = d²S/dφ² = (H/Φ²)·s″(u), u = (φ − φ_start)/Φ. A return phase runs
the same law downwards, S = H·(1 − s(u)).

The laws (the usual names of the textbooks):

- ``linear``: S = aφ, a = H/Φ. S′ jumps from 0 to a at the start and back at the end, so S″ has
  impulses there (rigid impacts, «жёсткие удары»);
- ``constant_acceleration`` (parabolic): S″ = ±4H/Φ², its sign changing at mid-phase; S′ is
  continuous, S″ jumps (soft impacts, «мягкие удары»);
- ``harmonic`` (cosine): s = (1 − cos πu)/2; S″ jumps at the ends;
- ``cycloidal`` (sine acceleration): s = u − sin(2πu)/(2π); S, S′, S″ all continuous;
- ``poly345``: s = 10u³ − 15u⁴ + 6u⁵; S, S′, S″ all continuous;
- ``modified_trapezoid``: the acceleration rises along a quarter sine over u ∈ [0, 1/8], stays
  at its peak to 3/8, falls along a half sine through 0 at 1/2 to the negative peak at 5/8,
  stays there to 7/8 and returns along a quarter sine; its peak s″ = 1/0.20458 ≈ 4.888 is the
  lowest of the smooth laws here. S, S′, S″ all continuous.

A :class:`CamProgram` is the sequence of phases as data. Before φ = 0 and after its last phase
the follower rests at the level it has there (a dwell). At a phase boundary a law may jump in S′
or S″; :meth:`CamProgram.motion` takes the value on the ``right`` (the phase that starts there)
or on the ``left`` (the phase that ends there), so both one-sided values are available.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt

from geomcad import tol
from geomcad.errors import ParameterError

FloatArray = npt.NDArray[np.float64]
Side = Literal["left", "right"]
PhaseKind = Literal["rise", "dwell", "return"]

#: The law names, as the interface's ``law`` choice spells them.
LAWS: tuple[str, ...] = ("linear", "constant_acceleration", "harmonic", "cycloidal", "poly345")

#: Every law a program may use: the five, and the modified trapezoid (the design files' laws;
#: 2013-2's ``law`` choice keeps the five).
ALL_LAWS: tuple[str, ...] = (*LAWS, "modified_trapezoid")

#: Russian names of the laws, for sheets.
LAW_TITLES_RU: dict[str, str] = {
    "linear": "линейный, S = aφ",
    "constant_acceleration": "равноускоренный (параболический)",
    "harmonic": "косинусоидальный (гармонический)",
    "cycloidal": "синусоидальный (циклоидальный)",
    "poly345": "полином 3-4-5",
    "modified_trapezoid": "модифицированная трапеция",
}

#: Inner points u of a phase where a law's S″ jumps (besides the phase ends).
LAW_BREAKS: dict[str, tuple[float, ...]] = {"constant_acceleration": (0.5,)}


def _as_array(x: npt.ArrayLike) -> FloatArray:
    return np.asarray(x, dtype=np.float64)


def normalised(law: str, u: npt.ArrayLike) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The law's s(u), s′(u) = ds/du and s″(u) for u in [0, 1] (values outside are clipped).

    At the inner break of ``constant_acceleration`` (u = 1/2), s″ takes the value of the second
    half (−4), so the law is right-continuous like :meth:`CamProgram.motion`.
    """
    uu = np.clip(_as_array(u), 0.0, 1.0)
    if law == "linear":
        return uu.copy(), np.ones_like(uu), np.zeros_like(uu)
    if law == "constant_acceleration":
        first = uu < 0.5
        s = np.where(first, 2.0 * uu**2, 1.0 - 2.0 * (1.0 - uu) ** 2)
        ds = np.where(first, 4.0 * uu, 4.0 * (1.0 - uu))
        dds = np.where(first, 4.0, -4.0)
        return s, ds, dds
    if law == "harmonic":
        pu = math.pi * uu
        return (
            (1.0 - np.cos(pu)) / 2.0,
            math.pi / 2.0 * np.sin(pu),
            math.pi**2 / 2.0 * np.cos(pu),
        )
    if law == "cycloidal":
        tu = 2.0 * math.pi * uu
        return (
            uu - np.sin(tu) / (2.0 * math.pi),
            1.0 - np.cos(tu),
            2.0 * math.pi * np.sin(tu),
        )
    if law == "poly345":
        return (
            uu**3 * (10.0 - 15.0 * uu + 6.0 * uu**2),
            30.0 * uu**2 * (1.0 - uu) ** 2,
            60.0 * uu * (1.0 - 3.0 * uu + 2.0 * uu**2),
        )
    if law == "modified_trapezoid":
        return _modified_trapezoid(uu)
    raise ParameterError("law", law, f"must be one of {', '.join(ALL_LAWS)}")


def _mt_knots() -> tuple[float, list[tuple[float, float]]]:
    """The modified trapezoid's peak acceleration A and (s, s′) at u = 0, 1/8, 3/8, 5/8, 7/8,
    integrated piece by piece in closed form (w = 4π): A follows from s(1) = 1."""
    w = 4.0 * math.pi
    # (s, s′) per unit A, knot by knot
    v1, s1 = 1.0 / w, 1.0 / (8.0 * w) - 1.0 / w**2
    v2, s2 = v1 + 0.25, s1 + v1 / 4.0 + 1.0 / 32.0
    v3, s3 = v2, s2 + v2 / 4.0 + 2.0 / w**2
    v4, s4 = v3 - 0.25, s3 + v3 / 4.0 - 1.0 / 32.0
    s5 = s4 + v4 / 8.0 - 1.0 / w**2
    a = 1.0 / s5
    return a, [(0.0, 0.0), (a * s1, a * v1), (a * s2, a * v2), (a * s3, a * v3), (a * s4, a * v4)]


def _modified_trapezoid(u: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    a, knots = _mt_knots()
    w = 4.0 * math.pi
    starts = (0.0, 0.125, 0.375, 0.625, 0.875)
    k = np.clip(np.searchsorted(starts, u, side="right") - 1, 0, 4)
    t = u - np.asarray(starts)[k]
    s0 = np.asarray([kn[0] for kn in knots])[k]
    v0 = np.asarray([kn[1] for kn in knots])[k]
    wt = w * t
    # per piece: a″ = A sin wt, A, A cos wt, −A, −A cos wt
    dds = np.select(
        [k == 0, k == 1, k == 2, k == 3],
        [a * np.sin(wt), np.full_like(t, a), a * np.cos(wt), np.full_like(t, -a)],
        -a * np.cos(wt),
    )
    ds = v0 + np.select(
        [k == 0, k == 1, k == 2, k == 3],
        [a * (1.0 - np.cos(wt)) / w, a * t, a * np.sin(wt) / w, -a * t],
        -a * np.sin(wt) / w,
    )
    s = s0 + v0 * t + np.select(
        [k == 0, k == 1, k == 2, k == 3],
        [a * (t / w - np.sin(wt) / w**2) - v0 * t, a * t**2 / 2.0, a * (1.0 - np.cos(wt)) / w**2,
         -a * t**2 / 2.0],
        -a * (1.0 - np.cos(wt)) / w**2,
    )  # fmt: skip
    return s, ds, dds


@dataclass(frozen=True)
class Phase:
    """One phase of a cam program: ``kind`` over ``angle`` radians, by ``law`` (rise, return)."""

    kind: PhaseKind
    angle: float
    law: str = "linear"


@dataclass(frozen=True)
class Motion:
    """The follower's motion at angles ``phi``: S (m), S′ = dS/dφ (m/rad), S″ (m/rad²)."""

    phi: FloatArray
    S: FloatArray
    S1: FloatArray
    S2: FloatArray


@dataclass(frozen=True)
class CamProgram:
    """A cam program: the follower's stroke ``H`` (m) and its phases from φ = 0 on.

    The follower starts at S = 0 (the lower dwell before φ = 0); a rise lifts it by H, a return
    lowers it by H, a dwell holds it. The phases must keep S between 0 and H and may not turn the
    cam more than once in all.

    >>> p = CamProgram.of(0.04, [Phase("rise", math.pi)])
    >>> m = p.motion([0.0, math.pi / 8])
    >>> round(float(m.S[1]), 12), round(float(m.S1[0]), 6)
    (0.005, 0.012732)
    """

    H: float
    phases: tuple[Phase, ...]

    @classmethod
    def of(cls, H: float, phases: Sequence[Phase]) -> CamProgram:
        """A checked program (a :class:`ParameterError` names the offending part)."""
        if not (math.isfinite(H) and H > 0.0):
            raise ParameterError("H", H, "the stroke must be a finite number > 0")
        level = 0
        total = 0.0
        for i, ph in enumerate(phases):
            if not (math.isfinite(ph.angle) and ph.angle > 0.0):
                raise ParameterError(f"phase {i + 1} ({ph.kind}) angle", ph.angle, "must be > 0")
            if ph.kind not in ("rise", "dwell", "return"):
                raise ParameterError(f"phase {i + 1} kind", ph.kind, "must be rise, dwell, return")
            if ph.kind != "dwell" and ph.law not in ALL_LAWS:
                raise ParameterError(f"phase {i + 1} law", ph.law, f"must be one of {ALL_LAWS}")
            if ph.kind == "rise":
                if level != 0:
                    raise ParameterError(f"phase {i + 1}", "rise", "a rise must start at S = 0")
                level = 1
            elif ph.kind == "return":
                if level != 1:
                    raise ParameterError(f"phase {i + 1}", "return", "a return must start at S = H")
                level = 0
            total += ph.angle
        if total > 2.0 * math.pi * (1.0 + tol.DERIVED):
            raise ParameterError(
                "phases", math.degrees(total), "the phases add up to more than a full turn (360°)"
            )
        return cls(float(H), tuple(phases))

    @property
    def boundaries(self) -> FloatArray:
        """The phase boundaries φ_0 = 0, φ_1, …, φ_n (rad)."""
        return np.concatenate([[0.0], np.cumsum([ph.angle for ph in self.phases])])

    @property
    def total(self) -> float:
        """The angle the phases take in all (rad)."""
        return float(self.boundaries[-1])

    @property
    def closes(self) -> bool:
        """True when the follower is back at S = 0 after the last phase."""
        return self._levels()[-1] == 0.0

    def _levels(self) -> list[float]:
        """S at the start of each phase, and after the last one."""
        levels = [0.0]
        for ph in self.phases:
            step = {"rise": self.H, "return": -self.H, "dwell": 0.0}[ph.kind]
            levels.append(levels[-1] + step)
        return levels

    def breaks(self) -> FloatArray:
        """Every angle where S′ or S″ may jump: the phase boundaries and the laws' inner breaks."""
        out = list(self.boundaries)
        for ph, start in zip(self.phases, self.boundaries[:-1], strict=True):
            if ph.kind != "dwell":
                out += [float(start) + u * ph.angle for u in LAW_BREAKS.get(ph.law, ())]
        return np.unique(np.asarray(out, dtype=np.float64))

    def motion(self, phi: npt.ArrayLike, side: Side = "right") -> Motion:
        """S, S′, S″ at the angles ``phi`` (rad), all at once.

        ``side`` says which phase an angle on a boundary belongs to: ``right``, the one that
        starts there; ``left``, the one that ends there. Angles before 0 and after the last phase
        are dwells at the level there.
        """
        f = _as_array(phi)
        b = self.boundaries
        idx = np.searchsorted(b, f, side="right" if side == "right" else "left") - 1
        levels = self._levels()
        S = np.where(idx < 0, 0.0, levels[-1])
        S1 = np.zeros_like(f)
        S2 = np.zeros_like(f)
        for k, ph in enumerate(self.phases):
            sel = idx == k
            if not np.any(sel):
                continue
            S = np.where(sel, levels[k], S)
            if ph.kind == "dwell":
                continue
            u = (f[sel] - b[k]) / ph.angle
            # the phase's ends (up to rounding) are exactly 0 and 1, so S lands on 0 and H
            u = np.where(np.abs(u) <= tol.DERIVED, 0.0, u)
            u = np.where(np.abs(u - 1.0) <= tol.DERIVED, 1.0, u)
            at_break = np.zeros(u.shape, dtype=bool)
            for ub in LAW_BREAKS.get(ph.law, ()):
                # an angle on an inner break (up to rounding) is exactly on it
                near = np.abs(u - ub) <= tol.DERIVED
                u = np.where(near, ub, u)
                at_break |= near
            s, ds, dds = normalised(ph.law, u)
            if side == "left" and np.any(at_break):
                # on an inner break the left value is the first half's
                _, ds_l, dds_l = normalised(ph.law, np.nextafter(u, -np.inf))
                ds = np.where(at_break, ds_l, ds)
                dds = np.where(at_break, dds_l, dds)
            sign = 1.0 if ph.kind == "rise" else -1.0
            S[sel] = levels[k] + sign * self.H * s
            S1[sel] = sign * self.H / ph.angle * ds
            S2[sel] = sign * self.H / ph.angle**2 * dds
        return Motion(f, S, S1, S2)

    def full_turn(self) -> CamProgram:
        """This program with a lower dwell added to complete the turn (when it closes)."""
        rest = 2.0 * math.pi - self.total
        if rest <= 2.0 * math.pi * tol.DERIVED:
            return self
        return CamProgram(self.H, (*self.phases, Phase("dwell", rest)))


def standard_program(
    H: float,
    phi_rise: float,
    law: str = "linear",
    phi_dwell: float = 0.0,
    phi_return: float = 0.0,
    law_return: str | None = None,
) -> CamProgram:
    """Rise, then an outer dwell (if ``phi_dwell`` > 0), then a return (if ``phi_return`` > 0);
    a program with a return is completed to a full turn by the lower dwell."""
    phases = [Phase("rise", phi_rise, law)]
    if phi_dwell > 0.0:
        phases.append(Phase("dwell", phi_dwell))
    if phi_return > 0.0:
        phases.append(Phase("return", phi_return, law_return or law))
    prog = CamProgram.of(H, phases)
    return prog.full_turn() if phi_return > 0.0 else prog

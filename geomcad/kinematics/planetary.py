"""Planetary synthesis: the tooth numbers of the four standard planetary schemes for a ratio.

The schemes (one module for every gear; H the carrier; the last gear is held; tooth numbers in
the order of the list ``z``):

- ``A``: sun 1 – planet 2 – ring 3 (held); z = [z1, z2, z3]; input 1, output H:
  u = u_1H = 1 + z3/z1; coaxiality z3 = z1 + 2·z2;
- ``B``: sun 1 – planet block 2-3 – ring 4 (held), an external and an internal mesh;
  z = [z1, z2, z3, z4]; input 1, output H: u = 1 + z2·z4/(z1·z3); coaxiality z1 + z2 = z4 − z3;
- ``C``: gear 1 – block 2-3 – gear 4 (held), two external meshes; input H, output 1:
  u = u_H1 = 1/(1 − z2·z4/(z1·z3)); coaxiality z1 + z2 = z4 + z3;
- ``D``: ring 1 – block 2-3 – ring 4 (held), two internal meshes; input H, output 1:
  u = u_H1 = 1/(1 − z2·z4/(z1·z3)); coaxiality z1 − z2 = z4 − z3.

Conditions on a candidate: the ratio within ``tolerance`` (relative); every z ≥ z_min; in an
internal mesh the ring has at least ``internal_difference`` teeth more than its pinion; the
assembly of k planets equally spaced (z1·u_1H^(held)/k·(1 + k·p) a whole number for some whole
p ≥ 0, the textbooks' condition; for ``A`` it is (z1 + z3)/k whole); the neighbouring condition
(the planets' tip circles clear: 2·a_w·sin(π/k) > d_a of the larger planet gear, in modules
(z_a + z_b)·sin(π/k) > z_p + 2 for the external row or (z_ring − z_p)… for an internal one).
The candidates are sorted by size (the outer diameter in modules), then by the ratio's error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import numpy.typing as npt

from geomcad.errors import ConstructionError, ParameterError
from geomcad.kinematics.trains import Mesh, solve_speeds

SCHEMES = ("A", "B", "C", "D")
STEP = "tooth numbers (ratio, coaxiality, assembly, neighbours)"

IntArr = npt.NDArray[np.int64]


@dataclass(frozen=True)
class Candidate:
    """A set of tooth numbers, its exact ratio, its error and size (outer diameter in modules)."""

    z: tuple[int, ...]
    u: Fraction
    error: float
    size: int


def ratio(scheme: str, z: tuple[int, ...]) -> Fraction:
    """The scheme's ratio u (input/output, module doc), exact."""
    if scheme == "A":
        z1, _, z3 = z
        return 1 + Fraction(z3, z1)
    z1, z2, z3, z4 = z
    if scheme == "B":
        return 1 + Fraction(z2 * z4, z1 * z3)
    w = 1 - Fraction(z2 * z4, z1 * z3)
    if w == 0:
        raise ConstructionError(STEP, "u_1H = 0: the carrier cannot drive gear 1")
    return 1 / w


def meshes(scheme: str, z: tuple[int, ...]) -> list[Mesh]:
    """The scheme's meshes for :func:`geomcad.kinematics.trains.solve_speeds` (links "1", the
    planet block "2" (and "3" of it), the held gear, the carrier "H")."""
    if scheme == "A":
        z1, z2, z3 = z
        return [Mesh("1", z1, "2", z2, "H"), Mesh("2", z2, "3", z3, "H", internal=True)]
    z1, z2, z3, z4 = z
    inner1 = scheme == "D"
    inner2 = scheme in ("B", "D")
    return [
        Mesh("2", z2, "1", z1, "H", internal=inner1),
        Mesh("2", z3, "4", z4, "H", internal=inner2),
    ]


def ratio_by_meshes(scheme: str, z: tuple[int, ...]) -> Fraction:
    """The ratio from the mesh equations in absolute angular velocities (the held gear at rest),
    an independent check of :func:`ratio`."""
    held = "3" if scheme == "A" else "4"
    if scheme in ("A", "B"):
        w = solve_speeds(meshes(scheme, z), {held: 0, "1": 1})
        return Fraction(1) / w["H"]
    w = solve_speeds(meshes(scheme, z), {held: 0, "H": 1})
    return Fraction(1) / w["1"]


def _assembles(e: Fraction, k: int) -> bool:
    """(e/k)·(1 + k·p) is a whole number for some p = 0 … k·den − 1."""
    return any((e * (1 + k * p) / k).denominator == 1 for p in range(k * e.denominator + 1))


def u_held(scheme: str, z: tuple[int, ...]) -> Fraction:
    """u_1H with the last gear held (for the assembly condition)."""
    if scheme in ("A", "B"):
        return ratio(scheme, z)
    z1, z2, z3, z4 = z
    return 1 - Fraction(z2 * z4, z1 * z3)


def conditions(
    scheme: str, z: tuple[int, ...], k: int, z_min: int, internal_difference: int
) -> list[str]:
    """Every condition the tooth numbers break, in words (empty: all hold)."""
    out = []
    if min(z) < z_min:
        out.append(f"a gear has fewer than z_min = {z_min} teeth")
    if scheme == "A":
        z1, z2, z3 = z
        if z3 != z1 + 2 * z2:
            out.append("coaxiality z3 = z1 + 2·z2")
        if z3 - z2 < internal_difference:
            out.append(f"internal mesh: z3 − z2 ≥ {internal_difference}")
        if (z1 + z3) % k:
            out.append(f"assembly: (z1 + z3)/k = {z1 + z3}/{k} is not whole")
        if not (z1 + z2) * math.sin(math.pi / k) > z2 + 2:
            out.append("neighbours: (z1 + z2)·sin(π/k) > z2 + 2")
        return out
    z1, z2, z3, z4 = z
    coax = {
        "B": z1 + z2 == z4 - z3,
        "C": z1 + z2 == z4 + z3,
        "D": z1 - z2 == z4 - z3,
    }[scheme]
    if not coax:
        out.append("coaxiality")
    if scheme in ("B", "D") and z4 - z3 < internal_difference:
        out.append(f"internal mesh: z4 − z3 ≥ {internal_difference}")
    if scheme == "D" and z1 - z2 < internal_difference:
        out.append(f"internal mesh: z1 − z2 ≥ {internal_difference}")
    if not _assembles(z1 * u_held(scheme, z), k):
        out.append("assembly")
    two_a = z1 - z2 if scheme == "D" else z1 + z2
    if not two_a * math.sin(math.pi / k) > max(z2, z3) + 2:
        out.append("neighbours: 2a_w·sin(π/k) > z_planet + 2")
    return out


def _grid(lo: int, hi: int) -> IntArr:
    return np.arange(lo, hi + 1, dtype=np.int64)


def synthesise(
    scheme: str,
    u: float,
    tolerance: float = 0.02,
    planets: int = 3,
    z_min: int = 17,
    z_max: int = 120,
    internal_difference: int = 8,
    keep: int = 5,
) -> list[Candidate]:
    """The tooth numbers for the ratio ``u``, smallest size first (``keep`` of them).

    No set of tooth numbers within the limits is a :class:`ConstructionError` naming the step
    and the range of ratios the scheme reaches there."""
    if scheme not in SCHEMES:
        raise ParameterError("scheme", scheme, f"must be one of {', '.join(SCHEMES)}")
    if not (math.isfinite(u) and u != 0.0):
        raise ParameterError("ratio", u, "must be a finite number ≠ 0")
    if not 0.0 < tolerance < 1.0:
        raise ParameterError("tolerance", tolerance, "must lie between 0 and 1")
    if not 2 <= planets <= 12:
        raise ParameterError("planets", planets, "must lie between 2 and 12")
    g = _grid(z_min, z_max)
    zz: list[IntArr]
    if scheme == "A":
        a2, b2 = np.meshgrid(g, g, indexing="ij")
        a, b = a2.ravel(), b2.ravel()
        c = a + 2 * b
        zz = [a, b, c]
        uu = 1.0 + c / a
        size = c
    else:
        a, b, c = (x.ravel() for x in np.meshgrid(g, g, g, indexing="ij"))
        if scheme == "B":
            d = a + b + c
            zz = [a, b, c, d]
            size = d
        elif scheme == "C":
            d = a + b - c
            zz = [a, b, c, d]
            size = a + b + np.maximum(b, c)
        else:
            # D: z1 is the outer ring; take (z2, z3, z4) from the grid, z1 = z4 − z3 + z2
            b, c, d = a, b, c
            a = d - c + b
            zz = [a, b, c, d]
            size = np.maximum(a, d)
        with np.errstate(divide="ignore", invalid="ignore"):
            prod = zz[1] * zz[3] / (zz[0] * zz[2])
        if scheme == "B":
            uu = 1.0 + prod
        else:
            with np.errstate(divide="ignore"):
                uu = 1.0 / (1.0 - prod)
    ok = np.all(np.stack([x >= z_min for x in zz]), axis=0) & np.isfinite(uu)
    reach = uu[ok]
    err = np.abs(uu - u) / abs(u)
    ok &= err <= tolerance
    idx = np.nonzero(ok)[0]
    order = idx[np.lexsort((err[idx], size[idx]))]
    out: list[Candidate] = []
    for i in order:
        z = tuple(int(x[i]) for x in zz)
        if conditions(scheme, z, planets, z_min, internal_difference):
            continue
        uf = ratio(scheme, z)
        out.append(Candidate(z, uf, float(abs(float(uf) - u) / abs(u)), int(size[i])))
        if len(out) >= keep:
            break
    if not out:
        lo, hi = (float(np.min(reach)), float(np.max(reach))) if reach.size else (math.nan,) * 2
        raise ConstructionError(
            STEP,
            f"no tooth numbers z_min = {z_min} … z_max = {z_max} give u = {u:g} within "
            f"{tolerance:.3g} with coaxiality, assembly of {planets} planets and neighbours "
            f"(scheme {scheme} reaches u = {lo:.4g} … {hi:.4g} with these tooth numbers)",
        )
    return out

"""Compare values measured off a drawing with the exact construction (``geomcad verify``).

A measurement is named like a result:

- ``NAME=VALUE`` is a result in its own SI units (angles ``*_deg`` in degrees);
- ``NAME_mm=VALUE`` is a length result read off the mechanism drawing in sheet millimetres,
  converted to metres at k_l: the ``scale`` argument, else the seed's k_l where the seed states
  one (``Problem.seed_k_l``), else the project's own sheet's (``Solution.scales["l"]``);
- an item of a list is ``NAME.INDEX`` (0-based, e.g. ``r.2``), and a path goes on into a list of
  objects: ``solutions.1.O1B0`` or ``solutions.1.O1B0_mm``.

The precision an item must meet (problems.md):

- a length read in mm: 0.5 mm at k_l;
- a vector read in mm off its plan (``V_B_mm``, ``a_B_mm``, ``R_3_4_mm``: a result whose spec
  has ``drawn`` = "v", "a" or "F"): converted at that plan's factor, 0.5 mm on the plan;
- an angle ``*_deg``: 0.5°;
- a quantity drawn on the project's own sheet (its :class:`~geomcad.problem.ResultSpec` has
  ``drawn`` = "l", "v", "a" or "F"): 0.5 mm at that plan's scale;
- anything else (a ratio, a shift coefficient): 0.5 % of the exact value.

A field of a list of objects takes the spec of its own name where the problem declares one, else
its parent's. Every value in a :class:`Report` is in the result's SI unit (degrees for ``*_deg``);
``deviation_mm`` is the deviation on the sheet where the item's plan scale is known.

This module computes and never prints; the CLI words the report.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

from geomcad import tol
from geomcad.errors import GeomcadError, ParameterError

if TYPE_CHECKING:
    from geomcad.problem import ResultSpec, Solution

#: Drawing precision: half a millimetre on the sheet.
DRAWING_PRECISION_MM = 0.5
#: Precision of an angle read with a protractor, in degrees.
ANGLE_PRECISION_DEG = 0.5
#: Precision of a value that is not drawn, relative to the exact value (0.5 %).
RELATIVE_PRECISION = 0.005

MM_SUFFIX = "_mm"
DEG_SUFFIX = "_deg"

#: The scale factors k_l that --scale accepts (m/mm): from 1000:1 to 1:10⁹, far past any
#: drawing's, so that a reading times k_l stays a finite number.
SCALE_RANGE = (1e-6, 1e6)

#: How each plan's scale is written, with its unit (k_l in m/mm, ...).
PLAN_SCALES: dict[str, tuple[str, str]] = {
    "l": ("k_l", "m/mm"),
    "v": ("k_v", "(m/s)/mm"),
    "a": ("k_a", "(m/s²)/mm"),
    "F": ("k_F", "N/mm"),
    "ls": ("k_l", "m/mm"),  # the synthesis drawing of a linkage file (issue 31)
}

Rule = Literal["drawing", "angle", "relative"]


@dataclass(frozen=True)
class Item:
    """One measured value against the exact one.

    ``measured``, ``exact``, ``deviation`` (= measured − exact) and ``precision`` are in the
    result's SI unit ``unit`` (degrees for ``*_deg``). ``deviation_mm`` is the deviation on the
    sheet at ``scale`` (the plan ``plan``'s factor, units per mm), or ``None`` where no plan scale
    applies. ``measured_mm`` is the reading in sheet mm for a ``NAME_mm`` item. ``rule`` says
    which precision applies. ``name`` is the name as given; ``result`` is its path without
    ``_mm``.
    """

    name: str
    result: str
    measured: float
    exact: float
    deviation: float
    deviation_mm: float | None
    precision: float
    ok: bool
    unit: str
    rule: Rule
    scale: float | None = None
    plan: str | None = None
    measured_mm: float | None = None

    def to_json(self) -> dict[str, Any]:
        """The item as the interface's ``verify --json`` writes it."""
        return {
            "name": self.name,
            "measured": self.measured,
            "exact": self.exact,
            "deviation": self.deviation,
            "deviation_mm": self.deviation_mm,
            "precision": self.precision,
            "ok": self.ok,
        }


@dataclass(frozen=True)
class Report:
    """Every item of one ``verify`` run; ``ok`` when each lies within its precision."""

    id: str
    items: tuple[Item, ...]

    @property
    def ok(self) -> bool:
        return all(it.ok for it in self.items)

    def to_json(self) -> dict[str, Any]:
        """``{"id", "items": [...], "ok"}``, as ``verify --json`` prints it."""
        return {"id": self.id, "items": [it.to_json() for it in self.items], "ok": self.ok}


def verify(
    solution: Solution[Any], measured: Mapping[str, float | str], scale: float | None = None
) -> Report:
    """Compare each ``NAME[=VALUE]`` of ``measured`` with ``solution``'s exact results.

    ``scale`` is k_l in m/mm for the ``NAME_mm`` items (``None``: the seed's k_l, else the
    sheet's). Values may be numbers or text (a decimal comma is accepted).

    Raises :class:`~geomcad.errors.GeomcadError` naming the item for an unknown result name (the
    message lists the known ones), an index out of range, a path into a number, a value that is
    not a finite number, a result that is not a number (a bool, a whole list), a ``_mm`` reading of
    a result that is not a length, or when no k_l is known; :class:`ParameterError` for
    ``scale`` ≤ 0.
    """
    if scale is not None and not (math.isfinite(scale) and scale > 0.0):
        raise ParameterError("scale", scale, "must be a number > 0 (k_l in m/mm)")
    lo, hi = SCALE_RANGE
    if scale is not None and not lo <= scale <= hi:
        raise ParameterError("scale", scale, f"must lie between {lo:g} and {hi:g} (k_l in m/mm)")
    items = tuple(
        _finite(_item(solution, name, value, scale), value) for name, value in measured.items()
    )
    return Report(solution.problem.id, items)


def _finite(it: Item, raw: object) -> Item:
    """The item, unless a number in it is not finite (a reading so far off that its deviation
    overflows): that reading is bad input, named."""
    values = (it.measured, it.exact, it.deviation, it.deviation_mm, it.precision, it.measured_mm)
    if all(v is None or math.isfinite(v) for v in values):
        return it
    raise ParameterError(
        f"measured {it.name}",
        raw,
        f"its deviation from the exact value {it.exact:.6g} is not a finite number in "
        "float64: a reading off a drawing is never that large or that small",
    )


def _item(solution: Solution[Any], name: str, raw: float | str, scale: float | None) -> Item:
    value = _number(name, raw)
    results = solution.results
    from_mm = name.endswith(MM_SUFFIX) and not _resolves(results, name)
    path = name.removesuffix(MM_SUFFIX) if from_mm else name
    parts = path.split(".")
    exact = _lookup(solution, parts)
    spec = _spec(solution, parts)
    unit = spec.unit if spec is not None else ""
    leaf = next((p for p in reversed(parts) if not p.isdecimal()), parts[0])

    plan = spec.drawn if spec is not None else None
    if from_mm and plan in ("v", "a", "F", "ls"):  # ls: the synthesis drawing's k_l
        # a vector read off its plan (V_B_mm, a_B_mm, R_3_4_mm): mm at that plan's factor
        k_plan = solution.scales.get(plan)
        if k_plan is None or not k_plan > 0.0:
            raise GeomcadError(f"measured {name}: the sheet gives no factor of the {plan} plan")
        dev = value * k_plan - exact
        prec = DRAWING_PRECISION_MM * k_plan
        return Item(name, path, value * k_plan, exact, dev, dev / k_plan, prec,
                    _within(dev, prec), unit, "drawing", k_plan, plan, value)  # fmt: skip
    if from_mm:
        if unit not in ("m", ""):
            raise GeomcadError(
                f"measured {name}: {path} is not a length (its unit is {_unit_word(unit)}); "
                f"give it as {path}=VALUE"
            )
        k = _k_l(solution, scale, name)
        m = value * k
        dev = m - exact
        prec = DRAWING_PRECISION_MM * k
        return Item(
            name,
            path,
            m,
            exact,
            dev,
            dev / k,
            prec,
            _within(dev, prec),
            "m",
            "drawing",
            k,
            "l",
            value,
        )

    dev = value - exact
    if leaf.endswith(DEG_SUFFIX):
        prec = ANGLE_PRECISION_DEG
        return Item(name, path, value, exact, dev, None, prec, _within(dev, prec), "deg", "angle")
    k_plan = solution.scales.get(plan) if plan is not None else None
    if plan is not None and k_plan is not None and k_plan > 0.0:
        prec = DRAWING_PRECISION_MM * k_plan
        return Item(
            name,
            path,
            value,
            exact,
            dev,
            dev / k_plan,
            prec,
            _within(dev, prec),
            unit,
            "drawing",
            k_plan,
            plan,
        )
    prec = RELATIVE_PRECISION * abs(exact)
    return Item(name, path, value, exact, dev, None, prec, _within(dev, prec), unit, "relative")


def _within(dev: float, prec: float) -> bool:
    # a reading exactly on the limit counts as within, despite the last bit of rounding
    return abs(dev) <= prec * (1.0 + tol.DERIVED)


def _number(name: str, raw: float | str) -> float:
    if isinstance(raw, bool):
        raise GeomcadError(f"measured {name} = {raw!r}: must be a number")
    if isinstance(raw, str):
        text = raw.strip()
        if text.count(",") == 1 and "." not in text:
            text = text.replace(",", ".")  # a decimal comma, as the seeds write numbers
        try:
            x = float(text)
        except ValueError:
            raise GeomcadError(f"measured {name} = {raw!r}: must be a number") from None
    elif isinstance(raw, numbers.Real):
        x = float(raw)
    else:
        raise GeomcadError(f"measured {name} = {raw!r}: must be a number")
    if not math.isfinite(x):
        raise GeomcadError(f"measured {name} = {raw!r}: must be a finite number")
    return x


def _resolves(results: Mapping[str, Any], path: str) -> bool:
    """True when ``path`` names a value as it stands (a result whose own name ends in _mm)."""
    node: Any = results
    for p in path.split("."):
        if isinstance(node, Mapping) and p in node:
            node = node[p]
        elif isinstance(node, list | tuple) and p.isdecimal() and int(p) < len(node):
            node = node[int(p)]
        else:
            return False
    return True


def _is_number(x: object) -> bool:
    return isinstance(x, numbers.Real) and not isinstance(x, bool)


def _lookup(solution: Solution[Any], parts: list[str]) -> float:
    results = solution.results
    head = parts[0]
    if head not in results:
        known = ", ".join(results)
        raise GeomcadError(f"unknown result {head!r}; the results are {known}")
    node: Any = results[head]
    where = head
    for p in parts[1:]:
        if isinstance(node, list | tuple):
            if not p.isdecimal():
                raise GeomcadError(f"{where} is a list: name an item by its index, {where}.0")
            i = int(p)
            if i >= len(node):
                raise GeomcadError(
                    f"{where}.{p}: index out of range ({where} has {len(node)} items, "
                    f"{where}.0 … {where}.{len(node) - 1})"
                    if node
                    else f"{where}.{p}: index out of range ({where} is empty)"
                )
            node = node[i]
        elif isinstance(node, Mapping):
            if p not in node:
                known = ", ".join(str(k) for k in node)
                raise GeomcadError(f"{where} has no field {p!r}; its fields are {known}")
            node = node[p]
        else:
            raise GeomcadError(f"{where} is a single value: it has no item {p!r}")
        where = f"{where}.{p}"
    if _is_number(node):
        return float(node)
    if isinstance(node, list | tuple):
        raise GeomcadError(f"{where} is a list: name an item by its index, {where}.0")
    if isinstance(node, Mapping):
        fields = ", ".join(str(k) for k in node)
        raise GeomcadError(f"{where} is an object: name one of its fields ({fields})")
    raise GeomcadError(f"{where} = {node!r} is not a number, so it cannot be measured")


def _spec(solution: Solution[Any], parts: list[str]) -> ResultSpec | None:
    """The spec of the innermost named component that has one (the field's, else its parent's)."""
    for p in reversed(parts):
        if p.isdecimal():
            continue
        spec = solution.problem.result_spec(p)
        if spec is not None:
            return spec
    return None


def _k_l(solution: Solution[Any], scale: float | None, name: str) -> float:
    if scale is not None:
        return scale
    if solution.problem.seed_k_l is not None:
        return solution.problem.seed_k_l
    k = solution.scales.get("l")
    if k is None or not k > 0.0:
        raise GeomcadError(
            f"measured {name}: no k_l is known to convert sheet mm; give --scale in m/mm"
        )
    return k


def _unit_word(unit: str) -> str:
    return {"1": "a pure number", "deg": "degrees"}.get(unit, unit)

"""The force plans' rules on every forces sheet of the examples and the test files (issue 27,
review 6 items 3, 4 and 6): no plan's vector crosses a caption or any other text of the sheet
(sixbar_coupler_slider's group (2, 3) was drawn over its own caption), and no detail is drawn
larger than its plan (its Г2 at 1 Н/мм was a 220 mm column beside a 45 mm plan); no plan
crosses itself where an order of its known loads does not, nor draws a resultant as a twin
line along its component (the shaper's and whitworth's groups (4, 5))."""

from __future__ import annotations

import itertools
import math
from pathlib import Path
from typing import Any

import pytest

import geomcad
from geomcad.forces import ForcePolygon, PlanVector
from geomcad.geom import Vec
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import solve
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.model import Polyline, TextItem
from geomcad.sheet.text import box as text_box
from geomcad.sheet.text import parse
from geomcad.sheet.views import (
    DETAIL_BOUND_MM,
    LISTED_MM,
    STUB_MM,
    Polygon,
    crossings,
    main_arrows,
    regroup,
    resultants,
    short_runs,
    twin_resultants,
)

ROOT = Path(__file__).resolve().parents[1]
TESTS = Path(__file__).resolve().parent
FILES = [
    p
    for p in [
        *sorted((ROOT / "examples").glob("*.toml")),
        *sorted((TESTS / "linkages").glob("*.toml")),
        *sorted((TESTS / "linkages_plans").glob("*.toml")),
    ]
    if "[drive]" in p.read_text(encoding="utf-8") and "[[group]]" in p.read_text(encoding="utf-8")
]

XY = tuple[float, float]


def _crosses(a: XY, b: XY, box: tuple[float, float, float, float]) -> bool:
    """Whether segment ab enters the box (Liang–Barsky)."""
    x0, y0, x1, y1 = box
    t0, t1 = 0.0, 1.0
    dx, dy = b[0] - a[0], b[1] - a[1]
    for p, q in ((-dx, a[0] - x0), (dx, x1 - a[0]), (-dy, a[1] - y0), (dy, y1 - a[1])):
        if p == 0.0:
            if q < 0.0:
                return False
            continue
        t = q / p
        if p < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


def _text_box(it: TextItem, shrink: float = 0.3) -> tuple[float, float, float, float]:
    w, up, down = text_box(it.runs, it.height)
    return (
        it.at[0] + shrink,
        it.at[1] - up + shrink,
        it.at[0] + w - shrink,
        it.at[1] + down - shrink,
    )


def _plans(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> tuple[Any, list[tuple[Polygon, Any, list[Any]]]]:
    from geomcad.sheet import views

    rec: list[tuple[Polygon, Any, list[Any]]] = []
    draw = views.Polygon.draw

    def rec_draw(self: Polygon, d: Any, at: Any) -> None:
        i = len(d.sheet.items)
        draw(self, d, at)
        rec.append((self, at, d.sheet.items[i:]))

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    s = solve(geomcad.solve(str(path)).data.linkage)
    if analyse(s).forces is None:
        pytest.skip("no force analysis")
    sheet = dict(geomcad.solve(str(path)).sheets())["forces"]
    assert rec
    return sheet, rec


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_no_plan_vector_crosses_a_text_and_no_detail_outgrows_its_plan(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every force plan's vectors (their lines, the details' too) keep clear of every text of
    the sheet that the plan does not write itself (the captions of all views, their notes,
    the tables), and of the captions of its own details; each detail is drawn no larger than
    its plan (or DETAIL_BOUND_MM), and every vector a detail draws as an arrow is at least one
    arrowhead long (review 14: one detail μ_F; a shorter one is named under the caption)."""
    sheet, rec = _plans(path, monkeypatch)
    for p, at, items in rec:
        own = {id(it) for it in items}
        texts = [it for it in sheet.items if isinstance(it, TextItem) and id(it) not in own]
        texts += [it for it in items if isinstance(it, TextItem) and "μ" in it.text]
        boxes = [(_text_box(t), t.text) for t in texts]
        for it in items:
            if not isinstance(it, Polyline) or it.role not in ("vector", "result"):
                continue
            for a, b in zip(it.points, it.points[1:], strict=False):
                for box, text in boxes:
                    assert not _crosses(tuple(a), tuple(b), box), (path.stem, p.title, text)
        k = at.viewport.scale.k
        poly = p.layers[-1][0]
        xs = [q.x for pv in poly.vectors for q in (pv.tail, pv.head)]
        ys = [q.y for pv in poly.vectors for q in (pv.tail, pv.head)]
        plan_mm = max(max(xs) - min(xs), max(ys) - min(ys)) / k
        for dt in p.details:
            pts = [q for n in dt.run for q in (poly[n].tail, poly[n].head)]
            run_mm = max(max(q.x for q in pts) - min(q.x for q in pts),
                         max(q.y for q in pts) - min(q.y for q in pts)) / dt.k  # fmt: skip
            assert run_mm + 2.0 * STUB_MM <= max(plan_mm, DETAIL_BOUND_MM) * (1 + 1e-9), (
                path.stem, p.title, dt.letter, run_mm, plan_mm,
            )  # fmt: skip
            zero = max(1e-9 * max(pv.magnitude for pv in poly.vectors), dt.floor)
            finer = {n for d2 in p.details if d2.host is dt for n in d2.run}
            for n in dt.run:
                if (poly[n].magnitude > zero and n not in dt.listed and n not in finer
                        and n not in main_arrows(poly)):  # fmt: skip
                    # (review 14: one detail μ_F, an arrow down to one arrowhead in it; a
                    # reaction is an arrow however short, of its plan and in its detail)
                    assert poly[n].magnitude / dt.k >= LISTED_MM * (1 - 1e-9), (p.title, n)


@pytest.mark.parametrize(
    "path",
    FILES,
    ids=lambda p: p.stem,
)
def test_no_plan_crosses_itself_and_no_resultant_is_a_twin_line(
    path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every force plan as drawn: its sides two arrowheads long never cross one another (the
    shaper's group (4, 5) laid G5 before F_D and its R^n_34 cut F_D: the known loads are laid
    off in an order that does not cross), and a reaction's resultant whose other component is
    too short to part it from its long one is not drawn as a second line along it (whitworth's
    R34 beside R^n34): the one line is named "R^n34 ≈ R34"."""
    sheet, rec = _plans(path, monkeypatch)
    texts = {t.text for t in sheet.texts()}
    for p, at, _ in rec:
        k = at.viewport.scale.k
        poly = p.layers[-1][0]
        if crossings(poly, SHORT_MM * k):
            # inherent to the forces: every order of its known loads crosses too
            fixed = {n for n, _ in poly.solved}
            free = [n for n in poly.names if n not in fixed and "^" not in n]
            assert len(free) <= 7, (path.stem, p.title)
            for perm in itertools.permutations(free):
                order = iter(perm)
                names = [next(order) if n in free else n for n in poly.names]
                assert crossings(_laid(poly, names), SHORT_MM * k), (path.stem, p.title, perm)
        names = p.names or {}
        x0, y0, x1, y1 = at.box
        inside = [(t, h, sc) for t, h, sc in sheet.scaled
                  if all(x0 <= q[0] <= x1 and y0 <= q[1] <= y1 for q in (t, h))]  # fmt: skip
        arrows = [math.dist(t, h) * sc.k for t, h, sc in inside if sc.q == "F"]
        for r, long in twin_resultants(poly, k).items():
            R = next(rr for rr, _ in resultants(poly) if rr.name == r)
            assert not any(math.isclose(F, R.magnitude, rel_tol=1e-9) for F in arrows), r
            label = f"{names.get(long, long)} ≈ {names.get(r, r)}"
            assert "".join(run.text for run in parse(label)) in texts, (path.stem, r)


def _laid(poly: ForcePolygon, order: list[str]) -> ForcePolygon:
    out, tail = [], poly.pole
    for n in order:
        out.append(PlanVector(n, tail, tail + poly[n].force))
        tail = out[-1].head
    return ForcePolygon(poly.pole, tuple(out), poly.solved)


def test_regroup_lays_the_loads_off_in_an_order_that_does_not_cross() -> None:
    """A group's polygon as the kinetostatics lays it off (R^τ, the small loads, a weight, the
    large load, then the unknowns) crosses itself where the weight turns the chain down
    before the large load; regroup keeps every force and the unknowns' places, the short
    loads one run, and the polygon uncrossed; a polygon that does not cross keeps its order."""
    pole = Vec(0.0, 0.0)
    loads = [("R^τ_{34}", Vec(5.0, 12.0)), ("G_{4}", Vec(0.0, -29.0)),
             ("Ф_{4}", Vec(-10.0, 14.0)), ("G_{5}", Vec(0.0, -245.0)),
             ("Ф_{5}", Vec(148.0, 0.0)), ("F_{D}", Vec(-2200.0, 0.0))]  # fmt: skip
    out, tail = [], pole
    for n, F in loads:
        out.append(PlanVector(n, tail, tail + F))
        tail = out[-1].head
    # R_05 along the guide's normal, R^n_34 along the rod back to the pole
    r05 = PlanVector("R_{05}", tail, tail + Vec(0.0, -340.0))
    rn = PlanVector("R^n_{34}", r05.head, pole)
    poly = ForcePolygon(pole, (*out, r05, rn), (("R_{05}", 1.0), ("R^n_{34}", 1.0)))
    k = 20.0
    assert crossings(poly, SHORT_MM * k) == 1
    new = regroup(poly, k)
    assert crossings(new, SHORT_MM * k) == 0
    assert sorted(new.names) == sorted(poly.names)
    assert [new.names[0], *new.names[-2:]] == [poly.names[0], *poly.names[-2:]]
    for n in poly.names:
        assert (new[n].force - poly[n].force).norm < 1e-9
    assert (new.vectors[-1].head - pole).norm < 1e-9
    assert len(short_runs(new.vectors, SHORT_MM * k)) == 1
    kept = _laid(poly, [poly.names[0], "Ф_{4}", "G_{4}", "Ф_{5}", "F_{D}", "G_{5}",
                        *poly.names[-2:]])  # fmt: skip
    assert crossings(kept, SHORT_MM * k) == 0
    assert regroup(kept, k).names == kept.names


@pytest.mark.parametrize("path", [p for p in FILES if p.parent.name == "linkages_plans"],
                         ids=lambda p: p.stem)  # fmt: skip
def test_a_force_is_named_once_in_its_plan(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A plan with its details names each of its forces once: a detail's line joining a vector
    that another detail draws (a run cut in two: sixbar_coupler_slider's Ю1 and Я1 both named
    Ф4) is lettered with that detail's letter."""
    from geomcad.sheet import views
    from geomcad.sheet.drawing import Viewport

    labels: list[list[str]] = []
    draw, label = views.Polygon.draw, Viewport.label

    def rec_draw(self: Polygon, d: Any, at: Any) -> None:
        labels.append([])
        draw(self, d, at)

    def rec_label(v: Viewport, q: Any, markup: str, *args: Any, **kw: Any) -> Any:
        if labels:
            labels[-1].append(markup)
        return label(v, q, markup, *args, **kw)

    monkeypatch.setattr(views.Polygon, "draw", rec_draw)
    monkeypatch.setattr(Viewport, "label", rec_label)
    dict(geomcad.solve(str(path)).sheets())
    assert labels
    for names in labels:
        forces = [n for n in names if n.startswith(("R", "G", "F", "Ф")) and "=" not in n]
        assert len(forces) == len(set(forces)), sorted(forces)

"""The forces sheet's scales (review 13, item 2): the crank at least CRANK_MM long on the main
view (the size rule the kinematic sheet keeps), else the main view as fine as the field lets it
be with the crank enlarged beside it (the crank cut out at its own stated μ_l, or a detail
"Г (1:1)"): never a 5 mm crank at 1:10 beside an empty field (on main the coining press, 1:10,
its crank 5,5 mm, where 1:2 holds the sheet). The groups cut out at the main view's μ_l wherever
a sheet with one μ_l holds (on main the gang saw's groups at 1:15 beside its 1:10, the yarn
traverse's at 2:1 beside its 2,5:1), else at a coarser one stated in their captions.

Over every linkage file of tests/linkages_* and the examples with a forces sheet; each file's
layout is searched once (:func:`_found`).
"""

from __future__ import annotations

import functools
import re
from fractions import Fraction
from pathlib import Path

import pytest

import geomcad
from geomcad import tol
from geomcad.linkage.analysis import analyse
from geomcad.sheet import linkage_forces as lf
from geomcad.sheet.compose import _GOST_K as GOST_K
from geomcad.sheet.compose import Field, round_scale
from geomcad.sheet.frame import FORMATS
from geomcad.sheet.linkage import CRANK_MM, sheet_formats
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ("shaper", "sixbar-2013-6", "crusher", "four-bar", "rocking-slider", "scotch-yoke",
            "slider-crank")  # fmt: skip
FILES = sorted(
    p for p in (ROOT / "tests").glob("linkages_*/*.toml") if p.parent.name != "linkages_bad"
) + [ROOT / "examples" / f"{n}.toml" for n in EXAMPLES]
IDS = [f"{p.parent.name}/{p.stem}" for p in FILES]
E = 1.0 + tol.REL_LENGTH


@functools.cache
def _found(path: Path) -> tuple[object, object] | None:
    """The file's solution and its forces sheet's layout (None: no forces sheet)."""
    s = geomcad.solve(str(path)).data
    if analyse(s).forces is None:
        return None
    return s, lf.force_layout(s)[1]


def _scales(path: Path) -> tuple[object, float, list[float], float | None]:
    got = _found(path)
    if got is None:
        pytest.skip("no forces sheet")
    s, z = got
    lay = z.layout  # type: ignore[attr-defined]
    main = [pl.scale.k for pl in lay if isinstance(pl.view, lf._Loaded) and pl.scale]
    groups = [pl.scale.k for pl in lay if isinstance(pl.view, lf._FreeBody)
              and pl.view.gf.group is not None and pl.scale]  # fmt: skip
    crank = [pl.scale.k for pl in lay if isinstance(pl.view, lf._FreeBody)
             and pl.view.gf.group is None and pl.scale]  # fmt: skip
    assert len(main) == 1
    return s, main[0], groups, crank[0] if crank else None


def _field(s: object) -> tuple[str, Field]:
    fmts = sheet_formats(s.linkage)  # type: ignore[attr-defined]
    largest = max(fmts, key=lambda fm: FORMATS[fm][0] * FORMATS[fm][1])
    return largest, Field.of_format(largest, True)


def _one_scale_holds(s: object, pin: float, groups: float, was: object = None) -> bool:
    """Whether a sheet with the mechanism at ``pin`` and the groups at ``groups`` holds on the
    largest format with every rule kept (the pinned search's own test, :func:`lf._pin_try`);
    with ``was`` (a layout found), only where it keeps every force plan read
    (:data:`lf.PLAN_READ_MM`) and every other view no coarser than ``was`` (the lever one step
    of its series at most): one μ_l is not bought with plans a quarter of their size."""
    P, f, k = lf.force_position(s)  # type: ignore[arg-type]
    fmt, field = _field(s)
    got = lf._pin_try(s, P, f, k, None, fmt, field, pin, groups)  # type: ignore[arg-type]
    if got is None or was is None:
        return got is not None
    lay = got[1].layout
    return lf._plans_read(lay) and _lever_kept(was, lay)


def _lever_kept(was: object, now: object) -> bool:
    """Whether ``now`` draws Zhukovsky's lever at most one step of its series coarser than
    ``was`` does."""
    (a,) = [pl for pl in was if isinstance(pl.view, lf._Lever) and pl.scale]  # type: ignore[attr-defined]
    (b,) = [pl for pl in now if isinstance(pl.view, lf._Lever) and pl.scale]  # type: ignore[attr-defined]
    step = round_scale(a.scale.k * (1.0 + 4.0 * tol.REL_LENGTH), a.scale.q, a.view.series).k
    return bool(b.scale.k <= step * E)


def _detail_k(s: object) -> list[float]:
    """The μ_l (m/mm) of every crank detail ("Г (1:1)") the drawn forces sheet states."""
    (sheet,) = [sh for name, sh in lf.force_sheets(s) if name == "forces"]  # type: ignore[arg-type]
    out = []
    for it in sheet.items:
        if isinstance(it, TextItem):
            text = "".join(r.text for r in it.runs)
            m = re.fullmatch(r"\S{1,3} \((\d+(?:,\d+)?):(\d+(?:,\d+)?)\)", text)
            if m:
                a, b = (Fraction(x.replace(",", ".")) for x in m.groups())
                out.append(float(b / a / 1000))
    return out


@pytest.mark.parametrize("path", FILES, ids=IDS)
def test_forces_sheet_scales(path: Path) -> None:
    """Both rules on one layout search per file (:func:`_crank_on_the_main_view`,
    :func:`_groups_at_the_main_views_scale`)."""
    _groups_at_the_main_views_scale(path)
    _crank_on_the_main_view(path)


def _crank_on_the_main_view(path: Path) -> None:
    """The crank CRANK_MM long on the main view; where it is shorter, the main view no coarser
    than the field allows (the next finer GOST step holds no sheet, even with the groups one
    step apart; where the crank is under CRANK_FLOOR of the rule) and
    the crank enlarged at least CRANK_MM long beside it: the crank cut out at its own μ_l or a
    detail of the crank (the knot's 50 mm crank at 1:2, a detail at 1:1)."""
    s, mk, _groups, crank = _scales(path)
    length = s.linkage.length  # type: ignore[attr-defined]
    if length / mk >= CRANK_MM / E:
        return
    finer = [g for g in GOST_K if g < mk / E]
    # the main view as fine as the field allows where the crank is under CRANK_FLOOR of the
    # rule (the sweep waiving it or not); above, at least an enlarged crank view (the sine
    # file's 18 mm crank at 1:2,5 beside its detail at 1:1: at 1:2 the detail finds no room)
    if finer and length / mk < CRANK_MM * lf.CRANK_FLOOR / E:
        pin = max(finer)
        for pg in (pin, *[g for g in GOST_K if g > pin * E and pin / g >= lf.GROUPS_SHARE / E]):
            assert not _one_scale_holds(s, pin, pg), (
                f"{path.stem}: crank {length / mk:.1f} mm at μ_l {mk}; {pin} holds the sheet"
            )
    if crank is not None and length / crank >= CRANK_MM / E:
        return
    assert any(length / kk >= CRANK_MM / E for kk in _detail_k(s)), (
        f"{path.stem}: crank {length / mk:.1f} mm on the main view, no enlarged crank view"
    )


def _groups_at_the_main_views_scale(path: Path) -> None:
    """The groups cut out at the main view's μ_l, or (stated in their captions) at a coarser
    one at least GROUPS_SHARE of it only where no sheet at one μ_l holds; the crank cut out at
    the main view's μ_l or enlarged (at least CRANK_MM long)."""
    s, mk, groups, crank = _scales(path)
    if any(not (mk / E <= kk <= mk * E) for kk in groups):
        assert all(mk / kk >= lf.GROUPS_SHARE / E for kk in groups), (mk, groups)
        was = _found(path)[1].layout  # type: ignore[index]
        assert not _one_scale_holds(s, mk, mk, was), f"{path.stem}: groups {groups} beside {mk}"
    if crank is not None and not (mk / E <= crank <= mk * E):
        assert s.linkage.length / crank >= CRANK_MM / E, (mk, crank)  # type: ignore[attr-defined]

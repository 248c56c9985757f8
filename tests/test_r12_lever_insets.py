"""Round 12, lever (review 12 fix 3): every inset of a forces sheet's views (the mechanism,
the groups' free bodies, Zhukovsky's lever) draws its forces at ONE stated μ_F (the needle's
inset Г held Φ5* and G5**): a place's forces at two of the insets' μ_F are drawn at the finer
where that keeps them within INSET_ONE_MM, else as two insets (twins) of one μ_F each; and
the lever draws no point nothing on the sheet explains (the bloom shear's "d₄": the point of
P_MФ4, a force left out as negligible; a moment is now an arc on its link's image)."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

import pytest

from geomcad.linkage import parse
from geomcad.linkage.solution import solve
from geomcad.sheet.model import TextItem

ROOT = Path(__file__).resolve().parent.parent
FILES = [
    *sorted((ROOT / "tests" / "linkages_review12").glob("*.toml")),
    *sorted((ROOT / "tests" / "linkages_layout").glob("*.toml")),
    ROOT / "examples" / "shaper.toml",
]


def _draw(path: Path, mp: pytest.MonkeyPatch) -> dict[str, Any]:
    """The forces sheet of ``path`` with each inset's forces recorded (the Insets, its
    letter, its short forces) and the lever's texts."""
    from geomcad.sheet import insets as ins_mod
    from geomcad.sheet import linkage_forces as lf

    rec: dict[str, Any] = {"insets": [], "lever": []}
    orig_one = ins_mod.Insets._one

    def one(self: Any, d: Any, v: Any, free: Any, q: Any, p: Any, letter: str, shorts: Any,
            *a: Any, **kw: Any) -> Any:  # fmt: skip
        rec["insets"].append((d.sheet, self, letter, list(shorts)))
        return orig_one(self, d, v, free, q, p, letter, shorts, *a, **kw)

    mp.setattr(ins_mod.Insets, "_one", one)
    orig_lever = lf._Lever.draw

    def lever(self: Any, d: Any, at: Any) -> Any:
        n0 = len(d.sheet.items)
        out = orig_lever(self, d, at)
        rec["lever"].append((d.sheet, self, d.sheet.items[n0:]))
        return out

    mp.setattr(lf._Lever, "draw", lever)
    lk = parse(tomllib.loads(path.read_text("utf-8")))
    sheets = lf.force_sheets(solve(lk), "x")
    rec["sheet"] = sheets[0][1] if sheets else None
    return rec


@pytest.fixture(scope="module", params=FILES, ids=[p.stem for p in FILES])
def drawn(request: pytest.FixtureRequest) -> dict[str, Any]:
    with pytest.MonkeyPatch.context() as mp:
        return _draw(request.param, mp)


def test_no_inset_holds_forces_at_two_scales(drawn: dict[str, Any]) -> None:
    """Each inset drawn on the sheet: its forces drawn to scale all at one μ_F (a direction
    arrow, at no scale, may stand beside them)."""
    if drawn["sheet"] is None:
        pytest.skip("no forces sheet")
    for sheet, ins, letter, shorts in drawn["insets"]:
        if sheet is not drawn["sheet"]:
            continue
        ks = {ins.fs.k_at(s.F.norm) for s in shorts if not ins.fixed(s)}
        assert len(ks) <= 1, (letter, [s.label for s in shorts], sorted(ks))


def test_the_lever_draws_only_explained_points(drawn: dict[str, Any]) -> None:
    """Every point lettered on the lever is a point of the velocity plan, one a force drawn
    on the lever acts at (never a point of loads all left out), or one a moment's arc is
    drawn on (the ends of its link's image: its couple's points)."""
    if drawn["sheet"] is None:
        pytest.skip("no forces sheet")
    from geomcad.sheet.linkage_forces import lever_loads

    for sheet, lev, _ in drawn["lever"]:
        if sheet is not drawn["sheet"]:
            continue
        P, f = lev.P, lev.f
        forces, moments = lever_loads(f)
        named = set(P.vp.points) | {
            P.pn(it.point) for it in forces if it.point and lev.fs.tier(it.force.norm) is not None
        }
        named |= {P.pn(it.point) for m in moments for it in m.pair if it.point}
        # the points' labels are placed once the sheet's views are drawn: the sheet's
        for t in drawn["sheet"].items:
            if not isinstance(t, TextItem):
                continue
            words = "".join(r.text for r in t.runs).split(", ")
            if all(re.fullmatch(r"[a-z]\d*", w) for w in words):
                assert set(words) <= named, (words, sorted(named))

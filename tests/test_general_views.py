"""The general views the seed sheets are composed from (issue 32): each takes model data and
draws it wherever it is placed; what each promises is checked on its own, apart from a sheet."""

from __future__ import annotations

import math

import numpy as np
import pytest

import geomcad
from geomcad.geom import Vec
from geomcad.kinematics.trains import RayPlan
from geomcad.sheet import TitleBlock, start
from geomcad.sheet.assur import cut_out, group_kind, groups_table, pairs_table
from geomcad.sheet.cams import CamAt, Inversion
from geomcad.sheet.compose import Column, Field, View, arrange, compose
from geomcad.sheet.lang import language
from geomcad.sheet.model import Item, Polyline, TextItem
from geomcad.sheet.overline import MACRON, overline_marks
from geomcad.sheet.teeth import CutTooth, clip_band, tooth_extent
from geomcad.sheet.text import parse
from geomcad.sheet.trains import at_kl, scaled_rays


def _inside(ext: tuple[float, float, float, float], pts: np.ndarray) -> bool:
    x0, y0, x1, y1 = ext
    tol = 1e-12 * max(x1 - x0, y1 - y0)
    return bool(
        np.all(pts[:, 0] >= x0 - tol)
        and np.all(pts[:, 0] <= x1 + tol)
        and np.all(pts[:, 1] >= y0 - tol)
        and np.all(pts[:, 1] <= y1 + tol)
    )


def _drawn(view: View) -> list[Item]:
    d = start("A3", TitleBlock(title="t", designation="d"))
    compose(d, Column(view))
    return d.finish().items


@pytest.mark.parametrize("follower", ["flat", "knife", "roller"])
def test_the_cam_views_cover_what_they_draw(follower: str) -> None:
    sets: dict[str, object] = {"follower": follower}
    if follower == "roller":
        sets["r_roller"] = 0.01
    sol = geomcad.solve("2013-2", **sets)
    geo = sol.data
    f = geo.follower
    inv = Inversion(f, geo.profile, geo.divisions, geo.closed, geo.rest, "end")
    ext = inv.extent()
    assert ext is not None
    assert _inside(ext, geo.profile.contact) and _inside(ext, geo.divisions.pitch)
    at = CamAt(f, geo.profile, geo.plan, geo.closed, geo.rest)
    cam, _rest = at.cam_now()
    # the cam turned to the plan's φ touches the follower at B (a roller: at r_roller from its
    # centre B)
    B = geo.plan.B
    gap = float(np.min(np.hypot(cam[:, 0] - B.x, cam[:, 1] - B.y)))
    want = f.r_roller if f.kind == "roller" else 0.0
    assert gap == pytest.approx(want, abs=2e-3 * f.r0)
    at_ext = at.extent()
    assert at_ext is not None and _inside(at_ext, cam)


def test_cut_out_keeps_the_groups_pairs_and_ghosts_the_links_it_hangs_on() -> None:
    geo = geomcad.solve("2013-1").data
    mech, dec = geo.seed_route, geo.decomposition
    for g in dec.groups:
        sub = cut_out(mech, g.links)
        own = set(g.links)
        assert {p.name for p in sub.pairs} == {p.name for p in mech.pairs if own & set(p.links)}
        ghosts = {lk.id for lk in sub.links} - own
        assert all(x.endswith("'") for x in ghosts)
        # a pair to the frame stays on the frame; one to another moving link goes to its ghost
        for p in sub.pairs:
            for lk in p.links:
                assert lk in own or lk == mech.frame or lk in ghosts


def test_the_structure_tables_read_the_model() -> None:
    geo = geomcad.solve("2013-1").data
    with language("ru"):
        t = pairs_table(geo.before)
        assert group_kind("RRP") == "ВВП"
    assert len(t.rows) == 1 + len(geo.before.pairs)
    assert [r[0] for r in t.rows[1:]] == [p.name for p in geo.before.pairs]
    g = groups_table(geo.decomposition)
    assert len(g.rows) == 1 + len(geo.decomposition.primary) + len(geo.decomposition.groups)


def test_clip_band_cuts_a_polyline_at_the_band_edges() -> None:
    pts = [(-2.0, 0.0), (0.0, 2.0), (2.0, 0.0), (4.0, 2.0)]
    parts = clip_band(pts, -1.0, 3.0)
    assert parts == [[(-1.0, 1.0), (0.0, 2.0), (2.0, 0.0), (3.0, 1.0)]]
    assert clip_band(pts, 5.0, 6.0) == []


def test_the_tooth_view_covers_the_tooth_and_the_rack() -> None:
    geo = geomcad.solve("2013-4").data
    gear = geo.gear
    ext = tooth_extent(gear)
    assert _inside(ext, np.asarray(geo.flank.involute))
    assert ext[3] >= gear.r_a  # the tip circle is in the view
    view = CutTooth(gear, geo.flank, [(geo.r_y, "d_y")])
    names = " ".join(it.text for it in _drawn(view) if isinstance(it, TextItem))
    for name in ("d_a", "d_b", "d_f", "d_y"):
        assert name.replace("_", "") in names.replace("_", "")


def test_overline_marks_bar_the_letter_and_drop_the_mark() -> None:
    d = start("A3", TitleBlock(title="t", designation="d"))
    d.text(f"s{MACRON} = 1", (50.0, 50.0), 3.5)
    sheet = d.finish()
    before = sum(isinstance(it, Polyline) for it in sheet.items)
    overline_marks(sheet)
    texts = [it for it in sheet.items if isinstance(it, TextItem) and it.text.startswith("s")]
    assert texts and all(MACRON not in it.text for it in texts)
    assert sum(isinstance(it, Polyline) for it in sheet.items) == before + 1


def test_scaled_rays_read_omega_at_the_factor() -> None:
    rays = RayPlan(Vec(0.0, -1.0), 1.0, {"1": Vec(2.0, 0.0), "H": Vec(-0.5, 0.0)})
    k_v, k_w = 0.02, 0.5
    r = scaled_rays(rays, k_v, k_w)
    pole_distance = r.H
    assert pole_distance == pytest.approx(k_v / k_w)
    for link, e in rays.ends.items():
        # the same ray (direction kept), and the intercept over μ_V reads ω / μ_ω
        a, b = e - rays.S, r.ends[link] - r.S
        assert a.cross(b) == pytest.approx(0.0, abs=1e-15)
        omega = (e.x - rays.S.x) / rays.H  # ω = slope of the link's line
        assert (b.x / k_v) * k_w == pytest.approx(omega)
    assert at_kl(Vec(1.0, 2.0), 0.002, 0.01) == Vec(0.2, 2.0)


def test_the_views_place_at_the_layouts_scale() -> None:
    geo = geomcad.solve("2013-4").data
    view = CutTooth(geo.gear, geo.flank)
    lay = arrange(Column(view), Field.of_format("A3"))
    k = lay[view].scale
    assert k is not None and math.isfinite(k.k) and k.k > 0.0


@pytest.mark.parametrize("name", ["cam-rocking-roller", "cam-translating-roller", "cam-flat"])
def test_a_design_files_profile_is_the_inversion_view(name: str) -> None:
    """The cam file's profile is drawn by the same Inversion view as 2013-2's: a rocker's arms
    hang on its pivots A_i turned back round the circle of radius OA (inside the view's
    extent); every division point is numbered; ω and −ω stand outside the profile."""
    from pathlib import Path

    from geomcad.files import cam_sheets

    path = Path(__file__).resolve().parents[1] / "examples" / f"{name}.toml"
    des = geomcad.solve(str(path)).data
    inv = cam_sheets._profile(des)
    assert isinstance(inv, Inversion) and not inv.lettered
    ext = inv.extent()
    assert ext is not None
    a_w = math.hypot(*des.pivot) if des.spec.motion == "rocking" else des.r0
    x0, y0, x1, y1 = ext
    assert min(-x0, -y0, x1, y1) >= a_w * (1.0 - 1e-12)
    texts = {it.text for it in _drawn(inv) if isinstance(it, TextItem)}
    n = len(des.divisions.phi) - 1
    assert {str(i) for i in range(n)} <= texts
    assert {"ω", "".join(r.text for r in parse("−ω"))} <= texts  # the minus as the font sets it
    pivots = {f"A{i}" for i in range(n)}
    assert (pivots <= texts) == (des.spec.motion == "rocking")


def test_composed_names_the_sheet_from_its_words_and_scale() -> None:
    """form.composed: the tree composed under the title block the sheet's words name, with the
    main view's scale in Масштаб."""
    from geomcad.sheet.compose import Spacer
    from geomcad.sheet.form import composed
    from geomcad.sheet.lang import Words

    words = Words("geomcad_constructions", "sheets_2013_3")
    with language("en"):
        sheet = composed("A3", Column(Spacer((40.0, 30.0))), words, "1:2")
        title, designation = words("tb_title"), words("designation")
    assert sheet.format == "A3" and sheet.lang == "en" and sheet.title == title
    assert sheet.block is not None
    assert (sheet.block.designation, sheet.block.scale) == (designation, "1:2")

"""The rules a teacher checks on every generated sheet of a linkage file (issue 27), measured on
the project's examples and on files written here: a force is an arrow at a stated μ_F (never a
dot), the designation is printed exactly as typed, every mechanism view shows ω1, and the plans
carry every named point."""

from __future__ import annotations

import math
import re
import shutil
from pathlib import Path

import pytest

import geomcad
from geomcad.files import code
from geomcad.linkage.analysis import analyse
from geomcad.linkage.solution import solve
from geomcad.sheet import fmt_number
from geomcad.sheet.drawing import SHORT_MM
from geomcad.sheet.linkage_forces import force_position, load_name
from geomcad.sheet.loads import force_scales
from geomcad.sheet.model import ArcItem, Sheet
from geomcad.sheet.text import literal, parse
from geomcad.sheet.titleblock import TitleData

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
LINKAGES = [
    p
    for p in sorted(EXAMPLES.glob("*.toml"))
    if "[drive]" in p.read_text(encoding="utf-8") and "[[group]]" in p.read_text(encoding="utf-8")
]


def plain(markup: str) -> str:
    return "".join(r.text for r in parse(markup))


def test_force_scales_never_leave_a_force_too_short() -> None:
    forces = [2576.0, 2200.0, 245.0, 29.4, 24.0, 3.6, 0.5, 1e-14]
    fs = force_scales(forces, 24.0)
    assert len(fs.scales) > 1
    for F in forces[:-1]:
        tier = fs.tier(F)
        assert tier is not None
        mm = F / fs.scales[tier].k
        assert SHORT_MM * (1.0 - 1e-9) <= mm <= 24.0 * (1.0 + 1e-9), (F, mm)
    assert fs.tier(forces[-1]) is None  # round-off of a zero force
    # every scale is stated in the caption, the marks in order
    assert fs.caption() == "μ_F = 200 Н/мм"
    further = fs.further()
    assert further.startswith("μ_F^{*} = 20, μ_F^{**} = 2, ") and further.endswith(" Н/мм")
    # forces within one μ: one scale, no mark
    one = force_scales([100.0, 60.0, 40.0], 24.0)
    assert len(one.scales) == 1 and not one.tiered and one.mark(0) == ""


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_no_force_is_a_dot(path: Path) -> None:
    """Every non-zero load and reaction of the forces sheet is a labelled arrow, no label says
    it is drawn as a point, and every scale its marks use is stated."""
    s = solve(geomcad.solve(str(path)).data.linkage)
    a = analyse(s)
    if a.forces is None:
        pytest.skip("no force analysis")
    sheets = dict(geomcad.solve(str(path)).sheets())
    sheet = sheets["forces"]
    texts = [t.text for t in sheet.texts()]
    assert not any("(·)" in t for t in texts)
    names = {t.text.rstrip("*") for t in sheet.texts() if t.role == "label"}
    # or named, too short in a plan's detail, on the line under the plan's caption
    for t in sheet.texts():  # each plan's line (one per plan: its names after its own colon)
        if t.text.startswith(_LISTED):
            names |= _named(t.text)

    _, f, _ = force_position(s)
    big = max(r.force.norm for r in f.reactions)
    for lds in f.loads.values():
        for ld in lds:
            if ld.force is not None and ld.at is not None and ld.force.norm > 1e-9 * big:
                assert plain(load_name(ld.name)) in names, ld.name
    for r in f.reactions:
        if r.force.norm > 1e-9 * big:
            assert plain(load_name(r.name)) in names, r.name
    labels = [t.text.split(" = ")[0] for t in sheet.texts() if t.role == "label"]
    marks = {len(t) - len(t.rstrip("*")) for t in labels}
    caption = " ".join(texts)
    for m in range(1, max(marks, default=0) + 1):
        assert re.search(rf"μF\*{{{m}}} = \d", caption), m


#: The start of the line under a force plan's caption that names what its details cannot show.
_LISTED = ("на выносн", "короче ")


def _named(text: str) -> set[str]:
    """The names in the list ("…: G4 = 3,9 Н, Ф4 = 6,1 Н" or "…: G4, Ф4") ending ``text``."""
    return {item.split(" = ")[0].strip() for item in text.rsplit(": ", 1)[-1].split(", ")}


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_no_polygon_vector_is_a_dot(path: Path) -> None:
    """Every non-zero vector of every force polygon is an arrow at a μ_F the sheet states: at
    the polygon's own, or, too short there, in the plan's one detail at its larger μ_F (the
    vector's length on the paper is |F|/μ_F of that arrow), or, too short even there, named
    with its value under the plan's caption. An arrow is at least one arrowhead long
    (LISTED_MM, round 14's one detail μ_F), except a reaction on its own plan: every reaction
    is an arrow of the plan however short (``views.main_arrows``: the plan's equation closes
    on the plan), and one shorter than an arrowhead there is drawn again, at least an
    arrowhead long, in the plan's detail."""
    from layout import unstated_vectors

    from geomcad.sheet.views import LISTED_MM, WORDS

    s = solve(geomcad.solve(str(path)).data.linkage)
    if analyse(s).forces is None:
        pytest.skip("no force analysis")
    sheet = dict(geomcad.solve(str(path)).sheets())["forces"]
    assert not unstated_vectors(sheet)
    arrows = [(math.dist(t, h), sc.k) for t, h, sc in sheet.scaled if sc.q == "F"]
    _, f, _ = force_position(s)
    polys = [poly for gf in f.groups for _, poly in gf.polygons]
    big = max(pv.magnitude for poly in polys for pv in poly.vectors)
    reactions = [pv.magnitude for poly in polys for pv in poly.vectors if pv.name.startswith("R_")]
    least = LISTED_MM * (1.0 - 1e-9)

    def enlarged(force: float) -> bool:
        return any(mm >= least and math.isclose(mm * k, force, rel_tol=1e-6) for mm, k in arrows)

    def reaction_enlarged(mm: float, k: float) -> bool:
        return any(math.isclose(mm * k, r, rel_tol=1e-6) and enlarged(r) for r in reactions)

    short = [(mm, k) for mm, k in arrows if mm < least and not reaction_enlarged(mm, k)]
    assert not short
    head = WORDS("detail_listed", mm=fmt_number(LISTED_MM), items="")
    texts = [t.text for t in sheet.texts()]
    lists = []
    for i, t in enumerate(texts):
        if t.startswith((head, *_LISTED)):
            # a note broken into lines for its box: its lines joined up to the names
            j = i
            while ": " not in t and j + 1 < len(texts):
                j += 1
                t += " " + texts[j]
            lists.append(t)
    for poly in polys:
        for pv in poly.vectors:
            if pv.magnitude > 1e-9 * big:
                at = [k for mm, k in arrows if math.isclose(mm * k, pv.magnitude, rel_tol=1e-6)]
                plain = "".join(r.text for r in parse(load_name(pv.name)))
                listed = [t for t in lists if f"{plain} = " in t or plain in _named(t)]
                assert at or listed, (pv.name, pv.magnitude)


def test_designation_printed_as_typed(tmp_path: Path) -> None:
    """A designation with an underscore keeps it (no subscript) in графа 2 and 26, and a file's
    default designation is a code: its title's initials (review 13), ``ТММ.КПМ.01`` for a
    Кривошипно-ползунный механизм, in both графы."""
    src = EXAMPLES / "slider-crank.toml"
    path = tmp_path / "sixbar_press.toml"
    shutil.copy(src, path)
    assert code(str(path), "Кривошипно-ползунный механизм") == "КПМ"
    sol = geomcad.solve(str(path))
    default = sol.sheets()
    des = [t.text for _, sh in default for t in sh.texts() if "ТММ." in t.text]
    assert des and set(des) == {"ТММ.КПМ.01"} and len(des) == 2 * len(default)
    typed = "ТММ.press_01.000 ^x{y}"
    sheets = sol.sheets(TitleData(designation=typed))
    for _, sheet in sheets:
        hits = [t for t in sheet.texts() if t.text == typed]
        assert len(hits) == 2  # графа 2 and графа 26 (turned)
        assert all(r.shift == "base" for t in hits for r in t.runs)
    assert plain(literal("a_b^c{d}\\e")) == "a_b^c{d}\\e"


def _omega_arcs(sheet: Sheet) -> list[ArcItem]:
    """The arcs that carry the label ω1 next to them."""
    labels = [t for t in sheet.texts() if t.text == "ω1"]
    arcs = [it for it in sheet.items if isinstance(it, ArcItem)]
    out = []
    for a in arcs:
        mid = ((a.start[0] + a.end[0]) / 2.0, (a.start[1] + a.end[1]) / 2.0)
        if any(math.dist(mid, t.at) < a.r + 10.0 for t in labels):
            out.append(a)
    return out


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_omega_arrow_on_every_mechanism(path: Path) -> None:
    sheets = dict(geomcad.solve(str(path)).sheets())
    assert _omega_arcs(sheets[""]), "kinematic sheet"
    if "forces" in sheets:
        assert _omega_arcs(sheets["forces"]), "forces sheet"


COUPLER = """
title = "four-bar with a coupler point"
[frame]
O = [0.0, 0.0]
C = [0.30, 0.0]
[drive]
pivot = "O"
joint = "A"
length = 0.08
omega = 12.0
positions = 12
[[group]]
kind = "RRR"
links = [2, 3]
joint = "B"
ends = ["A", "C"]
lengths = [0.28, 0.20]
assembly = "left"
[[point]]
name = "M"
link = 2
from = "A"
toward = "B"
along = 0.14
left = 0.08
"""


def _named_points_complete(path: Path) -> None:
    """On every velocity and acceleration plan of the file, every moving named point of the
    mechanism has its plan point and its absolute vector from the pole: a recorded vector
    from the pole, or an image by similarity (drawn with its triangle and its pole vector)."""
    from geomcad.linkage.plans import plan_name

    s = solve(geomcad.solve(str(path)).data.linkage)
    lk = s.linkage
    moving = [n for n, link in lk.owner.items() if link != 0]
    assert moving
    for P in s.positions:
        for plan in (P.vp, P.ap):
            from_pole = {v.head for v in plan.vectors if v.tail in {plan.pole, *plan.at_pole}}
            imaged = {q for _, _, q in plan.images}
            for n in moving:
                q = plan.name(plan_name(n))
                assert q in plan.points, (path.name, n, q)
                assert q in from_pole | imaged, (path.name, n, q, plan.kind)


@pytest.mark.parametrize("path", LINKAGES, ids=lambda p: p.stem)
def test_every_named_point_on_the_plans(path: Path) -> None:
    _named_points_complete(path)


def test_coupler_point_by_similarity(tmp_path: Path) -> None:
    path = tmp_path / "coupler.toml"
    path.write_text(COUPLER, encoding="utf-8")
    _named_points_complete(path)
    s = solve(geomcad.solve(str(path)).data.linkage)
    P = s.positions[1]
    # m is an image of the coupler's a, b (the triangle abm is similar to ABM)
    a, b, m = next((a, b, q) for a, b, q in P.vp.images if q == "m")
    A, B, M = P.pos["A"], P.pos["B"], P.pos["M"]
    ab, am = P.vp.points[b] - P.vp.points[a], P.vp.points[m] - P.vp.points[a]
    assert math.isclose(am.norm / ab.norm, (M - A).norm / (B - A).norm, rel_tol=1e-9)
    assert math.isclose(ab.cross(am) / ab.norm**2, (B - A).cross(M - A) / (B - A).norm ** 2,
                        rel_tol=1e-9)  # fmt: skip


def test_dynamics_table_has_the_diagrams_sign_and_one_format_per_column() -> None:
    """The M_пр column reads as the diagram does (> 0 in the sense of ω1: ΣP/|ω1|), also for a
    crank turning clockwise, and each column writes its numbers with one count of decimals."""
    from geomcad.sheet.lang import language
    from geomcad.sheet.linkage_forces import _tables3

    path = EXAMPLES / "sixbar-2013-6.toml"
    s = solve(geomcad.solve(str(path)).data.linkage)
    assert s.linkage.omega < 0
    fw = analyse(s).flywheel
    assert fw is not None
    with language("en"):
        table = _tables3(s.linkage, fw, 3.5)[0]
    body = table.rows[1:]
    for row, M in zip(body, fw.M_pr, strict=False):
        value = float(row[3].replace("\u2013", "-"))
        assert value == pytest.approx(-M, abs=0.06 * max(abs(x) for x in fw.M_pr)), row
    for col in range(1, 4):
        decimals = {len(r[col].split(".")[1]) if "." in r[col] else 0 for r in body}
        assert len(decimals) == 1 or (
            decimals == {0, max(decimals)} and all(r[col] == "0" for r in body if "." not in r[col])
        ), (col, decimals)


def _ratios(sheet: Sheet) -> list[str]:
    return [t.text.split("(М ")[1].split(")")[0] for t in sheet.texts() if "μl = " in t.text]


def test_forces_sheet_scales_from_geometry(tmp_path: Path) -> None:
    """The forces sheet's drawings of links are never finer than the scale the geometry gives
    them (links_scale: the crank 30 mm long, or the mechanism's sweep 200 mm) grown by at most
    GROW_L_STEPS GOST steps into the field (review 10's rule in _pinned: the shaper's 1:2,5
    grows to 1:2 since round 12's pinned forms hold it), its Масштаб cell is the loaded
    mechanism's, and a change of ω alone rescales no drawing of links (the shaper at ω1 = −8
    and −12 1/s)."""
    from geomcad.sheet.linkage_forces import GOST_K, GROW_L_STEPS, links_scale

    src = (EXAMPLES / "shaper.toml").read_text(encoding="utf-8")
    seen = []
    for omega in ("-8.0", "-12.0"):
        path = tmp_path / f"shaper{omega}.toml"
        path.write_text(src.replace("omega = -8.0", f"omega = {omega}"), encoding="utf-8")
        sol = geomcad.solve(str(path))
        sheets = dict(sol.sheets())
        forces = _ratios(sheets["forces"])
        k_l = links_scale(sol.data).k
        finer = sorted((g for g in GOST_K if g < k_l * (1.0 - 1e-9)), reverse=True)
        k_least = finer[GROW_L_STEPS - 1] if len(finer) >= GROW_L_STEPS else k_l
        least = 0.001 / k_least  # the reduction 1:n of the finest step allowed
        assert all(float(r.split(":")[1].replace(",", ".")) >= least * (1.0 - 1e-9)
                   for r in forces), forces  # fmt: skip
        block = forces[0]
        assert block in {t.text for t in sheets["forces"].texts() if t.role == "title"}
        seen.append(forces)
    assert seen[0][0] == seen[1][0]  # the loaded mechanism


def test_drafting_rules() -> None:
    """Frame hinges' supports stand square to the sheet; a slotted link ends at its last joint
    where that is beyond its block (the shaper's link 3 at B, not 0.09 m past it)."""
    from geomcad.linkage.solution import scheme
    from geomcad.sheet.linkage import link_bodies
    from geomcad.sheet.scheme import _support_direction

    s = solve(geomcad.solve(str(EXAMPLES / "shaper.toml")).data.linkage)
    lk = s.linkage
    checked = 0
    for P in s.positions:
        mech = scheme(lk, P)
        for pair in mech.pairs:
            if mech.frame in pair.links and pair.kind == "R":
                dx, dy = _support_direction(mech, pair)
                assert (abs(dx), abs(dy)) in {(0.0, 1.0), (1.0, 0.0)}, (dx, dy)
                checked += 1
        (body,) = link_bodies(lk, P, [3])["3"]
        end = body.points[-1]
        far = max(P.pos["B"].dist(P.pos["C"]), 1.15 * P.pos["A"].dist(P.pos["C"]))
        assert end.dist(P.pos["C"]) == pytest.approx(far, rel=1e-9)
    assert checked >= 2 * len(s.positions)  # O and C in every position


def test_the_star_of_a_further_scale_is_a_superscript() -> None:
    """The mark of a force at a larger μ_F is a raised star (osifont sets ``*`` on the line at
    the height of ``=``), in the force's label and in the μ_F* it is drawn at."""
    fs = force_scales([1000.0, 100.0, 10.0], 24.0)
    assert [r.shift for r in parse("R_{03}" + fs.mark(1))] == ["base", "sub", "sup"]
    assert parse("R_{03}" + fs.mark(2))[-1].text == "**"
    assert all(r.shift == "sup" for r in parse(fs.further()) if "*" in r.text)


def test_the_free_body_note_states_both_force_scales() -> None:
    """The dynamics sheets' note names μ_F and, by value, the μ_F* of the short forces."""
    from geomcad.sheet.free_body import scales_of, short_note

    sol = geomcad.solve("kulisa-23110713")
    k_F = sol.scales["F"]
    fs = scales_of(sol.data.dynamic, k_F)
    assert fs.tiered
    note = short_note(k_F, sol.data.dynamic)
    assert note.startswith(f"μ_F = {fmt_number(k_F)} ")
    assert f"μ_F^{{*}} = {fmt_number(fs.scales[1].k)} " in note

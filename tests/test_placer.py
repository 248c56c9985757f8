"""The label placer (geomcad.sheet.placer): labels near their points, clear of lines and of one
another, inside the field; dimension texts along their lines, clear of what crosses them."""

from __future__ import annotations

import math

from layout import findings, layout_problems, text_poly
from shapely.geometry import Point

from geomcad.sheet import Scale, TitleBlock, start
from geomcad.sheet.drawing import Drawing
from geomcad.sheet.model import Polyline, Sheet


def _a3() -> Drawing:
    return start("A3", TitleBlock(title="t", designation="x"))


def _crossed(sheet: Sheet) -> list[str]:
    return [f.text for f in findings(sheet) if f.kind == "label-line"]


def test_a_label_keeps_off_the_lines_through_its_point() -> None:
    d = _a3()
    for k in range(3):  # a star of three lines through the point, 60° apart
        a = math.pi * k / 3 + 0.2
        c, s = 12.0 * math.cos(a), 12.0 * math.sin(a)
        d.sheet.add(Polyline(((150.0 - c, 100.0 - s), (150.0 + c, 100.0 + s)), "link"))
    d.label((150.0, 100.0), "B_1", clear=1.5)
    sheet = d.finish()
    (t, anchor), *_ = sheet.anchors
    assert anchor == (150.0, 100.0)
    assert not _crossed(sheet)
    assert text_poly(t).distance(Point(anchor)) < 6.0


def test_a_label_on_a_line_sits_beside_it() -> None:
    d = _a3()
    d.sheet.add(Polyline(((100.0, 150.0), (180.0, 90.0)), "link"))  # slanted
    d.label((140.0, 120.0), "2", clear=1.0)  # a link's number at its middle
    sheet = d.finish()
    assert not _crossed(sheet)
    (t, anchor), *_ = sheet.anchors
    assert text_poly(t).distance(Point(anchor)) < 3.0


def test_labels_of_one_point_and_of_a_crowd_never_overlap() -> None:
    d = _a3()
    for i in range(8):
        for j in range(5):
            p = (60.0 + 9.0 * i, 60.0 + 7.0 * j)
            d.sheet.add(Polyline(((p[0] - 3.0, p[1]), (p[0] + 3.0, p[1])), "construction"))
            d.label(p, f"A_{{{i}{j}}}", clear=0.8)
    for name in ("π", "o_2", "c"):
        d.label((200.0, 60.0), name)
    sheet = d.finish()
    assert layout_problems(sheet) == []  # no text on another
    far = [f.text for f in findings(sheet) if f.kind == "anchor"]
    assert len(far) <= 4, far


def test_labels_stay_in_the_field() -> None:
    d = _a3()
    corners = [(21.0, 100.0), (300.0, 6.0), (414.0, 100.0), (300.0, 236.0), (60.0, 18.0)]
    for p in corners:  # the frame's edges, the title block's top, графа 26
        d.label(p, "Long label text")
    sheet = d.finish()
    assert layout_problems(sheet) == []


def test_dimension_text_runs_along_its_line_and_moves_off_a_crossing_line() -> None:
    d = _a3()
    v = d.viewport(Scale(0.001, "l"), (0, 0), (100.0, 200.0))
    a, b = (0.0, 0.0), (0.08, 0.06)  # 100 mm at 36.87°
    v.seg(a, b)
    mid = v.p((0.04, 0.03))
    # a thick line across the middle of the dimension (10 mm to the left of a → b on the paper),
    # where its text would go first
    n = (-0.6, -0.8)
    d.sheet.add(Polyline(((mid[0] + 30 * n[0], mid[1] + 30 * n[1]),
                          (mid[0] - 5 * n[0], mid[1] - 5 * n[1])), "link"))  # fmt: skip
    v.dim_linear(a, b, "100", offset=10.0)
    sheet = d.finish()
    text = next(t for t in sheet.texts() if t.text == "100")
    assert math.isclose(text.angle, math.degrees(math.atan2(0.06, 0.08)), abs_tol=1e-9)
    assert not _crossed(sheet)
    mid_dim = (mid[0] + 10 * n[0], mid[1] + 10 * n[1])
    assert text_poly(text).distance(Point(mid_dim)) > 1.0  # moved along, off the middle

"""DXF output: every sheet read back with ezdxf, and one rendered by ezdxf's drawing add-on and
compared with the SVG that the same sheet gives."""

from __future__ import annotations

import io
import math
from collections import Counter
from pathlib import Path

import ezdxf
import ezdxf.bbox
import numpy as np
import pytest
from ezdxf.document import Drawing
from test_golden import _sheets  # the sheets the golden test draws, drawn once

import geomcad
from geomcad.cli import main
from geomcad.errors import MissingDependency
from geomcad.render import dxf, to_png, to_svg, write_sheets
from geomcad.render.dxf import LINETYPE_NAMES, PAPER_LAYER, TEXT_STYLE, lineweight, to_dxf
from geomcad.render.svg import main_line
from geomcad.sheet.model import ArcItem, CircleItem, Dash, Polyline, Run, Sheet, TextItem
from geomcad.sheet.style import STYLES, fit_closed, fit_open
from geomcad.sheet.text import font_path, metrics

PIDS = geomcad.problem_ids()


def _read(data: bytes) -> Drawing:
    return ezdxf.read(io.StringIO(data.decode("utf-8")))


def _is_segment(item: object) -> bool:
    return isinstance(item, Polyline) and len(item.points) == 2 and not item.closed


@pytest.mark.parametrize("pid", PIDS)
def test_every_sheet_reads_back_as_the_same_drawing(pid: str) -> None:
    for name, sheet in _sheets(pid):
        where = f"{pid} {name!r}"
        doc = _read(to_dxf(sheet))
        assert doc.dxfversion == "AC1024"  # R2010
        auditor = doc.audit()
        assert not auditor.has_errors, (where, [str(e) for e in auditor.errors[:3]])

        # millimetres, and the paper format is the drawing's extent
        assert doc.header["$INSUNITS"] == 4 and doc.header["$MEASUREMENT"] == 1
        assert tuple(doc.header["$EXTMIN"])[:2] == (0.0, 0.0)
        assert tuple(doc.header["$EXTMAX"])[:2] == (sheet.width, sheet.height)
        msp = doc.modelspace()
        paper = ezdxf.bbox.extents(e for e in msp if e.dxf.layer == PAPER_LAYER)
        assert paper.extmin.isclose((0, 0, 0))
        assert paper.extmax.isclose((sheet.width, sheet.height, 0))
        # the outermost ink is the GOST 2.301 frame: 20 mm from the left edge, 5 from the others
        lines = ezdxf.bbox.extents(
            e for e in msp if e.dxf.layer != PAPER_LAYER and e.dxftype() != "TEXT"
        )
        assert lines.extmin.isclose((20.0, 5.0, 0.0)), (where, lines)
        assert lines.extmax.isclose((sheet.width - 5.0, sheet.height - 5.0, 0.0)), (where, lines)
        for t in msp.query("TEXT"):
            assert 0.0 < t.dxf.insert.x < sheet.width and 0.0 < t.dxf.insert.y < sheet.height

        # one layer per role the sheet uses, with the role's line
        roles = {i.role for i in sheet.items}
        assert {layer.dxf.name for layer in doc.layers} == roles | {"0", "Defpoints", PAPER_LAYER}
        s = main_line(sheet.format)
        for role in roles:
            layer, st = doc.layers.get(role), STYLES[role]
            assert layer.dxf.linetype == LINETYPE_NAMES.get(st.line, "Continuous"), role
            if st.weight > 0.0:
                assert layer.dxf.lineweight == lineweight(st.weight * s), role
                assert abs(layer.dxf.lineweight / 100.0 - st.weight * s) <= 0.1
        assert not doc.layers.get(PAPER_LAYER).dxf.plot

        # entity kinds and counts, item for item
        kinds = Counter(e.dxftype() for e in msp)
        circles = sum(isinstance(i, CircleItem) for i in sheet.items)
        runs = sum(1 for t in sheet.texts() for r in t.runs if r.text)
        filled = sum(isinstance(i, Polyline | CircleItem) and i.fill for i in sheet.items)
        assert kinds == Counter(
            {
                k: n
                for k, n in {
                    "LINE": sum(_is_segment(i) for i in sheet.items),
                    "LWPOLYLINE": sum(
                        isinstance(i, Polyline) and not _is_segment(i) for i in sheet.items
                    )
                    + 1,  # the paper's edge
                    "CIRCLE": circles,
                    "ARC": sum(isinstance(i, ArcItem) for i in sheet.items),
                    "TEXT": runs,
                    "HATCH": filled,
                }.items()
                if n
            }
        ), where
        assert all(e.dxf.style == TEXT_STYLE for e in msp.query("TEXT"))
        assert all(h.dxf.solid_fill for h in msp.query("HATCH"))


def test_text_is_real_text_in_the_gost_font() -> None:
    sheet = _sheets("2013-6")[0][1]
    doc = _read(to_dxf(sheet))
    style = doc.styles.get(TEXT_STYLE)
    assert style.dxf.font == "osifont.ttf"
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert "Разраб." in texts and "Исходные данные" in texts
    # the cap height of each base run is the label's GOST cap height
    title = next(t for t in sheet.texts() if t.text == "Исходные данные")
    entity = next(e for e in doc.modelspace().query("TEXT") if e.dxf.text == title.text)
    assert entity.dxf.height == pytest.approx(title.height)
    assert entity.dxf.insert.x == pytest.approx(title.at[0])
    assert entity.dxf.insert.y == pytest.approx(sheet.height - title.at[1])


def test_a_subscript_is_its_own_smaller_text_after_its_base() -> None:
    fs = metrics().font_size(5.0)
    t = TextItem((50.0, 40.0), (Run("V"), Run("B3", "sub")), 5.0, fs, 0.0, "label")
    sheet = Sheet(210.0, 297.0, "A4", "t", [t])
    base, sub = _read(to_dxf(sheet)).modelspace().query("TEXT")
    assert (base.dxf.text, sub.dxf.text) == ("V", "B3")
    assert sub.dxf.height == pytest.approx(5.0 * 0.7)
    assert sub.dxf.insert.x == pytest.approx(50.0 + metrics().advance("V", fs))
    assert sub.dxf.insert.y < base.dxf.insert.y == pytest.approx(297.0 - 40.0)


def test_arcs_keep_their_side_and_sweep() -> None:
    """An arc turning either way on the paper comes back through the same middle point."""
    c, r = (100.0, 100.0), 20.0
    arcs = []
    for a0, sweep in ((0.3, 1.2), (0.3, -1.2), (2.5, 4.0), (-1.0, -4.5)):
        start = (c[0] + r * math.cos(a0), c[1] + r * math.sin(a0))
        end = (c[0] + r * math.cos(a0 + sweep), c[1] + r * math.sin(a0 + sweep))
        arcs.append(ArcItem(c, r, start, end, sweep, "construction"))
    sheet = Sheet(210.0, 297.0, "A4", "t", list(arcs))
    got = list(_read(to_dxf(sheet)).modelspace().query("ARC"))
    assert len(got) == len(arcs)
    for a, e in zip(arcs, got, strict=True):
        a0 = math.atan2(a.start[1] - c[1], a.start[0] - c[0])
        mid = (
            c[0] + r * math.cos(a0 + a.sweep / 2),
            297.0 - (c[1] + r * math.sin(a0 + a.sweep / 2)),
        )
        span = (e.dxf.end_angle - e.dxf.start_angle) % 360.0
        assert span == pytest.approx(math.degrees(abs(a.sweep)))
        mid_angle = math.radians(e.dxf.start_angle + span / 2)
        centre = e.dxf.center
        assert (centre.x + r * math.cos(mid_angle), centre.y + r * math.sin(mid_angle)) == (
            pytest.approx(mid)
        )


def test_dash_patterns_are_the_ones_the_svg_draws() -> None:
    line = Polyline(((20.0, 20.0), (120.0, 20.0)), "centre", dash=fit_open("dashdot", 100.0))
    circle = CircleItem((60.0, 80.0), 30.0, "centre", dash=fit_closed("dashdot", 2 * math.pi * 30))
    short = Polyline(((20.0, 40.0), (24.0, 40.0)), "centre", dash=fit_open("dashdot", 4.0))
    assert short.dash is None and line.dash and circle.dash
    doc = _read(to_dxf(Sheet(210.0, 297.0, "A4", "t", [line, circle, short])))
    lw, cw, sw = doc.modelspace().query("LINE CIRCLE")
    assert sw.dxf.linetype == "Continuous"  # drawn solid, as in the SVG

    def pattern(entity: ezdxf.entities.DXFGraphic) -> list[float]:
        tags = doc.linetypes.get(entity.dxf.linetype).pattern_tags.tags
        return [float(t.value) for t in tags if t.code == 49]

    d, g, dot = line.dash.array[0], line.dash.array[1], line.dash.array[2]
    assert pattern(lw) == pytest.approx([d, -g, dot, -g], abs=1e-3)
    # n dashes and n − 1 gaps fill the line exactly: it starts and ends with a dash
    n = round((100.0 + 2 * g + dot) / (d + 2 * g + dot))
    assert n * d + (n - 1) * (2 * g + dot) == pytest.approx(100.0)
    # the circle's pattern starts in the middle of its dot, as the SVG's offset puts it
    p = pattern(cw)
    dd = circle.dash.array[0]
    assert p == pytest.approx([dot / 2, -g, dd, -g, dot / 2], abs=1e-3)
    period = sum(abs(v) for v in p)
    assert period * round(2 * math.pi * 30 / period) == pytest.approx(2 * math.pi * 30, abs=0.01)


def test_the_pattern_of_an_offset_dash_array_is_rotated_to_its_start() -> None:
    assert dxf._pattern(Dash((4.0, 1.5), offset=4.75)) == [-0.75, 4.0, -0.75]
    assert dxf._pattern(Dash((4.0, 1.5), offset=2.0)) == [2.0, -1.5, 2.0]
    assert dxf._pattern(Dash((4.0, 1.5))) == [4.0, -1.5]


def test_the_same_sheet_gives_the_same_bytes() -> None:
    sheet = _sheets("2013-3")[0][1]
    assert to_dxf(sheet) == to_dxf(sheet)


def _ink(png: bytes) -> np.ndarray:
    from PIL import Image

    grey = np.asarray(Image.open(io.BytesIO(png)).convert("L"), dtype=np.float64)
    h, w = grey.shape
    cell = 10  # 5 mm at 50 dpi
    dark = (grey < 128.0)[: h // cell * cell, : w // cell * cell]
    return dark.reshape(h // cell, cell, w // cell, cell).mean(axis=(1, 3))


def _dxf_png(sheet: Sheet, dpi: int) -> bytes:
    """The DXF drawn by ezdxf's drawing add-on (its SVG backend), then rasterised by cairo."""
    import cairosvg
    from ezdxf.addons.drawing import Frontend, RenderContext, config, layout, svg
    from ezdxf.fonts import fonts

    fonts.font_manager.scan_folder(font_path().parent)  # the pinned osifont, as the SVG uses
    doc = _read(to_dxf(sheet))
    backend = svg.SVGBackend()
    cfg = config.Configuration(
        background_policy=config.BackgroundPolicy.WHITE,
        color_policy=config.ColorPolicy.COLOR,
        lineweight_scaling=1.0,
    )
    Frontend(RenderContext(doc), backend, config=cfg).draw_layout(doc.modelspace())
    page = layout.Page(sheet.width, sheet.height, layout.Units.mm, margins=layout.Margins.all(0))
    text = backend.get_string(page, settings=layout.Settings(fit_page=False, scale=1))
    return bytes(cairosvg.svg2png(bytestring=text.encode(), dpi=dpi, background_color="white"))


def _alike(got: np.ndarray, want: np.ndarray) -> bool:
    """Whether two ink maps show the same drawing: inked cells agree, ink correlates, and the
    total ink is within 15 % (the fonts' rasterisers differ a little)."""
    agree = float(((got > 0) == (want > 0)).mean())
    corr = float(np.corrcoef(got.ravel(), want.ravel())[0, 1])
    return agree > 0.95 and corr > 0.85 and abs(got.mean() / want.mean() - 1.0) < 0.15


def test_the_dxf_drawn_by_ezdxf_looks_like_the_svg() -> None:
    """Ink per 5 mm cell: the DXF as ezdxf's drawing add-on draws it against the SVG as cairo
    draws it."""
    sheet = _sheets("2013-6")[0][1]
    try:
        want = _ink(to_png(to_svg(sheet), dpi=50))
    except MissingDependency:
        pytest.skip("libcairo is missing")
    got = _ink(_dxf_png(sheet, 50))
    assert got.shape == want.shape  # the same paper at 1:1
    assert _alike(got, want)
    # the comparison sees a drawing upside down (y not flipped) or moved by 10 mm
    assert not _alike(got[::-1], want)
    assert not _alike(np.roll(got, 2, axis=1), want)


def test_build_writes_dxf_beside_the_svg(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["build", "2013-3", "--out", str(tmp_path), "--format", "svg,dxf"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out == [str(tmp_path / "2013-3.svg"), str(tmp_path / "2013-3.dxf")]
    doc = ezdxf.readfile(tmp_path / "2013-3.dxf")
    assert doc.modelspace().query("TEXT")


def test_dxf_needs_no_cairo(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from geomcad.render import files

    def no_cairo(*args: object) -> bytes:
        raise MissingDependency("no libcairo")

    monkeypatch.setattr(files, "sheet_pdf", no_cairo)
    sheets = [("", _sheets("2013-3")[0][1])]
    with pytest.raises(MissingDependency):
        write_sheets("p", sheets, tmp_path, ["pdf", "dxf", "svg"])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.dxf", "p.svg"]


def test_build_without_cairo_still_writes_the_svg_and_the_dxf(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    from geomcad.render import files

    def no_cairo(*args: object) -> bytes:
        raise MissingDependency("PDF and PNG output need the cairo library")

    monkeypatch.setattr(files, "sheet_pdf", no_cairo)
    code = main(["build", "2013-3", "--out", str(tmp_path), "--format", "pdf,dxf"])
    out, err = capsys.readouterr()
    assert code == 2
    assert out.splitlines() == [str(tmp_path / "2013-3.svg"), str(tmp_path / "2013-3.dxf")]
    assert err.startswith("error: ") and "SVG and DXF files" in err and len(err.splitlines()) == 1


def test_a_dashed_polyline_runs_its_pattern_across_its_vertices() -> None:
    pts = ((20.0, 20.0), (60.0, 20.0), (60.0, 55.0))
    locus = Polyline(pts, "locus", dash=fit_open("dashed", 75.0))
    # a solid role's line that the sheet dashes all the same is drawn dashed too
    odd = Polyline(((20.0, 80.0), (95.0, 80.0)), "construction", dash=fit_open("dashed", 75.0))
    doc = _read(to_dxf(Sheet(210.0, 297.0, "A4", "t", [locus, odd])))
    pl = doc.modelspace().query("LWPOLYLINE")[1]
    assert pl.dxf.flags & ezdxf.const.LWPOLYLINE_PLINEGEN
    line = doc.modelspace().query("LINE")[0]
    assert pl.dxf.linetype == line.dxf.linetype
    assert pl.dxf.linetype.startswith("GOST_DASHED_")
    assert doc.layers.get("construction").dxf.linetype == "Continuous"


def test_a_linkage_file_builds_as_dxf(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    example = Path(__file__).resolve().parents[1] / "examples" / "slider-crank.toml"
    assert main(["build", str(example), "--out", str(tmp_path), "--format", "dxf"]) == 0
    paths = [Path(line) for line in capsys.readouterr().out.splitlines()]
    assert paths and all(p.suffix == ".dxf" for p in paths)
    doc = ezdxf.readfile(paths[0])  # the kinematic sheet (the force sheet follows)
    assert not doc.audit().has_errors
    assert tuple(doc.header["$EXTMAX"])[:2] == (841.0, 594.0)  # A1
    assert {"link", "frame", "title"} <= {layer.dxf.name for layer in doc.layers}


def test_black_like_the_svg_unless_in_colour() -> None:
    sheet = _sheets("2013-6")[0][1]
    black, coloured = _read(to_dxf(sheet)), _read(to_dxf(sheet, colour=True))
    for layer in black.layers:
        assert layer.dxf.color in (7, 8) and not layer.has_dxf_attrib("true_color")
    assert coloured.layers.get("construction").dxf.true_color == 0x1F4E9C
    assert coloured.layers.get("result").dxf.true_color == 0xB01C1C
    # a joint's disc is paper white in both: it hides the links under it
    for doc in (black, coloured):
        discs = [h for h in doc.modelspace().query("HATCH") if h.dxf.layer == "joint"]
        assert discs and all(h.dxf.true_color == 0xFFFFFF for h in discs)


def test_turned_texts_stay_turned() -> None:
    """графа 26 (turned 180°) and a dimension's text along its slanted line (GOST 2.307) keep
    their angle in the DXF, each run placed along the turned baseline."""
    _, sheet = _sheets("2013-3")[0]
    turned = [t for t in sheet.texts() if t.angle]
    assert any(t.angle == 180.0 for t in turned) and any(t.angle % 90.0 for t in turned)
    doc = _read(to_dxf(sheet))
    rotations = Counter(round(e.dxf.rotation % 360.0, 6) for e in doc.modelspace().query("TEXT"))
    for t in turned:
        assert rotations[round(t.angle % 360.0, 6)] >= 1
    # the runs of the designation read right to left on the paper (turned 180°)
    des = next(t for t in turned if t.angle == 180.0)
    xs = [
        e.dxf.insert.x
        for e in doc.modelspace().query("TEXT")
        if round(e.dxf.rotation % 360.0) == 180 and e.dxf.text in {r.text for r in des.runs}
    ]
    assert xs and max(xs) <= des.at[0] + 1e-6

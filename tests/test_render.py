"""The render layer: SVG structure and byte stability, PDF/PNG through cairosvg, the pinned font in
both renderers, and the atomic file writer."""

from __future__ import annotations

import io
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from geomcad.errors import GeomcadError, MissingDependency, ParameterError
from geomcad.render import FORMATS, raster, svg, to_pdf, to_png, to_svg, write_sheets
from geomcad.render.pdf import sheet_pdf
from geomcad.sheet.model import ArcItem, CircleItem, Polyline, Sheet, TextItem
from geomcad.sheet.style import MAIN_LINE, STYLES, circle_length, fit_closed, style
from geomcad.sheet.text import SUB_DROP, font_path, metrics, parse, run_size, width

SVG_NS = "{http://www.w3.org/2000/svg}"
INK_NS = "{http://www.inkscape.org/namespaces/inkscape}"
MM_PER_PT = 25.4 / 72.0
LABEL = "V_{B3B2} План скоростей"


def label(markup: str, at: tuple[float, float], cap: float = 5.0, tid: str = "") -> TextItem:
    runs = parse(markup)
    fs = metrics().font_size(cap)
    return TextItem(at, runs, cap, fs, width(runs, fs), "label", id=tid)


def sample_sheet() -> Sheet:
    s = Sheet(width=420, height=297, format="A3", title="t")
    s.add(Polyline(((10.0, 10.0), (100.0, 10.0), (100.0, 50.0)), "link"))
    s.add(label(LABEL, (50.0, 150.0), tid="label V_B3B2"))
    s.add(Polyline(((110.0, 10.0), (120.0, 12.0), (110.0, 14.0)), "vector", closed=True, fill=True))
    s.add(CircleItem((200.0, 100.0), 30.0, "centre", dash=fit_closed("dashdot", circle_length(30))))
    s.add(ArcItem((200.0, 200.0), 20.0, (220.0, 200.0), (200.0, 220.0), math.pi / 2, "link"))
    s.add(label("O_1 μ_V = 0,02 (м/с)/мм", (50.0, 170.0), cap=3.5, tid="label V_B3B2"))
    s.add(CircleItem((100.0, 50.0), 1.5, "joint", fill=True))
    return s


def parse_svg(text: str) -> ET.Element:
    return ET.fromstring(text.encode("utf-8"))


# --- SVG -------------------------------------------------------------------------------------


def test_svg_is_byte_stable() -> None:
    a = to_svg(sample_sheet())
    b = to_svg(sample_sheet())
    assert a == b
    assert "-0," not in a and '"-0"' not in a and " -0 " not in a


def test_svg_root_is_in_paper_millimetres() -> None:
    root = parse_svg(to_svg(sample_sheet()))
    assert root.tag == f"{SVG_NS}svg"
    assert root.get("width") == "420mm"
    assert root.get("height") == "297mm"
    assert root.get("viewBox") == "0 0 420 297"


def test_every_inner_length_is_a_plain_number() -> None:
    text = to_svg(sample_sheet())
    assert text.count('"420mm"') == 1 and text.count('"297mm"') == 1
    body = text.replace('width="420mm"', "").replace('height="297mm"', "")
    values = re.findall(r'="([^"]*)"', body)
    assert len(values) > 40
    for v in values:
        assert not re.search(r"\d\s*(mm|%|px|pt|cm|in|em)\b", v), v
    assert "%" not in body


def test_numbers_are_fixed_decimals_and_never_negative_zero() -> None:
    assert svg.num(1.0) == "1"
    assert svg.num(-0.0001) == "0"
    assert svg.num(2.5) == "2.5"
    assert svg.num(1 / 3) == "0.333"
    assert svg.num(-12.34567) == "-12.346"
    with pytest.raises(ValueError, match="non-finite"):
        svg.num(math.nan)


def test_one_group_per_role_in_styles_order_with_the_role_style() -> None:
    sheet = sample_sheet()
    root = parse_svg(to_svg(sheet))
    groups = root.findall(f"{SVG_NS}g")
    roles = [g.get(f"{INK_NS}label") for g in groups]
    used = {i.role for i in sheet.items}
    assert roles == [r for r in STYLES if r in used]
    assert roles == ["centre", "vector", "link", "joint", "label"]
    s = MAIN_LINE["A3"]
    for g in groups:
        role = g.get(f"{INK_NS}label")
        assert role is not None
        st = style(role)
        assert g.get("id") == f"layer-{role}"
        assert g.get(f"{INK_NS}groupmode") == "layer"
        assert g.get("fill") == "none"
        if st.weight > 0:
            assert g.get("stroke") == st.stroke
            assert float(g.get("stroke-width", "nan")) == pytest.approx(st.weight * s, abs=5e-4)
            assert g.get("stroke-linecap") == "round"
            assert g.get("stroke-linejoin") == "round"
        else:
            assert g.get("stroke") == "none"
    link = groups[roles.index("link")]
    # items keep the sheet's order inside their layer
    assert [c.tag.removeprefix(SVG_NS) for c in link] == ["polyline", "path"]
    assert link.get("stroke-width") == "0.7"


def test_unknown_format_uses_default_main_line() -> None:
    sheet = Sheet(width=100, height=50, format="B5", title="")
    sheet.add(Polyline(((0.0, 0.0), (10.0, 0.0)), "link"))
    root = parse_svg(to_svg(sheet))
    g = root.find(f"{SVG_NS}g")
    assert g is not None and g.get("stroke-width") == "0.7"
    assert root.get("width") == "100mm" and root.get("viewBox") == "0 0 100 50"


def test_shapes_fill_dash_and_arc_flags() -> None:
    root = parse_svg(to_svg(sample_sheet()))
    polygon = root.find(f".//{SVG_NS}polygon")
    assert polygon is not None
    assert polygon.get("fill") == "#000000"
    assert polygon.get("points") == "110,10 120,12 110,14"
    circle = root.find(f".//{SVG_NS}g[@id='layer-centre']/{SVG_NS}circle")
    assert circle is not None
    dash = fit_closed("dashdot", circle_length(30))
    assert dash is not None
    assert [float(v) for v in circle.get("stroke-dasharray", "").split()] == pytest.approx(
        dash.array, abs=5e-4
    )
    assert float(circle.get("stroke-dashoffset", "nan")) == pytest.approx(dash.offset, abs=5e-4)
    assert circle.get("fill") is None
    joint = root.find(f".//{SVG_NS}g[@id='layer-joint']/{SVG_NS}circle")
    assert joint is not None and joint.get("fill") == STYLES["joint"].fill
    path = root.find(f".//{SVG_NS}path")
    assert path is not None
    assert path.get("d") == "M220,200 A20,20 0 0 1 200,220"


def test_arc_sweep_direction_and_large_arcs() -> None:
    ccw = ArcItem((0.0, 0.0), 10.0, (10.0, 0.0), (0.0, -10.0), -math.pi / 2, "link")
    assert svg._arc_path(ccw) == "M10,0 A10,10 0 0 0 0,-10"
    # three quarters clockwise: two halves through the midpoint (at 135° in y-down paper terms)
    big = ArcItem((0.0, 0.0), 10.0, (10.0, 0.0), (0.0, -10.0), 1.5 * math.pi, "link")
    d = svg._arc_path(big)
    assert d == "M10,0 A10,10 0 0 1 -7.071,7.071 A10,10 0 0 1 0,-10"
    full = ArcItem((0.0, 0.0), 10.0, (10.0, 0.0), (10.0, 0.0), 2 * math.pi, "link")
    assert svg._arc_path(full) == "M10,0 A10,10 0 0 1 -10,0 A10,10 0 0 1 10,0"


def test_tspans_have_absolute_positions_from_the_font_metrics() -> None:
    sheet = Sheet(width=420, height=297, format="A3", title="t")
    item = label(LABEL, (50.0, 150.0))
    sheet.add(item)
    root = parse_svg(to_svg(sheet))
    text = root.find(f".//{SVG_NS}text")
    assert text is not None
    assert text.get("font-family") == "osifont"
    assert text.get("{http://www.w3.org/XML/1998/namespace}space") == "preserve"
    assert text.get("stroke") == "none"
    assert text.get("text-anchor") in (None, "start")
    spans = list(text)
    assert (
        [s.text for s in spans] == [r.text for r in item.runs] == ["V", "B3B2", " План скоростей"]
    )
    m = metrics()
    x = 50.0
    for span, run in zip(spans, item.runs, strict=True):
        size = run_size(item.font_size, run.shift)
        assert float(span.get("x", "nan")) == pytest.approx(x, abs=5e-4)
        y = 150.0 + (SUB_DROP * item.font_size if run.shift == "sub" else 0.0)
        assert float(span.get("y", "nan")) == pytest.approx(y, abs=5e-4)
        assert float(span.get("font-size", "nan")) == pytest.approx(size, abs=5e-4)
        x += m.advance(run.text, size)
    assert x - 50.0 == pytest.approx(item.width)
    # no whitespace between tspans (pretty printing would insert visible spaces)
    assert "</tspan><tspan" in to_svg(sheet)


def test_text_ids_are_valid_and_unique() -> None:
    root = parse_svg(to_svg(sample_sheet()))
    ids = [t.get("id") for t in root.iter(f"{SVG_NS}text")]
    assert ids == ["label_V_B3B2", "label_V_B3B2-2"]
    assert svg.xml_id("1 План") == "t-1_План"
    assert svg.xml_id("a/b:c") == "a_b_c"
    assert svg.xml_id("") == "t-"
    all_ids = [e.get("id") for e in root.iter() if e.get("id")]
    assert len(all_ids) == len(set(all_ids))


def test_result_label_takes_the_role_colour_without_outline() -> None:
    sheet = Sheet(width=100, height=100, format="A4", title="")
    runs = parse("B_0")
    fs = metrics().font_size(3.5)
    sheet.add(TextItem((5.0, 5.0), runs, 3.5, fs, width(runs, fs), "result"))
    text = parse_svg(to_svg(sheet, colour=True)).find(f".//{SVG_NS}text")
    assert text is not None
    assert text.get("fill") == STYLES["result"].fill
    assert text.get("stroke") == "none"


def test_unknown_role_is_refused() -> None:
    sheet = Sheet(width=100, height=100, format="A4", title="")
    sheet.add(Polyline(((0.0, 0.0), (1.0, 1.0)), "nonsense"))
    with pytest.raises(KeyError, match="nonsense"):
        to_svg(sheet)


# --- PDF and PNG -----------------------------------------------------------------------------


def text_sheet() -> Sheet:
    sheet = Sheet(width=420, height=297, format="A3", title="t")
    sheet.add(label(LABEL, (40.0, 100.0), cap=10.0))
    sheet.add(label("Пров. Т.контр. № 5 ⌀20 ±0,1", (40.0, 160.0), cap=7.0))
    return sheet


def _svg_pdf(sheet: Sheet) -> bytes:
    return to_pdf(to_svg(sheet))


#: The two ways to a PDF: the SVG through cairosvg, and the sheet straight into cairo.
PDF_WAYS = pytest.mark.parametrize("pdf_of", [_svg_pdf, sheet_pdf], ids=["cairosvg", "direct"])


@PDF_WAYS
def test_pdf_page_size_text_and_embedded_font(pdf_of: Callable[[Sheet], bytes]) -> None:
    from pypdf import PdfReader
    from pypdf.generic import DictionaryObject

    pdf = pdf_of(text_sheet())
    reader = PdfReader(io.BytesIO(pdf))
    assert len(reader.pages) == 1
    page = reader.pages[0]
    assert float(page.mediabox.width) == pytest.approx(420 / MM_PER_PT, abs=0.01)
    assert float(page.mediabox.height) == pytest.approx(297 / MM_PER_PT, abs=0.01)
    assert float(page.mediabox.width) == pytest.approx(1190.55, abs=0.01)
    assert float(page.mediabox.height) == pytest.approx(841.89, abs=0.01)
    text = page.extract_text()
    for word in ("План", "скоростей", "Пров", "контр"):
        assert word in text
    resources = page["/Resources"].get_object()
    assert isinstance(resources, DictionaryObject)
    fonts = resources["/Font"].get_object()
    assert isinstance(fonts, DictionaryObject)
    names = []
    for ref in fonts.values():
        font = ref.get_object()
        assert isinstance(font, DictionaryObject)
        names.append(str(font["/BaseFont"]))
    assert names and all("osifont" in n.lower() for n in names), names


@PDF_WAYS
def test_pdf_is_byte_stable_and_still_valid(pdf_of: Callable[[Sheet], bytes]) -> None:
    """cairo stamps the time of writing (to the second); to_pdf pins it, so the same sheet
    written a second later gives the same bytes."""
    import time

    from pypdf import PdfReader

    sheet = text_sheet()
    first = pdf_of(sheet)
    time.sleep(1.1)
    second = pdf_of(sheet)
    assert first == second
    assert b"/CreationDate (D:19700101000000Z)" in first
    reader = PdfReader(io.BytesIO(first), strict=True)
    assert "План" in reader.pages[0].extract_text()


def test_png_decodes_at_the_expected_size() -> None:
    from PIL import Image

    png = to_png(to_svg(sample_sheet()), dpi=100)
    img = Image.open(io.BytesIO(png))
    assert img.format == "PNG"
    assert img.size == (round(420 / 25.4 * 100), round(297 / 25.4 * 100))
    gray = np.asarray(img.convert("L"))
    assert gray.min() < 64 and gray.max() == 255  # ink on a white page


@pytest.mark.parametrize("dpi", [100, 150])
def test_png_records_its_resolution_so_it_prints_at_true_size(dpi: int) -> None:
    from PIL import Image

    png = to_png(to_svg(sample_sheet()), dpi=dpi)
    img = Image.open(io.BytesIO(png))
    img.load()  # reads every chunk: a wrong CRC would raise
    x_dpi, y_dpi = img.info["dpi"]
    assert x_dpi == pytest.approx(dpi, abs=0.02) and y_dpi == pytest.approx(dpi, abs=0.02)
    width_mm, height_mm = (n / x_dpi * 25.4 for n in img.size)
    assert width_mm == pytest.approx(420.0, abs=0.2) and height_mm == pytest.approx(297.0, abs=0.2)
    # splicing again replaces the chunk instead of adding a second one
    again = raster.with_resolution(png, 300)
    assert again.count(b"pHYs") == 1 and len(again) == len(png)
    assert Image.open(io.BytesIO(again)).info["dpi"][0] == pytest.approx(300, abs=0.02)
    with pytest.raises(ValueError, match="not a PNG"):
        raster.with_resolution(b"GIF89a", 150)


def test_fontconfig_file_finds_the_shipped_font() -> None:
    if shutil.which("fc-match") is None:
        pytest.skip("fc-match (fontconfig) is not installed")
    conf = raster.fonts_conf()
    assert conf.is_file()
    env = {**os.environ, "FONTCONFIG_FILE": str(conf)}
    out = subprocess.run(
        ["fc-match", "-f", "%{file}", "osifont"],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    assert Path(out.stdout).resolve() == (conf.parent / "osifont.ttf").resolve()


def _rsvg(svg_text: str, tmp_path: Path, dpi: int) -> np.ndarray:
    from PIL import Image

    src = tmp_path / "in.svg"
    src.write_text(svg_text, encoding="utf-8")
    dst = tmp_path / "rsvg.png"
    env = {**os.environ, "FONTCONFIG_FILE": str(raster.fonts_conf())}
    subprocess.run(
        ["rsvg-convert", "-d", str(dpi), "-p", str(dpi), "-b", "white", "-o", str(dst), str(src)],
        env=env,
        check=True,
    )
    return np.asarray(Image.open(dst).convert("L"), dtype=float)


def _cairo(svg_text: str, dpi: int) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(to_png(svg_text, dpi=dpi))).convert("L"), dtype=float)


def _ink_box(img: np.ndarray) -> tuple[int, int, int, int]:
    ys, xs = np.nonzero(img < 128)
    assert len(xs) > 0, "no ink"
    return int(xs.min()), int(ys.min()), int(xs.max()), int(ys.max())


@pytest.mark.skipif(shutil.which("rsvg-convert") is None, reason="rsvg-convert is not installed")
@pytest.mark.parametrize("make", [sample_sheet, text_sheet], ids=["mixed", "text"])
def test_cairosvg_and_rsvg_agree(make: Callable[[], Sheet], tmp_path: Path) -> None:
    dpi = 100
    text = to_svg(make())
    a = _cairo(text, dpi)
    b = _rsvg(text, tmp_path, dpi)
    # cairo rounds the page to whole pixels, rsvg rounds up: compare the common area
    assert abs(a.shape[0] - b.shape[0]) <= 1 and abs(a.shape[1] - b.shape[1]) <= 1
    h, w = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
    a, b = a[:h, :w], b[:h, :w]
    assert float(np.mean(np.abs(a - b))) < 1.0  # grey levels out of 255, page mean
    px_mm = 25.4 / dpi
    box_a, box_b = _ink_box(a), _ink_box(b)
    # a one-pixel edge at 100 dpi is 0.254 mm; allow 0.2 mm plus antialiasing's pixel
    tol_px = 0.2 / px_mm + 1
    for ea, eb in zip(box_a, box_b, strict=True):
        assert abs(ea - eb) <= tol_px, (box_a, box_b)


def _pdf_raster(pdf: bytes, tmp_path: Path, name: str, dpi: int) -> np.ndarray:
    from PIL import Image

    src = tmp_path / f"{name}.pdf"
    src.write_bytes(pdf)
    subprocess.run(
        ["pdftoppm", "-r", str(dpi), "-gray", "-singlefile", str(src), str(tmp_path / name)],
        check=True,
    )
    return np.asarray(Image.open(tmp_path / f"{name}.pgm").convert("L"), dtype=float)


def _kinematic_sheet() -> Sheet:
    import geomcad

    return geomcad.solve("2013-3").sheets()[0][1]


@pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm is not installed")
@pytest.mark.parametrize(
    "make", [sample_sheet, text_sheet, _kinematic_sheet], ids=["mixed", "text", "2013-3"]
)
def test_direct_pdf_draws_what_the_svg_draws(make: Callable[[], Sheet], tmp_path: Path) -> None:
    """The sheet written straight into cairo and its SVG through cairosvg: the same ink, the
    same places (rasterised by poppler at 100 dpi), in colour and in black."""
    dpi = 100
    for colour in (False, True):
        sheet = make()
        a = _pdf_raster(to_pdf(to_svg(sheet, colour)), tmp_path, f"svg{colour:d}", dpi)
        b = _pdf_raster(sheet_pdf(sheet, colour), tmp_path, f"direct{colour:d}", dpi)
        assert a.shape == b.shape
        assert float(np.mean(np.abs(a - b))) < 0.5  # grey levels out of 255, page mean
        assert abs(float(np.sum(255.0 - a)) / float(np.sum(255.0 - b)) - 1.0) < 0.02  # ink
        tol_px = 0.2 / (25.4 / dpi) + 1
        for ea, eb in zip(_ink_box(a), _ink_box(b), strict=True):
            assert abs(ea - eb) <= tol_px


def _glyph_ink_box(text: str, at: tuple[float, float], font_size: float) -> tuple[float, ...]:
    """The ink box (mm) of ``text`` set in the shipped font: (left, top, right, bottom)."""
    from fontTools.ttLib import TTFont

    with TTFont(str(font_path())) as f:
        glyf, cmap, upm = f["glyf"], f.getBestCmap(), f["head"].unitsPerEm
        k = font_size / upm
        x, boxes = at[0], []
        for ch in text:
            g = glyf[cmap[ord(ch)]]
            if g.numberOfContours:
                boxes.append(
                    (x + g.xMin * k, at[1] - g.yMax * k, x + g.xMax * k, at[1] - g.yMin * k)
                )
            x += metrics().advance(ch, font_size)
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


@pytest.mark.skipif(shutil.which("rsvg-convert") is None, reason="rsvg-convert is not installed")
def test_text_ink_in_both_renderers_is_where_the_shipped_font_puts_it(tmp_path: Path) -> None:
    """Both renderers set a text-only sheet in osifont, where the metrics placed it (0.2 mm).

    Another font (a fallback) would move the ink's edges by far more than that.
    """
    dpi = 200
    px_mm = 25.4 / dpi
    sheet = Sheet(width=120, height=40, format="A4", title="")
    item = label("НЕ ПЛАН", (10.0, 25.0), cap=10.0)
    sheet.add(item)
    text = to_svg(sheet)
    expected = _glyph_ink_box(item.text, item.at, item.font_size)
    boxes = []
    for img in (_cairo(text, dpi), _rsvg(text, tmp_path, dpi)):
        x0, y0, x1, y1 = _ink_box(img)
        box = (x0 * px_mm, y0 * px_mm, (x1 + 1) * px_mm, (y1 + 1) * px_mm)
        boxes.append(box)
        for got, want in zip(box, expected, strict=True):
            assert got == pytest.approx(want, abs=0.2 + px_mm), (box, expected)
    for a, b in zip(*boxes, strict=True):
        assert a == pytest.approx(b, abs=0.2), boxes


# --- files -----------------------------------------------------------------------------------


def test_write_sheets_writes_all_formats(tmp_path: Path) -> None:
    out = tmp_path / "new" / "dir"
    sheets = [("", sample_sheet()), ("plan", text_sheet())]
    paths = write_sheets("2013-6", sheets, out)
    names = [p.name for p in paths]
    assert names == [
        "2013-6.svg",
        "2013-6-plan.svg",
        "2013-6.pdf",
        "2013-6-plan.pdf",
        "2013-6.png",
        "2013-6-plan.png",
    ]
    assert sorted(p.name for p in out.iterdir()) == sorted(names)
    assert (out / "2013-6.svg").read_text(encoding="utf-8") == to_svg(sample_sheet())
    assert (out / "2013-6.pdf").read_bytes().startswith(b"%PDF")
    assert (out / "2013-6-plan.png").read_bytes().startswith(b"\x89PNG")
    assert FORMATS == ("svg", "pdf", "png", "dxf")


def test_write_sheets_svg_only_needs_no_cairo(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def boom() -> None:
        raise AssertionError("cairosvg must not be imported for SVG output")

    monkeypatch.setattr(raster, "_cairosvg", boom)
    paths = write_sheets("p", [("", sample_sheet())], tmp_path, formats=["svg"])
    assert paths == [tmp_path / "p.svg"]


def test_failure_mid_write_leaves_no_partial_or_temp_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "p.pdf").write_bytes(b"old pdf")
    calls = {"n": 0}
    real_replace = os.replace

    def flaky_replace(src: str | os.PathLike[str], dst: str | os.PathLike[str]) -> None:
        calls["n"] += 1
        if calls["n"] == 3:  # the first PDF: after both SVGs
            raise OSError("disk full")
        real_replace(src, dst)

    monkeypatch.setattr("geomcad.render.files.os.replace", flaky_replace)
    sheets = [("", sample_sheet()), ("b", text_sheet())]
    with pytest.raises(OSError, match="disk full"):
        write_sheets("p", sheets, tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p-b.svg", "p.pdf", "p.svg"]
    assert (tmp_path / "p.pdf").read_bytes() == b"old pdf"


def test_failure_while_writing_data_removes_the_temp_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def bad_fsync(fd: int) -> None:
        raise OSError("I/O error")

    monkeypatch.setattr("geomcad.render.files.os.fsync", bad_fsync)
    with pytest.raises(OSError, match="I/O error"):
        write_sheets("p", [("", sample_sheet())], tmp_path, formats=["svg"])
    assert list(tmp_path.iterdir()) == []


def test_a_sheet_that_cannot_be_drawn_writes_nothing(tmp_path: Path) -> None:
    bad = Sheet(width=100, height=100, format="A4", title="")
    bad.add(Polyline(((0.0, math.inf), (1.0, 1.0)), "link"))
    with pytest.raises(ValueError, match="non-finite"):
        write_sheets("p", [("", sample_sheet()), ("bad", bad)], tmp_path)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("pid", "name", "param"),
    [
        ("../x", "", "id"),
        ("a/b", "", "id"),
        ("a\\b", "", "id"),
        ("..", "", "id"),
        ("", "", "id"),
        ("p", "../x", "sheet name"),
        ("p", "sub/plan", "sheet name"),
    ],
)
def test_names_that_leave_the_directory_are_refused(
    tmp_path: Path, pid: str, name: str, param: str
) -> None:
    out = tmp_path / "out"
    with pytest.raises(ParameterError) as info:
        write_sheets(pid, [(name, sample_sheet())], out, formats=["svg"])
    assert info.value.name == param
    assert isinstance(info.value, GeomcadError)
    assert not out.exists()


def test_duplicate_sheet_names_are_refused(tmp_path: Path) -> None:
    with pytest.raises(ParameterError, match="share"):
        write_sheets("p", [("a", sample_sheet()), ("a", sample_sheet())], tmp_path)


def test_unknown_format_names_the_option_and_the_choices(tmp_path: Path) -> None:
    with pytest.raises(ParameterError) as info:
        write_sheets("p", [("", sample_sheet())], tmp_path, formats=["svg", "eps"])
    msg = str(info.value)
    assert info.value.name == "--format"
    assert "'eps'" in msg and "svg, pdf, png, dxf" in msg
    assert list(tmp_path.iterdir()) == []


def test_missing_libcairo_is_one_line_and_svgs_are_still_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import builtins

    real_import = builtins.__import__

    def no_cairo(name: str, *args: object, **kwargs: object) -> object:
        if name == "cairosvg" or name.startswith("cairocffi"):
            raise OSError('no library called "cairo-2" was found')
        return real_import(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.delitem(__import__("sys").modules, "cairosvg", raising=False)
    monkeypatch.setattr(builtins, "__import__", no_cairo)
    sheets = [("", sample_sheet()), ("b", text_sheet())]
    with pytest.raises(MissingDependency) as info:
        write_sheets("p", sheets, tmp_path)
    msg = str(info.value)
    assert "\n" not in msg
    assert "apt-get install libcairo2" in msg
    assert isinstance(info.value.__cause__, OSError)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p-b.svg", "p.svg"]


def test_missing_cairosvg_package_is_missing_dependency(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(__import__("sys").modules, "cairosvg", None)  # import raises ImportError
    with pytest.raises(MissingDependency, match="libcairo2"):
        to_pdf(to_svg(sample_sheet()))


@pytest.mark.parametrize("dpi", [100, 150, 300])
def test_png_text_ends_where_its_metrics_say(dpi: int) -> None:
    """Unhinted advances (text-rendering="geometricPrecision"): a long 2.5 mm line on a PNG
    ends within 0.5 mm of its width from the font's metrics, at any resolution."""
    import io

    import numpy as np
    from PIL import Image

    from geomcad.render.raster import to_png
    from geomcad.sheet import TitleBlock, start

    d = start("A4", TitleBlock(title="t", designation="x"), landscape=False)
    line = "крестовина скользит по звеньям 3 и 5 под прямым углом: ω_5 = ω_3, длинная строка W"
    item = d.text(line, (25.0, 30.0), 2.5)
    png = to_png(to_svg(d.finish()), dpi=dpi)
    px = dpi / 25.4
    im = np.asarray(Image.open(io.BytesIO(png)).convert("L"))
    band = im[int(26 * px) : int(31 * px), : int(200 * px)]
    right = np.nonzero((band < 128).any(axis=0))[0].max() / px
    assert abs(right - (25.0 + item.width)) <= 0.5


def test_black_by_default() -> None:
    """ESKD has no colour: a default SVG paints in black (and paper white) only."""
    sheet = Sheet(width=100, height=100, format="A4", title="")
    sheet.add(Polyline(((5.0, 5.0), (50.0, 50.0)), "construction"))
    sheet.add(Polyline(((5.0, 5.0), (9.0, 5.0), (9.0, 9.0)), "result", closed=True, fill=True))
    svg = to_svg(sheet)
    assert "#1f4e9c" not in svg and "#b01c1c" not in svg
    assert "#1f4e9c" in to_svg(sheet, colour=True)


def test_cairo_ffi_modules_are_the_installed_cairocffis() -> None:
    """geomcad/render/_cairo_ffi*.py are what cffi generates from the installed cairocffi's
    declarations, with their SHA-256 (else: ``python scripts/cairo_ffi.py``). In a fresh
    process: here cairocffi may already run on them."""
    code = (
        "import sys\n"
        "from geomcad.render.raster import cairo_ffi_code\n"
        "sys.stdout.write('\\x00'.join(cairo_ffi_code()))\n"
    )
    from geomcad.render import _cairo_ffi

    if raster.cairo_ffi_sources() != _cairo_ffi.SOURCES:
        pytest.skip(
            "another cairocffi is installed: `python scripts/cairo_ffi.py` regenerates them"
        )
    out = subprocess.run(
        [sys.executable, "-c", code], check=True, capture_output=True, text=True
    ).stdout
    shipped = [
        (Path(raster.__file__).parent / f"{name.rsplit('.', 1)[1]}.py").read_text(encoding="utf-8")
        for name in raster.CAIRO_FFI
    ]
    assert out.split("\x00") == shipped
    assert f'SOURCES = "{raster.cairo_ffi_sources()}"' in shipped[0]


def test_a_pdf_through_the_generated_ffi_is_cairocffis_own() -> None:
    """cairocffi on the generated declarations (no C header parsed: pycparser never loads;
    with another cairocffi it parses its header as before) writes the same PDF bytes as
    cairocffi parsing its header itself (imported first, the generated modules are not used)."""
    code = (
        "import sys\n"
        "{first}"
        "from geomcad.render.pdf import sheet_pdf\n"
        "from geomcad.render.raster import cairo\n"
        "from geomcad.sheet import start\n"
        "from geomcad.sheet.frame import TitleBlock\n"
        "d = start('A4', TitleBlock('Лист', 'ТММ.01'))\n"
        "d.text('V_{B3B2}', (60.0, 80.0), 5.0)\n"
        "pdf = sheet_pdf(d.finish())\n"
        "generated = type(cairo().ffi).__module__ != 'cffi.api'\n"
        "print(generated, 'pycparser' in sys.modules, pdf.hex())\n"
    )
    runs = []
    for first in ("", "import cairocffi\n"):
        out = subprocess.run(
            [sys.executable, "-c", code.replace("{first}", first)],
            check=True,
            capture_output=True,
            text=True,
        ).stdout.split()
        runs.append(out)
    from geomcad.render import _cairo_ffi

    if raster.cairo_ffi_sources() == _cairo_ffi.SOURCES:
        assert runs[0][:2] == ["True", "False"]  # the generated declarations, no parser
    else:  # another cairocffi: it parses its own header, as without the modules
        assert runs[0][:2] == ["False", "True"]
    assert runs[1][:2] == ["False", "True"]  # cairocffi's own parse
    assert runs[0][2] == runs[1][2]

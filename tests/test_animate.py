"""``geomcad animate``: a self-contained SMIL animation of a mechanism over one crank turn, at
true scale, read back frame by frame."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import geomcad
from geomcad.cli import main
from geomcad.render.animate import to_animated_svg
from geomcad.sheet.motion import Frames, turn

NS = {"s": "http://www.w3.org/2000/svg"}
FRAMES = 36


def _frames(el: ET.Element, attr: str) -> list[str]:
    anim = el.find(f"s:animate[@attributeName='{attr}']", NS)
    assert anim is not None, f"{el.get('id')} has no animated {attr}"
    return anim.get("values", "").split(";")


def _vertices(values: str) -> list[tuple[float, float]]:
    return [(float(a), float(b)) for a, b in (p.split(",") for p in values.split())]


def _ratio(root: ET.Element) -> float:
    """The paper : nature ratio printed in the heading, e.g. (М 1:4) → 0.25."""
    text = " ".join("".join(t.itertext()) for t in root.iter(f"{{{NS['s']}}}text"))
    m = re.search(r"\(М (\d+(?:,\d+)?):(\d+(?:,\d+)?)\)", text)
    assert m, text
    a, b = (float(g.replace(",", ".")) for g in m.groups())
    return a / b


@pytest.fixture(scope="module")
def six_bar(tmp_path_factory: pytest.TempPathFactory) -> tuple[ET.Element, str]:
    out = tmp_path_factory.mktemp("anim")
    assert main(["animate", "2013-6", "--out", str(out), "--frames", str(FRAMES)]) == 0
    text = (out / "2013-6-animated.svg").read_text(encoding="utf-8")
    return ET.fromstring(text.encode("utf-8")), text


def test_the_animation_is_one_svg_with_a_frame_per_position(
    six_bar: tuple[ET.Element, str],
) -> None:
    root, text = six_bar
    assert root.tag == f"{{{NS['s']}}}svg"
    assert "<script" not in text and "href" not in text  # self-contained, no script
    w, h = (float(root.get(a, "").removesuffix("mm")) for a in ("width", "height"))
    assert root.get("viewBox") == f"0 0 {w:g} {h:g}"
    anims = root.findall(".//s:animate", NS)
    assert len(anims) > 10
    for a in anims:
        assert len(a.get("values", "").split(";")) == FRAMES
        assert a.get("calcMode") == "discrete" and a.get("repeatCount") == "indefinite"
        assert a.get("dur") == "6s"


def test_links_keep_their_true_length_in_every_frame(six_bar: tuple[ET.Element, str]) -> None:
    root, _ = six_bar
    r = geomcad.solve("2013-6").results
    mm_per_m = 1000.0 * _ratio(root)
    lengths = {"link-O1A": r["l1"], "link-AB": r["l2"], "link-O2B": 0.3, "link-BC": 0.3}
    for lid, length in lengths.items():
        el = root.find(f".//*[@id='{lid}']", NS)
        assert el is not None, lid
        for frame in _frames(el, "points"):
            (ax, ay), (bx, by) = _vertices(frame)
            assert math.hypot(bx - ax, by - ay) == pytest.approx(length * mm_per_m, abs=2e-3)
    # the crank turns once: A's angle about O1 covers the circle in equal steps
    crank = root.find(".//*[@id='link-O1A']", NS)
    assert crank is not None
    angles = [
        math.atan2(-(v[1][1] - v[0][1]), v[1][0] - v[0][0])
        for v in (_vertices(f) for f in _frames(crank, "points"))
    ]
    steps = np.diff(np.unwrap(angles))
    assert steps == pytest.approx(np.full(FRAMES - 1, 2 * math.pi / FRAMES), abs=1e-4)


def test_paths_and_the_velocity_plan_are_drawn(six_bar: tuple[ET.Element, str]) -> None:
    root, _ = six_bar
    path_c = root.find(".//*[@id='path-C']", NS)
    assert path_c is not None
    ys = {round(y, 3) for _, y in _vertices(path_c.get("points", ""))}
    assert len(ys) == 1  # C runs on its straight guide
    # pa = ω1·l1 / μ_V in every frame
    sol = geomcad.solve("2013-6")
    head = root.find(".//*[@id='plan-heading']", NS)
    assert head is not None
    m = re.search(r"= (\d+,?\d*) \(м/с\)/мм", "".join(head.itertext()))
    assert m is not None
    k_v = float(m.group(1).replace(",", "."))
    pa = root.find(".//*[@id='v-pa']", NS)
    assert pa is not None
    x1, y1 = float(pa.get("x1", "")), float(pa.get("y1", ""))
    for x2, y2 in zip(_frames(pa, "x2"), _frames(pa, "y2"), strict=True):
        v = math.hypot(float(x2) - x1, float(y2) - y1) * k_v
        assert v == pytest.approx(10.0 * sol.results["l1"], abs=k_v * 2e-3)
    for vid in ("v-pb", "v-pc", "v-ab", "v-bc"):
        assert root.find(f".//*[@id='{vid}']", NS) is not None


def test_the_slotted_link_mechanism_animates(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["animate", "kulisa-23110713", "--out", str(tmp_path), "--frames", "24"]) == 0
    assert capsys.readouterr().out == f"{tmp_path / 'kulisa-23110713-animated.svg'}\n"
    root = ET.parse(tmp_path / "kulisa-23110713-animated.svg").getroot()
    crank = root.find(".//*[@id='link-OA']", NS)
    assert crank is not None
    OA = geomcad.solve("kulisa-23110713").params["OA"]
    for frame in _frames(crank, "points"):
        (ax, ay), (bx, by) = _vertices(frame)
        assert math.hypot(bx - ax, by - ay) == pytest.approx(1000 * _ratio(root) * OA, abs=2e-3)
    # the slot stays vertical through the pin
    slot = root.find(".//*[@id='link-S1S2']", NS)
    assert slot is not None
    for f, g in zip(_frames(slot, "points"), _frames(crank, "points"), strict=True):
        (sx1, _), (sx2, _) = _vertices(f)
        assert sx1 == sx2 == _vertices(g)[1][0]


def _bad(capsys: pytest.CaptureFixture[str], *args: str) -> str:
    code = main(["animate", *args])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and len(err.splitlines()) == 1 and err.startswith("error: ")
    return err


def test_bad_input(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    err = _bad(capsys, "2013-3", "--out", str(tmp_path))
    assert "no crank mechanism" in err and "2013-6" in err and "kulisa-23110713" in err
    assert "--frames" in _bad(capsys, "2013-6", "--frames", "1", "--out", str(tmp_path))
    assert "--frames" in _bad(capsys, "2013-6", "--frames", "many", "--out", str(tmp_path))
    assert "K" in _bad(capsys, "2013-6", "--set", "K=0.5", "--out", str(tmp_path))
    assert list(tmp_path.iterdir()) == []


def test_frames_check_their_points() -> None:
    phi = turn(4)
    ring = np.column_stack([np.cos(phi), np.sin(phi)])
    still = np.zeros((4, 2))
    with pytest.raises(ValueError, match="no such point"):
        Frames("t", phi, {"O": still, "A": ring}, (("O", "B"),))
    with pytest.raises(ValueError, match="shape"):
        Frames("t", phi, {"O": still[:3], "A": ring}, (("O", "A"),))
    bad = ring.copy()
    bad[2, 0] = math.nan
    with pytest.raises(ValueError, match="finite"):
        Frames("t", phi, {"O": still, "A": bad}, (("O", "A"),))
    svg = to_animated_svg(Frames("t", phi, {"O": still, "A": ring}, (("O", "A"),), fixed=("O",)))
    assert svg == to_animated_svg(
        Frames("t", phi, {"O": still, "A": ring}, (("O", "A"),), fixed=("O",))
    )
    assert "План скоростей" not in svg  # no velocities, no plan

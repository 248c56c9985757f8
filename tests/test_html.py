"""The interactive page (geomcad.render.html): its numbers are the library's, it is one
self-contained file, and in a real browser (headless Chromium driven by Selenium) the slider
moves the mechanism and the plans and the table shows the values of ``solve`` at that angle.

The browser tests need Debian's ``chromium`` and ``chromium-driver`` and the ``selenium``
package (``sh scripts/setup.sh test`` installs them); where one is missing they are skipped with
the reason. ``GEOMCAD_SHOTS=DIR`` keeps their screenshots in DIR.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import time
import tomllib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import geomcad
from geomcad.cli import main
from geomcad.linkage import parse
from geomcad.linkage.plan_sweep import plan_points
from geomcad.linkage.solution import Solved, results, solve
from geomcad.linkage.sweep import sweep
from geomcad.render.html import Page, frame_count, linkage_page, page_of, to_html

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

#: A mechanism none of the examples has: a slotted link with an offset slide line, a point on
#: it, and a rod to a slider on an inclined guide, turning clockwise, numbered in 10 positions.
UNSEEN = """
title = "Кулисный механизм со смещённой кулисой"
[frame]
O = [0.0, 0.0]
C = [0.05, -0.28]
[drive]
pivot = "O"
joint = "A"
length = 0.09
omega = -6.0
positions = 10
output = "F"
[[group]]
kind = "RPR"
links = [2, 3]
slider = "A"
pivot = "C"
offset = 0.015
[[point]]
name = "E"
link = 3
from = "C"
toward = "A"
along = 0.45
[[group]]
kind = "RRP"
links = [4, 5]
joint = "F"
end = "E"
length = 0.2
guide = { through = [0.0, 0.16], angle = 10.0 }
assembly = "forward"
"""


def _linkage_files() -> list[Path]:
    out = []
    for f in sorted(EXAMPLES.glob("*.toml")):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        if "drive" in data and "synthesis" not in data:
            out.append(f)
    return out


LINKAGES = _linkage_files()


def _solved(text: str) -> Solved:
    return solve(parse(tomllib.loads(text)))


@pytest.fixture(scope="module")
def unseen_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("unseen") / "offset-slotted.toml"
    path.write_text(UNSEEN, encoding="utf-8")
    return path


def _texts(unseen: Path) -> list[tuple[str, str]]:
    return [(f.name, f.read_text(encoding="utf-8")) for f in [*LINKAGES, unseen]]


def test_the_examples_include_the_linkage_files() -> None:
    names = {f.name for f in LINKAGES}
    assert {"slider-crank.toml", "shaper.toml", "four-bar.toml"} <= names


# --- the numbers ----------------------------------------------------------------------------------


@pytest.mark.parametrize("name", [f.name for f in LINKAGES] + ["unseen"])
def test_plan_points_over_a_sweep_are_the_recorded_plans(name: str, unseen_file: Path) -> None:
    """Every point of both plans, at every numbered position, as the recorded construction
    draws it (same names, same values)."""
    path = unseen_file if name == "unseen" else EXAMPLES / name
    s = _solved(path.read_text(encoding="utf-8"))
    phis = np.array([P.phi for P in s.positions])
    vp, ap = plan_points(s.linkage, sweep(s.linkage, phis, order=2))
    for i, P in enumerate(s.positions):
        for plan, mine in ((P.vp, vp), (P.ap, ap)):
            size = max(q.norm for q in plan.points.values())
            for point, q in plan.points.items():
                assert point in mine, f"{name}: plan point {point} missing"
                got = mine[point][i]
                assert math.hypot(got[0] - q.x, got[1] - q.y) <= 1e-9 * size, (name, i, point)


def test_plan_points_differ_from_a_wrong_plan() -> None:
    """The comparison can fail: the plan of another mechanism's ω is not the recorded one."""
    s = _solved((EXAMPLES / "slider-crank.toml").read_text(encoding="utf-8"))
    P = s.positions[1]
    vp, _ = plan_points(s.linkage, sweep(s.linkage, np.array([P.phi + 0.1]), order=2))
    b = P.vp.points["b"]
    assert math.hypot(vp["b"][0][0] - b.x, vp["b"][0][1] - b.y) > 1e-3


def _table(page: Page, frame: int) -> dict[str, float]:
    return {s.key: float(s.values[frame]) for s in page.table}


@pytest.mark.parametrize("name", [f.name for f in LINKAGES])
def test_the_table_at_each_numbered_position_is_solve(name: str) -> None:
    data = tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))
    s = solve(parse(data))
    page = linkage_page(s)
    # results.positions lists the numbered positions unless the file names its own `phi`
    # (linkages.md, second round): the same file without `phi` gives the numbered ones
    data["drive"].pop("phi", None)
    res = results(solve(parse(data)))["positions"]
    assert len(page.stops) == len(s.drawn) == len(res)
    for (no, frame), row in zip(page.stops, res, strict=True):
        table = _table(page, frame)
        assert math.isclose(table["phi_deg"], row["phi_deg"], abs_tol=1e-9) or math.isclose(
            abs(table["phi_deg"] - row["phi_deg"]), 360.0, abs_tol=1e-9
        ), (name, no)
        checked = 0
        for key, value in table.items():
            if key in row:
                scale = max(abs(row[key]), 1.0)
                assert abs(value - row[key]) <= 1e-9 * scale, (name, no, key, value, row[key])
                checked += 1
        assert checked >= 4


def test_frames_are_a_multiple_of_the_positions() -> None:
    assert frame_count(12) == 360
    assert frame_count(8) == 360
    assert frame_count(7) % 7 == 0 and abs(frame_count(7) - 360) <= 3
    assert frame_count(500) == 500


# --- the document ---------------------------------------------------------------------------------

NETWORK = re.compile(r"""(?:src|href)\s*=\s*["'](?!data:|#)|url\((?!data:|#)|@import|<link\b""")


@pytest.mark.parametrize("name", [f.name for f in LINKAGES])
def test_the_page_is_self_contained_and_byte_stable(name: str) -> None:
    text = (EXAMPLES / name).read_text(encoding="utf-8")
    page = to_html(linkage_page(_solved(text)))
    assert page == to_html(linkage_page(_solved(text)))
    assert page.startswith("<!DOCTYPE html>")
    assert not NETWORK.search(page), NETWORK.search(page)
    assert "@font-face" in page and "font/ttf;base64," in page
    assert len(page.encode("utf-8")) < 3_000_000


def test_the_network_check_can_fail() -> None:
    assert NETWORK.search('<img src="https://example.org/a.png">')
    assert NETWORK.search("background: url(http://x/y.png)")
    assert not NETWORK.search('<img src="data:image/png;base64,AAAA">')


def test_a_problem_with_a_motion_gets_its_mechanism_and_velocity_plan() -> None:
    sol = geomcad.solve("2013-6")
    page = page_of(sol)
    assert [p.kind for p in page.plans] == ["v"]
    motion = sol.problem.motion
    assert motion is not None
    frames = motion(sol, page.motion.frames)
    for name, v in frames.velocities.items():
        row = next(s for s in page.table if s.key == f"V_{name}")
        assert np.allclose(row.values, np.hypot(v[:, 0], v[:, 1]))
    assert "<svg" in to_html(page)


def test_build_writes_the_page_with_the_sheets_as_tabs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    assert main(["build", str(EXAMPLES / "scotch-yoke.toml"), "--format", "html", "--out",
                 str(out)]) == 0  # fmt: skip
    written = capsys.readouterr().out.split()
    assert written == [str(out / "scotch-yoke.html")]
    page = (out / "scotch-yoke.html").read_text(encoding="utf-8")
    assert page.count('role="tabpanel"') >= 3  # the motion, a sheet, the data
    assert page.count("<svg") >= 6
    assert "positions = 8" in page  # the file's own text on the data tab
    assert not NETWORK.search(page)
    assert len(page.encode("utf-8")) < 3_000_000


@pytest.mark.parametrize("pid", ["2013-1", str(EXAMPLES / "gear-pair.toml")])
def test_html_of_a_problem_without_a_motion_is_refused(
    pid: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    assert main(["build", pid, "--format", "svg,html", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ")
    assert "no crank mechanism" in err and "Traceback" not in err
    assert not out.exists()


# --- in a real browser ----------------------------------------------------------------------------


def _browser_or_skip() -> Any:
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.options import Options
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        pytest.skip("selenium is not installed (sh scripts/setup.sh test installs it)")
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if binary is None or driver is None:
        pytest.skip(
            "headless Chromium is not installed: Debian's chromium and chromium-driver "
            "(sh scripts/setup.sh test installs them as root)"
        )
    opts = Options()
    opts.binary_location = binary
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1400,1000", "--lang=ru"):  # fmt: skip
        opts.add_argument(arg)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    try:  # the driver named, so that selenium downloads nothing
        return webdriver.Chrome(options=opts, service=Service(driver))
    except Exception as exc:  # a browser that cannot start here (no display libraries, …)
        pytest.skip(f"headless Chromium does not start: {str(exc).splitlines()[0]}")


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    drv = _browser_or_skip()
    try:
        yield drv
    finally:
        drv.quit()


def _errors(drv: Any) -> list[str]:
    return [e["message"] for e in drv.get_log("browser") if e["level"] == "SEVERE"]


def _state(drv: Any) -> dict[str, Any]:
    """What the page shows now: the frame, the links, the plans' vectors, the table."""
    return drv.execute_script(
        """
        const q = (s) => Array.from(document.querySelectorAll(s));
        const plans = q("svg.plan").map((svg) => ({
          k: Number(svg.dataset.k), pole: svg.dataset.pole.split(" ").map(Number),
          vectors: q("#" + svg.id + " .vec line").map((l) =>
            ["x1", "y1", "x2", "y2"].map((a) => Number(l.getAttribute(a)))),
          dots: Object.fromEntries(q("#" + svg.id + " circle[id]").map((c) =>
            [c.id.replace(/^p\\d+-d-/, ""), [Number(c.getAttribute("cx")),
                                               Number(c.getAttribute("cy"))]])),
        }));
        const mech = document.getElementById("mech");
        return {
          frame: Number(document.body.dataset.frame),
          phi: document.getElementById("phi").textContent,
          links: q("#mech .link").map((e) => e.getAttribute("points")),
          joints: Object.fromEntries(q("#mech circle.joint").map((c) =>
            [c.id.slice(4), [Number(c.getAttribute("cx")), Number(c.getAttribute("cy"))]])),
          k: Number(mech.dataset.k),
          plans,
          table: Object.fromEntries(q("#values tbody tr").map((r) =>
            [r.dataset.key, [Number(r.cells[1].dataset.value), r.cells[1].textContent]])),
        };
        """
    )


def _shot(drv: Any, tmp_path: Path, name: str) -> Path:
    folder = Path(os.environ.get("GEOMCAD_SHOTS", tmp_path))
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / name
    drv.save_screenshot(str(path))
    assert path.stat().st_size > 10_000  # a picture, not a blank
    return path


def _solve_at(text: str, phi_deg: float) -> dict[str, Any]:
    """``geomcad solve FILE --set drive.phi=[φ] --json``'s position, through the library."""
    data = tomllib.loads(text)
    data["drive"].pop("positions", None)
    data["drive"]["phi"] = [phi_deg]
    row: dict[str, Any] = results(solve(parse(data)))["positions"][0]
    return row


def _four_figures(x: float) -> str:
    """The page's way to write a value: 4 significant figures, a decimal comma, a true minus."""
    if x == 0.0:
        return "0"
    text = f"{float(f'{x:.4g}'):.12g}"
    if "e" in text:
        text = f"{x:.3e}"
    return text.replace(".", ",").replace("-", "\u2212")


def test_the_slider_turns_the_mechanism_and_the_plans_in_chromium(
    browser: Any, tmp_path: Path
) -> None:
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    text = (EXAMPLES / "sixbar-2013-6.toml").read_text(encoding="utf-8")
    s = _solved(text)
    page = tmp_path / "sixbar.html"
    page.write_text(to_html(linkage_page(s)), encoding="utf-8")
    browser.get(page.as_uri())
    before = _state(browser)
    assert before["frame"] == 0 and not _errors(browser)
    _shot(browser, tmp_path, "html-sixbar-0.png")

    slider = browser.find_element(By.ID, "frame")
    slider.send_keys(Keys.PAGE_UP, Keys.PAGE_UP, Keys.PAGE_UP, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    after = _state(browser)
    assert after["frame"] == 32
    assert after["links"] != before["links"]
    for p0, p1 in zip(before["plans"], after["plans"], strict=True):
        assert p0["vectors"] != p1["vectors"] and p0["k"] == p1["k"]  # one μ for the turn
    _shot(browser, tmp_path, "html-sixbar-32.png")

    # the values are solve's at the angle the page shows
    phi = after["table"]["phi_deg"][0]
    assert after["phi"] == _four_figures(phi)
    row = _solve_at(text, phi)
    lk = s.linkage
    checked = 0
    for key, (value, shown) in after["table"].items():
        if key in row and key != "phi_deg":
            assert math.isclose(value, row[key], rel_tol=1e-6, abs_tol=1e-9), key
            assert shown == _four_figures(value), key
            checked += 1
    assert checked >= 8
    # the mechanism drawn at μ_l: its joints where solve puts them (0.01 mm of the field)
    jo = after["joints"]
    pivot, B = lk.pivot, lk.output
    for axis, sign in ((0, 1.0), (1, -1.0)):
        drawn = sign * (jo[B][axis] - jo[pivot][axis]) * after["k"]
        exact = row[f"{'xy'[axis]}_{B}"] - (lk.frame[pivot].x, lk.frame[pivot].y)[axis]
        assert abs(drawn - exact) <= 0.011 * after["k"]
    # the velocity plan at μ_V: pole → b is V_B
    vplan = after["plans"][0]
    b = vplan["dots"][B.lower()]
    for axis, sign in ((0, 1.0), (1, -1.0)):
        drawn = sign * (b[axis] - vplan["pole"][axis]) * vplan["k"]
        assert abs(drawn - row[f"V_{B}_{'xy'[axis]}"]) <= 0.011 * vplan["k"]

    # the numbered positions are stops, play moves on, the sheets' tabs switch
    browser.find_element(By.CSS_SELECTOR, '.stop[data-frame="90"]').click()
    assert _state(browser)["frame"] == 90
    browser.find_element(By.TAG_NAME, "body").send_keys("]")
    assert _state(browser)["frame"] == 120
    browser.find_element(By.ID, "play").click()
    time.sleep(0.4)
    browser.find_element(By.ID, "play").click()
    assert _state(browser)["frame"] != 120
    browser.find_element(By.ID, "tab-data").click()
    assert not browser.find_element(By.ID, "panel-data").get_property("hidden")
    assert browser.find_element(By.ID, "panel-motion").get_property("hidden")
    assert not _errors(browser)


def test_every_linkage_file_turns_in_chromium(
    browser: Any, tmp_path: Path, unseen_file: Path
) -> None:
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    for name, text in _texts(unseen_file):
        path = tmp_path / f"{name}.html"
        path.write_text(to_html(linkage_page(_solved(text))), encoding="utf-8")
        browser.get(path.as_uri())
        before = _state(browser)
        browser.find_element(By.ID, "frame").send_keys(Keys.PAGE_UP, Keys.ARROW_RIGHT)
        after = _state(browser)
        assert after["frame"] == 11, name
        assert after["links"] != before["links"], name
        assert all(p0["vectors"] != p1["vectors"] for p0, p1 in
                   zip(before["plans"], after["plans"], strict=True)), name  # fmt: skip
        row = _solve_at(text, after["table"]["phi_deg"][0])
        for key, (value, _) in after["table"].items():
            if key in row and key != "phi_deg":
                assert math.isclose(value, row[key], rel_tol=1e-6, abs_tol=1e-9), (name, key)
        assert not _errors(browser), name
        if name == "offset-slotted.toml":
            _shot(browser, tmp_path, "html-unseen-11.png")


def test_the_page_speaks_the_language_being_drawn() -> None:
    from geomcad.sheet.lang import language

    s = _solved((EXAMPLES / "slider-crank.toml").read_text(encoding="utf-8"))
    with language("en"):
        en = to_html(linkage_page(s))
    with language("ru"):
        ru = to_html(linkage_page(s))
    assert '<html lang="en">' in en and "Velocity plan" in en and "μ<sub>V</sub> = 0." in en
    assert '<html lang="ru">' in ru and "План скоростей" in ru and "μ<sub>V</sub> = 0," in ru


def test_a_round_off_of_zero_is_written_0() -> None:
    """A value at most 1e-9 of its quantity's largest is 0 on the page (as on the sheet); the
    crank angle keeps 10 figures, the rest 7."""
    from geomcad.render.html import Series, _column

    row = Series("out_1", "v", "m/s", "", np.array([9.6e-17, 0.8617123456, -1.5]))
    assert _column(row) == [0.0, 0.8617123, -1.5]
    phi = Series("phi_deg", "φ_1", "°", "", np.array([242.7412345678912, 1e-17]))
    assert _column(phi) == [242.7412346, 1e-17]
    s = _solved((EXAMPLES / "sixbar-2013-6.toml").read_text(encoding="utf-8"))
    text = to_html(linkage_page(s))  # position 0: the slider at rest, v written 0
    assert '"key":"out_1","values":[0.0,' in text

"""The sheets' words come from one table per language (geomcad.sheet.lang), not drawing code."""

from __future__ import annotations

import ast
import json
import re
import tomllib
from pathlib import Path

import pytest

from geomcad.sheet.lang import LANGS, Words, current, language

ROOT = Path(__file__).resolve().parent.parent
CYRILLIC = re.compile("[\u0400-\u04ff]")
#: Drawing code: what draws a sheet. Its words belong in a strings/<lang>/*.toml table.
DRAWING_CODE = (
    sorted((ROOT / "geomcad" / "sheet").glob("*.py"))
    + sorted((ROOT / "geomcad" / "render").glob("*.py"))
    + sorted((ROOT / "constructions").glob("sheets_*.py"))
)
#: Files that still hold Russian literals, with how many; a count may only fall, and a file not
#: listed must hold none.
BASELINE = json.loads((Path(__file__).parent / "lang_baseline.json").read_text())


def russian_literals(path: Path) -> int:
    """How many string literals (docstrings aside) in ``path`` hold Cyrillic letters."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docs: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            first = node.body[0] if node.body else None
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                docs.add(id(first.value))
    return sum(
        1
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and id(node) not in docs
        and CYRILLIC.search(node.value)
    )


@pytest.mark.parametrize("path", DRAWING_CODE, ids=lambda p: p.name)
def test_no_new_russian_in_drawing_code(path: Path) -> None:
    rel = path.relative_to(ROOT).as_posix()
    n = russian_literals(path)
    allowed = BASELINE.get(rel, 0)
    assert n <= allowed, f"{rel}: {n} Russian literals (at most {allowed}); move them to a table"


def test_baseline_is_current() -> None:
    """Lower the baseline when a file is cleaned, so that it cannot grow back."""
    stale = {
        rel: (n, russian_literals(ROOT / rel))
        for rel, n in BASELINE.items()
        if russian_literals(ROOT / rel) < n
    }
    assert not stale, f"lower tests/lang_baseline.json: {stale}"


def _tables() -> dict[Path, dict[str, set[str]]]:
    roots = [ROOT / "geomcad" / "sheet" / "strings", ROOT / "constructions" / "strings"]
    out: dict[Path, dict[str, set[str]]] = {}
    for root in roots:
        for lang in LANGS:
            for f in sorted((root / lang).glob("*.toml")) if (root / lang).is_dir() else []:
                keys = set(tomllib.loads(f.read_text(encoding="utf-8")))
                out.setdefault(root / f.name, {})[lang] = keys
    return out


def test_every_language_has_the_same_keys() -> None:
    tables = _tables()
    assert tables
    for name, by_lang in tables.items():
        assert set(by_lang) == set(LANGS), f"{name}: tables for {sorted(by_lang)} only"
        ru = by_lang["ru"]
        for lang, keys in by_lang.items():
            assert keys == ru, f"{name} [{lang}]: missing {ru - keys}, extra {keys - ru}"


def test_english_tables_hold_no_russian() -> None:
    for name in _tables():
        f = name.parent / "en" / name.name
        assert not CYRILLIC.search(f.read_text(encoding="utf-8")), f


def test_words_follow_the_language_being_drawn() -> None:
    words = Words("geomcad.sheet", "frame")
    assert current() == "ru"
    assert words("sheet") == "Лист"
    with language("en"):
        assert current() == "en"
        assert words("sheet") == "Sheet"
        assert words("sheet", lang="ru") == "Лист"
    assert current() == "ru"
    with pytest.raises(LookupError, match="no key 'nonesuch'"):
        words("nonesuch")
    with pytest.raises(ValueError, match="not a language"), language("de"):
        pass


def test_per_language_keeps_one_result_per_object_and_language() -> None:
    """The arrangement cache: one call per object and language, by identity, freed with it."""
    import gc
    from dataclasses import dataclass

    from geomcad.sheet.lang import per_language

    @dataclass(frozen=True)
    class Model:
        x: int

    calls: list[tuple[int, str]] = []

    @per_language
    def arrange(m: Model) -> list[str]:
        from geomcad.sheet.lang import current

        calls.append((id(m), current()))
        return [current()]

    a, b = Model(1), Model(1)  # equal, but two solutions
    assert arrange(a) == ["ru"] and arrange(a) is arrange(a)
    with language("en"):
        assert arrange(a) == ["en"]
    assert arrange(b) == ["ru"]
    assert len(calls) == 3
    kept = arrange.__closure__  # type: ignore[attr-defined]
    del a, b
    gc.collect()
    store = next(c.cell_contents for c in kept if isinstance(c.cell_contents, dict))
    assert store == {}

"""A task card's given data and what to find, as a student reads them.

The card names each quantity in the subject's notation: words, a symbol (label markup: ``l_{OA}``,
``ω_1``, ``F_{пс}``), a value with the language's decimal sign (``0,08`` on a Russian card) and a
unit (``с^{-1}``, ``Н·м``). A linkage file's data are named from the meaning of its keys
(linkages.md): the crank's length is ``l_{OA}``, its speed ``ω_1``, a point load ``F_{пс}``; a
key this module does not name is left off the card rather than shown as a file key. A problem
id's parameters and results take their words from its package's ``cards`` table
(:func:`geomcad.registry.card_words`), else, on an English card, their own docs; on a card in
another language a name without words is shown by its symbol alone.

    >>> symbol("theta_deg"), symbol("O1B0"), symbol("omega_3"), symbol("l_AB"), symbol("I_pr_A")
    ('θ', 'O_{1}B_{0}', 'ω_{3}', 'l_{AB}', 'I_{pr,A}')
    >>> number(0.08, "ru"), number(2500.0, "en"), number(-10.0, "ru")
    ('0,08', '2500', '-10')
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from geomcad.problem import Problem

#: A row of the data table: words, symbol (markup), value (markup), unit (markup).
Row = tuple[str, str, str, str]

GREEK = {
    "theta": "θ", "omega": "ω", "eps": "ε", "epsilon": "ε", "phi": "φ", "psi": "ψ",
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "lambda": "λ", "mu": "μ",
    "rho": "ρ", "tau": "τ", "Omega": "Ω",
}  # fmt: skip

UNITS: dict[str, dict[str, str]] = {
    "ru": {
        "m": "м", "m/s": "м/с", "m/s²": "м/с^{2}", "rad/s": "с^{-1}", "rad/s²": "с^{-2}",
        "N": "Н", "N·m": "Н·м", "kg": "кг", "kg·m²": "кг·м^{2}", "deg": "°", "1": "", "": "",
        "s": "с", "Pa": "Па", "rpm": "об/мин", "1/s": "с^{-1}", "N/m": "Н/м", "N·s/m": "Н·с/м",
        "J": "Дж", "W": "Вт",
    },
    "en": {
        "m/s²": "m/s^{2}", "rad/s": "s^{-1}", "rad/s²": "s^{-2}", "kg·m²": "kg·m^{2}",
        "deg": "°", "1": "", "": "", "1/s": "s^{-1}",
    },
}  # fmt: skip


def unit(u: str, lang: str) -> str:
    """A SI unit as the card writes it (markup)."""
    return UNITS.get(lang, {}).get(u, u)


def number(x: object, lang: str) -> str:
    """A value as the card prints it: up to six significant figures, a decimal comma in
    Russian."""
    if isinstance(x, bool):
        return str(x)
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        text = format(x, ".6g")
        if "e" in text:
            text = format(x, ".6f").rstrip("0").rstrip(".")
        return text.replace(".", ",") if lang == "ru" else text
    return str(x)


def escape(text: str) -> str:
    """Plain words as label markup."""
    return text.replace("\\", "\\\\").replace("_", "\\_").replace("^", "\\^")


def point(name: str) -> str:
    """A point's name with its digits as subscripts: ``O1`` → ``O_{1}`` (markup)."""
    return re.sub(r"(\d+)", r"_{\1}", escape(name)).replace("\\_{", "_{")


def symbol(name: str) -> str:
    """A parameter's or result's name as its symbol: Greek letters spelt out become letters,
    ``_deg`` goes, a trailing index or ``_X`` becomes a subscript (markup)."""
    base = name.removesuffix("_deg")
    head, sep, tail = base.partition("_")
    if sep:
        return f"{GREEK.get(head, escape(head))}_{{{escape(tail.replace('_', ','))}}}"
    for word, letter in sorted(GREEK.items(), key=lambda kv: -len(kv[0])):
        if base.startswith(word) and (base[len(word) :].isdecimal() or base == word):
            rest = base[len(word) :]
            return letter + (f"_{{{rest}}}" if rest else "")
    m = re.fullmatch(r"([A-Za-z]+)(\d+)", base)
    if m and len(m.group(1)) == 1:
        return f"{m.group(1)}_{{{m.group(2)}}}"
    return point(base)


# --- words ------------------------------------------------------------------------------------

WORDS: dict[str, dict[str, str]] = {
    "ru": {
        "crank": "длина кривошипа {a}{b}",
        "omega": "кривошип, {sense}",
        "cw": "по часовой",
        "ccw": "против часовой",
        "link": "длина звена {a}{b}",
        "frame": "опора {p}",
        "guide": "направляющая {p}: точка",
        "guide_angle": "наклон направляющей {p}",
        "guide_link": "смещение направляющей ползуна {p} от линии {a}{b} (влево)",
        "rpr_offset": "смещение линии кулисы от центра {p}",
        "slot": "угол паза кулисы к направляющей",
        "along": "положение точки {p} на звене {a}{b} (от {a})",
        "left": "смещение точки {p} влево от линии {a}{b}",
        "mass": "масса звена {i}",
        "J": "момент инерции звена {i}",
        "force": "сопротивление на {p}, {stroke}",
        "moment": "момент сопротивления, звено {i}",
        "moment_stroke": "момент сопр., звено {i}, {stroke}",
        "working": "раб. ход",
        "idle": "хол. ход",
        "both": "оба хода",
        "shape": ", по графику",
        "delta": "коэфф. неравномерности",
        "gravity": "ускорение св. падения",
        "no_gravity": "силы тяжести не учитывать",
        "positions": "положений кривошипа",
        "phi": "положения кривошипа",
        "forces_k": "положение для силового анализа",
        "forces_phi": "угол кривошипа для силового анализа",
        "stroke": "ход ползуна",
        "swing": "угол размаха коромысла",
        "K": "коэффициент изменения средней скорости",
        "offset": "смещение (дезаксиал) направляющей",
        "lambda": "отношение длин шатуна и кривошипа",
        "rocker": "длина коромысла",
        "sframe": "межосевое расстояние",
        "rod": "длина шатуна",
        "kind_slider-crank": "кривошипно-ползунный механизм",
        "kind_crank-rocker": "кривошипно-коромысловый механизм",
        "kind_slotted-lever": "кулисный механизм",
        "kind": "тип механизма",
        # results
        "r_stroke": "ход выходного звена",
        "r_swing_deg": "угол размаха выходного звена",
        "r_K": "коэффициент изменения средней скорости",
        "r_omega": "угловую скорость звена {i}",
        "r_eps": "угловое ускорение звена {i}",
        "r_V": "скорость точки {p}",
        "r_a": "ускорение точки {p}",
        "r_M_bal": "уравновешивающий момент на кривошипе",
        "r_M_bal_lever": "уравновешивающий момент по рычагу Жуковского",
        "r_J_flywheel": "момент инерции маховика",
        "r_R": "реакцию в кинематической паре {i}–{j}",
        "r_A_cycle": "работу сил сопротивления за цикл",
        "r_M_drive": "момент движущих сил",
        "r_I_pr": "приведённый момент инерции",
        "r_M_pr": "приведённый момент сил",
        "r_V_rel": "относительную скорость в точке {p}",
        "r_a_cor": "кориолисово ускорение в точке {p}",
        "r_omega_max": "наибольшую угловую скорость кривошипа",
        "r_omega_min": "наименьшую угловую скорость кривошипа",
    },
    "en": {
        "crank": "length of the crank {a}{b}",
        "omega": "crank, {sense}",
        "cw": "clockwise",
        "ccw": "counter-clockwise",
        "link": "length of the link {a}{b}",
        "frame": "fixed point {p}",
        "guide": "guide of {p} through",
        "guide_angle": "angle of the guide of {p}",
        "guide_link": "offset of the guide of the slider {p} from the line {a}{b} (to the left)",
        "rpr_offset": "offset of the slide line from the centre {p}",
        "slot": "angle of the slot to the guide",
        "along": "position of the point {p} on the link {a}{b} (from {a})",
        "left": "offset of the point {p} to the left of the line {a}{b}",
        "mass": "mass of the link {i}",
        "J": "moment of inertia, link {i}",
        "force": "resistance at {p}, {stroke}",
        "moment": "resisting moment, link {i}",
        "moment_stroke": "resisting moment, link {i}, {stroke}",
        "working": "working stroke",
        "idle": "idle stroke",
        "both": "both strokes",
        "shape": ", by its diagram",
        "delta": "speed fluctuation",
        "gravity": "acceleration of gravity",
        "no_gravity": "weights are neglected",
        "positions": "crank positions",
        "phi": "crank angles",
        "forces_k": "position for the force analysis",
        "forces_phi": "crank angle for the force analysis",
        "stroke": "stroke of the slider",
        "swing": "swing angle of the rocker",
        "K": "coefficient of velocity change",
        "offset": "offset of the guide",
        "lambda": "ratio of the rod to the crank",
        "rocker": "length of the rocker",
        "sframe": "distance between the fixed pivots",
        "rod": "length of the rod",
        "kind_slider-crank": "slider-crank mechanism",
        "kind_crank-rocker": "crank-rocker mechanism",
        "kind_slotted-lever": "slotted-lever mechanism",
        "kind": "mechanism",
        "r_stroke": "the stroke of the output",
        "r_swing_deg": "the swing angle of the output",
        "r_K": "the coefficient of velocity change",
        "r_omega": "the angular velocity of the link {i}",
        "r_eps": "the angular acceleration of the link {i}",
        "r_V": "the velocity of the point {p}",
        "r_a": "the acceleration of the point {p}",
        "r_M_bal": "the balancing moment on the crank",
        "r_M_bal_lever": "the balancing moment by Zhukovsky's lever",
        "r_J_flywheel": "the flywheel's moment of inertia",
        "r_R": "the reaction in the pair {i}–{j}",
        "r_A_cycle": "the work of the resistances per cycle",
        "r_M_drive": "the driving moment",
        "r_I_pr": "the reduced moment of inertia",
        "r_M_pr": "the reduced moment of the forces",
        "r_V_rel": "the relative velocity at the point {p}",
        "r_a_cor": "the Coriolis acceleration at the point {p}",
        "r_omega_max": "the largest angular velocity of the crank",
        "r_omega_min": "the smallest angular velocity of the crank",
    },
}

#: Symbols of a point load and of a resisting moment, per language.
LOAD_SYMBOLS = {"ru": ("F_{пс}", "M_{пс}"), "en": ("F_{r}", "M_{r}")}


def _f(x: Any) -> float | None:
    return float(x) if isinstance(x, int | float) and not isinstance(x, bool) else None


def linkage_rows(data: Mapping[str, Any], lang: str) -> list[Row]:
    """The given data of a linkage file as named quantities (see the module's docstring)."""
    w = WORDS[lang]
    rows: list[Row] = []

    def add(words: str, sym: str, value: Any, u: str = "") -> None:
        text = number(value, lang) if not isinstance(value, str) else value
        rows.append((escape(words), sym, text, unit(u, lang)))

    def pair(xy: Any) -> str | None:
        if isinstance(xy, list | tuple) and len(xy) == 2 and all(_f(v) is not None for v in xy):
            sep = "; " if lang == "ru" else ", "
            return f"({number(float(xy[0]), lang)}{sep}{number(float(xy[1]), lang)})"
        return None

    synthesis = data.get("synthesis")
    if isinstance(synthesis, Mapping):
        kind = str(synthesis.get("kind", ""))
        add(w["kind"], "", escape(w.get(f"kind_{kind}", kind)))
        names = {"stroke": ("stroke", "H", "m"), "swing_deg": ("swing", "ψ", "deg"),
                 "K": ("K", "K", "1"), "offset": ("offset", "e", "m"),
                 "lambda": ("lambda", "λ", "1"), "rocker": ("rocker", "l_{BC}", "m"),
                 "frame": ("sframe", "l_{OC}", "m"), "rod": ("rod", "l_{BD}", "m")}  # fmt: skip
        for key, (word, sym, u) in names.items():
            if _f(synthesis.get(key)) is not None:
                add(w[word], sym, float(synthesis[key]), u)
    frame = data.get("frame")
    if isinstance(frame, Mapping):
        for name, xy in frame.items():
            if (text := pair(xy)) is not None:
                add(w["frame"].format(p=name), f"({point('x')}; {point('y')})"
                    if lang == "ru" else "(x, y)", text, "m")  # fmt: skip
    drive = data.get("drive")
    if isinstance(drive, Mapping):
        a, b = str(drive.get("pivot", "")), str(drive.get("joint", ""))
        if _f(drive.get("length")) is not None:
            add(w["crank"].format(a=a, b=b), f"l_{{{a}{b}}}", float(drive["length"]), "m")
        if (om := _f(drive.get("omega"))) is not None:
            add(w["omega"].format(sense=w["cw" if om < 0 else "ccw"]), "ω_{1}", abs(om), "rad/s")
        if isinstance(drive.get("positions"), int):
            add(w["positions"], "n", int(drive["positions"]))
        phi = drive.get("phi")
        if isinstance(phi, list) and all(_f(p) is not None for p in phi):
            add(w["phi"], "φ_{1}", "; ".join(number(float(p), lang) for p in phi), "deg")
    for g in data.get("group", []) or []:
        if not isinstance(g, Mapping):
            continue
        kind, joint = str(g.get("kind", "")), str(g.get("joint", ""))
        if kind == "RRR":
            ends, lengths = g.get("ends", []), g.get("lengths", [])
            for e, ln in zip(ends, lengths, strict=False):
                if _f(ln) is not None:
                    add(w["link"].format(a=e, b=joint), f"l_{{{e}{joint}}}", float(ln), "m")
        elif kind == "RRP":
            end = str(g.get("end", ""))
            if _f(g.get("length")) is not None:
                add(
                    w["link"].format(a=end, b=joint), f"l_{{{end}{joint}}}", float(g["length"]), "m"
                )
            guide = g.get("guide")
            if isinstance(guide, Mapping) and "link" not in guide:
                if (text := pair(guide.get("through"))) is not None:
                    add(w["guide"].format(p=joint), "(x; y)" if lang == "ru" else "(x, y)",
                        text, "m")  # fmt: skip
                if (ang := _f(guide.get("angle"))) is not None and ang != 0.0:
                    add(w["guide_angle"].format(p=joint), f"α_{{{joint}}}", ang, "deg")
            elif isinstance(guide, Mapping):
                off = _f(guide.get("offset"))
                if off:
                    fa, tb = guide.get("from", ""), guide.get("toward", "")
                    add(w["guide_link"].format(p=joint, a=fa, b=tb), "e", off, "m")
        elif kind == "RPR":
            off = _f(g.get("offset"))
            if off:
                add(w["rpr_offset"].format(p=g.get("pivot", "")), "e", off, "m")
        elif kind == "PRP":
            if (ang := _f(g.get("slot_angle"))) is not None:
                add(w["slot"], "β", ang, "deg")
            guide = g.get("guide")
            if isinstance(guide, Mapping) and (text := pair(guide.get("through"))) is not None:
                add(w["guide"].format(p=g.get("point", "")), "(x; y)" if lang == "ru"
                    else "(x, y)", text, "m")  # fmt: skip
    for p in data.get("point", []) or []:
        if not isinstance(p, Mapping):
            continue
        name, fa, tb = str(p.get("name", "")), str(p.get("from", "")), str(p.get("toward", ""))
        if _f(p.get("along")) is not None:
            add(w["along"].format(p=name, a=fa, b=tb), f"l_{{{fa}{name}}}", float(p["along"]), "m")
        if _f(p.get("left")):
            add(w["left"].format(p=name, a=fa, b=tb), f"h_{{{name}}}", float(p["left"]), "m")
    links = data.get("links")
    if isinstance(links, Mapping):
        for i, link in links.items():
            if not isinstance(link, Mapping):
                continue
            if _f(link.get("mass")) is not None:
                add(w["mass"].format(i=i), f"m_{{{i}}}", float(link["mass"]), "kg")
            if _f(link.get("J")) is not None:
                add(w["J"].format(i=i), f"J_{{S{i}}}", float(link["J"]), "kg·m²")
    f_sym, m_sym = LOAD_SYMBOLS[lang]
    loads = [ld for ld in data.get("load", []) or [] if isinstance(ld, Mapping)]
    for ld in loads:
        stroke = w.get(str(ld.get("stroke", "working")), str(ld.get("stroke", "")))
        if "point" in ld and _f(ld.get("value")) is not None:
            words = w["force"].format(p=ld["point"], stroke=stroke)
            add(words + (w["shape"] if "shape" in ld else ""), f_sym, float(ld["value"]), "N")
        elif "link" in ld and _f(ld.get("moment")) is not None:
            key = "moment_stroke" if "stroke" in ld else "moment"
            add(w[key].format(i=ld["link"], stroke=stroke), m_sym, float(ld["moment"]), "N·m")
    dyn = data.get("dynamics")
    if isinstance(dyn, Mapping) and _f(dyn.get("delta")) is not None:
        add(w["delta"], "δ", float(dyn["delta"]))
    if loads or isinstance(links, Mapping):
        g = _f(data.get("gravity"))
        if g == 0.0:
            add(w["no_gravity"], "", "")
        else:
            add(w["gravity"], "g", 9.81 if g is None else g, "m/s²")
    forces = data.get("forces")
    if isinstance(forces, Mapping):
        if isinstance(forces.get("position"), int):
            add(w["forces_k"], "k", int(forces["position"]))
        if _f(forces.get("phi")) is not None:
            add(w["forces_phi"], "φ_{1}", float(forces["phi"]), "deg")
    return rows


def problem_rows(problem: Problem[Any], params: Mapping[str, Any], lang: str) -> list[Row]:
    """The given data of a problem id's variant (see the module's docstring)."""
    from geomcad.registry import card_words

    words = card_words(problem, lang)
    rows: list[Row] = []
    for p in problem.params:
        if p.name not in params:
            continue
        text = words.get(p.name, p.doc if lang == "en" else "")
        value = params[p.name]
        shown = number(value, lang) if isinstance(value, int | float) else escape(str(value))
        rows.append((text if p.name in words else escape(text), symbol(p.name), shown,
                     unit(p.unit, lang)))  # fmt: skip
    return rows


# --- what to find -----------------------------------------------------------------------------


def result_words(
    problem: Problem[Any], name: str, lang: str, linkage: bool
) -> tuple[str, str, str]:
    """(words as markup, symbol, unit) of a result ``name`` (a path's leaf)."""
    spec = problem.result_spec(name)
    u = unit("deg" if name.endswith("_deg") else (spec.unit if spec is not None else ""), lang)
    if linkage:
        w = WORDS[lang]
        m = re.fullmatch(r"(omega|eps)_(\d+)", name)
        if m:
            return escape(w[f"r_{m.group(1)}"].format(i=m.group(2))), symbol(name), u
        m = re.fullmatch(r"R_(\d+)_(\d+)", name)
        if m:
            return (escape(w["r_R"].format(i=m.group(1), j=m.group(2))),
                    f"R_{{{m.group(1)}{m.group(2)}}}", u)  # fmt: skip
        m = re.fullmatch(r"(V_rel|a_cor|V|a)_([A-Za-z]\w*)", name)
        if m and not m.group(2).endswith(("_x", "_y")):
            sym = {"V_rel": "V_{rel,", "a_cor": "a_{cor,"}.get(m.group(1))
            p = m.group(2)
            symbol_text = f"{sym}{p}}}" if sym else f"{m.group(1)}_{{{p}}}"
            return escape(w[f"r_{m.group(1)}"].format(p=p)), symbol_text, u
        if f"r_{name}" in w:
            ru = lang == "ru"
            syms = {"stroke": "H", "swing_deg": "ψ", "K": "K",
                    "M_bal": "M_{ур}" if ru else "M_{bal}",
                    "J_flywheel": "J_{м}" if ru else "J_{fw}"}  # fmt: skip
            return escape(w[f"r_{name}"]), syms.get(name, symbol(name)), u
        return "", symbol(name), u
    from geomcad.registry import card_words

    words = card_words(problem, lang)
    own = spec.symbol if spec is not None and spec.name == name and spec.symbol else ""
    if name in words:
        return words[name], own or symbol(name), u
    if problem.id.lower().endswith(".toml") and name in FILE_RESULTS:
        ru_words, sym = FILE_RESULTS[name]
        doc = spec.doc if spec is not None and spec.name == name else ""
        return escape(ru_words if lang == "ru" else doc), own or sym, u
    doc = spec.doc if spec is not None and spec.name == name and lang == "en" else ""
    return escape(doc), own or symbol(name), u


def is_internal(name: str) -> bool:
    """A result that checks the solver (``H_check``, ``K_check``), never asked of a student."""
    return name.endswith("_check")


def find_lines(
    problem: Problem[Any],
    columns: Sequence[str],
    positions: Sequence[Mapping[str, Any]],
    lang: str,
    linkage: bool,
    at: str,
    each: str,
) -> list[str]:
    """What to find, one markup line per quantity: words, symbol, unit and where it is asked
    (the crank angles of its positions), each quantity once."""
    order: dict[str, list[str]] = {}
    for c in columns:
        parts = c.split(".")
        leaf = next((p for p in reversed(parts) if not p.isdecimal()), c)
        if is_internal(leaf):
            continue
        order.setdefault(leaf, []).append(c)
    lines = []
    for leaf, paths in order.items():
        words, sym, u = result_words(problem, leaf, lang, linkage)
        where = ""
        if paths[0].startswith("positions."):
            phis = []
            for p in paths:
                i = p.split(".")[1]
                if i.isdecimal() and int(i) < len(positions):
                    phi = positions[int(i)].get("phi_deg")
                    if isinstance(phi, int | float):
                        phis.append(number(round(float(phi), 1), lang) + "°")
            where = (
                f" {at} φ_{{1}} = {', '.join(phis)}"
                if 0 < len(phis) <= 4
                else f" {each.format(n=len(paths))}"
            )
        elif len(paths) > 1:
            where = f" ({', '.join(escape(p.rsplit('.', 1)[1]) for p in paths)})"
        head = f"{words} {sym}" if words else sym
        lines.append(head + (f", {u}" if u else "") + where)
    return lines


# --- cam and gear files -----------------------------------------------------------------------

#: A cam or gear file's keys (a table's key, a list's items counted apart): (ru words, en words,
#: symbol, SI unit).
FILE_KEYS: dict[str, tuple[str, str, str, str]] = {
    "cam.follower": ("толкатель", "follower", "", ""),
    "cam.motion": ("движение толкателя", "follower's motion", "", ""),
    "cam.rotation": ("вращение кулачка", "cam's rotation", "", ""),
    "cam.stroke": ("ход толкателя", "stroke of the follower", "H", "m"),
    "cam.swing_deg": ("угол размаха коромысла", "swing of the rocker", "ψ_{max}", "deg"),
    "cam.arm": ("длина коромысла", "length of the rocker", "l_{AB}", "m"),
    "cam.pressure_angle_deg": ("допустимый угол давления (подъём)",
                               "allowed pressure angle (rise)", "ϑ_{доп}", "deg"),
    "cam.return_pressure_angle_deg": ("допустимый угол давления (опускание)",
                                      "allowed pressure angle (return)", "ϑ'_{доп}", "deg"),
    "cam.offset": ("эксцентриситет", "offset", "e", "m"),
    "cam.r0_step": ("шаг округления радиуса r0", "rounding step of r0", "", "m"),
    "cam.roller_radius": ("радиус ролика", "roller's radius", "r_{р}", "m"),
    "cam.rho_allowed": ("наименьший радиус кривизны", "smallest radius of curvature", "ρ_{min}",
                        "m"),
    "cam.divisions": ("число делений фаз", "divisions of each phase", "n", ""),
    "gears.pair.z1": ("число зубьев шестерни", "teeth of the pinion", "z_{1}", ""),
    "gears.pair.z2": ("число зубьев колеса", "teeth of the wheel", "z_{2}", ""),
    "gears.pair.m": ("модуль", "module", "m", "m"),
    "gears.pair.shift": ("смещение", "shift", "", ""),
    "gears.pair.x1": ("коэффициент смещения шестерни", "shift of the pinion", "x_{1}", ""),
    "gears.pair.x2": ("коэффициент смещения колеса", "shift of the wheel", "x_{2}", ""),
    "gears.pair.x_sum": ("сумма коэффициентов смещения", "sum of the shifts", "x_{Σ}", ""),
    "gears.pair.alpha_deg": ("угол профиля", "pressure angle", "α", "deg"),
    "gears.pair.ha": ("коэффициент высоты головки", "addendum coefficient", "h^{*}_{a}", ""),
    "gears.pair.c": ("коэффициент радиального зазора", "clearance coefficient", "c^{*}", ""),
    "gears.planetary.scheme": ("схема редуктора", "scheme", "", ""),
    "gears.planetary.ratio": ("передаточное отношение", "gear ratio", "u", ""),
    "gears.planetary.tolerance": ("допуск передаточного отношения", "tolerance of the ratio",
                                  "Δu", ""),
    "gears.planetary.planets": ("число сателлитов", "planets", "k", ""),
    "gears.planetary.m": ("модуль", "module", "m", "m"),
}  # fmt: skip

#: Word values of a cam or gear file, per language (others are shown as written).
FILE_WORDS = {
    "ru": {"roller": "роликовый", "knife": "острый", "flat": "тарельчатый",
           "translating": "поступательное", "rocking": "качательное", "cw": "по часовой",
           "ccw": "против часовой", "best": "наилучший", "rise": "подъём", "dwell": "выстой",
           "return": "опускание", "equal_sliding": "равные скольжения",
           "no_undercut": "без подрезания", "max_contact_ratio": "наибольшее перекрытие",
           "given": "задано", "linear": "линейный", "constant_acceleration": "равноускоренный",
           "harmonic": "косинусоидальный", "cycloidal": "синусоидальный",
           "poly345": "полином 3-4-5", "modified_trapezoid": "модифицированная трапеция",
           "phase": "фаза {i}: {kind}"},
    "en": {"constant_acceleration": "constant acceleration", "equal_sliding": "equal sliding",
           "no_undercut": "no undercut", "max_contact_ratio": "largest contact ratio",
           "modified_trapezoid": "modified trapezoid", "phase": "phase {i}: {kind}"},
}  # fmt: skip


def file_rows(data: Mapping[str, Any], lang: str) -> list[Row]:
    """The given data of a cam or gear file as named quantities (a key not in
    :data:`FILE_KEYS` is named by its own name as a symbol)."""
    words = FILE_WORDS[lang]
    rows: list[Row] = []

    def word(v: Any) -> str:
        return escape(words.get(str(v), str(v))) if isinstance(v, str) else number(v, lang)

    def walk(node: Any, path: str) -> None:
        if isinstance(node, Mapping):
            for k, v in node.items():
                walk(v, f"{path}.{k}" if path else str(k))
            return
        if path in ("title",) or path.startswith("sheet"):
            return
        if path.endswith(".phases") and isinstance(node, list):
            for i, ph in enumerate(node, start=1):
                if not isinstance(ph, Mapping):
                    continue
                kind = words.get(str(ph.get("kind", "")), str(ph.get("kind", "")))
                law = ph.get("law")
                text = words["phase"].format(i=i, kind=kind)
                text += f", {words.get(str(law), str(law))}" if law else ""
                rows.append((escape(text), f"φ_{{{i}}}", word(ph.get("angle_deg", "")), "°"))
            return
        ru, en, sym, u = FILE_KEYS.get(path, ("", "", symbol(path.rsplit(".", 1)[-1]), ""))
        value = word(node) if not isinstance(node, list) else "; ".join(word(v) for v in node)
        rows.append((escape(ru if lang == "ru" else en), sym, value, unit(u, lang)))

    walk(data, "")
    return rows


#: What a cam or gear file's results are, in Russian, and their symbols.
FILE_RESULTS: dict[str, tuple[str, str]] = {
    "H": ("ход толкателя", "H"),
    "swing_deg": ("угол размаха коромысла", "ψ_{max}"),
    "e": ("эксцентриситет", "e"),
    "r0_min": ("наименьший радиус основной шайбы", "r_{0,min}"),
    "r0": ("принятый радиус основной шайбы", "r_{0}"),
    "r_roller": ("радиус ролика", "r_{р}"),
    "rho_min": ("наименьший радиус кривизны профиля", "ρ_{min}"),
    "rho_pitch_min": ("наименьший радиус кривизны центрового профиля", "ρ_{0,min}"),
    "pressure_angle_allowed_deg": ("допустимый угол давления (подъём)", "ϑ_{доп}"),
    "return_pressure_angle_allowed_deg": ("допустимый угол давления (опускание)", "ϑ'_{доп}"),
    "pressure_angle_max_deg": ("наибольший угол давления", "ϑ_{max}"),
    "pressure_angle_max_rise_deg": ("наибольший угол давления на подъёме", "ϑ_{max}"),
    "pressure_angle_max_return_deg": ("наибольший угол давления на опускании", "ϑ'_{max}"),
    "a": ("делительное межосевое расстояние", "a"),
    "a_w": ("межосевое расстояние", "a_{w}"),
    "alpha_w_deg": ("угол зацепления", "α_{w}"),
    "y": ("коэффициент воспринимаемого смещения", "y"),
    "delta_y": ("коэффициент уравнительного смещения", "Δy"),
    "x1": ("коэффициент смещения шестерни", "x_{1}"),
    "x2": ("коэффициент смещения колеса", "x_{2}"),
    "d1": ("делительный диаметр шестерни", "d_{1}"),
    "d2": ("делительный диаметр колеса", "d_{2}"),
    "d_b1": ("основной диаметр шестерни", "d_{b1}"),
    "d_b2": ("основной диаметр колеса", "d_{b2}"),
    "d_w1": ("начальный диаметр шестерни", "d_{w1}"),
    "d_w2": ("начальный диаметр колеса", "d_{w2}"),
    "d_a1": ("диаметр вершин шестерни", "d_{a1}"),
    "d_a2": ("диаметр вершин колеса", "d_{a2}"),
    "d_f1": ("диаметр впадин шестерни", "d_{f1}"),
    "d_f2": ("диаметр впадин колеса", "d_{f2}"),
    "s_a1": ("толщина зуба шестерни по окружности вершин", "s_{a1}"),
    "s_a2": ("толщина зуба колеса по окружности вершин", "s_{a2}"),
    "eps_alpha": ("коэффициент торцового перекрытия", "ε_{α}"),
    "eps_alpha_drawn": ("коэффициент перекрытия по чертежу зацепления", "ε'_{α}"),
    "lambda1_max": ("наибольшее удельное скольжение шестерни", "λ_{1,max}"),
    "lambda2_max": ("наибольшее удельное скольжение колеса", "λ_{2,max}"),
    "u": ("достигнутое передаточное отношение", "u"),
    "u_error": ("относительная ошибка передаточного отношения", "δu"),
    "z": ("числа зубьев колёс", "z"),
    "z1": ("число зубьев шестерни", "z_{1}"),
    "z2": ("число зубьев колеса", "z_{2}"),
    "m": ("модуль", "m"),
}

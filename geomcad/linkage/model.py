"""A lever mechanism of a crank and class-II Assur groups, read from a linkage file.

The file's format is the interface of ``../shared/linkages.md``: ``[frame]`` points, the
``[drive]`` crank (link 1), ``[[group]]`` tables (RRR, RRP, RPR, PRP) attached one after another,
``[[point]]`` points of links, ``[links.N]`` mass data, ``[[load]]`` rules and ``[dynamics]``.
:func:`parse` turns the TOML data into a :class:`Linkage` (SI units, angles in radians) and checks
everything that can be checked before a position is constructed; every failure is a
:class:`~geomcad.errors.FileKeyError` naming the file's key, e.g. ``group 2: point "Q" is not
known yet``.

What a link "owns", for the groups and points that attach to it later:

- frame points: link 0; the crank's joint: link 1;
- a group's new joint: the group's second link (the rocker of an RRR, the slider of an RRP);
- a PRP group's reference point ``point``: its second link (the sliding yoke);
- a ``[[point]]``: its ``link``.

>>> lk = parse({"frame": {"O": [0, 0], "C": [0.3, 0.0]},
...             "drive": {"pivot": "O", "joint": "A", "length": 0.1, "omega": 10, "phi": [30]},
...             "group": [{"kind": "RRR", "links": [2, 3], "joint": "B", "ends": ["A", "C"],
...                        "lengths": [0.3, 0.2], "assembly": "left"}]})
>>> [g.kind for g in lk.groups], lk.output, lk.owner["B"], lk.link_points(3)
(['RRR'], 'B', 3, ('C', 'B'))
"""

from __future__ import annotations

import difflib
import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from geomcad.errors import FileKeyError
from geomcad.geom import Vec

GroupKind = Literal["RRR", "RRP", "RPR", "PRP"]
KINDS: tuple[GroupKind, ...] = ("RRR", "RRP", "RPR", "PRP")

TOP_KEYS = (
    "title",
    "gravity",
    "frame",
    "drive",
    "group",
    "point",
    "links",
    "load",
    "dynamics",
    "forces",
    "sheet",
)
DRIVE_KEYS = ("pivot", "joint", "length", "omega", "phi", "positions", "output", "working")
FORCES_KEYS = ("position", "phi")
GROUP_KEYS: dict[str, tuple[str, ...]] = {
    "RRR": ("kind", "links", "joint", "ends", "lengths", "assembly"),
    "RRP": ("kind", "links", "joint", "end", "length", "guide", "assembly"),
    "RPR": ("kind", "links", "slider", "pivot", "offset"),
    "PRP": ("kind", "links", "slider", "slot_angle", "guide", "point"),
}
POINT_KEYS = ("name", "link", "from", "toward", "along", "left")
LINK_KEYS = ("mass", "J", "centre")
LOAD_KEYS = ("point", "value", "stroke", "working", "shape", "link", "moment")
DYNAMICS_KEYS = ("delta", "drive", "flywheel", "density", "ratio")
FIXED_GUIDE_KEYS = ("through", "angle")
MOVING_GUIDE_KEYS = ("link", "from", "toward", "offset")

#: A length of a link, a radius: more than this fraction of the mechanism's size and less than
#: this many times it is a sensible drawing. Lengths are checked against absolute bounds only.
MAX_LENGTH = 1.0e4  # m
MIN_LENGTH = 1.0 / 1_000_000  # m: a link shorter than a micrometre is a typing error
MAX_OMEGA = 1.0e5  # rad/s
MIN_OMEGA = 1.0 / 1_000_000  # rad/s
MAX_POSITIONS = 360
#: A slot closer than this (the sine of its angle) to the guide's direction runs along it.
MIN_SLOT_SIN = math.sin(math.radians(0.01))
MAX_MASS = 1.0e7  # kg
MAX_FORCE = 1.0e9  # N or N·m


@dataclass(frozen=True)
class Guide:
    """A straight guide: fixed (``link`` 0, through ``through`` at ``angle`` rad) or on a moving
    link (``link`` > 0, from point ``frm`` towards ``toward``, shifted ``offset`` m to the left)."""

    link: int
    through: Vec = field(default_factory=lambda: Vec(0.0, 0.0))
    angle: float = 0.0
    frm: str = ""
    toward: str = ""
    offset: float = 0.0

    @property
    def fixed(self) -> bool:
        return self.link == 0

    @property
    def direction(self) -> Vec:
        """A fixed guide's unit direction."""
        return Vec(math.cos(self.angle), math.sin(self.angle))


@dataclass(frozen=True)
class Group:
    """A class-II Assur group as the file states it (``index`` counts from 1, as in keys).

    - RRR: ``ends`` (P1, P2), ``lengths`` (l_P1J, l_P2J), the new ``joint`` J; ``branch`` +1: J on
      the left of P1 → P2.
    - RRP: ``ends[0]`` the rod's known end, ``lengths[0]`` the rod, ``joint`` the slider's joint on
      ``guide``; ``branch`` +1: J ahead of the end's foot along the guide.
    - RPR: ``slider`` the block's known joint, ``pivot`` the slotted link's known joint,
      ``offset`` (m, to the left of the pivot looking from it to the slider).
    - PRP: ``slider`` the block's known joint, ``guide`` of the yoke (link b) on the frame,
      ``slot_angle`` (rad, from the guide's direction), ``joint`` = the yoke's reference point.
    """

    index: int
    kind: GroupKind
    links: tuple[int, int]
    joint: str = ""
    ends: tuple[str, ...] = ()
    lengths: tuple[float, ...] = ()
    branch: int = 1
    guide: Guide | None = None
    slider: str = ""
    pivot: str = ""
    offset: float = 0.0
    slot_angle: float = 0.0

    @property
    def key(self) -> str:
        return f"group {self.index}"

    @property
    def known(self) -> tuple[str, ...]:
        """The points the group hangs on (they must be known before it)."""
        if self.kind == "RRR":
            return self.ends
        if self.kind == "RRP":
            g = self.guide
            extra = (g.frm, g.toward) if g is not None and not g.fixed else ()
            return (*self.ends, *extra)
        if self.kind == "RPR":
            return (self.slider, self.pivot)
        return (self.slider,)

    @property
    def sliding(self) -> bool:
        """True for the groups with a sliding pair."""
        return self.kind != "RRR"


@dataclass(frozen=True)
class PointDef:
    """A named point of a link: ``along`` m from ``frm`` towards ``toward``, ``left`` m to its
    left (``slide`` True: the direction is the link's slide direction)."""

    name: str
    link: int
    frm: str
    toward: str
    along: float
    left: float
    slide: bool = False


@dataclass(frozen=True)
class Mass:
    """Mass data of a moving link: mass (kg), J about the centre of mass (kg·m²), the centre."""

    link: int
    mass: float
    J: float
    centre: str


@dataclass(frozen=True)
class Load:
    """A ``[[load]]``: a resistance force on ``point`` (``value``·shape(s/H) against the point's
    velocity along its guide, on the named ``stroke``) or a ``moment`` on ``link``."""

    index: int
    point: str = ""
    value: float = 0.0
    stroke: Literal["working", "idle", "both"] = "working"
    shape: tuple[tuple[float, float], ...] = ()
    link: int = 0
    moment: float = 0.0
    #: a moment load with a ``stroke``: |moment| against the link's ω on that stroke only
    on_stroke: bool = False


@dataclass(frozen=True)
class Dynamics:
    """``[dynamics]``: the allowed coefficient of speed fluctuation and the motor's law."""

    delta: float
    drive: Literal["constant"] = "constant"
    flywheel: Literal["disc", "rim"] = "disc"
    density: float = 7800.0
    ratio: float = 0.2


@dataclass(frozen=True)
class Linkage:
    """A lever mechanism: frame points, the crank (link 1), groups, points, masses and loads."""

    title: str
    gravity: float
    frame: Mapping[str, Vec]
    pivot: str
    joint: str
    length: float
    omega: float
    phi: tuple[float, ...] | None  # rad, as listed: the plans' positions; None: the numbered ones
    positions: int  # N of the numbering (12 unless the file says)
    output: str
    working: Literal["forward", "backward"]
    groups: tuple[Group, ...]
    points: tuple[PointDef, ...]
    masses: Mapping[int, Mass]
    loads: tuple[Load, ...]
    dynamics: Dynamics | None
    sheet: Mapping[str, Any]
    owner: Mapping[str, int] = field(default_factory=dict)
    #: the output's link when the output is a rocker (a link turning about a frame point), else 0
    rocker: int = 0
    #: ``[forces] position`` (a numbered position) or ``[forces] phi`` (rad); None: the default
    forces_position: int | None = None
    forces_phi: float | None = None
    #: the key that says the output's working stroke (``drive.working``, ``load 2: working``),
    #: "" where it is the default
    working_key: str = ""

    # -- structure -------------------------------------------------------------------------
    @property
    def moving_links(self) -> tuple[int, ...]:
        """The moving links in order: the crank, then each group's two links."""
        return (1, *(i for g in self.groups for i in g.links))

    def group_of(self, link: int) -> Group | None:
        """The group a link belongs to (``None`` for the crank)."""
        for g in self.groups:
            if link in g.links:
                return g
        return None

    def link_points(self, link: int) -> tuple[str, ...]:
        """The joints of a link (its revolute axes, in the group's order), without the
        ``[[point]]`` points on it."""
        if link == 1:
            return (self.pivot, self.joint)
        g = self.group_of(link)
        if g is None:
            return ()
        first = link == g.links[0]
        if g.kind == "RRR":
            return (g.ends[0], g.joint) if first else (g.ends[1], g.joint)
        if g.kind == "RRP":
            return (g.ends[0], g.joint) if first else (g.joint,)
        if g.kind == "RPR":
            return (g.slider,) if first else (g.pivot,)
        return (g.slider,) if first else (g.joint,)

    def points_on(self, link: int) -> tuple[str, ...]:
        """Every point that moves with the link: its joints and its ``[[point]]`` points."""
        return (*self.link_points(link), *(p.name for p in self.points if p.link == link))

    def has_slide(self, link: int) -> bool:
        """True for the links whose direction is a slide: the slider of an RRP, both links of an
        RPR and of a PRP."""
        g = self.group_of(link)
        return g is not None and (
            g.kind in ("RPR", "PRP") or (g.kind == "RRP" and link == g.links[1])
        )

    def centre(self, link: int) -> str:
        """The point that is the link's centre of mass (a ``[links.N]`` ``centre``, or the
        default of linkages.md; ``""``: the middle of its two joints)."""
        m = self.masses.get(link)
        if m is not None and m.centre:
            return m.centre
        joints = self.link_points(link)
        return joints[0] if len(joints) == 1 else ""

    def frame_pivot(self, link: int) -> str:
        """The frame point a moving link (not the crank) turns about, or ``""``: an RRR's link
        whose end is a frame point, link 3 of an RPR whose pivot is one."""
        g = self.group_of(link)
        if g is None or link == 1:
            return ""
        if g.kind == "RRR":
            end = g.ends[0] if link == g.links[0] else g.ends[1]
            return end if self.owner.get(end) == 0 else ""
        if g.kind == "RPR" and link == g.links[1]:
            return g.pivot if self.owner.get(g.pivot) == 0 else ""
        return ""

    @property
    def output_guide(self) -> Group | None:
        """The group whose slider is the output (an RRP's joint, a PRP's yoke point), if any."""
        for g in self.groups:
            if g.joint == self.output and g.kind in ("RRP", "PRP"):
                return g
        return None


# --- parsing ----------------------------------------------------------------------------------


#: Tables of a list ([[group]] …) are named "group 2" in messages, their keys "group 2: ends".
_LISTED = ("group ", "point ", "load ")


def _label(where: str, key: str) -> str:
    """A key as messages name it: ``group 2: ends`` in a listed table, ``drive.omega`` else."""
    return f"{where}: {key}" if where.startswith(_LISTED) else _join(where, key)


def _suggest(key: str, known: Sequence[str]) -> str:
    close = difflib.get_close_matches(key, known, n=1)
    return f" (did you mean {close[0]!r}?)" if close else f" (known keys: {', '.join(known)})"


def _check_keys(where: str, table: Mapping[str, Any], known: Sequence[str]) -> None:
    for k in table:
        if k not in known:
            raise FileKeyError(
                f"{where}.{k}" if where else k, table[k], "unknown key" + _suggest(k, known)
            )


def _table(data: Mapping[str, Any], key: str, where: str, required: bool = True) -> dict[str, Any]:
    v = data.get(key)
    if v is None:
        if required:
            raise FileKeyError(_join(where, key), None, "missing (a table is required)")
        return {}
    if not isinstance(v, dict):
        raise FileKeyError(_join(where, key), v, "must be a table")
    return v


def _tables(data: Mapping[str, Any], key: str) -> list[dict[str, Any]]:
    v = data.get(key, [])
    if isinstance(v, dict):
        v = [v]
    if not isinstance(v, list) or not all(isinstance(t, dict) for t in v):
        raise FileKeyError(key, v, f"must be a list of tables ([[{key}]])")
    return v


def _join(where: str, key: str) -> str:
    return f"{where}.{key}" if where else key


def _number(
    t: Mapping[str, Any],
    key: str,
    where: str,
    *,
    default: float | None = None,
    gt: float | None = None,
    ge: float | None = None,
    lt: float | None = None,
    le: float | None = None,
    unit: str = "",
) -> float:
    name = _label(where, key)
    if key not in t:
        if default is None:
            raise FileKeyError(name, None, "missing (a number is required)")
        return default
    v = t[key]
    if isinstance(v, bool) or not isinstance(v, int | float):
        raise FileKeyError(name, v, f"must be a number, not {v!r}")
    x = float(v)
    u = f" {unit}" if unit else ""
    if not math.isfinite(x):
        raise FileKeyError(name, v, "must be a finite number")
    if gt is not None and not x > gt:
        raise FileKeyError(name, v, f"must be > {gt:g}{u}, not {x:g}")
    if ge is not None and not x >= ge:
        raise FileKeyError(name, v, f"must be ≥ {ge:g}{u}, not {x:g}")
    if lt is not None and not x < lt:
        raise FileKeyError(name, v, f"must be < {lt:g}{u}, not {x:g}")
    if le is not None and not x <= le:
        raise FileKeyError(name, v, f"must be ≤ {le:g}{u}, not {x:g}")
    return x


def _name(where: str, t: Mapping[str, Any], key: str, *, default: str | None = None) -> str:
    label = _label(where, key)
    if key not in t:
        if default is None:
            raise FileKeyError(label, None, "missing (a point's name is required)")
        return default
    v = t[key]
    if not isinstance(v, str) or not v.strip():
        raise FileKeyError(label, v, f"must be a point's name (a string), not {v!r}")
    return v.strip()


def _working(where: str, t: dict[str, Any], working: str, said: str) -> tuple[str, str]:
    """A load's ``working``, which must agree with the one ``said`` before (the output has one
    working stroke): (the working stroke, where it was said)."""
    w = _word(where, t, "working", ("forward", "backward"), "forward")
    if said and w != working:
        raise FileKeyError(
            f"{where}: working",
            w,
            f"disagrees with {said} = {working!r} (the output has one working stroke)",
        )
    return w, f"{where}: working"


def _word(where: str, t: Mapping[str, Any], key: str, choices: Sequence[str], default: str) -> str:
    label = _label(where, key)
    v = t.get(key, default)
    if v not in choices:
        raise FileKeyError(
            label, v, f"must be one of {', '.join(repr(c) for c in choices)}, not {v!r}"
        )
    return str(v)


def _point(label: str, v: object) -> Vec:
    if (
        not isinstance(v, list)
        or len(v) != 2
        or not all(isinstance(x, int | float) and not isinstance(x, bool) for x in v)
    ):
        raise FileKeyError(label, v, f"must be a point [x, y] in metres, not {v!r}")
    x, y = float(v[0]), float(v[1])
    if not (math.isfinite(x) and math.isfinite(y)) or max(abs(x), abs(y)) > MAX_LENGTH:
        raise FileKeyError(label, v, f"must be finite and within ±{MAX_LENGTH:g} m")
    return Vec(x, y)


def _link_no(label: str, v: object) -> int:
    if isinstance(v, bool) or not isinstance(v, int):
        raise FileKeyError(label, v, f"must be a link number (a whole number), not {v!r}")
    return v


def _lengths(where: str, t: Mapping[str, Any], key: str, n: int) -> tuple[float, ...]:
    label = f"{where}: {key}"
    v = t.get(key)
    if n == 1 and isinstance(v, int | float) and not isinstance(v, bool):
        v = [v]
    if not isinstance(v, list) or len(v) != n:
        raise FileKeyError(
            label, v, f"must be {'a length' if n == 1 else f'{n} lengths'} in metres"
        )
    out = []
    for i, x in enumerate(v, start=1):
        out.append(
            _number({key: x}, key, where, ge=MIN_LENGTH, le=MAX_LENGTH, unit="m")
            if n == 1
            else _number(
                {f"{key}.{i}": x}, f"{key}.{i}", where, ge=MIN_LENGTH, le=MAX_LENGTH, unit="m"
            )
        )
    return tuple(out)


def parse(data: Mapping[str, Any]) -> Linkage:
    """The :class:`Linkage` a linkage file's data states; see the module's docstring."""
    if not isinstance(data, Mapping):
        raise FileKeyError("file", data, "must be a TOML table")
    if "synthesis" in data:  # the variant's design data: the explicit file it finds (issue 31)
        from geomcad.linkage.synthesis import synthesize

        data = synthesize(data).linkage
    _check_keys("", data, TOP_KEYS)
    title = data.get("title", "Рычажный механизм")
    if not isinstance(title, str):
        raise FileKeyError("title", title, "must be a string")
    gravity = _number(data, "gravity", "", default=9.81, ge=0.0, le=1000.0, unit="m/s²")
    sheet = _table(data, "sheet", "", required=False)

    # frame
    frame_t = _table(data, "frame", "")
    frame: dict[str, Vec] = {}
    for k, v in frame_t.items():
        frame[k] = _point(f"frame.{k}", v)
    if not frame:
        raise FileKeyError("frame", frame_t, "must name at least the crank's pivot")
    owner: dict[str, int] = dict.fromkeys(frame, 0)

    # drive
    drive = _table(data, "drive", "")
    _check_keys("drive", drive, DRIVE_KEYS)
    pivot = _name("drive", drive, "pivot")
    if pivot not in frame:
        raise FileKeyError("drive.pivot", pivot, f'point "{pivot}" is not a [frame] point')
    joint = _name("drive", drive, "joint")
    if joint in owner:
        raise FileKeyError("drive.joint", joint, f'point "{joint}" is named twice')
    owner[joint] = 1
    length = _number(drive, "length", "drive", ge=MIN_LENGTH, le=MAX_LENGTH, unit="m")
    omega = _number(drive, "omega", "drive", unit="rad/s")
    if not MIN_OMEGA <= abs(omega) <= MAX_OMEGA:
        raise FileKeyError(
            "drive.omega",
            omega,
            f"|ω1| must be {MIN_OMEGA:g} … {MAX_OMEGA:g} rad/s (the sign: the sense)",
        )
    phi: tuple[float, ...] | None = None
    if "phi" in drive:
        v = drive["phi"]
        if isinstance(v, int | float) and not isinstance(v, bool):
            v = [v]
        if not isinstance(v, list) or not v or len(v) > MAX_POSITIONS:
            raise FileKeyError(
                "drive.phi", v, f"must be a list of 1 … {MAX_POSITIONS} crank angles in degrees"
            )
        angles = [
            _number({f"phi.{i}": x}, f"phi.{i}", "drive", ge=-1.0e6, le=1.0e6, unit="°")
            for i, x in enumerate(v, start=1)
        ]
        phi = tuple(math.radians(math.remainder(a, 360.0)) for a in angles)
    v = drive.get("positions", 12)
    if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= MAX_POSITIONS:
        raise FileKeyError("drive.positions", v, f"must be a whole number 1 … {MAX_POSITIONS}")
    positions: int = v

    lk = Linkage(
        title=title,
        gravity=gravity,
        frame=frame,
        pivot=pivot,
        joint=joint,
        length=length,
        omega=omega,
        phi=phi,
        positions=positions,
        output="",
        working="forward",
        groups=(),
        points=(),
        masses={},
        loads=(),
        dynamics=None,
        sheet=sheet,
        owner=owner,
    )
    # groups in order; each [[point]] is known as soon as its link and what it names are
    pending = list(enumerate(_tables(data, "point"), start=1))
    lk = _take_points(lk, pending, owner, final=False)
    used_links = {1}
    for i, t in enumerate(_tables(data, "group"), start=1):
        g = _group(i, t, owner, used_links)
        _check_guide(lk, g)
        _check_sliding_point(lk, g)
        lk = _replace(lk, groups=(*lk.groups, g))
        lk = _take_points(lk, pending, owner, final=False)
    groups = list(lk.groups)
    if not groups:
        raise FileKeyError("group", None, "missing: a mechanism needs at least one [[group]]")
    lk = _take_points(lk, pending, owner, final=True)

    output, rocker = _output(lk, drive)
    lk = _replace(lk, output=output, rocker=rocker)

    masses = _masses(lk, _table(data, "links", "", required=False))
    loads, working, working_key = _loads(lk, _tables(data, "load"), output, _drive_working(drive))
    fpos, fphi = _forces(_table(data, "forces", "", required=False), positions)
    if (fpos is not None or fphi is not None) and not masses and not loads:
        raise FileKeyError(
            "forces", "", "the force analysis needs the links' masses ([links.N]) or loads"
        )
    dyn_t = _table(data, "dynamics", "", required=False)
    dynamics = _dynamics(dyn_t) if dyn_t else None
    if dynamics is not None and not masses:
        raise FileKeyError("dynamics", "", "needs the links' masses ([links.N] tables)")
    return _replace(
        lk,
        masses=masses,
        loads=loads,
        working=working,
        working_key=working_key,
        dynamics=dynamics,
        forces_position=fpos,
        forces_phi=fphi,
    )


def _drive_working(drive: Mapping[str, Any]) -> str | None:
    """``[drive] working`` when the file gives it."""
    if "working" not in drive:
        return None
    return _word("drive", drive, "working", ("forward", "backward"), "forward")


def _output(lk: Linkage, drive: Mapping[str, Any]) -> tuple[str, int]:
    """The output point and, for a rocker output, its link (linkages.md, second round).

    ``output`` names a point or a link number; without it the last group's slider (RRP,
    PRP), or for RRR/RPR its second link when that link turns about a frame point (else, as in
    the first round, its joint or slider, a point with no strokes)."""
    last = lk.groups[-1]
    if "output" not in drive:
        b = last.links[1]
        if last.kind in ("RRR", "RPR") and lk.frame_pivot(b):
            return _rocker_point(lk, b), b
        return last.joint or last.slider, 0
    v = drive["output"]
    if isinstance(v, int) and not isinstance(v, bool):
        if v not in lk.moving_links or v == 1:
            them = ", ".join(map(str, lk.moving_links[1:]))
            raise FileKeyError(
                "drive.output", v, f"link {v} is not a link of a group (they are {them})"
            )
        g = lk.group_of(v)
        assert g is not None
        if g.kind in ("RRP", "PRP") and v == g.links[1]:
            return g.joint, 0  # a slider's link: its joint
        if not lk.frame_pivot(v):
            raise FileKeyError(
                "drive.output",
                v,
                f"link {v} is neither a slider nor a rocker (a link turning about a frame point)",
            )
        return _rocker_point(lk, v), v
    output = _name("drive", drive, "output")
    if output not in lk.owner:
        raise FileKeyError(
            "drive.output", output, f'point "{output}" is not a point of the mechanism'
        )
    link = lk.owner[output]
    if link == 0:
        raise FileKeyError(
            "drive.output", output, f'point "{output}" is a frame point: it does not move'
        )
    if any(g.joint == output and g.kind in ("RRP", "PRP") for g in lk.groups):
        return output, 0
    return output, (link if lk.frame_pivot(link) else 0)


def _rocker_point(lk: Linkage, link: int) -> str:
    """The point that stands for a rocker output on the drawings: its moving joint (an RRR's
    joint), else its first [[point]], else the block's joint (an RPR's slider)."""
    g = lk.group_of(link)
    assert g is not None
    if g.kind == "RRR":
        return g.joint
    own = [p.name for p in lk.points if p.link == link]
    return own[0] if own else g.slider


def _forces(t: Mapping[str, Any], positions: int) -> tuple[int | None, float | None]:
    """``[forces] position`` or ``phi`` (rad in [0, 2π))."""
    if not t:
        return None, None
    _check_keys("forces", t, FORCES_KEYS)
    if "position" in t and "phi" in t:
        raise FileKeyError("forces", "", "give position or phi, not both")
    if "position" in t:
        v = t["position"]
        if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v < positions:
            raise FileKeyError(
                "forces.position",
                v,
                f"must be a numbered position 0 … {positions - 1} (drive.positions = {positions})",
            )
        return v, None
    if "phi" in t:
        a = _number(t, "phi", "forces", ge=-1.0e6, le=1.0e6, unit="°")
        return None, math.radians(a % 360.0) % (2.0 * math.pi)
    return None, None


def _replace(lk: Linkage, **kw: Any) -> Linkage:
    from dataclasses import replace

    return replace(lk, **kw)


def _known(where: str, name: str, owner: Mapping[str, int], key: str) -> None:
    if name not in owner:
        raise FileKeyError(where, name, f'{key}: point "{name}" is not known yet')


def _new(where: str, name: str, owner: dict[str, int], link: int, key: str) -> None:
    if name in owner:
        raise FileKeyError(where, name, f'{key}: point "{name}" is named twice')
    owner[name] = link


def _sliding_points(g: Group) -> tuple[tuple[str, str], ...]:
    """The points that name ``g``'s sliding pairs (their relative velocity and Coriolis
    acceleration are the pair's, keyed by the point), each with its file key: an RRP's slider
    joint, an RPR's slider, a PRP's point and slider."""
    if g.kind == "RRP":
        return (("joint", g.joint),)
    if g.kind == "RPR":
        return (("slider", g.slider),)
    if g.kind == "PRP":
        return (("point", g.joint), ("slider", g.slider))
    return ()


def _check_sliding_point(lk: Linkage, g: Group) -> None:
    """Two sliding pairs named by one point are refused: each pair's v_rel and a_cor belong
    to its point (review 10: an RPR block turning on an RRP's slider joint B stopped the
    solve with an internal error)."""
    for key, name in _sliding_points(g):
        for h in lk.groups:
            if name in (n for _, n in _sliding_points(h)):
                raise FileKeyError(
                    f"group {g.index}",
                    name,
                    f"{key}: {name} already names the sliding pair of group {h.index} "
                    f"({h.kind}); one point names one sliding pair: add a point on link "
                    f"{lk.owner.get(name, '…')} at {name} "
                    "([[point]] with along = 0, left = 0) and use it here",
                )


def _group(i: int, t: Mapping[str, Any], owner: dict[str, int], used: set[int]) -> Group:
    where = f"group {i}"
    kind = t.get("kind")
    if kind not in KINDS:
        raise FileKeyError(where, kind, f"kind must be one of {', '.join(KINDS)}, not {kind!r}")
    for k in t:
        if k not in GROUP_KEYS[kind]:
            raise FileKeyError(
                where, t[k], f"{k}: unknown key for a {kind} group" + _suggest(k, GROUP_KEYS[kind])
            )
    lv = t.get("links")
    if not isinstance(lv, list) or len(lv) != 2:
        raise FileKeyError(where, lv, "links must be the group's two link numbers, e.g. [2, 3]")
    links = (_link_no(f"{where}: links", lv[0]), _link_no(f"{where}: links", lv[1]))
    for n in links:
        if n < 2 or n > 99:
            raise FileKeyError(
                where, n, f"links: link {n} must be 2 … 99 (0 is the frame, 1 the crank)"
            )
        if n in used:
            raise FileKeyError(where, n, f"links: link {n} is used twice")
    if links[0] == links[1]:
        raise FileKeyError(where, links, "links: the two links must differ")
    used.update(links)
    b = links[1]
    if kind == "RRR":
        ends_v = t.get("ends")
        if (
            not isinstance(ends_v, list)
            or len(ends_v) != 2
            or not all(isinstance(e, str) for e in ends_v)
        ):
            raise FileKeyError(where, ends_v, 'ends must be two known points, e.g. ["A", "C"]')
        ends = (ends_v[0], ends_v[1])
        for e in ends:
            _known(where, e, owner, "ends")
        if ends[0] == ends[1]:
            raise FileKeyError(where, ends, "ends: the two ends must differ")
        lengths = _lengths(where, t, "lengths", 2)
        branch = 1 if _word(where, t, "assembly", ("left", "right"), "left") == "left" else -1
        joint = _name(where, t, "joint")
        _new(where, joint, owner, b, "joint")
        return Group(i, kind, links, joint=joint, ends=ends, lengths=lengths, branch=branch)
    if kind == "RRP":
        end = _name(where, t, "end")
        _known(where, end, owner, "end")
        lengths = _lengths(where, t, "length", 1)
        guide = _guide(where, t, owner, used_links=links)
        branch = (
            1
            if _word(where, t, "assembly", ("forward", "backward"), "forward") == "forward"
            else -1
        )
        joint = _name(where, t, "joint")
        _new(where, joint, owner, b, "joint")
        return Group(
            i, kind, links, joint=joint, ends=(end,), lengths=lengths, branch=branch, guide=guide
        )
    if kind == "RPR":
        slider = _name(where, t, "slider")
        _known(where, slider, owner, "slider")
        pivot = _name(where, t, "pivot")
        _known(where, pivot, owner, "pivot")
        if slider == pivot:
            raise FileKeyError(where, pivot, "pivot: the pivot and the slider must differ")
        offset = _number(t, "offset", where, default=0.0, ge=-MAX_LENGTH, le=MAX_LENGTH, unit="m")
        return Group(i, kind, links, slider=slider, pivot=pivot, offset=offset)
    # PRP
    slider = _name(where, t, "slider")
    _known(where, slider, owner, "slider")
    slot = _number(t, "slot_angle", where, default=90.0, ge=-360.0, le=360.0, unit="°")
    if abs(math.sin(math.radians(slot))) < MIN_SLOT_SIN:
        raise FileKeyError(
            where, slot, "slot_angle: the slot must not run along the guide (0° or 180°)"
        )
    guide = _guide(where, t, owner, used_links=links, fixed_only=True)
    joint = _name(where, t, "point")
    _new(where, joint, owner, b, "point")
    return Group(
        i, kind, links, joint=joint, slider=slider, guide=guide, slot_angle=math.radians(slot)
    )


def _guide(
    where: str,
    t: Mapping[str, Any],
    owner: Mapping[str, int],
    used_links: tuple[int, int],
    fixed_only: bool = False,
) -> Guide:
    g = t.get("guide")
    if not isinstance(g, dict):
        raise FileKeyError(
            where,
            g,
            "guide must be a table: { through = [x, y], angle = deg } "
            "or { link = N, from = …, toward = … }",
        )
    label = f"{where}: guide"
    if "link" not in g or fixed_only:
        for k in g:
            if k not in FIXED_GUIDE_KEYS:
                raise FileKeyError(
                    label,
                    g[k],
                    f"{k}: unknown key of a fixed guide" + _suggest(k, FIXED_GUIDE_KEYS),
                )
        through = _point(f"{label}.through", g.get("through", [0.0, 0.0]))
        angle = _number(g, "angle", label, default=0.0, ge=-360.0, le=360.0, unit="°")
        return Guide(0, through=through, angle=math.radians(angle))
    for k in g:
        if k not in MOVING_GUIDE_KEYS:
            raise FileKeyError(
                label,
                g[k],
                f"{k}: unknown key of a guide on a link" + _suggest(k, MOVING_GUIDE_KEYS),
            )
    link = _link_no(f"{label}.link", g["link"])
    if link == 0:
        raise FileKeyError(
            f"{label}.link", link, "0 is the frame: give a fixed guide { through, angle }"
        )
    if link in used_links:
        raise FileKeyError(
            f"{label}.link", link, "the guide must be on a link of an earlier group or the crank"
        )
    frm = _name(label, g, "from")
    toward = _name(label, g, "toward")
    for p in (frm, toward):
        _known(where, p, owner, "guide")
    offset = _number(
        g, "offset", f"{where}: guide", default=0.0, ge=-MAX_LENGTH, le=MAX_LENGTH, unit="m"
    )
    return Guide(link, frm=frm, toward=toward, offset=offset)


def _check_guide(lk: Linkage, g: Group) -> None:
    """A guide on a moving link must lie on the crank or an earlier group's link, through two
    points of that link."""
    gd = g.guide
    if gd is None or gd.fixed:
        return
    where = f"{g.key}: guide"
    if gd.link not in lk.moving_links:
        them = ", ".join(map(str, lk.moving_links))
        raise FileKeyError(
            where, gd.link, f"link: {gd.link} is not a link placed before (they are {them})"
        )
    on = lk.points_on(gd.link)
    for key, p in (("from", gd.frm), ("toward", gd.toward)):
        if p not in on:
            why = (
                f'{key}: point "{p}" is not a point of link {gd.link} (its points: {", ".join(on)})'
            )
            raise FileKeyError(where, p, why)
    if gd.frm == gd.toward:
        raise FileKeyError(where, gd.toward, "from and toward must differ")


def _take_points(
    lk: Linkage, pending: list[tuple[int, dict[str, Any]]], owner: dict[str, int], final: bool
) -> Linkage:
    """Add the pending ``[[point]]`` tables whose link is placed and whose ``from``/``toward``
    are known (removing them from ``pending``); with ``final``, any left over is an error."""
    progress = True
    while progress:
        progress = False
        for item in list(pending):
            p = _point_def(lk, *item, owner, final)
            if p is not None:
                pending.remove(item)
                owner[p.name] = p.link
                lk = _replace(lk, points=(*lk.points, p))
                progress = True
    return lk


def _point_def(
    lk: Linkage, i: int, t: dict[str, Any], owner: Mapping[str, int], final: bool
) -> PointDef | None:
    """The point table ``t`` (the i-th), or ``None`` while what it names is not known yet."""
    where = f"point {i}"
    _check_keys(where, t, POINT_KEYS)
    name = _name(where, t, "name")
    where = f'point "{name}"'
    link = _link_no(f"{where}: link", t.get("link"))
    if not 1 <= link <= 99:
        raise FileKeyError(where, link, f"link: {link} is not a moving link of the mechanism")
    frm = _name(where, t, "from")
    toward = _name(where, t, "toward")
    bounds: dict[str, Any] = {"default": 0.0, "ge": -MAX_LENGTH, "le": MAX_LENGTH, "unit": "m"}
    along = _number(t, "along", where, **bounds)
    left = _number(t, "left", where, **bounds)
    if name in owner:
        raise FileKeyError(where, name, f'name: point "{name}" is named twice')
    if link not in lk.moving_links:
        if final:
            raise FileKeyError(where, link, f"link: {link} is not a moving link of the mechanism")
        return None
    on = lk.points_on(link)
    if frm not in on:
        if final:
            why = f'from: point "{frm}" is not a point of link {link}'
            raise FileKeyError(where, frm, f"{why} (its points: {', '.join(on)})")
        return None
    slide = False
    if toward not in on:
        if not lk.has_slide(link) or toward not in owner:
            if final:
                why = f'toward: point "{toward}" is not a point of link {link}'
                raise FileKeyError(where, toward, f"{why} (its points: {', '.join(on)})")
            return None
        slide = True
    elif toward == frm:
        raise FileKeyError(where, toward, "toward: from and toward must differ")
    return PointDef(name, link, frm, toward, along, left, slide)


def _masses(lk: Linkage, t: Mapping[str, Any]) -> dict[int, Mass]:
    out: dict[int, Mass] = {}
    for k, v in t.items():
        where = f"links.{k}"
        if not k.isdigit() or int(k) not in lk.moving_links:
            raise FileKeyError(
                where,
                k,
                f"{k} is not a moving link (they are {', '.join(map(str, lk.moving_links))})",
            )
        if not isinstance(v, dict):
            raise FileKeyError(where, v, "must be a table with mass, J, centre")
        _check_keys(where, v, LINK_KEYS)
        n = int(k)
        mass = _number(v, "mass", where, default=0.0, ge=0.0, le=MAX_MASS, unit="kg")
        J = _number(v, "J", where, default=0.0, ge=0.0, le=MAX_MASS, unit="kg·m²")
        centre = ""
        if "centre" in v:
            centre = _name(where, v, "centre")
            if centre not in lk.points_on(n):
                raise FileKeyError(
                    f"{where}.centre", centre, f'point "{centre}" is not a point of link {n}'
                )
        out[n] = Mass(n, mass, J, centre)
    return out


def _loads(
    lk: Linkage, tables: list[dict[str, Any]], output: str, drive_working: str | None
) -> tuple[tuple[Load, ...], Literal["forward", "backward"], str]:
    out: list[Load] = []
    working = drive_working or "forward"
    said = "drive.working" if drive_working is not None else ""
    has_strokes = lk.rocker != 0 or lk.output_guide is not None
    for i, t in enumerate(tables, start=1):
        where = f"load {i}"
        _check_keys(where, t, LOAD_KEYS)
        if "moment" in t or "link" in t:
            if "point" in t or "value" in t:
                raise FileKeyError(
                    where,
                    "",
                    "a load is a force (point, value) or a moment (link, moment), not both",
                )
            link = _link_no(f"{where}: link", t.get("link"))
            if link not in lk.moving_links:
                raise FileKeyError(where, link, f"link: {link} is not a moving link")
            moment = _number(t, "moment", where, ge=-MAX_FORCE, le=MAX_FORCE, unit="N·m")
            if "shape" in t:
                raise FileKeyError(
                    f"{where}: shape", t["shape"], "a moment load has no shape (a force's only)"
                )
            on_stroke = "stroke" in t
            if "working" in t and not on_stroke:
                raise FileKeyError(
                    f"{where}: working",
                    t["working"],
                    "a moment load without stroke is a constant moment: working has no meaning",
                )
            stroke = _word(where, t, "stroke", ("working", "idle", "both"), "working")
            if on_stroke and not has_strokes:
                raise FileKeyError(
                    f"{where}: stroke",
                    stroke,
                    f'the output "{output}" is neither a slider nor a rocker: it has no strokes',
                )
            if "working" in t:
                working, said = _working(where, t, working, said)
            out.append(
                Load(i, link=link, moment=moment, stroke=stroke, on_stroke=on_stroke)  # type: ignore[arg-type]
            )
            continue
        point = _name(where, t, "point")
        if point not in lk.owner:
            raise FileKeyError(where, point, f'point: "{point}" is not a point of the mechanism')
        g = next((g for g in lk.groups if g.joint == point and g.kind in ("RRP", "PRP")), None)
        if g is None:
            raise FileKeyError(
                where,
                point,
                f'point: "{point}" is not a slider\'s joint (a force load acts along a guide)',
            )
        value = _number(t, "value", where, ge=0.0, le=MAX_FORCE, unit="N")
        stroke = _word(where, t, "stroke", ("working", "idle", "both"), "working")
        if point == output and "working" in t:
            working, said = _working(where, t, working, said)
        elif "working" in t:
            _word(where, t, "working", ("forward", "backward"), "forward")
        shape = _shape(where, t.get("shape"))
        out.append(Load(i, point=point, value=value, stroke=stroke, shape=shape))  # type: ignore[arg-type]
    if drive_working is not None and not has_strokes:
        raise FileKeyError(
            "drive.working",
            drive_working,
            f'the output "{output}" is neither a slider nor a rocker: it has no working stroke',
        )
    return tuple(out), working, said  # type: ignore[return-value]


def _shape(where: str, v: object) -> tuple[tuple[float, float], ...]:
    if v is None:
        return ()
    label = f"{where}: shape"
    if not isinstance(v, list) or len(v) < 2:
        raise FileKeyError(label, v, "must be a list of at least two [s/H, F/value] pairs")
    pts: list[tuple[float, float]] = []
    for j, p in enumerate(v, start=1):
        q = _point(f"{label}.{j}", p)
        pts.append((q.x, q.y))
    xs = [p[0] for p in pts]
    if xs[0] != 0.0 or xs[-1] != 1.0 or any(b <= a for a, b in itertools.pairwise(xs)):
        raise FileKeyError(label, v, "its s/H values must rise strictly from 0 to 1")
    return tuple(pts)


def _dynamics(t: Mapping[str, Any]) -> Dynamics:
    _check_keys("dynamics", t, DYNAMICS_KEYS)
    delta = _number(t, "delta", "dynamics", gt=0.0, lt=1.0)
    drive = _word("dynamics", t, "drive", ("constant",), "constant")
    fly = _word("dynamics", t, "flywheel", ("disc", "rim"), "disc")
    density = _number(t, "density", "dynamics", default=7800.0, gt=0.0, le=1.0e5, unit="kg/m³")
    ratio = _number(t, "ratio", "dynamics", default=0.2, gt=0.0, le=1.0)
    return Dynamics(delta, drive, fly, density, ratio)  # type: ignore[arg-type]

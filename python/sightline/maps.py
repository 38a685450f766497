"""Sightline maps written from Python: a small model of sectors, the
regions (polygons) that draw them, line overrides and things, written
out as a RON map in format version 2 (``docs/map-format.md``) for
:func:`sightline.make_scenario`, :func:`sightline.check` or a file.

    from sightline.maps import Map

    m = Map("Goal")
    hall = m.room(0, 0, 512, 256)                          # sector 0
    goal = m.room(512, 64, 640, 192, light=255)            # sector 1, sharing the wall x = 512
    m.player_start(64, 128, angle=0)
    m.thing("imp", 400, 200, angle=180)
    m.thing("medikit", 256, 64)
    text = m.to_ron()

Lines are not written by hand: every region's outline becomes lines, an
edge drawn by two regions (of different sectors, in opposite directions)
a two-sided line between them, an edge drawn once a wall. Outlines are
turned as the format wants them (rooms clockwise, holes counter-clockwise,
y up), and every edge is split where another region's corner lies on it,
so rooms of different sizes may share a wall. Two regions that overlap
raise ``ValueError``; what else is wrong with the geometry (crossing
lines, a thing outside every sector) the engine's validation says, in
:func:`sightline.check`.

Coordinates should be exact binary fractions (whole numbers are) within
Doom's ±32767, the range the simulation stores.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction
from typing import Any, Iterable, Optional, Sequence

__all__ = ["Map"]

Point = tuple


def _num(v: Any) -> str:
    """A number as the map format writes it: a decimal point, no exponent."""
    v = float(v)
    if not math.isfinite(v):
        raise ValueError(f"{v} is not a finite number")
    s = repr(v)
    if "e" in s or "E" in s:
        s = f"{v:.10f}".rstrip("0")
    if "." not in s:
        s += ".0"
    if s.endswith("."):
        s += "0"
    return s


def _str(s: str) -> str:
    return json.dumps(str(s))


def _area2(pts: Sequence[Point]) -> Fraction:
    s = Fraction(0)
    for i in range(len(pts)):
        (x1, y1), (x2, y2) = pts[i], pts[(i + 1) % len(pts)]
        s += Fraction(x1) * Fraction(y2) - Fraction(x2) * Fraction(y1)
    return s


def _turned(pts: Iterable[Point], clockwise: bool) -> list:
    pts = [(float(x), float(y)) for x, y in pts]
    if len(pts) < 3:
        raise ValueError(f"a region needs at least 3 corners, not {len(pts)}")
    area = _area2(pts)
    if area == 0:
        raise ValueError(f"the region {pts} has no area")
    return pts if (area < 0) == clockwise else pts[::-1]


class Map:
    """A map being drawn: sectors, the regions that draw them, line
    overrides (textures, specials such as an exit) and things."""

    def __init__(self, name: str = "Made in Python", sky: Optional[str] = None):
        self.name = name
        self.sky = sky
        self._sectors: list = []
        self._loops: list = []  # (sector, points, wall)
        self._edges: list = []  # (p, q, line fields, side fields)
        self._things: list = []

    # ---- sectors and regions ---------------------------------------------

    def sector(
        self,
        floor: float = 0.0,
        ceiling: float = 128.0,
        light: int = 160,
        floor_texture: Optional[str] = "FLOOR",
        ceiling_texture: Optional[str] = "CEIL",
        wall: str = "BRICK",
        damage: Any = None,
        secret: bool = False,
        tag: int = 0,
    ) -> int:
        """A new sector; returns its index (what a reward's ``reach``
        names). ``damage`` hurts a player standing on its floor: a number
        (that much every 32 tics, as Doom's nukage 5, 10 and 20) or a dict
        of the format's ``Damage`` fields (``amount``, ``every``,
        ``exit_below``, ``suit``). ``secret`` counts it as a secret when
        first entered. ``wall`` is the texture of its one-sided walls."""
        if not 0 <= int(light) <= 255:
            raise ValueError(f"sector {len(self._sectors)}: light {light} is outside 0..=255")
        if float(floor) > float(ceiling):
            raise ValueError(f"sector {len(self._sectors)}: floor {floor} is above ceiling {ceiling}")
        if isinstance(damage, (int, float)) and not isinstance(damage, bool):
            damage = {"amount": int(damage)}
        self._sectors.append(
            dict(
                floor=float(floor),
                ceiling=float(ceiling),
                light=int(light),
                floor_texture=floor_texture,
                ceiling_texture=ceiling_texture,
                wall=wall,
                damage=damage,
                secret=bool(secret),
                tag=int(tag),
            )
        )
        return len(self._sectors) - 1

    def region(
        self,
        sector: int,
        points: Sequence[Point],
        holes: Sequence[Sequence[Point]] = (),
        wall: Optional[str] = None,
    ) -> None:
        """Draws ``sector`` over the polygon ``points`` (corners in either
        order), less ``holes`` (pillars: solid, walled with ``wall`` or the
        sector's)."""
        self._sector_index(sector)
        self._loops.append((sector, _turned(points, clockwise=True), wall))
        for h in holes:
            self._loops.append((sector, _turned(h, clockwise=False), wall))

    def room(self, x0: float, y0: float, x1: float, y1: float, **sector: Any) -> int:
        """A rectangle from ``(x0, y0)`` to ``(x1, y1)`` as a new sector
        (keyword arguments as :meth:`sector`); returns its index."""
        if x0 == x1 or y0 == y1:
            raise ValueError(f"the room ({x0}, {y0})-({x1}, {y1}) has no area")
        s = self.sector(**sector)
        self.region(s, [(x0, y0), (x0, y1), (x1, y1), (x1, y0)])
        return s

    def _sector_index(self, sector: int) -> None:
        if not isinstance(sector, int) or not 0 <= sector < len(self._sectors):
            raise ValueError(f"sector {sector!r} is not one of this map's (0..{len(self._sectors)})")

    # ---- lines -----------------------------------------------------------

    def edge(
        self,
        p: Point,
        q: Point,
        *,
        middle: Optional[str] = None,
        upper: Optional[str] = None,
        lower: Optional[str] = None,
        impassable: Optional[bool] = None,
        block_monsters: Optional[bool] = None,
        special: Optional[str] = None,
    ) -> None:
        """Overrides every line lying on the segment ``p``-``q``: side
        textures (both sides), flags, or a line special in the format's RON
        (``"LineSpecial(on: Use, action: Exit)"``). Matching no line is an
        error when the map is written."""
        flags = (("impassable", impassable), ("block_monsters", block_monsters), ("special", special))
        line = {k: v for k, v in flags if v is not None}
        side = {k: v for k, v in (("middle", middle), ("upper", upper), ("lower", lower)) if v is not None}
        self._edges.append(((float(p[0]), float(p[1])), (float(q[0]), float(q[1])), line, side))

    def exit(self, p: Point, q: Point, on: str = "Walk") -> None:
        """The lines on ``p``-``q`` end the level: crossed (``on="Walk"``),
        used (``"Use"``: a switch, facing the line's front) or shot."""
        if on not in ("Walk", "Use", "Shoot"):
            raise ValueError(f"an exit is set off on Walk, Use or Shoot, not {on!r}")
        self.edge(p, q, special=f"LineSpecial(on: {on}, action: Exit)")

    # ---- things ----------------------------------------------------------

    def thing(
        self,
        kind: str,
        x: float,
        y: float,
        angle: float = 0.0,
        *,
        skills: Optional[Sequence[str]] = None,
        ambush: bool = False,
    ) -> int:
        """A thing of type ``kind`` (the actor table's names:
        ``"player_start"``, ``"imp"``, ``"medikit"``, ``"clip"``, ...) at
        ``(x, y)`` facing ``angle`` degrees (0 east, 90 north); ``skills``
        a subset of ``("Easy", "Medium", "Hard")``, ``ambush`` a monster
        that waits deaf until it sees the player. Returns its index."""
        fields = [f"kind: {_str(kind)}", f"x: {_num(x)}", f"y: {_num(y)}", f"angle: {_num(angle)}"]
        if skills is not None:
            for s in skills:
                if s not in ("Easy", "Medium", "Hard"):
                    raise ValueError(f"thing {len(self._things)}: skill {s!r} is not Easy, Medium or Hard")
            fields.append(f"skills: [{', '.join(skills)}]")
        if ambush:
            fields.append("ambush: true")
        self._things.append(", ".join(fields))
        return len(self._things) - 1

    def player_start(self, x: float, y: float, angle: float = 0.0) -> int:
        """Where the player starts, facing ``angle`` degrees."""
        return self.thing("player_start", x, y, angle)

    # ---- writing ---------------------------------------------------------

    def build(self) -> tuple:
        """The map's vertices and lines: ``([(x, y)], [dict])``, each line
        ``from``, ``to``, ``front`` and ``back`` (a side dict or None) and
        its flags."""
        index: dict = {}
        vertices: list = []

        def vid(p: Point) -> int:
            if p not in index:
                index[p] = len(vertices)
                vertices.append(p)
            return index[p]

        for _, pts, _ in self._loops:
            for p in pts:
                vid(p)
        exact = [(Fraction(x), Fraction(y)) for x, y in vertices]

        def inside(a: int, b: int) -> list:
            (ax, ay), (bx, by) = exact[a], exact[b]
            found = []
            for k, (px, py) in enumerate(exact):
                if k in (a, b) or (bx - ax) * (py - ay) != (by - ay) * (px - ax):
                    continue
                if min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by):
                    found.append(((px - ax) * (bx - ax) + (py - ay) * (by - ay), k))
            return [k for _, k in sorted(found)]

        uses: dict = {}
        order: list = []
        for sector, pts, wall in self._loops:
            ids = [vid(p) for p in pts]
            for i in range(len(ids)):
                chain = [ids[i]] + inside(ids[i], ids[(i + 1) % len(ids)]) + [ids[(i + 1) % len(ids)]]
                for u, v in zip(chain, chain[1:]):
                    key = frozenset((u, v))
                    if key not in uses:
                        uses[key] = []
                        order.append(key)
                    uses[key].append((sector, u, v, wall))
        lines = []
        for key in order:
            drawn = uses[key]
            if len(drawn) == 1:
                s, u, v, wall = drawn[0]
                front = {"sector": s, "middle": wall or self._sectors[s]["wall"]}
                lines.append({"from": u, "to": v, "front": front, "back": None})
                continue
            if len(drawn) > 2 or drawn[0][0] == drawn[1][0] or (drawn[0][1], drawn[0][2]) != (drawn[1][2], drawn[1][1]):
                a, b = (vertices[k] for k in sorted(key))
                sectors = sorted({d[0] for d in drawn})
                raise ValueError(f"regions of sectors {sectors} overlap at the edge {a}-{b}")
            lines.append(self._two_sided(drawn[0], drawn[1]))
        self._override(vertices, lines)
        return vertices, lines

    def _two_sided(self, one: tuple, other: tuple) -> dict:
        # The front is the sector with the higher floor (then the lower
        # ceiling): the step's riser faces down into the other.
        (s1, u1, v1, _), (s2, _, _, _) = one, other
        f1, f2 = self._sectors[s1], self._sectors[s2]
        if (f2["floor"], -f2["ceiling"]) > (f1["floor"], -f1["ceiling"]):
            (s1, u1, v1, _), (s2, _, _, _) = other, one
            f1, f2 = f2, f1
        front, back = {"sector": s1}, {"sector": s2}
        higher = f1 if f1["floor"] > f2["floor"] else f2
        lower_ceiling = f1 if f1["ceiling"] < f2["ceiling"] else f2
        both_sky = f1["ceiling_texture"] == "SKY" and f2["ceiling_texture"] == "SKY"
        for side in (front, back):
            if f1["floor"] != f2["floor"]:
                side["lower"] = higher["wall"]
            if f1["ceiling"] != f2["ceiling"] and not both_sky:
                side["upper"] = lower_ceiling["wall"]
        return {"from": u1, "to": v1, "front": front, "back": back}

    def _override(self, vertices: list, lines: list) -> None:
        def on(p: Point, a: Point, b: Point) -> bool:
            (px, py), (ax, ay), (bx, by) = [(Fraction(x), Fraction(y)) for x, y in (p, a, b)]
            if (bx - ax) * (py - ay) != (by - ay) * (px - ax):
                return False
            return min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by)

        for p, q, line, side in self._edges:
            hit = [ln for ln in lines if on(vertices[ln["from"]], p, q) and on(vertices[ln["to"]], p, q)]
            if not hit:
                raise ValueError(f"the edge override {p}-{q} lies on no line of the map")
            for ln in hit:
                ln.update(line)
                for s in (ln["front"], ln["back"]):
                    if s is not None:
                        s.update(side)

    def to_ron(self) -> str:
        """The map as RON text (format version 2)."""
        vertices, lines = self.build()
        out = ["// Written by sightline.maps.", "Map(", "    version: 2,", f"    name: {_str(self.name)},"]
        if self.sky is not None:
            out.append(f"    sky: {_str(self.sky)},")
        out.append("    vertices: [")
        out += [f"        ({_num(x)}, {_num(y)}), // {k}" for k, (x, y) in enumerate(vertices)]
        out.append("    ],")
        out.append("    sectors: [")
        for k, s in enumerate(self._sectors):
            fields = [f"floor: {_num(s['floor'])}", f"ceiling: {_num(s['ceiling'])}", f"light: {s['light']}"]
            for key in ("floor_texture", "ceiling_texture"):
                if s[key]:
                    fields.append(f"{key}: {_str(s[key])}")
            if s["tag"]:
                fields.append(f"tag: {s['tag']}")
            special = []
            if s["damage"]:
                fields_of = s["damage"].items()
                damage = ", ".join(f"{k}: {v if isinstance(v, (int, str)) else _num(v)}" for k, v in fields_of)
                special.append(f"damage: Damage({damage})")
            if s["secret"]:
                special.append("secret: true")
            if special:
                fields.append(f"special: SectorSpecial({', '.join(special)})")
            out.append(f"        Sector({', '.join(fields)}), // {k}")
        out.append("    ],")
        out.append("    lines: [")
        for k, ln in enumerate(lines):
            fields = [f"from: {ln['from']}", f"to: {ln['to']}", f"front: {_side(ln['front'])}"]
            if ln["back"] is not None:
                fields.append(f"back: {_side(ln['back'])}")
            for flag in ("impassable", "block_monsters"):
                if ln.get(flag):
                    fields.append(f"{flag}: true")
            if ln.get("special"):
                fields.append(f"special: {ln['special']}")
            out.append(f"        Line({', '.join(fields)}), // {k}")
        out.append("    ],")
        out.append("    things: [")
        out += [f"        Thing({t})," for t in self._things]
        out.append("    ],")
        out.append(")")
        return "\n".join(out) + "\n"

    def save(self, path: str) -> None:
        """Writes the map to ``path`` (a ``.ron`` file ``sightline play``
        and ``sightline check`` read)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_ron())

    def check(self, rewards: Any = None, skill: int = 3) -> list:
        """:func:`sightline.check` on this map."""
        from .made import check

        return check(self, rewards=rewards, skill=skill)


def _side(side: dict) -> str:
    fields = [f"sector: {side['sector']}"]
    for key in ("upper", "middle", "lower"):
        if side.get(key):
            fields.append(f"{key}: {_str(side[key])}")
    return f"Side({', '.join(fields)})"

#!/usr/bin/env python3
"""Independent checker for Sightline sector maps (RON), stdlib only.

Usage:  python3 maps/generators/check.py [--textures] [MAP.ron ...]
        (no arguments: every maps/*.ron next to this script's parent folder)

It parses the RON subset used by the map format (structs, tuples, lists,
strings, numbers, Some(...)/None, // and /* */ comments) and checks:

  R1  every sector is closed: for each sector S, take each line side that
      references S, directed so that S is on its right (front: from->to,
      back: to->from); at every vertex in-degree == out-degree.  Also: every
      sector's signed area (from those directed edges) is positive, i.e. its
      outer boundary runs clockwise and holes counter-clockwise.
  R2  no two lines cross or overlap (not even collinear partial overlap), no
      vertex lies strictly inside a line, no duplicate lines, no zero-length
      line, no two distinct vertices at identical coordinates.
  R3  |coordinate| <= 2^24, |height| <= 2^24, floor <= ceiling, light 0..=255.
  R4  exactly one player_start; it lies inside exactly one sector (crossing
      number over that sector's line sides) and at least 1 unit from every
      line.  Every other thing must lie inside a sector too.
  R6  the map is closed and consistent: from the midpoint of every line a ray
      is cast into each of its two sides; the first line it hits must present
      the same thing towards it: the same sector, or solid space (the back of
      a one-sided wall) when looking out of the back of a one-sided wall.  A
      sector side that sees nothing means the map leaks.  This also checks
      that a two-sided line's front sector is on its right, and catches
      pillars wound the wrong way and overlapping regions.

All geometry is exact: every coordinate is a binary float, so all of them are
scaled by one common power of two into Python integers.  A uniform grid keeps
the pairwise tests fast enough for maps with many thousands of lines.

  R7  (only with --textures) texturing follows the Doom conventions: every
      sector has a floor and a ceiling texture; every one-sided line has a
      middle texture; on a two-sided line, a side whose neighbour has a higher
      floor has a lower texture and a side whose neighbour has a lower ceiling
      has an upper texture (unless both ceilings are SKY); a middle texture on a
      two-sided line is a masked one (GRATE, FENCE).

Also parsed and checked: the optional Map fields `diminishing_light` (true or
false) and `fog: Some(Fog(colour: (r, g, b), distance: D))` (channels
0..=255, D finite and > 0); the Line flags `upper_unpegged`,
`lower_unpegged`, `impassable`, `door` (an error on a one-sided line); the
Side offsets `x_offset`, `y_offset`.

Warnings (not failures): coordinates not exactly representable as f32,
unused vertices, sectors unreachable from the player start, two-sided lines
with no vertical opening (except door lines: a shut door has none),
`impassable` on a one-sided line.
"""

import math
import os
import re
import struct
import sys
from fractions import Fraction

LIMIT = 16777216
TEXTURES = {"BRICK", "STONE", "WOOD", "METAL", "TILE", "FLOOR", "STEP", "SKY",
            "DOOR", "SUPPORT", "GRATE", "FENCE", "GRASS", "WATER", "CEIL", "DIRT",
            "SWITCH1", "SWITCH2", "EXITSW1", "EXITSW2", "CHEVRON", "GOO1", "GOO2", "GOO3", "TELEPAD"}
MASKED_TEXTURES = {"GRATE", "FENCE"}
THING_KINDS = {"player_start", "lamp", "barrel", "column", "torch", "crate", "plant", "statue"}
# Fields of map format version 2 (specials, thing flags): the engine checks
# what they mean; this checker accepts them and checks the geometry.
SPECIAL_MAP_FIELDS = ("version", "sky", "trigger_lines")
SPECIAL_SECTOR_FIELDS = ("tag", "special", "floor_light", "ceiling_light", "carry")
SPECIAL_LINE_FIELDS = ("trigger", "special", "translucent")
SPECIAL_THING_FIELDS = ("skills", "ambush", "multiplayer", "not_in")


# ---------------------------------------------------------------- RON parsing
class RonError(Exception):
    pass


class Num:
    __slots__ = ("text",)

    def __init__(self, text):
        self.text = text

    @property
    def is_float_literal(self):
        return "." in self.text or "e" in self.text.lower()

    def __float__(self):
        return float(self.text)

    def __repr__(self):
        return self.text


class Ident:
    __slots__ = ("name",)

    def __init__(self, name):
        self.name = name

    def __repr__(self):
        return self.name


class Struct:
    """Name(...) or (...).  `fields` is a dict (named) or list (positional)."""

    __slots__ = ("name", "fields", "line")

    def __init__(self, name, fields, line):
        self.name, self.fields, self.line = name, fields, line

    def __repr__(self):
        return f"{self.name}({self.fields!r})"


TOKEN_RE = re.compile(
    r"""(?P<ws>\s+)
      | (?P<lc>//[^\n]*)
      | (?P<bc>/\*.*?\*/)
      | (?P<str>"(?:[^"\\]|\\.)*")
      | (?P<num>[-+]?(?:\d[\d_]*(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)
      | (?P<id>[A-Za-z_][A-Za-z0-9_]*)
      | (?P<p>[()\[\],:])
    """,
    re.S | re.X,
)


def tokenize(text):
    toks, pos, line = [], 0, 1
    while pos < len(text):
        m = TOKEN_RE.match(text, pos)
        if not m:
            raise RonError(f"line {line}: unexpected character {text[pos]!r}")
        kind = m.lastgroup
        if kind not in ("ws", "lc", "bc"):
            toks.append((kind, m.group(), line))
        line += m.group().count("\n")
        pos = m.end()
    toks.append(("eof", "", line))
    return toks


class Parser:
    def __init__(self, text):
        self.toks = tokenize(text)
        self.i = 0

    def peek(self, k=0):
        return self.toks[self.i + k]

    def take(self, value=None):
        tok = self.toks[self.i]
        if value is not None and tok[1] != value:
            raise RonError(f"line {tok[2]}: expected {value!r}, found {tok[1]!r}")
        self.i += 1
        return tok

    def value(self):
        kind, text, line = self.peek()
        if kind == "str":
            self.take()
            return bytes(text[1:-1], "utf-8").decode("unicode_escape")
        if kind == "num":
            self.take()
            return Num(text)
        if kind == "id":
            self.take()
            if self.peek()[1] == "(":
                return self.group(text, line)
            return Ident(text)
        if text == "(":
            return self.group(None, line)
        if text == "[":
            self.take("[")
            items = []
            while self.peek()[1] != "]":
                items.append(self.value())
                if self.peek()[1] == ",":
                    self.take(",")
                elif self.peek()[1] != "]":
                    raise RonError(f"line {self.peek()[2]}: expected ',' or ']'")
            self.take("]")
            return items
        raise RonError(f"line {line}: unexpected token {text!r}")

    def group(self, name, line):
        self.take("(")
        named = self.peek()[0] == "id" and self.peek(1)[1] == ":"
        fields = {} if named else []
        while self.peek()[1] != ")":
            if named:
                key = self.take()[1]
                self.take(":")
                if key in fields:
                    raise RonError(f"line {line}: duplicate field {key!r}")
                fields[key] = self.value()
            else:
                fields.append(self.value())
            if self.peek()[1] == ",":
                self.take(",")
            elif self.peek()[1] != ")":
                raise RonError(f"line {self.peek()[2]}: expected ',' or ')'")
        self.take(")")
        return Struct(name, fields, line)


def parse_ron(text):
    p = Parser(text)
    v = p.value()
    if p.peek()[0] != "eof":
        raise RonError(f"line {p.peek()[2]}: trailing input {p.peek()[1]!r}")
    return v


# ---------------------------------------------------------------- map model
class MapData:
    pass


def load_map(path, errors, warnings):
    """Parse and structurally check a map file; returns MapData or None."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        root = parse_ron(text)
    except RonError as e:
        errors.append(f"parse: {e}")
        return None
    if not isinstance(root, Struct) or root.name != "Map" or not isinstance(root.fields, dict):
        errors.append("parse: top level must be Map(...) with named fields")
        return None
    f = root.fields
    for key in f:
        if key not in ("name", "vertices", "sectors", "lines", "things", "diminishing_light", "fog") \
                + SPECIAL_MAP_FIELDS:
            warnings.append(f"unknown Map field {key!r}")
    for key in ("name", "vertices", "sectors", "lines", "things"):
        if key not in f:
            errors.append(f"parse: Map is missing field {key!r}")
    if errors:
        return None

    def num(v, what, want_float):
        if not isinstance(v, Num):
            raise RonError(f"{what}: expected a number, found {v!r}")
        if want_float and not v.is_float_literal:
            raise RonError(f"{what}: float written without a decimal point ({v.text})")
        if not want_float:
            if v.is_float_literal:
                raise RonError(f"{what}: expected an integer, found {v.text}")
            return int(v.text)
        x = float(v)
        if not math.isfinite(x):
            raise RonError(f"{what}: not finite")
        return x

    def boolean(v, what):
        if not (isinstance(v, Ident) and v.name in ("true", "false")):
            raise RonError(f"{what}: expected true or false, found {v!r}")
        return v.name == "true"

    def tex(side_or_sector, key, what):
        v = side_or_sector.get(key)
        if v is None:
            return None
        if not isinstance(v, str):
            raise RonError(f"{what}.{key}: expected a string")
        if v not in TEXTURES:
            raise RonError(f"{what}.{key}: unknown texture {v!r}")
        return v

    m = MapData()
    m.name = f["name"]
    try:
        if not isinstance(m.name, str):
            raise RonError("name: expected a string")
        m.diminishing_light = boolean(f["diminishing_light"], "diminishing_light") \
            if "diminishing_light" in f else True
        m.fog = None
        fog = f.get("fog")
        if isinstance(fog, Struct) and fog.name == "Some" and isinstance(fog.fields, list) \
                and len(fog.fields) == 1:
            fog = fog.fields[0]
        if fog is None or (isinstance(fog, Ident) and fog.name == "None"):
            pass
        elif isinstance(fog, Struct) and fog.name in ("Fog", None) and isinstance(fog.fields, dict):
            for key in fog.fields:
                if key not in ("colour", "distance"):
                    raise RonError(f"fog: unknown field {key!r}")
            for key in ("colour", "distance"):
                if key not in fog.fields:
                    raise RonError(f"fog: missing {key!r}")
            col = fog.fields["colour"]
            if not (isinstance(col, Struct) and col.name is None and isinstance(col.fields, list)
                    and len(col.fields) == 3):
                raise RonError("fog.colour: expected (r, g, b)")
            rgb = tuple(num(c, "fog.colour", False) for c in col.fields)
            if not all(0 <= c <= 255 for c in rgb):
                raise RonError(f"fog.colour: {rgb} has a channel outside 0..=255")
            d = fog.fields["distance"]
            if not isinstance(d, Num):
                raise RonError("fog.distance: expected a number")
            dist = float(d)
            if not (math.isfinite(dist) and dist > 0):
                raise RonError(f"fog.distance: {d.text} must be finite and above 0")
            m.fog = (rgb, dist)
        else:
            raise RonError("fog: expected Some(Fog(colour: (r, g, b), distance: D)) or None")
        m.verts = []
        for k, v in enumerate(f["vertices"]):
            if not isinstance(v, Struct) or v.name is not None or not isinstance(v.fields, list) or len(v.fields) != 2:
                raise RonError(f"vertex {k}: expected (x, y)")
            m.verts.append((num(v.fields[0], f"vertex {k} x", True), num(v.fields[1], f"vertex {k} y", True)))
        m.sectors = []
        for k, s in enumerate(f["sectors"]):
            if not isinstance(s, Struct) or s.name != "Sector" or not isinstance(s.fields, dict):
                raise RonError(f"sector {k}: expected Sector(...)")
            sf = s.fields
            for key in sf:
                if key not in ("floor", "ceiling", "light", "floor_texture", "ceiling_texture") + SPECIAL_SECTOR_FIELDS:
                    raise RonError(f"sector {k}: unknown field {key!r}")
            for key in ("floor", "ceiling", "light"):
                if key not in sf:
                    raise RonError(f"sector {k}: missing {key!r}")
            m.sectors.append(dict(
                floor=num(sf["floor"], f"sector {k} floor", True),
                ceiling=num(sf["ceiling"], f"sector {k} ceiling", True),
                light=num(sf["light"], f"sector {k} light", False),
                floor_texture=tex(sf, "floor_texture", f"sector {k}"),
                ceiling_texture=tex(sf, "ceiling_texture", f"sector {k}"),
            ))

        def side(v, what):
            if not isinstance(v, Struct) or v.name != "Side" or not isinstance(v.fields, dict):
                raise RonError(f"{what}: expected Side(...)")
            for key in v.fields:
                if key not in ("sector", "upper", "middle", "lower", "x_offset", "y_offset", "scroll"):
                    raise RonError(f"{what}: unknown field {key!r}")
            for key in ("x_offset", "y_offset"):
                if key in v.fields:
                    o = v.fields[key]
                    if not isinstance(o, Num) or not math.isfinite(float(o)):
                        raise RonError(f"{what}.{key}: expected a finite number")
            if "sector" not in v.fields:
                raise RonError(f"{what}: missing sector")
            d = {"sector": num(v.fields["sector"], f"{what} sector", False)}
            for key in ("upper", "middle", "lower"):
                d[key] = tex(v.fields, key, what)
            return d

        m.lines = []
        for k, ln in enumerate(f["lines"]):
            if not isinstance(ln, Struct) or ln.name != "Line" or not isinstance(ln.fields, dict):
                raise RonError(f"line {k}: expected Line(...)")
            lf = ln.fields
            for key in lf:
                if key not in ("from", "to", "front", "back", "upper_unpegged", "lower_unpegged",
                               "impassable", "door") + SPECIAL_LINE_FIELDS:
                    raise RonError(f"line {k}: unknown field {key!r}")
            for key in ("from", "to", "front"):
                if key not in lf:
                    raise RonError(f"line {k}: missing {key!r}")
            back = lf.get("back")
            if isinstance(back, Ident) and back.name == "None":
                back = None
            elif back is not None:
                if not (isinstance(back, Struct) and back.name == "Some" and isinstance(back.fields, list)
                        and len(back.fields) == 1):
                    raise RonError(f"line {k}: back must be Some(Side(...)) or None")
                back = side(back.fields[0], f"line {k} back")
            m.lines.append(dict(
                a=num(lf["from"], f"line {k} from", False),
                b=num(lf["to"], f"line {k} to", False),
                front=side(lf["front"], f"line {k} front"),
                back=back,
                **{key: boolean(lf[key], f"line {k} {key}") if key in lf else False
                   for key in ("upper_unpegged", "lower_unpegged", "impassable", "door")},
            ))
        m.things = []
        for k, t in enumerate(f["things"]):
            if not isinstance(t, Struct) or t.name != "Thing" or not isinstance(t.fields, dict):
                raise RonError(f"thing {k}: expected Thing(...)")
            tf = t.fields
            for key in ("kind", "x", "y", "angle"):
                if key not in tf:
                    raise RonError(f"thing {k}: missing {key!r}")
            for key in tf:
                if key not in ("kind", "x", "y", "angle") + SPECIAL_THING_FIELDS:
                    raise RonError(f"thing {k}: unknown field {key!r}")
            if not isinstance(tf["kind"], str):
                raise RonError(f"thing {k}: kind must be a string")
            m.things.append(dict(
                kind=tf["kind"],
                x=num(tf["x"], f"thing {k} x", True),
                y=num(tf["y"], f"thing {k} y", True),
                angle=num(tf["angle"], f"thing {k} angle", True),
            ))
    except RonError as e:
        errors.append(f"parse: {e}")
        return None
    return m


# ---------------------------------------------------------------- exact geometry
def orient(ax, ay, bx, by, cx, cy):
    """> 0 if c is left of a->b, < 0 if right, 0 if collinear (exact ints)."""
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def sgn(v):
    return (v > 0) - (v < 0)


def on_segment_strict(ax, ay, bx, by, px, py):
    """p collinear with a-b and strictly between the endpoints."""
    if orient(ax, ay, bx, by, px, py) != 0:
        return False
    if (px, py) == (ax, ay) or (px, py) == (bx, by):
        return False
    return min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by)


def segment_problem(p, q):
    """Relation of two segments given as ((ax,ay,ia),(bx,by,ib)).

    Returns None if they are disjoint or only share an endpoint vertex,
    otherwise a description.
    """
    (ax, ay, ia), (bx, by, ib) = p
    (cx, cy, ic), (dx, dy, id_) = q
    if {ia, ib} == {ic, id_}:
        return "duplicate line (same vertex pair)"
    if {(ax, ay), (bx, by)} == {(cx, cy), (dx, dy)}:
        return "duplicate line (same coordinates)"
    o1 = sgn(orient(ax, ay, bx, by, cx, cy))
    o2 = sgn(orient(ax, ay, bx, by, dx, dy))
    o3 = sgn(orient(cx, cy, dx, dy, ax, ay))
    o4 = sgn(orient(cx, cy, dx, dy, bx, by))
    if o1 == 0 and o2 == 0:
        # Collinear: project on the dominant axis.
        if ax != bx:
            lo1, hi1, lo2, hi2 = min(ax, bx), max(ax, bx), min(cx, dx), max(cx, dx)
        else:
            lo1, hi1, lo2, hi2 = min(ay, by), max(ay, by), min(cy, dy), max(cy, dy)
        lo, hi = max(lo1, lo2), min(hi1, hi2)
        if lo < hi:
            return "collinear overlap"
        if lo == hi:
            # Touch in one point, which is an endpoint of both.
            shared = {(ax, ay), (bx, by)} & {(cx, cy), (dx, dy)}
            if shared and len({ia, ib} & {ic, id_}) == 1:
                return None
            return "collinear lines touch at an endpoint without sharing the vertex"
        return None
    if o1 * o2 < 0 and o3 * o4 < 0:
        return "lines cross"
    # Touching cases: an endpoint of one lies on the other.
    for (px, py, ip), (sx, sy, _), (tx, ty, _), (us, ut) in (
        ((cx, cy, ic), (ax, ay, ia), (bx, by, ib), (ia, ib)),
        ((dx, dy, id_), (ax, ay, ia), (bx, by, ib), (ia, ib)),
        ((ax, ay, ia), (cx, cy, ic), (dx, dy, id_), (ic, id_)),
        ((bx, by, ib), (cx, cy, ic), (dx, dy, id_), (ic, id_)),
    ):
        if on_segment_strict(sx, sy, tx, ty, px, py):
            return f"vertex {ip} lies inside the other line (T-junction)"
        if (px, py) in ((sx, sy), (tx, ty)) and ip not in (us, ut):
            return "lines touch at equal coordinates but different vertices"
    return None


class Grid:
    def __init__(self, xmin, ymin, xmax, ymax, count):
        w, h = max(xmax - xmin, 1.0), max(ymax - ymin, 1.0)
        self.cs = max(math.sqrt(w * h / max(count, 1)) * 1.5, 1e-9)
        self.xmin, self.ymin = xmin, ymin
        self.nx = int(w / self.cs) + 1
        self.ny = int(h / self.cs) + 1
        self.cells = {}

    def cell_range(self, x0, y0, x1, y1):
        cs = self.cs
        i0 = max(int(math.floor((x0 - self.xmin) / cs)) - 1, 0)
        j0 = max(int(math.floor((y0 - self.ymin) / cs)) - 1, 0)
        i1 = min(int(math.floor((x1 - self.xmin) / cs)) + 1, self.nx)
        j1 = min(int(math.floor((y1 - self.ymin) / cs)) + 1, self.ny)
        return i0, j0, i1, j1

    def insert(self, item, x0, y0, x1, y1):
        i0, j0, i1, j1 = self.cell_range(x0, y0, x1, y1)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                self.cells.setdefault((i, j), []).append(item)

    def query(self, x0, y0, x1, y1):
        i0, j0, i1, j1 = self.cell_range(x0, y0, x1, y1)
        out = set()
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                c = self.cells.get((i, j))
                if c:
                    out.update(c)
        return out


def f32_exact(v):
    try:
        return struct.unpack("<f", struct.pack("<f", v))[0] == v
    except OverflowError:
        return False


# ---------------------------------------------------------------- the checks
def check_map(path, textures=False):
    errors, warnings = [], []
    m = load_map(path, errors, warnings)
    if m is None:
        return errors, warnings, None
    nv, ns = len(m.verts), len(m.sectors)

    def err(msg):
        if len(errors) < 200:
            errors.append(msg)
        elif len(errors) == 200:
            errors.append("... (further errors suppressed)")

    # R3 ranges and references -------------------------------------------------
    for k, (x, y) in enumerate(m.verts):
        if abs(x) > LIMIT or abs(y) > LIMIT:
            err(f"R3 vertex {k} ({x}, {y}) out of range")
    nonf32 = [k for k, (x, y) in enumerate(m.verts) if not (f32_exact(x) and f32_exact(y))]
    if nonf32:
        warnings.append(f"{len(nonf32)} vertices not exactly representable as f32 (first: {nonf32[0]})")
    for k, s in enumerate(m.sectors):
        for key in ("floor", "ceiling"):
            if abs(s[key]) > LIMIT:
                err(f"R3 sector {k} {key} {s[key]} out of range")
        if s["floor"] > s["ceiling"]:
            err(f"R3 sector {k} floor {s['floor']} above ceiling {s['ceiling']}")
        if not 0 <= s["light"] <= 255:
            err(f"R3 sector {k} light {s['light']} outside 0..=255")
    for k, t in enumerate(m.things):
        if abs(t["x"]) > LIMIT or abs(t["y"]) > LIMIT:
            err(f"R3 thing {k} position out of range")
        if t["kind"] not in THING_KINDS:
            warnings.append(f"thing {k}: unusual kind {t['kind']!r}")
    for k, ln in enumerate(m.lines):
        for key in ("a", "b"):
            if not 0 <= ln[key] < nv:
                err(f"line {k}: vertex index {ln[key]} out of range")
        for sd in ("front", "back"):
            if ln[sd] is not None and not 0 <= ln[sd]["sector"] < ns:
                err(f"line {k}: {sd} sector {ln[sd]['sector']} out of range")
    if errors:
        return errors, warnings, None

    # Exact integer coordinates: scale every value by one power of two.
    vals = [c for v in m.verts for c in v] + [c for t in m.things for c in (t["x"], t["y"])]
    shift = 0
    for v in vals:
        den = Fraction(v).denominator
        shift = max(shift, den.bit_length() - 1)
    shift += 1  # one extra bit so line midpoints are integers too
    scale = 1 << shift

    def to_int(v):
        fr = Fraction(v) * scale
        assert fr.denominator == 1
        return fr.numerator

    V = [(to_int(x), to_int(y)) for x, y in m.verts]

    # R2 vertices: distinct coordinates --------------------------------------
    seen = {}
    for k, p in enumerate(V):
        if p in seen:
            err(f"R2 vertices {seen[p]} and {k} have identical coordinates {m.verts[k]}")
        else:
            seen[p] = k

    used = set()
    for k, ln in enumerate(m.lines):
        used.update((ln["a"], ln["b"]))
        if ln["a"] == ln["b"] or V[ln["a"]] == V[ln["b"]]:
            err(f"R2 line {k} has zero length")
    unused = [k for k in range(nv) if k not in used]
    if unused:
        warnings.append(f"{len(unused)} unused vertices (first: {unused[0]})")

    # R1 closure + orientation ------------------------------------------------
    sector_edges = [[] for _ in range(ns)]  # directed (u, v, line index)
    for k, ln in enumerate(m.lines):
        sector_edges[ln["front"]["sector"]].append((ln["a"], ln["b"], k))
        if ln["back"] is not None:
            sector_edges[ln["back"]["sector"]].append((ln["b"], ln["a"], k))
            if ln["back"]["sector"] == ln["front"]["sector"]:
                warnings.append(f"line {k}: both sides reference sector {ln['front']['sector']}")
    for s in range(ns):
        if not sector_edges[s]:
            err(f"R1 sector {s} is referenced by no line")
            continue
        bal = {}
        for u, v, _ in sector_edges[s]:
            bal[u] = bal.get(u, 0) - 1
            bal[v] = bal.get(v, 0) + 1
        bad = [(vx, b) for vx, b in bal.items() if b != 0]
        if bad:
            vx, b = bad[0]
            err(f"R1 sector {s} not closed: {len(bad)} vertices unbalanced, e.g. vertex {vx} "
                f"{m.verts[vx]} (in - out = {b})")
        area2 = 0
        for u, v, _ in sector_edges[s]:
            (x1, y1), (x2, y2) = V[u], V[v]
            area2 += x1 * y2 - x2 * y1
        # Sector on the right of every edge => clockwise => negative shoelace.
        if area2 >= 0:
            err(f"R1 sector {s} has non-positive area (boundary runs counter-clockwise?)")

    # Spatial grid over the lines ------------------------------------------------
    fx = [float(x) for x, _ in V] or [0.0]
    fy = [float(y) for _, y in V] or [0.0]
    xmin, xmax, ymin, ymax = min(fx), max(fx), min(fy), max(fy)
    grid = Grid(xmin, ymin, xmax, ymax, len(m.lines))
    for k, ln in enumerate(m.lines):
        (x1, y1), (x2, y2) = V[ln["a"]], V[ln["b"]]
        grid.insert(k, min(x1, x2), min(y1, y2), max(x1, x2), max(y1, y2))

    # R2 pairwise line tests ------------------------------------------------------
    seg = []
    for ln in m.lines:
        a, b = ln["a"], ln["b"]
        seg.append(((V[a][0], V[a][1], a), (V[b][0], V[b][1], b)))
    bbox = [(min(p[0], q[0]), min(p[1], q[1]), max(p[0], q[0]), max(p[1], q[1])) for p, q in seg]
    done = set()
    for cell in grid.cells.values():
        for ii in range(len(cell)):
            i = cell[ii]
            bi = bbox[i]
            for jj in range(ii + 1, len(cell)):
                j = cell[jj]
                bj = bbox[j]
                if bi[0] > bj[2] or bj[0] > bi[2] or bi[1] > bj[3] or bj[1] > bi[3]:
                    continue
                key = (i, j) if i < j else (j, i)
                if key in done:
                    continue
                done.add(key)
                prob = segment_problem(seg[i], seg[j])
                if prob:
                    err(f"R2 lines {key[0]} and {key[1]}: {prob}")
    # Vertices (used or not) strictly inside a line.
    for k, (px, py) in enumerate(V):
        for li in grid.query(px, py, px, py):
            (ax, ay, _), (bx, by, _) = seg[li]
            if on_segment_strict(ax, ay, bx, by, px, py):
                err(f"R2 vertex {k} {m.verts[k]} lies strictly inside line {li}")

    if errors:
        return errors, warnings, None

    # R6 closure of the whole map: cast a ray from every line side ------------
    span = max(xmax - xmin, ymax - ymin, 1.0)

    def cast(ox, oy, dx, dy, skip):
        """First line hit by the ray o + t*d (t > 0).

        Returns (line, facing_side) with facing_side 'front'/'back', None if the
        ray escapes, or 'degenerate' if the nearest hit is at a vertex or runs
        along a line.
        """
        fox, foy = float(ox), float(oy)
        fdx, fdy = float(dx), float(dy)
        r = grid.cs
        dlen = math.hypot(fdx, fdy)
        while True:
            covers = fox - r <= xmin and fox + r >= xmax and foy - r <= ymin and foy + r >= ymax
            best = None  # (t as Fraction, line)
            degenerate_t = None
            for li in grid.query(fox - r, foy - r, fox + r, foy + r):
                if li == skip:
                    continue
                (cx, cy, _), (ex, ey, _) = seg[li]
                # Cheap float rejection: both endpoints clearly on one side of the ray's line.
                c1 = fdx * (cy - foy) - fdy * (cx - fox)
                c2 = fdx * (ey - foy) - fdy * (ex - fox)
                tol = 1e-12 * (abs(fdx) * (abs(cy - foy) + abs(ey - foy))
                               + abs(fdy) * (abs(cx - fox) + abs(ex - fox)))
                if (c1 > tol and c2 > tol) or (c1 < -tol and c2 < -tol):
                    continue
                sx, sy = ex - cx, ey - cy
                den = dx * sy - dy * sx
                wx, wy = cx - ox, cy - oy
                if den == 0:
                    # Parallel; collinear with the ray only if o lies on its line.
                    if wx * dy - wy * dx == 0:
                        t1 = Fraction(wx * dx + wy * dy, dx * dx + dy * dy)
                        t2 = Fraction((ex - ox) * dx + (ey - oy) * dy, dx * dx + dy * dy)
                        if max(t1, t2) > 0:
                            tt = max(min(t1, t2), Fraction(0))
                            if degenerate_t is None or tt < degenerate_t:
                                degenerate_t = tt
                    continue
                tn = wx * sy - wy * sx
                sn = wx * dy - wy * dx
                # t = tn/den, s = sn/den
                if den < 0:
                    tn, sn, den = -tn, -sn, -den
                if tn <= 0 or sn < 0 or sn > den:
                    continue
                t = Fraction(tn, den)
                if sn == 0 or sn == den:
                    if degenerate_t is None or t < degenerate_t:
                        degenerate_t = t
                    continue
                if best is None or t < best[0]:
                    best = (t, li)
            if degenerate_t is not None and (best is None or degenerate_t <= best[0]):
                if covers or float(degenerate_t) * dlen <= r * 0.999:
                    return "degenerate"
            elif best is not None and (covers or float(best[0]) * dlen <= r * 0.999):
                t, li = best
                (cx, cy, _), (ex, ey, _) = seg[li]
                o = orient(cx, cy, ex, ey, ox, oy)
                return li, ("front" if o < 0 else "back")
            if covers:
                return None
            r *= 2

    # From the midpoint of every line, look both ways.  Whatever is on a side
    # of the line (a sector, or solid space for the back of a one-sided line)
    # must be what the first line hit in that direction presents towards it.
    def what(side):
        return "solid space" if side is None else f"sector {side['sector']}"

    perturb = [(1, 0), (7, 1), (7, -1), (5, 2), (5, -2), (11, 3), (11, -3), (13, 5), (13, -5)]
    for k, ln in enumerate(m.lines):
        (ax, ay, _), (bx, by, _) = seg[k]
        mx, my = (ax + bx) // 2, (ay + by) // 2  # exact thanks to the extra bit
        tx, ty = bx - ax, by - ay
        for sd in ("front", "back"):
            side = ln[sd]
            # q * normal + p * tangent, q > 0: always strictly into this side.
            nx_, ny_ = (ty, -tx) if sd == "front" else (-ty, tx)
            result = "degenerate"
            for q, p in perturb:
                result = cast(mx, my, q * nx_ + p * tx, q * ny_ + p * ty, k)
                if result != "degenerate":
                    break
            if result == "degenerate":
                warnings.append(f"line {k} {sd}: could not cast a clean ray")
                continue
            if result is None:
                if side is not None:
                    err(f"R6 line {k} {sd} side ({what(side)}) faces the void: map not closed")
                continue
            li, facing = result
            other = m.lines[li][facing]
            mine = None if side is None else side["sector"]
            theirs = None if other is None else other["sector"]
            if mine != theirs:
                err(f"R6 line {k}: its {sd} side has {what(side)}, but the first line in that "
                    f"direction (line {li}, {facing} side) has {what(other)}: inconsistent "
                    f"orientation / overlapping or leaking sectors")

    # R7 texturing (opt-in) ------------------------------------------------------------
    if textures:
        for k, s in enumerate(m.sectors):
            for key in ("floor_texture", "ceiling_texture"):
                if s[key] is None:
                    err(f"R7 sector {k} has no {key}")
        for k, ln in enumerate(m.lines):
            if ln["back"] is None:
                if ln["front"]["middle"] is None:
                    err(f"R7 line {k}: one-sided wall without a middle texture")
                continue
            for sd, od in (("front", "back"), ("back", "front")):
                me, other = m.sectors[ln[sd]["sector"]], m.sectors[ln[od]["sector"]]
                if other["floor"] > me["floor"] and ln[sd]["lower"] is None:
                    err(f"R7 line {k} {sd}: the neighbour's floor is higher, but no lower texture")
                if other["ceiling"] < me["ceiling"] and ln[sd]["upper"] is None and not (
                        me["ceiling_texture"] == "SKY" and other["ceiling_texture"] == "SKY"):
                    err(f"R7 line {k} {sd}: the neighbour's ceiling is lower, but no upper texture")
                mid = ln[sd]["middle"]
                if mid is not None and mid not in MASKED_TEXTURES:
                    err(f"R7 line {k} {sd}: middle {mid!r} on a two-sided line is not masked "
                        f"({', '.join(sorted(MASKED_TEXTURES))})")
    for k, ln in enumerate(m.lines):
        if ln["impassable"] and ln["back"] is None:
            warnings.append(f"line {k}: impassable on a one-sided line (it is solid anyway)")
        if ln["door"] and ln["back"] is None:
            err(f"line {k}: a door must be two-sided (its back sector is the door)")

    # Two-sided lines with no opening.
    for k, ln in enumerate(m.lines):
        if ln["back"] is not None and not ln["door"]:
            f_, b_ = m.sectors[ln["front"]["sector"]], m.sectors[ln["back"]["sector"]]
            if max(f_["floor"], b_["floor"]) >= min(f_["ceiling"], b_["ceiling"]):
                warnings.append(f"line {k}: two-sided line with no vertical opening")

    # R4 things ----------------------------------------------------------------------
    def sector_of(px, py):
        """Sectors whose boundary (crossing number, even-odd) contains p."""
        inside = []
        for s in range(ns):
            c = 0
            for u, v, _ in sector_edges[s]:
                (x1, y1), (x2, y2) = V[u], V[v]
                if (y1 > py) != (y2 > py):
                    # x of the crossing > px  <=>  sign test, exact.
                    lhs = (x2 - x1) * (py - y1) - (px - x1) * (y2 - y1)
                    if (lhs > 0) == (y2 > y1):
                        c += 1
            if c % 2:
                inside.append(s)
        return inside

    def min_dist2(px, py):
        best = None
        for (ax, ay, _), (bx, by, _) in seg:
            dx, dy = bx - ax, by - ay
            wx, wy = px - ax, py - ay
            dot = wx * dx + wy * dy
            l2 = dx * dx + dy * dy
            if dot <= 0:
                d2 = Fraction(wx * wx + wy * wy)
            elif dot >= l2:
                d2 = Fraction((px - bx) ** 2 + (py - by) ** 2)
            else:
                cr = wx * dy - wy * dx
                d2 = Fraction(cr * cr, l2)
            if best is None or d2 < best:
                best = d2
        return best

    starts = [t for t in m.things if t["kind"] == "player_start"]
    if len(starts) != 1:
        err(f"R4 expected exactly one player_start, found {len(starts)}")
    player_sector = None
    for k, t in enumerate(m.things):
        px, py = to_int(t["x"]), to_int(t["y"])
        ins = sector_of(px, py)
        if len(ins) != 1:
            err(f"R4 thing {k} ({t['kind']}) at ({t['x']}, {t['y']}) is inside sectors {ins} "
                f"(expected exactly one)")
            continue
        if t["kind"] == "player_start":
            player_sector = ins[0]
            d2 = min_dist2(px, py)
            if d2 < scale * scale:
                err(f"R4 player start is only {math.sqrt(float(d2)) / scale:.4f} units from a line")
        elif min_dist2(px, py) == 0:
            err(f"R4 thing {k} lies on a line")

    # Reachability of sectors through two-sided lines (warning only).
    if player_sector is not None:
        adj = [set() for _ in range(ns)]
        for ln in m.lines:
            if ln["back"] is not None:
                a, b = ln["front"]["sector"], ln["back"]["sector"]
                adj[a].add(b)
                adj[b].add(a)
        seen_s, stack = {player_sector}, [player_sector]
        while stack:
            for n in adj[stack.pop()]:
                if n not in seen_s:
                    seen_s.add(n)
                    stack.append(n)
        if len(seen_s) != ns:
            warnings.append(f"sectors unreachable from the player start: {sorted(set(range(ns)) - seen_s)}")

    two = sum(1 for ln in m.lines if ln["back"] is not None)
    stats = dict(vertices=nv, lines=len(m.lines), one_sided=len(m.lines) - two, two_sided=two,
                 sectors=ns, things=len(m.things), player_sector=player_sector)
    return errors, warnings, stats


def main(argv):
    textures = "--textures" in argv[1:]
    argv = [a for a in argv if a != "--textures"]
    if len(argv) > 1:
        paths = argv[1:]
    else:
        here = os.path.dirname(os.path.abspath(__file__))
        mdir = os.path.dirname(here)
        paths = sorted(os.path.join(mdir, f) for f in os.listdir(mdir) if f.endswith(".ron"))
    failed = 0
    for path in paths:
        errors, warnings, stats = check_map(path, textures)
        name = os.path.relpath(path)
        if errors:
            failed += 1
            print(f"FAIL {name}")
            for e in errors:
                print(f"    error: {e}")
        else:
            print(f"ok   {name}: {stats['vertices']} vertices, {stats['lines']} lines "
                  f"({stats['one_sided']} one-sided, {stats['two_sided']} two-sided), "
                  f"{stats['sectors']} sectors, {stats['things']} things; "
                  f"player start in sector {stats['player_sector']}")
        for w in warnings:
            print(f"    warning: {w}")
    print(f"{len(paths) - failed}/{len(paths)} maps pass")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

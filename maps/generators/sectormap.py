"""Tiny helper for writing Sightline sector maps from region polygons (stdlib only).

Describe each sector as regions: an outer polygon plus optional hole polygons.
Orientation is fixed up automatically (outer boundaries clockwise, holes
counter-clockwise, y up) so the sector is always on the right of its edges.
Then `build()` turns the regions into lines:

* every polygon edge is split at any other map vertex lying strictly inside it
  (so neighbouring regions never form T-junctions);
* an edge used by one region side only becomes a one-sided wall;
* an edge used by two regions in opposite directions becomes a two-sided line
  (front = the sector with the higher floor, as in two_rooms.ron);
* anything else (the same edge used twice in one direction, or three times)
  means overlapping regions and raises an error.

Coordinates are kept as Python floats and must be exact binary fractions;
vertices are deduplicated by exact coordinates.

Texturing (defaults keep the output of older scripts unchanged):

* a one-sided wall gets `middle` = its sector's `wall` (or the `wall` given to
  the region/hole that drew it);
* on a two-sided line whose floors differ, both sides get `lower` = the
  `riser` of the sector with the higher floor (the step owns its riser), or
  "STEP" when that sector has no `riser`;
* where the ceilings differ (and not both are "SKY"), both sides get `upper`
  = the `lintel` of the sector with the lower ceiling, or, when it has none,
  each side its own sector's `wall`;
* `edge(p, q, ...)` then overrides textures and line flags of every line
  lying on the segment p-q (e.g. a GRATE middle and `impassable` on a window).

Map options: `diminishing_light` (None: not written, the engine's default
true) and `fog=((r, g, b), distance)`.

Map format version 2 (`version=2`): sectors take a `tag` and a `special`
(RON text such as `SectorSpecial(light: Flicker)`), `edge()` a line
`special` (RON text such as `LineSpecial(on: Use, tag: 2, action: Lift())`),
a side `scroll=(x, y)`, and `front=SECTOR` to turn the line so that sector
is in front (a switch must face the player); `thing()` takes `extra` fields.
"""

from fractions import Fraction


def fmt(v):
    """Format a float the way the map format wants it: always a decimal point."""
    v = float(v)
    s = repr(v)
    if "e" in s or "E" in s or "inf" in s or "nan" in s:
        raise ValueError(f"cannot write {v!r} without an exponent")
    if "." not in s:
        s += ".0"
    return s


def signed_area2(pts):
    s = 0.0
    for i in range(len(pts)):
        x1, y1 = pts[i]
        x2, y2 = pts[(i + 1) % len(pts)]
        s += Fraction(x1) * Fraction(y2) - Fraction(x2) * Fraction(y1)
    return s


def clockwise(pts):
    pts = [(float(x), float(y)) for x, y in pts]
    return pts if signed_area2(pts) < 0 else pts[::-1]


def counter_clockwise(pts):
    pts = [(float(x), float(y)) for x, y in pts]
    return pts if signed_area2(pts) > 0 else pts[::-1]


class SectorMap:
    def __init__(self, name, header_comment="", diminishing_light=None, fog=None, version=None, music=None):
        self.name = name
        self.music = music  # None: no music field
        self.version = version  # None: leave the field out (version 1)
        self.header = header_comment
        self.diminishing_light = diminishing_light  # None: leave the field out
        self.fog = fog  # None or ((r, g, b), distance)
        self.sectors = []  # dicts
        self.loops = []  # (sector, [points], label) with the sector on the right
        self.loop_walls = {}  # loop index -> one-sided wall texture for that loop
        self.edges = []  # edge() overrides, applied in order
        self.things = []

    def sector(self, floor, ceiling, light, floor_texture=None, ceiling_texture=None,
               wall="BRICK", label="", riser=None, lintel=None, tag=0, special=None):
        self.sectors.append(dict(floor=float(floor), ceiling=float(ceiling), light=int(light),
                                 floor_texture=floor_texture, ceiling_texture=ceiling_texture,
                                 wall=wall, label=label, riser=riser, lintel=lintel,
                                 tag=int(tag), special=special))
        return len(self.sectors) - 1

    def region(self, sector, outer, holes=(), label="", wall=None):
        """A piece of `sector`: outer boundary plus holes (pillars, platforms...).

        `wall` overrides the sector's wall texture on this region's one-sided walls."""
        self._loop(sector, clockwise(outer), label or "outline", wall)
        for h in holes:
            self._loop(sector, counter_clockwise(h), "hole", wall)

    def hole(self, sector, pts, label="pillar", wall=None):
        self._loop(sector, counter_clockwise(pts), label, wall)

    def _loop(self, sector, pts, label, wall):
        if wall is not None:
            self.loop_walls[len(self.loops)] = wall
        self.loops.append((sector, pts, label))

    def edge(self, p, q, sector=None, wall=None, upper=None, middle=None, lower=None,
             x_offset=None, y_offset=None, impassable=None, upper_unpegged=None,
             lower_unpegged=None, special=None, scroll=None, front=None):
        """Override every line lying on the segment p-q (end points included).

        Side textures (`upper`, `middle`, `lower`, offsets) go to the side facing
        `sector`, or to both sides when `sector` is None; `wall` sets the middle of
        one-sided lines only.  Flags (`impassable`, `*_unpegged`) go to the line.
        Matching no line at all is an error."""
        side = {k: v for k, v in (("upper", upper), ("middle", middle), ("lower", lower),
                                  ("x_offset", x_offset), ("y_offset", y_offset), ("scroll", scroll))
                if v is not None}
        flags = {k: v for k, v in (("impassable", impassable), ("upper_unpegged", upper_unpegged),
                                   ("lower_unpegged", lower_unpegged), ("special", special),
                                   ("front_sector", front)) if v is not None}
        self.edges.append(((float(p[0]), float(p[1])), (float(q[0]), float(q[1])),
                           sector, wall, side, flags))

    def thing(self, kind, x, y, angle=0.0, extra=""):
        self.things.append((kind, float(x), float(y), float(angle), extra))

    # ------------------------------------------------------------------ build
    def build(self):
        # Vertex table in order of first appearance.
        vindex, verts = {}, []

        def vid(p):
            if p not in vindex:
                vindex[p] = len(verts)
                verts.append(p)
            return vindex[p]

        for _, pts, _ in self.loops:
            for p in pts:
                vid(p)
        exact = [(Fraction(x), Fraction(y)) for x, y in verts]

        def split(a, b):
            """Vertex ids strictly inside segment a-b, ordered from a to b."""
            (ax, ay), (bx, by) = exact[a], exact[b]
            inner = []
            for k, (px, py) in enumerate(exact):
                if k in (a, b):
                    continue
                if (bx - ax) * (py - ay) - (by - ay) * (px - ax) != 0:
                    continue
                if min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by):
                    t = (px - ax) * (bx - ax) + (py - ay) * (by - ay)
                    inner.append((t, k))
            return [k for _, k in sorted(inner)]

        # Directed edges with their sector, in loop order.
        uses = {}  # frozenset(u, v) -> list of (sector, u, v)
        order = []  # (key, label) in first-use order
        for li, (sector, pts, label) in enumerate(self.loops):
            ids = [vid(p) for p in pts]
            for i in range(len(ids)):
                a, b = ids[i], ids[(i + 1) % len(ids)]
                chain = [a] + split(a, b) + [b]
                for u, v in zip(chain, chain[1:]):
                    key = frozenset((u, v))
                    if key not in uses:
                        uses[key] = []
                        order.append((key, self.sectors[sector]["label"], label))
                    uses[key].append((sector, u, v, li))

        lines = []
        for key, slabel, label in order:
            us = uses[key]
            if len(us) == 1:
                s, u, v, li = us[0]
                wall = self.loop_walls.get(li, self.sectors[s]["wall"])
                lines.append(dict(a=u, b=v, front=dict(sector=s, middle=wall),
                                  back=None, group=f"{slabel} {label}"))
            elif len(us) == 2:
                (s1, u1, v1, _), (s2, u2, v2, _) = us
                if (u1, v1) != (v2, u2) or s1 == s2:
                    raise ValueError(f"overlapping regions at edge {verts[u1]}-{verts[v1]} "
                                     f"(sectors {s1}, {s2})")
                f1, f2 = self.sectors[s1], self.sectors[s2]
                # Front = higher floor (ties: lower ceiling, then lower index).
                if (f2["floor"], -f2["ceiling"], -s2) > (f1["floor"], -f1["ceiling"], -s1):
                    (s1, u1, v1), (s2, u2, v2) = (s2, u2, v2), (s1, u1, v1)
                    f1, f2 = f2, f1
                front, back = dict(sector=s1), dict(sector=s2)
                higher = f1 if f1["floor"] > f2["floor"] else f2
                lower_ceiling = f1 if f1["ceiling"] < f2["ceiling"] else f2
                for side, me, other in ((front, f1, f2), (back, f2, f1)):
                    if me["floor"] != other["floor"]:
                        side["lower"] = higher["riser"] or "STEP"
                    if me["ceiling"] != other["ceiling"] and not (
                            me["ceiling_texture"] == "SKY" and other["ceiling_texture"] == "SKY"):
                        side["upper"] = lower_ceiling["lintel"] or me["wall"]
                lines.append(dict(a=u1, b=v1, front=front, back=back,
                                  group=f"{self.sectors[s1]['label']} / {self.sectors[s2]['label']} opening"))
            else:
                raise ValueError(f"edge {verts[min(key)]}-{verts[max(key)]} used {len(us)} times")
        self._apply_edges(verts, lines)
        return verts, lines

    def _apply_edges(self, verts, lines):
        def on(p, a, b):
            (px, py), (ax, ay), (bx, by) = [(Fraction(x), Fraction(y)) for x, y in (p, a, b)]
            if (bx - ax) * (py - ay) - (by - ay) * (px - ax) != 0:
                return False
            return min(ax, bx) <= px <= max(ax, bx) and min(ay, by) <= py <= max(ay, by)

        for p, q, sector, wall, side, flags in self.edges:
            hit = 0
            for ln in lines:
                if not (on(verts[ln["a"]], p, q) and on(verts[ln["b"]], p, q)):
                    continue
                hit += 1
                ln.update(flags)
                if wall is not None and ln["back"] is None:
                    ln["front"]["middle"] = wall
                for sd in (ln["front"], ln["back"]):
                    if sd is not None and sector in (None, sd["sector"]):
                        sd.update(side)
            if not hit:
                raise ValueError(f"edge override {p}-{q} matches no line")
        for ln in lines:
            want = ln.pop("front_sector", None)
            if want is None or ln["front"]["sector"] == want:
                continue
            if ln["back"] is None or ln["back"]["sector"] != want:
                raise ValueError(f"line {verts[ln['a']]}-{verts[ln['b']]} has no side in sector {want}")
            ln["a"], ln["b"] = ln["b"], ln["a"]
            ln["front"], ln["back"] = ln["back"], ln["front"]

    # ------------------------------------------------------------------ write
    def render(self, vertex_comments=True, per_row=1):
        verts, lines = self.build()
        out = []
        for c in self.header.strip("\n").splitlines():
            out.append(f"// {c}".rstrip())
        out.append("Map(")
        if self.version is not None:
            out.append(f"    version: {self.version},")
        out.append(f"    name: \"{self.name}\",")
        if self.music is not None:
            out.append(f"    music: \"{self.music}\",")
        if self.diminishing_light is not None:
            out.append(f"    diminishing_light: {'true' if self.diminishing_light else 'false'},")
        if self.fog is not None:
            (r, g, b), dist = self.fog
            out.append(f"    fog: Some(Fog(colour: ({int(r)}, {int(g)}, {int(b)}), distance: {fmt(dist)})),")
        out.append("    vertices: [")
        if vertex_comments:
            for k, (x, y) in enumerate(verts):
                out.append(f"        ({fmt(x)}, {fmt(y)}), // {k}")
        else:
            for i in range(0, len(verts), per_row):
                out.append("        " + " ".join(f"({fmt(x)}, {fmt(y)})," for x, y in verts[i:i + per_row]))
        out.append("    ],")
        out.append("    sectors: [")
        for k, s in enumerate(self.sectors):
            extra = ""
            if s["floor_texture"]:
                extra += f", floor_texture: \"{s['floor_texture']}\""
            if s["ceiling_texture"]:
                extra += f", ceiling_texture: \"{s['ceiling_texture']}\""
            if s.get("tag"):
                extra += f", tag: {s['tag']}"
            if s.get("special"):
                extra += f", special: {s['special']}"
            label = f" // {k}: {s['label']}" if s["label"] else f" // {k}"
            out.append(f"        Sector(floor: {fmt(s['floor'])}, ceiling: {fmt(s['ceiling'])}, "
                       f"light: {s['light']}{extra}),{label}")
        out.append("    ],")
        out.append("    lines: [")
        last_group = None
        for ln in lines:
            if ln["group"] != last_group:
                out.append(f"        // {ln['group']}")
                last_group = ln["group"]
            flags = "".join(f", {k}: true" for k in ("upper_unpegged", "lower_unpegged", "impassable", "door")
                            if ln.get(k))
            if ln.get("special"):
                flags += f", special: {ln['special']}"
            out.append(f"        Line(from: {ln['a']}, to: {ln['b']}, front: {side_text(ln['front'])}"
                       + (f", back: Some({side_text(ln['back'])})" if ln["back"] else "") + flags + "),")
        out.append("    ],")
        out.append("    things: [")
        for kind, x, y, a, extra in self.things:
            more = f", {extra}" if extra else ""
            out.append(f"        Thing(kind: \"{kind}\", x: {fmt(x)}, y: {fmt(y)}, angle: {fmt(a)}{more}),")
        out.append("    ],")
        out.append(")")
        return "\n".join(out) + "\n", len(verts), len(lines)


def side_text(side):
    parts = [f"sector: {side['sector']}"]
    for key in ("upper", "middle", "lower"):
        if side.get(key):
            parts.append(f"{key}: \"{side[key]}\"")
    for key in ("x_offset", "y_offset"):
        if side.get(key):
            parts.append(f"{key}: {fmt(side[key])}")
    if side.get("scroll"):
        x, y = side["scroll"]
        parts.append(f"scroll: (x: {fmt(x)}, y: {fmt(y)})")
    return "Side(" + ", ".join(parts) + ")"

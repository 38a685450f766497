"""SectorMap (maps/generators/sectormap.py) for version-2 maps with specials.

Adds to the shipped helper what the special test maps need, and nothing else:

* sectors with a `tag` and a `special` (RON text, e.g.
  `SectorSpecial(damage: Damage(amount: 10))`);
* `front(a, b)`: every two-sided line between sectors a and b gets a in
  front (the helper's own rule puts the higher floor in front; stairs,
  donuts and teleporters care which side is which);
* `special(p, q, text, note)`: the line lying on segment p-q carries a
  `LineSpecial` (RON text; `{line(x0, y0, x1, y1)}` inside it is replaced by
  the index of the line on that segment, for a line teleporter's exit);
* `trigger(p, q, text, note)`: an invisible trigger line from p to q
  (its front is its right-hand side walking p -> q);
* output in map format version 2, every sector, special line and trigger
  line with a comment saying what it is.
"""

import os
import re
import sys
import zlib
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "maps", "generators"))
from sectormap import SectorMap, fmt, side_text  # noqa: E402


class SpecialMap(SectorMap):
    def __init__(self, name, header_comment=""):
        super().__init__(name, header_comment)
        self.fronts = []  # (front sector, other sector)
        self.specials = []  # (p, q, text, note)
        self.triggers = []  # (p, q, text, note)

    def sector(self, floor, ceiling, light=160, floor_texture="FLOOR", ceiling_texture="CEIL",
               label="", tag=0, special=None, **kw):
        # Line comments name a sector by the start of its label ("Lift A
        # (tag 1)"); the sector list gives all of it.
        short = re.split(r", |: ", label)[0]
        s = super().sector(floor, ceiling, light, floor_texture, ceiling_texture, label=short, **kw)
        self.sectors[s]["note"] = label
        self.sectors[s]["tag"] = tag
        self.sectors[s]["special"] = special
        return s

    def front(self, a, b):
        """Lines between sectors a and b face a."""
        self.fronts.append((a, b))

    def special(self, p, q, text, note):
        self.specials.append(((float(p[0]), float(p[1])), (float(q[0]), float(q[1])), text, note))

    def trigger(self, p, q, text, note):
        self.triggers.append(((float(p[0]), float(p[1])), (float(q[0]), float(q[1])), text, note))

    def build(self):
        verts, lines = super().build()
        for a, b in self.fronts:
            hit = 0
            for ln in lines:
                if ln["back"] is None or {ln["front"]["sector"], ln["back"]["sector"]} != {a, b}:
                    continue
                hit += 1
                if ln["front"]["sector"] != a:
                    ln["a"], ln["b"] = ln["b"], ln["a"]
                    ln["front"], ln["back"] = ln["back"], ln["front"]
            if not hit:
                raise ValueError(f"front({a}, {b}): no line between those sectors")

        def line_on(p, q):
            found = [k for k, ln in enumerate(lines)
                     if {verts[ln["a"]], verts[ln["b"]]} == {p, q}]
            if len(found) != 1:
                raise ValueError(f"no single line from {p} to {q}: {found}")
            return found[0]

        def resolve(text):
            def one(m):
                x0, y0, x1, y1 = (float(v) for v in m.group(1).split(","))
                return str(line_on((x0, y0), (x1, y1)))
            return re.sub(r"\{line\(([^)]*)\)\}", one, text)

        for p, q, text, note in self.specials:
            k = line_on(p, q)
            lines[k]["special"] = resolve(text)
            lines[k]["note"] = note
        return verts, lines

    def render(self):
        verts, lines = self.build()
        verts = list(verts)
        trigger_ends = []
        for p, q, _, _ in self.triggers:
            ends = []
            for v in (p, q):
                if v not in verts:
                    verts.append(v)
                ends.append(verts.index(v))
            trigger_ends.append(ends)
        out = [f"// {c}".rstrip() for c in self.header.strip("\n").splitlines()]
        out.append("Map(")
        out.append("    version: 2,")
        out.append(f"    name: \"{self.name}\",")
        out.append("    vertices: [")
        for k, (x, y) in enumerate(verts):
            out.append(f"        ({fmt(x)}, {fmt(y)}), // {k}")
        out.append("    ],")
        out.append("    sectors: [")
        for k, s in enumerate(self.sectors):
            extra = ""
            for key in ("floor_texture", "ceiling_texture"):
                if s[key]:
                    extra += f", {key}: \"{s[key]}\""
            if s["tag"]:
                extra += f", tag: {s['tag']}"
            if s["special"]:
                extra += f", special: {s['special']}"
            out.append(f"        // {k}: {s['note']}")
            out.append(f"        Sector(floor: {fmt(s['floor'])}, ceiling: {fmt(s['ceiling'])}, "
                       f"light: {s['light']}{extra}),")
        out.append("    ],")
        out.append("    lines: [")
        last_group = None
        for k, ln in enumerate(lines):
            if ln.get("note"):
                out.append(f"        // line {k}: {ln['note']}")
                last_group = None
            elif ln["group"] != last_group:
                out.append(f"        // from line {k}: {ln['group']}")
                last_group = ln["group"]
            flags = "".join(f", {f}: true" for f in ("upper_unpegged", "lower_unpegged", "impassable")
                            if ln.get(f))
            special = f", special: {ln['special']}" if ln.get("special") else ""
            out.append(f"        Line(from: {ln['a']}, to: {ln['b']}, front: {side_text(ln['front'])}"
                       + (f", back: Some({side_text(ln['back'])})" if ln["back"] else "")
                       + flags + special + "),")
        out.append("    ],")
        if self.triggers:
            out.append("    trigger_lines: [")
            for k, ((_, _, text, note), (a, b)) in enumerate(zip(self.triggers, trigger_ends)):
                out.append(f"        // trigger line {k}: {note}")
                out.append(f"        TriggerLine(from: {a}, to: {b}, special: {text}),")
            out.append("    ],")
        out.append("    things: [")
        for kind, x, y, a, extra in self.things:
            more = f", {extra}" if extra else ""
            out.append(f"        Thing(kind: \"{kind}\", x: {fmt(x)}, y: {fmt(y)}, angle: {fmt(a)}{more}),")
        out.append("    ],")
        out.append(")")
        return "\n".join(out) + "\n", len(verts), len(lines)


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def write_png(path, width, height, pixel):
    """An RGBA PNG, `pixel(x, y)` -> (r, g, b, a); stdlib only."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    png = (b"\x89PNG\r\n\x1a\n"
           + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(rows, 9))
           + chunk(b"IEND", b""))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(png)

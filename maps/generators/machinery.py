#!/usr/bin/env python3
"""Generate maps/machinery.ron: the world's machinery, one piece after another.

    python3 maps/generators/machinery.py

A map of format version 2 (typed specials). The way through, in order:

  A  the hall (start, floor 0). Use the lift's face (east): the lift comes
     down; step on, ride it up to B. (Walking back onto the lift from B
     lowers it again.)
  B  the ledge (floor 128). The switch on the east wall opens door D1 (tag 2)
     in the north wall, and stays on.
  C  the slime hall (floor 128): a pool of animated slime (GOO1-3, 5 damage
     every 32 ticks) round a pedestal with the blue keycard; the north wall's
     chevrons scroll.
  D2 in C's west wall: a door locked with the blue key.
  E  the teleporter room: step onto the glowing pad.
  F  the arrival room (floor 0, tag 3), reachable only by teleport. A lit
     recess in its west wall is a secret.
  G  a corridor north, its light flickering.
  H  the exit room: the switch in the north wall ends the level.

Layout (y up):

          y=1792 +---------- H ----------+     (exit switch in the north wall)
                 |         exit          |
          y=1536 +-------+---+-----------+
                         | G |  flickering corridor
          y=1152 +-------+---+-------+
                 |                   |
               S |        F          |         C (x 576..896, y 400..784):
                 |  (teleport dest)  |            slime pool with pedestal
          y=832  +-------------------+         E (x 304..560, y 480..704):
                       +------ E ------+D2+-- C --+   teleporter pad in E
                       |   [pad]       |  |       |
                       +---------------+  +--D1---+ y=400
            +------------ A ----------+   +-- B --+ y=384
            | start ->         [lift] L   | switch|
            +-------------------------+   +-------+ y=0
           x=0                       512 576     896
Deterministic: no randomness at all.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sectormap import SectorMap  # noqa: E402


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def build():
    m = SectorMap("The Machinery", version=2, header_comment=__doc__.split("\nLayout")[0])
    # A: the hall.
    a = m.sector(0, 256, 176, "FLOOR", "CEIL", wall="STONE", label="A hall")
    m.region(a, rect(0, 0, 512, 384))
    # L: the lift, resting at the top (level with B), tag 1.
    lift = m.sector(128, 256, 176, "TILE", "CEIL", wall="METAL", label="L lift", riser="METAL", tag=1)
    m.region(lift, rect(512, 160, 576, 224))
    # B: the ledge.
    b = m.sector(128, 288, 160, "TILE", "CEIL", wall="STONE", label="B ledge")
    # (The east wall has vertices where the switch is.)
    m.region(b, [(576, 0), (896, 0), (896, 160), (896, 224), (896, 384), (576, 384)])
    # D1: the door opened by B's switch (shut: ceiling on the floor), tag 2.
    d1 = m.sector(128, 128, 160, "FLOOR", "CEIL", wall="SUPPORT", label="D1 door", lintel="DOOR", tag=2)
    m.region(d1, rect(704, 384, 768, 400))
    # C: the slime hall, with the pool and the pedestal.
    c = m.sector(128, 320, 144, "FLOOR", "CEIL", wall="BRICK", label="C slime hall")
    pool = m.sector(120, 320, 192, "GOO1", "CEIL", wall="BRICK", label="slime pool", riser="STEP",
                    special="SectorSpecial(damage: Damage(amount: 5))")
    pedestal = m.sector(144, 320, 192, "TILE", "CEIL", wall="BRICK", label="pedestal", riser="METAL")
    m.region(c, rect(576, 400, 896, 784), holes=[rect(672, 528, 800, 656)])
    m.region(pool, rect(672, 528, 800, 656), holes=[rect(712, 568, 760, 616)])
    m.region(pedestal, rect(712, 568, 760, 616))
    # D2: the blue door between C and E.
    d2 = m.sector(128, 128, 160, "FLOOR", "CEIL", wall="SUPPORT", label="D2 blue door", lintel="DOOR")
    m.region(d2, rect(560, 560, 576, 624))
    # E: the teleporter room, with its pad.
    e = m.sector(128, 256, 160, "FLOOR", "CEIL", wall="METAL", label="E teleporter room")
    pad = m.sector(128, 256, 224, "TELEPAD", "CEIL", wall="METAL", label="teleporter pad")
    m.region(e, rect(304, 480, 560, 704), holes=[rect(400, 560, 464, 624)])
    m.region(pad, rect(400, 560, 464, 624))
    # F: where the teleporter leads (tag 3), with the secret recess S.
    f = m.sector(0, 192, 176, "TILE", "CEIL", wall="WOOD", label="F arrival", tag=3)
    m.region(f, rect(0, 832, 384, 1152))
    s = m.sector(0, 128, 224, "TILE", "CEIL", wall="WOOD", label="S secret recess",
                 special="SectorSpecial(secret: true)")
    m.region(s, rect(-64, 992, 0, 1056))
    # G: the flickering corridor; H: the exit room.
    g = m.sector(0, 128, 176, "FLOOR", "CEIL", wall="STONE", label="G flickering corridor",
                 special="SectorSpecial(light: Flicker)")
    m.region(g, rect(160, 1152, 224, 1536))
    h = m.sector(0, 160, 192, "FLOOR", "CEIL", wall="STONE", label="H exit room")
    m.region(h, [(64, 1536), (320, 1536), (320, 1792), (224, 1792), (160, 1792), (64, 1792)])

    # The lift: used from the hall on its face, walked onto from the ledge.
    lift_use = "LineSpecial(on: Use, repeat: true, by: Anyone, tag: 1, action: Lift())"
    m.edge((512, 160), (512, 224), special=lift_use, front=a)
    lift_walk = "LineSpecial(on: Walk, repeat: true, by: Anyone, tag: 1, action: Lift())"
    m.edge((576, 160), (576, 224), special=lift_walk, front=b)
    # B's switch opens D1 for good.
    m.edge((896, 160), (896, 224), wall="SWITCH1",
           special="LineSpecial(on: Use, tag: 2, action: Door(kind: Open))")
    # D1's faces look into B and C, the door sector behind them.
    m.edge((704, 384), (768, 384), front=b)
    m.edge((704, 400), (768, 400), front=c)
    # C's north wall: chevrons scrolling a unit a tick.
    m.edge((576, 784), (896, 784), wall="CHEVRON", scroll=(1.0, 0.0))
    # D2: locked with the blue key, used from either room.
    blue = "LineSpecial(on: Use, repeat: true, action: Door(kind: Raise, key: Blue))"
    m.edge((576, 560), (576, 624), special=blue, front=c, upper="DOOR")
    m.edge((560, 560), (560, 624), special=blue, front=e, upper="DOOR")
    # The pad: stepping onto it from the room teleports to F.
    teleport = "LineSpecial(on: Walk, repeat: true, by: Anyone, tag: 3, action: Teleport)"
    for p, q in [((400, 560), (464, 560)), ((464, 560), (464, 624)), ((464, 624), (400, 624)),
                 ((400, 624), (400, 560))]:
        m.edge(p, q, special=teleport, front=e)
    # H's exit switch.
    m.edge((160, 1792), (224, 1792), wall="EXITSW1", special="LineSpecial(on: Use, action: Exit)")

    m.thing("player_start", 96, 192, 0)
    m.thing("blue_card", 736, 592)
    m.thing("teleport_destination", 192, 896, 90)
    for x, y in [(32, 32), (32, 352), (480, 32), (480, 352), (608, 432), (864, 432)]:
        m.thing("floor_lamp", x, y)
    m.thing("barrel", 848, 64)
    m.thing("barrel", 352, 672)
    m.thing("floor_lamp", -32, 1024)
    m.thing("floor_lamp", 96, 1568)
    m.thing("floor_lamp", 288, 1568)
    return m


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "machinery.ron")
    text, nv, nl = build().render()
    with open(out, "w") as fh:
        fh.write(text)
    print(f"wrote {os.path.normpath(out)}: {nv} vertices, {nl} lines")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Generate maps/outpost.ron: the default level, a short real fight.

    python3 maps/generators/outpost.py

Sightline's own level (map format version 2), played by the first command.
Every texture is procedural and every monster, item and weapon is drawn by
our own code (the roster: engine/data/roster.ron). The way through:

  S  the guardroom (start). A window in the north wall looks out on the
     courtyard; the door beside it opens onto it.
  C  the courtyard, open to the sky, 24 below: two sentries and a spitter.
     The shotgun lies in its north-west corner; the green armour stands on
     a pedestal in a pool of slime (animated, 5 damage every 32 ticks).
  L  the lift in C's east wall: use its face, ride it up to B.
  B  the control room, 104 up, where a stalker waits. Its switch opens the
     door in C's north wall (D2) for good.
  H  the hall, its light flickering: spitters, a stalker, a sentry. The
     blue keycard lies on a dais up two steps; a panel in the west wall
     opens onto a secret room (SR). The blue door (D3) is in the east wall.
  T  the teleporter room: step on the pad.
  X  the exit yard under the sky (reachable only by teleport), its east
     wall's chevrons scrolling; the exit switch is in the building to the
     north (E), and the intermission follows.

Layout (y up):

                                         +--E--+ exit switch
          y=1424 +-----------+dais+------+ +---+-----+---+
                 | H  (flicker)   |  T [pad]|  | X  exit yard   |
              SR=SD              D3         |  |    (sky)      |
          y=1040 +----D2-----------+--------+  +---------------+
                 | C  courtyard (sky)        |
                 |        [slime+pedestal]   L--+ B control room
                 |                           |  | (switch east)
          y=400  +--W1------D1---------------+  +
                 | S guardroom |
          y=0    +-------------+
                x=0          512            768 832         1152
Deterministic: no randomness at all.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sectormap import SectorMap  # noqa: E402


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def door_faces(m, a, b, c, d, sides, special, upper="DOOR"):
    """The special on both faces of a door: (a, b) faces sides[0], (c, d) sides[1]."""
    m.edge(a, b, special=special, front=sides[0], upper=upper)
    m.edge(c, d, special=special, front=sides[1], upper=upper)


def build():
    m = SectorMap("The Outpost", version=2, header_comment=__doc__.split("\nLayout")[0],
                  music="music/outpost.mid")
    # S: the guardroom.
    s = m.sector(0, 160, 176, "FLOOR", "CEIL", wall="STONE", label="S guardroom")
    m.region(s, rect(0, 0, 512, 384))
    # W1: a window onto the courtyard (a sill 40 up, a lintel at 120).
    w1 = m.sector(40, 120, 176, "FLOOR", "CEIL", wall="STONE", label="W1 window", riser="STONE", lintel="STONE")
    m.region(w1, rect(128, 384, 288, 400))
    # D1: the guardroom's door (shut: its ceiling on its floor).
    d1 = m.sector(0, 0, 176, "FLOOR", "CEIL", wall="SUPPORT", label="D1 door", lintel="DOOR", riser="STEP")
    m.region(d1, rect(384, 384, 448, 400))
    # C: the courtyard under the sky, with the slime pool and its pedestal.
    c = m.sector(-24, 256, 208, "GRASS", "SKY", wall="BRICK", label="C courtyard")
    pool = m.sector(-40, 256, 208, "GOO1", "SKY", wall="BRICK", label="slime pool", riser="STEP",
                    special="SectorSpecial(damage: Damage(amount: 5))")
    pedestal = m.sector(-16, 256, 208, "TILE", "SKY", wall="BRICK", label="pedestal", riser="METAL")
    m.region(c, rect(0, 400, 768, 1024), holes=[rect(448, 608, 640, 800)])
    m.region(pool, rect(448, 608, 640, 800), holes=[rect(512, 672, 576, 736)])
    m.region(pedestal, rect(512, 672, 576, 736))
    # L: the lift, resting at the top (level with B), tag 1.
    lift = m.sector(104, 232, 176, "TILE", "CEIL", wall="METAL", label="L lift", riser="METAL",
                    lintel="METAL", tag=1)
    m.region(lift, rect(768, 672, 832, 736))
    # B: the control room.
    b = m.sector(104, 232, 160, "TILE", "CEIL", wall="METAL", label="B control room")
    m.region(b, [(832, 576), (1152, 576), (1152, 688), (1152, 752), (1152, 864), (832, 864)])
    # D2: the door in the courtyard's north wall that B's switch opens (tag 2).
    d2 = m.sector(-24, -24, 176, "FLOOR", "CEIL", wall="SUPPORT", label="D2 remote door", lintel="DOOR", tag=2)
    m.region(d2, rect(320, 1024, 384, 1040))
    # H: the hall, flickering, with a dais up two steps at its north.
    h = m.sector(-24, 176, 160, "FLOOR", "CEIL", wall="WOOD", label="H hall",
                 special="SectorSpecial(light: Flicker)")
    m.region(h, [(128, 1040), (640, 1040), (640, 1184), (640, 1248), (640, 1424), (448, 1424), (448, 1296),
                 (320, 1296), (320, 1424), (128, 1424), (128, 1248), (128, 1184)])
    step = m.sector(-8, 176, 176, "TILE", "CEIL", wall="WOOD", label="dais step", riser="STEP")
    m.region(step, rect(320, 1296, 448, 1328))
    dais = m.sector(8, 176, 192, "TILE", "CEIL", wall="WOOD", label="dais", riser="STEP")
    m.region(dais, rect(320, 1328, 448, 1424))
    # SD and SR: a panel in the hall's west wall, and the secret room behind.
    sd = m.sector(-24, -24, 160, "FLOOR", "CEIL", wall="WOOD", label="SD secret panel", lintel="WOOD")
    m.region(sd, rect(112, 1184, 128, 1248))
    sr = m.sector(-24, 104, 208, "TILE", "CEIL", wall="WOOD", label="SR secret room",
                  special="SectorSpecial(secret: true)")
    m.region(sr, rect(48, 1168, 112, 1264))
    # D3: the blue door into the teleporter room.
    d3 = m.sector(-24, -24, 176, "FLOOR", "CEIL", wall="SUPPORT", label="D3 blue door", lintel="DOOR")
    m.region(d3, rect(640, 1184, 656, 1248))
    # T: the teleporter room and its pad.
    t = m.sector(-24, 112, 192, "FLOOR", "CEIL", wall="METAL", label="T teleporter room")
    pad = m.sector(-24, 112, 240, "TELEPAD", "CEIL", wall="METAL", label="teleporter pad")
    m.region(t, rect(656, 1120, 912, 1376), holes=[rect(752, 1216, 816, 1280)])
    m.region(pad, rect(752, 1216, 816, 1280))
    # X: the exit yard (tag 3, where the pad leads) and E, the exit building.
    x = m.sector(0, 288, 224, "DIRT", "SKY", wall="BRICK", label="X exit yard", tag=3)
    m.region(x, [(1024, 1040), (1408, 1040), (1408, 1424), (1280, 1424), (1152, 1424), (1024, 1424)])
    e = m.sector(0, 128, 255, "TILE", "CEIL", wall="METAL", label="E exit building", lintel="METAL")
    m.region(e, [(1152, 1424), (1280, 1424), (1280, 1552), (1248, 1552), (1184, 1552), (1152, 1552)])

    # The window and the doors.
    for p, q in [((128, 384), (288, 384)), ((128, 400), (288, 400))]:
        m.edge(p, q, impassable=True)
    door = "LineSpecial(on: Use, repeat: true, by: Anyone, action: Door(kind: Raise))"
    door_faces(m, (384, 384), (448, 384), (384, 400), (448, 400), (s, c), door)
    # The lift: used on its face from the courtyard, walked onto from B.
    m.edge((768, 672), (768, 736), front=c,
           special="LineSpecial(on: Use, repeat: true, by: Anyone, tag: 1, action: Lift())")
    m.edge((832, 672), (832, 736), front=b,
           special="LineSpecial(on: Walk, repeat: true, by: Anyone, tag: 1, action: Lift())")
    # B's switch opens D2 for good.
    m.edge((1152, 688), (1152, 752), wall="SWITCH1",
           special="LineSpecial(on: Use, tag: 2, action: Door(kind: Open))")
    m.edge((320, 1024), (384, 1024), front=c, upper="DOOR")
    m.edge((320, 1040), (384, 1040), front=h, upper="DOOR")
    # The secret panel looks like the wall round it.
    m.edge((128, 1184), (128, 1248), front=h, upper="WOOD",
           special="LineSpecial(on: Use, action: Door(kind: Open))")
    # D3: locked with the blue key, used from either room.
    blue = "LineSpecial(on: Use, repeat: true, action: Door(kind: Raise, key: Blue))"
    door_faces(m, (640, 1184), (640, 1248), (656, 1184), (656, 1248), (h, t), blue)
    # The pad: stepping onto it teleports to X.
    teleport = "LineSpecial(on: Walk, repeat: true, tag: 3, action: Teleport)"
    for p, q in [((752, 1216), (816, 1216)), ((816, 1216), (816, 1280)), ((816, 1280), (752, 1280)),
                 ((752, 1280), (752, 1216))]:
        m.edge(p, q, special=teleport, front=t)
    # X's east wall: chevrons scrolling a unit a tick; E's exit switch.
    m.edge((1408, 1040), (1408, 1424), wall="CHEVRON", scroll=(1.0, 0.0))
    m.edge((1184, 1552), (1248, 1552), wall="EXITSW1", special="LineSpecial(on: Use, action: Exit)")

    m.thing("player_start", 208, 140, 90)
    m.thing("teleport_destination", 1216, 1100, 90)
    # Monsters: in the courtyard, the control room, the hall, the teleporter
    # room and the exit yard.
    for kind, px, py, a in [
        ("sentry", 160, 880, 270), ("sentry", 640, 960, 225), ("spitter", 700, 480, 180),
        ("stalker", 1000, 720, 180),
        ("spitter", 200, 1380, 270), ("spitter", 560, 1380, 270), ("stalker", 384, 1200, 270),
        ("sentry", 600, 1100, 180),
        ("sentry", 860, 1330, 225),
        ("stalker", 1300, 1300, 270), ("sentry", 1100, 1350, 270), ("sentry", 1350, 1100, 180),
        ("spitter", 1216, 1390, 270),
    ]:
        m.thing(kind, px, py, a)
    # Weapons, ammunition, health and armour.
    for kind, px, py in [
        ("clip", 440, 60), ("stimpack", 460, 320), ("health_bonus", 160, 300), ("health_bonus", 208, 300),
        ("health_bonus", 256, 300), ("armor_bonus", 40, 340), ("armor_bonus", 80, 340),
        ("shotgun", 96, 960), ("shotgun_shells", 300, 480), ("clip", 620, 440), ("green_armor", 544, 704),
        ("medikit", 1100, 620), ("shotgun_shells", 1100, 820),
        ("blue_card", 384, 1390), ("stimpack", 170, 1080), ("clip", 610, 1400), ("shotgun_shells", 470, 1080),
        ("medikit", 80, 1190), ("shotgun_shells", 80, 1240), ("armor_bonus", 64, 1216), ("armor_bonus", 96, 1216),
        ("shotgun_shells", 690, 1150), ("health_bonus", 880, 1150), ("stimpack", 700, 1340),
        ("stimpack", 1060, 1080), ("shotgun_shells", 1380, 1080),
    ]:
        m.thing(kind, px, py)
    # Lamps and barrels.
    for kind, px, py in [
        ("floor_lamp", 24, 24), ("floor_lamp", 488, 24), ("floor_lamp", 856, 600), ("floor_lamp", 1128, 840),
        ("floor_lamp", 148, 1060), ("floor_lamp", 620, 1060), ("floor_lamp", 1176, 1530), ("floor_lamp", 1256, 1530),
        ("barrel", 600, 1000), ("barrel", 40, 440), ("barrel", 1040, 1400), ("barrel", 880, 1140),
    ]:
        m.thing(kind, px, py)
    return m


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "outpost.ron")
    text, nv, nl = build().render()
    with open(out, "w") as fh:
        fh.write(text)
    print(f"wrote {os.path.normpath(out)}: {nv} vertices, {nl} lines")


if __name__ == "__main__":
    main()

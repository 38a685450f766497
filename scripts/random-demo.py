#!/usr/bin/env python3
"""Writes a vanilla demo (version 109) of seeded random commands for one to
four players: co-op or deathmatch, any skill and map. Each player holds a
command (a walk or run, a strafe, a turn, fire, use, a weapon change) for 5
to 40 tics, then draws another. No one plays well, so players die, press
use and are reborn, monsters and players fight: a netgame's rules at work.
`tests/fixtures/demo-dumps/freedoom*-random-*.lmp` were written by it (the
commands are in the file's name and README) and Chocolate Doom's dumps of
them sit beside them (`scripts/chocolate-demo-dumps.sh`).

Usage: scripts/random-demo.py OUT --seed N --players P [--deathmatch]
       [--skill 1-5] [--episode E] [--map M] [--tics T]
"""

import argparse
import random
import struct
from pathlib import Path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--players", type=int, choices=range(1, 5), default=2)
    parser.add_argument("--deathmatch", action="store_true")
    parser.add_argument("--skill", type=int, choices=range(1, 6), default=4)
    parser.add_argument("--episode", type=int, default=1)
    parser.add_argument("--map", type=int, default=1)
    parser.add_argument("--tics", type=int, default=3000)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    # version, skill (0-4), episode, map, deathmatch, respawn, fast,
    # nomonsters, console player, the four players in the game.
    header = [109, args.skill - 1, args.episode, args.map, int(args.deathmatch), 0, 0, 0, 0]
    header += [int(n < args.players) for n in range(4)]
    held = [(0, 0, 0, 0)] * args.players
    left = [0] * args.players
    body = bytearray()
    for _ in range(args.tics):
        for p in range(args.players):
            if left[p] == 0:
                forward = rng.choice([50, 50, 25, 0, -25, 50])
                side = rng.choice([0, 0, 0, 24, -24, 40, -40])
                turn = rng.choice([0, 0, 0, 2, -2, 4, -4, 8, -8])
                buttons = 0
                if rng.random() < 0.4:
                    buttons |= 1  # fire
                if rng.random() < 0.15:
                    buttons |= 2  # use: doors, switches, rebirth
                if rng.random() < 0.05:
                    buttons |= 4 | (rng.randrange(0, 7) << 3)  # a weapon change
                held[p] = (forward, side, turn & 0xFF, buttons)
                left[p] = rng.randrange(5, 40)
            left[p] -= 1
            body += struct.pack("<bbBB", *held[p])
    args.out.write_bytes(bytes(header) + bytes(body) + b"\x80")


if __name__ == "__main__":
    main()

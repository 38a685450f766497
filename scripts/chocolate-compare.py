#!/usr/bin/env python3
"""Sightline against Chocolate Doom on Freedoom's E1M4, in one run.

Chocolate Doom: `chocolate-doom -iwad freedoom1.wad -timedemo demo1 -noblit
-nosound -nomusic` with SDL_VIDEODRIVER=dummy (demo1 plays E1M4; -noblit
skips copying the frame to the screen). Its fps is frames (game tics, one
frame each) over wall-clock time, so its ms/frame includes the game logic.

That wall-clock figure is mostly not rendering: the timed stretch includes
the screen melt at the level's start, which runs at 35 tics a second in
1 ms sleeps (d_main.c's wipe loop), about 1.1 s of the 1.3 s a run takes. So
the script also gives Chocolate's CPU time per frame: the CPU time of the
run less that of a run of the demo's first tic alone (start-up and level
load), over the tics between.

Sightline: `sightline bench tour e1m4.ron --size WxH --threads N --json`, the
median of render_frame over a fixed tour (every thing's position, eight
angles each) of the imported map, in 32-bit colour with textures, sprites,
sky and distance light.

The two are run alternately, ROUNDS times, and the medians of the rounds are
reported. Needs: apt-get install chocolate-doom freedoom.

Usage: scripts/chocolate-compare.py [--rounds N] [--out FILE]
"""

import argparse
import os
import re
import resource
import subprocess
import sys
from pathlib import Path

from e1m4 import WAD, one_tic_demo, prepared, report, rounds_table, sightline_tour

CHOCOLATE = "/usr/games/chocolate-doom"


def chocolate_run(home, demo):
    """Plays `demo` (a lump name or a file) timed; returns its reported ms per
    frame, its tics and the CPU seconds the run took."""
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", HOME=str(home))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(
        [CHOCOLATE, "-iwad", str(WAD), "-timedemo", str(demo), "-noblit", "-nosound", "-nomusic"],
        env=env, capture_output=True, text=True, cwd=home,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    text = out.stdout + out.stderr
    m = re.search(r"timed (\d+) gametics in (\d+) realtics \(([\d.inf]+) fps\)", text)
    if not m:
        sys.exit(f"chocolate-doom printed no timing:\n{text}")
    return 1000.0 / float(m.group(3)), int(m.group(1)), cpu


def chocolate_ms(home, short):
    """Chocolate's timedemo ms per frame, its tics, and its CPU ms per frame
    (the full run's CPU time less the one-tic run's, over the other tics)."""
    ms, tics, cpu = chocolate_run(home, "demo1")
    _, _, fixed = chocolate_run(home, short)
    return ms, tics, (cpu - fixed) * 1000.0 / max(tics - 1, 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()
    with prepared(CHOCOLATE, "chocolate-doom") as (binary, tmp, ron, demo):
        short = tmp / "short.lmp"
        one_tic_demo(demo, short)
        keys = ["chocolate", "chocolate cpu", "320x200 t1", "320x200 t2"]
        rounds = {k: [] for k in keys}
        frames, loads = {}, []
        for r in range(args.rounds):
            loads.append(os.getloadavg()[0])
            ms, tics, cpu_ms = chocolate_ms(tmp, short)
            rounds["chocolate"].append(ms)
            rounds["chocolate cpu"].append(cpu_ms)
            frames["chocolate"] = frames["chocolate cpu"] = tics
            for key, threads in (("320x200 t1", 1), ("320x200 t2", 2)):
                j = sightline_tour(binary, ron, "320x200", threads)
                rounds[key].append(j["median_ms"])
                frames[key] = j["frames"]
            print(f"round {r + 1} (load {loads[-1]:.2f}): "
                  + ", ".join(f"{k} {v[-1]:.3f} ms" for k, v in rounds.items()), file=sys.stderr)
    labels = {
        "chocolate": "Chocolate Doom timedemo demo1 (E1M4), 320x200, 8-bit, -noblit, as it reports",
        "chocolate cpu": "Chocolate Doom, the same runs' CPU time per frame (start-up left out; the melt's sleeps take none)",
        "320x200 t1": "Sightline E1M4 tour, 320x200, 1 thread",
        "320x200 t2": "Sightline E1M4 tour, 320x200, 2 threads",
    }
    lines, med = rounds_table(keys, labels, rounds, frames, loads)
    lines.append(f"Chocolate Doom / Sightline at 320x200, one thread: **{med['chocolate'] / med['320x200 t1']:.2f}x** "
                 f"against its timedemo figure (goal: at least 4x), "
                 f"{med['chocolate cpu'] / med['320x200 t1']:.2f}x against its CPU time per frame.")
    report(lines, args.out)


if __name__ == "__main__":
    main()

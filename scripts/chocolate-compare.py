#!/usr/bin/env python3
"""Sightline against Chocolate Doom, whole game against whole game, on
Freedoom's eight vanilla demos (freedoom1.wad and freedoom2.wad, DEMO1-4),
in one run.

Chocolate Doom: `chocolate-doom -iwad WAD -timedemo DEMOn -noblit -nosound
-nomusic` with SDL_VIDEODRIVER=dummy, in a scratch HOME and working
directory (-noblit skips copying the frame to the screen; it still runs
every tic and renders a frame per tic). Its own fps is frames over
wall-clock time and includes the screen melt at each level's start, which
runs at 35 tics a second in 1 ms sleeps (d_main.c's wipe loop, about 1.1 s
a level), so the figure compared is its CPU time per frame: the CPU time
(getrusage of the child) of the run less that of a run of the demo's first
tic alone (a cut of the demo: its header, its first tic and the 0x80 end;
start-up and level load), over the tics between.

Sightline: `sightline replay WAD:DEMOn --timedemo --size 320x200 --threads
1`, which runs every tic of the simulation and renders a frame per tic in
32-bit colour with textures, sprites, sky and distance light. The figure
compared is the CPU ms per frame it prints (its timed loop alone); its
child's CPU time, less that of a run of the same one-tic cut, over the tics
between, is given beside it as a like-for-like check of Chocolate's
measure.

Each round plays, demo by demo, Chocolate then Sightline (each its full run
and its one-tic run). Per demo the table gives the tics, the medians of the
rounds' figures and the ratio of those medians; the total row is each
program's CPU time over its frames summed over the eight demos, and its
ratio is the median of the rounds' total ratios (every round's is listed).
Takes about 85 s a round (Chocolate sleeps through a melt in each of its 16 runs).

--tour keeps the older comparison instead: Chocolate's timedemo of
freedoom1.wad's DEMO1 (E1M4) against `sightline bench tour` of the imported
E1M4 (render_frame alone, no game logic) at 320x200, one and two threads.

Needs: apt-get install chocolate-doom freedoom.
SIGHTLINE_BIN=PATH uses that binary instead of building one.

Usage: scripts/chocolate-compare.py [--rounds N] [--out FILE] [--tour]
"""

import argparse
import os
import re
import statistics
import sys
from pathlib import Path

from e1m4 import (WAD, demo_set, load_line, one_tic_demo, prepared, report, rounds_table,
                  sightline_timedemo, sightline_tour, timed_run)

CHOCOLATE = "/usr/games/chocolate-doom"


def chocolate_run(home, wad, demo):
    """Plays `demo` (a lump name or a file) of `wad` timed; returns its
    reported ms per frame, its tics and the CPU seconds the run took."""
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", HOME=str(home))
    text, cpu = timed_run([CHOCOLATE, "-iwad", str(wad), "-timedemo", str(demo), "-noblit", "-nosound", "-nomusic"],
                          env=env, cwd=home)
    m = re.search(r"timed (\d+) gametics in (\d+) realtics \(([\d.inf]+) fps\)", text)
    if not m:
        sys.exit(f"chocolate-doom -iwad {wad} -timedemo {demo} printed no timing:\n{text}")
    return 1000.0 / float(m.group(3)), int(m.group(1)), cpu


def chocolate_ms(home, short):
    """Chocolate's timedemo ms per frame, its tics, and its CPU ms per frame
    (the full run's CPU time less the one-tic run's, over the other tics)."""
    ms, tics, cpu = chocolate_run(home, WAD, "demo1")
    _, _, fixed = chocolate_run(home, WAD, short)
    return ms, tics, (cpu - fixed) * 1000.0 / max(tics - 1, 1)


def tour(args):
    """The older comparison: Chocolate's timedemo of E1M4 against Sightline's E1M4 tour."""
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


def demos(args):
    """Whole game against whole game on the eight demos."""
    with demo_set([CHOCOLATE], "chocolate-doom") as (binary, tmp, demos):
        # Per demo, per round: Chocolate's CPU s less its one-tic run's and
        # its reported ms/frame; Sightline's printed CPU ms/frame and its CPU
        # s less its one-tic run's.
        runs = {d.name: [] for d in demos}
        tics, loads = {}, []
        for r in range(args.rounds):
            loads.append(os.getloadavg()[0])
            print(f"round {r + 1}, load {loads[-1]:.2f}", file=sys.stderr)
            for d in demos:
                choc_ms, choc_tics, choc_cpu = chocolate_run(tmp, d.wad, d.lump)
                _, _, choc_fixed = chocolate_run(tmp, d.wad, d.short)
                sl_tics, sl_cpu_ms, _, sl_cpu = sightline_timedemo(binary, d, "320x200", 1)
                _, _, _, sl_fixed = sightline_timedemo(binary, d, "320x200", 1, short=True)
                if choc_tics != sl_tics:
                    print(f"  {d.name}: Chocolate played {choc_tics} tics, Sightline {sl_tics}", file=sys.stderr)
                tics[d.name] = (choc_tics, sl_tics)
                run = {
                    "choc cpu s": choc_cpu - choc_fixed,
                    "choc ms": choc_ms,
                    "sl ms": sl_cpu_ms,
                    "sl cpu s": sl_cpu - sl_fixed,
                }
                runs[d.name].append(run)
                print(f"  {d.name} ({d.map}, {choc_tics} tics): Chocolate {run['choc cpu s'] * 1000 / (choc_tics - 1):.3f}"
                      f" ms CPU, Sightline {sl_cpu_ms:.3f} printed / {run['sl cpu s'] * 1000 / (sl_tics - 1):.3f}"
                      " rusage ms CPU per frame", file=sys.stderr)

    def per_frame(d, k, r):
        """Round r's ms per frame of demo d: for a CPU-second figure, over
        the tics less the one-tic run's."""
        x = runs[d.name][r][k]
        if k.endswith(" s"):
            return x * 1000.0 / (tics[d.name][0 if k.startswith("choc") else 1] - 1)
        return x

    lines = [
        "| demo | map | tics | Chocolate CPU ms/frame | Sightline CPU ms/frame (printed) | Chocolate / Sightline "
        "| Sightline CPU ms/frame (rusage) | Chocolate / Sightline (rusage) | Chocolate timedemo ms/frame as it reports (wall, melt included) |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    n = args.rounds
    for d in demos:
        med = {k: statistics.median(per_frame(d, k, r) for r in range(n))
               for k in ("choc cpu s", "sl ms", "sl cpu s", "choc ms")}
        t = tics[d.name]
        lines.append(f"| {d.name} | {d.map} | {t[0] if t[0] == t[1] else f'{t[0]} (Sightline {t[1]})'} "
                     f"| {med['choc cpu s']:.3f} | {med['sl ms']:.3f} | **{med['choc cpu s'] / med['sl ms']:.2f}x** "
                     f"| {med['sl cpu s']:.3f} | {med['choc cpu s'] / med['sl cpu s']:.2f}x | {med['choc ms']:.3f} |")
    # Each round's totals: CPU over frames summed over the demos (a run's
    # frames less one where its one-tic run was subtracted).
    totals = []
    for r in range(n):
        choc = sum(runs[d.name][r]["choc cpu s"] for d in demos) * 1000 / sum(tics[d.name][0] - 1 for d in demos)
        sl = sum(runs[d.name][r]["sl ms"] * tics[d.name][1] for d in demos) / sum(tics[d.name][1] for d in demos)
        slr = sum(runs[d.name][r]["sl cpu s"] for d in demos) * 1000 / sum(tics[d.name][1] - 1 for d in demos)
        totals.append((choc, sl, slr))
    med = [statistics.median(t[i] for t in totals) for i in range(3)]
    ratios = [t[0] / t[1] for t in totals]
    ratios_r = [t[0] / t[2] for t in totals]
    all_tics = sum(tics[d.name][0] for d in demos)
    lines.append(f"| all eight | | {all_tics} | {med[0]:.3f} | {med[1]:.3f} | **{statistics.median(ratios):.2f}x** "
                 f"| {med[2]:.3f} | {statistics.median(ratios_r):.2f}x | |")
    lines.append("")
    lines.append(f"Chocolate Doom 320x200 8-bit -noblit against Sightline 320x200 32-bit, one thread, "
                 f"CPU per frame of the whole game (tics and rendering). Figures are medians of {n} round(s); "
                 "the ratio in bold is Chocolate's CPU per frame over Sightline's printed one (its timed loop); "
                 "the rusage columns time Sightline as Chocolate is timed (the process less a one-tic run). "
                 "The total ratio is the median of the rounds' total ratios: "
                 + ", ".join(f"{x:.2f}x" for x in ratios) + " (rusage: " + ", ".join(f"{x:.2f}x" for x in ratios_r) + ").")
    lines.append("")
    lines.append(load_line(loads))
    report(lines, args.out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--out", type=Path)
    parser.add_argument("--tour", action="store_true", help="the older E1M4 tour comparison instead")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("--rounds must be at least 1")
    (tour if args.tour else demos)(args)


if __name__ == "__main__":
    main()

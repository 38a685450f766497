#!/usr/bin/env python3
"""Sightline against dsda-doom's software renderer, whole game against whole
game, on Freedoom's eight vanilla demos (freedoom1.wad and freedoom2.wad,
DEMO1-4), in one run.

dsda-doom: `dsda-doom -iwad WAD -timedemo FILE.lmp -nosound -nomusic` with
SDL_VIDEODRIVER=dummy in a scratch HOME, its config's `videomode
"Software"` and `screen_resolution` set to --size (1920x1080 by default),
playing each demo lump extracted to a file. Its figure is its timedemo's
wall ms per frame: game tics (one frame each) over the wall-clock time it
prints, so it includes its game logic and the copy of each frame to the SDL
surface.

Two settings make that figure the engine's work alone. dsda-doom 0.25
sleeps 5 ms after every frame while its window lacks input focus (d_main.c,
"don't thrash cpu ... if the window doesnt have focus"), and a window of
SDL's dummy driver never has it: so it runs with a small LD_PRELOAD library
(written and compiled here with `cc`) that reports its window focused. And
its screen melt at each level's start runs at 35 tics a second inside the
timed stretch (about 1.2 s a level; 17% of freedoom2 DEMO4's figure), so
the config's `render_wipescreen` is set to 0; --melt leaves it on.

dsda-doom picks each demo's compatibility level itself (the table gives
what it printed) and may not keep every demo in sync as Chocolate Doom and
Sightline do: a desynced demo still plays every tic of the demo (its frame
count is the tics played, which is what is timed), only not the same game.

Sightline: `sightline replay WAD:DEMOn --timedemo --size WxH --threads 1`,
which runs every tic of the simulation and renders a frame per tic in
32-bit colour with textures, sprites, sky and distance light; its figure is
the wall ms per frame it prints (its timed loop, start-up left out as
dsda-doom's is).

Each round plays, demo by demo, dsda-doom then Sightline. Per demo the
table gives the tics, the medians of the rounds' figures and the ratio of
those medians; the total row is each program's wall time over its frames
summed over the eight demos, and its ratio is the median of the rounds'
total ratios (every round's is listed). Takes about three and a half minutes a round
at 1920x1080.

--tour keeps the older comparison instead: dsda-doom's timedemo of
freedoom1.wad's DEMO1 (E1M4), as is and focused, against `sightline bench
tour` of the imported E1M4 (render_frame alone, no game logic), one and two
threads.

Needs: apt-get install dsda-doom freedoom and a C compiler.
SIGHTLINE_BIN=PATH uses that binary instead of building one.

Usage: scripts/dsda-compare.py [--size WxH] [--rounds N] [--out FILE] [--melt] [--tour]
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
from pathlib import Path

from e1m4 import (WAD, demo_set, load_line, one_tic_demo, prepared, report, rounds_table,
                  sightline_timedemo, sightline_tour)

DSDA = "/usr/games/dsda-doom"

# SDL_GetWindowFlags with SDL_WINDOW_SHOWN (0x4) and SDL_WINDOW_INPUT_FOCUS
# (0x200) set: dsda-doom reads its focus from these flags.
FOCUS_SHIM = r"""
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
typedef struct SDL_Window SDL_Window;
uint32_t SDL_GetWindowFlags(SDL_Window *window) {
    static uint32_t (*real)(SDL_Window *);
    if (!real) real = (uint32_t (*)(SDL_Window *))dlsym(RTLD_NEXT, "SDL_GetWindowFlags");
    return real(window) | 0x4u | 0x200u;
}
"""


def dsda_setup(home, size, short, melt):
    """Writes dsda-doom's config (a first, one-tic run of the demo file
    `short` creates it) and the focus shim; returns the environment and the
    shim's path."""
    env = dict(os.environ, HOME=str(home), SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy")
    subprocess.run([DSDA, "-iwad", str(WAD), "-timedemo", str(short), "-nosound", "-nomusic"],
                   env=env, capture_output=True, cwd=home, check=False)
    cfg = home / ".dsda-doom" / "dsda-doom.cfg"
    if not cfg.exists():
        sys.exit(f"dsda-doom wrote no config at {cfg}")
    text = cfg.read_text()
    settings = {"screen_resolution": f'"{size}"', "videomode": '"Software"'}
    if not melt:
        settings["render_wipescreen"] = "0"
    for key, value in settings.items():
        text, n = re.subn(rf'(?m)^{key}\s+.*$', f'{key} {value}', text)
        if n != 1:
            sys.exit(f"{cfg}: no {key} line to set")
    cfg.write_text(text)
    shim_c, shim = home / "focus.c", home / "focus.so"
    shim_c.write_text(FOCUS_SHIM)
    subprocess.run(["cc", "-shared", "-fPIC", "-O2", "-o", str(shim), str(shim_c), "-ldl"], check=True)
    return env, shim


def dsda_ms(env, home, demo, shim=None, wad=WAD):
    """dsda-doom's timedemo of the demo file `demo` on `wad`: its wall ms per
    frame, its tics and the compatibility it printed."""
    env = dict(env, **({"LD_PRELOAD": str(shim)} if shim else {}))
    out = subprocess.run([DSDA, "-iwad", str(wad), "-timedemo", str(demo), "-nosound", "-nomusic"],
                         env=env, capture_output=True, text=True, cwd=home)
    text = out.stdout + out.stderr
    m = re.search(r"Timed (\d+) gametics in (\d+) realtics = ([\d.]+) frames per second", text)
    if not m:
        sys.exit(f"dsda-doom -iwad {wad} -timedemo {demo} printed no timing:\n{text}")
    compat = re.search(r"Compatibility: (.*)", text)
    return 1000.0 / float(m.group(3)), int(m.group(1)), compat.group(1).strip() if compat else "?"


def tour(args):
    """The older comparison: dsda-doom's timedemo of E1M4 against Sightline's E1M4 tour."""
    with prepared(DSDA, "dsda-doom") as (binary, tmp, ron, demo):
        short = tmp / "short.lmp"
        one_tic_demo(demo, short)
        env, shim = dsda_setup(tmp, args.size, short, args.melt)
        keys = ["dsda", "dsda focused", "t1", "t2"]
        rounds = {k: [] for k in keys}
        frames, parts, loads = {}, {}, []
        for r in range(args.rounds):
            loads.append(os.getloadavg()[0])
            for key, use_shim in (("dsda", None), ("dsda focused", shim)):
                ms, tics, _ = dsda_ms(env, tmp, demo, use_shim)
                rounds[key].append(ms)
                frames[key] = tics
            for key, threads in (("t1", 1), ("t2", 2)):
                j = sightline_tour(binary, ron, args.size, threads, repeat=1)
                rounds[key].append(j["median_ms"])
                frames[key] = j["frames"]
                parts[key] = j["breakdown"]
            print(f"round {r + 1} (load {loads[-1]:.2f}): "
                  + ", ".join(f"{k} {v[-1]:.3f} ms" for k, v in rounds.items()), file=sys.stderr)
    melt = "melt on" if args.melt else "no melt"
    labels = {
        "dsda": f"dsda-doom timedemo demo1 (E1M4), {args.size}, software, {melt}, as is (sleeps 5 ms a frame unfocused)",
        "dsda focused": f"dsda-doom timedemo demo1 (E1M4), {args.size}, software, {melt}, window reported focused",
        "t1": f"Sightline E1M4 tour, {args.size}, 1 thread",
        "t2": f"Sightline E1M4 tour, {args.size}, 2 threads",
    }
    lines, med = rounds_table(keys, labels, rounds, frames, loads)
    lines.append(f"dsda-doom / Sightline one thread: **{med['dsda focused'] / med['t1']:.2f}x** against the focused "
                 f"run, {med['dsda'] / med['t1']:.2f}x against the run as is (goal: at least 2x).")
    lines.append("")
    lines.append("Sightline's last round by part (ms per frame, summed over threads):")
    names = [f"{n}_ms" for n in ("setup", "walk", "walls", "spans", "masked", "copy")]
    lines.append("| threads | " + " | ".join(n.removesuffix("_ms") for n in names) + " |")
    lines.append("|---|" + "---|" * len(names))
    for k in ("t1", "t2"):
        lines.append(f"| {k[1:]} | " + " | ".join(f"{parts[k][n]:.3f}" for n in names) + " |")
    report(lines, args.out)


def demos(args):
    """Whole game against whole game on the eight demos."""
    with demo_set([DSDA], "dsda-doom") as (binary, tmp, demos):
        env, shim = dsda_setup(tmp, args.size, demos[0].short, args.melt)
        # Per demo, per round: dsda-doom's wall ms per frame, Sightline's
        # printed wall and CPU ms per frame.
        runs = {d.name: [] for d in demos}
        tics, compat, loads = {}, {}, []
        for r in range(args.rounds):
            loads.append(os.getloadavg()[0])
            print(f"round {r + 1}, load {loads[-1]:.2f}", file=sys.stderr)
            for d in demos:
                dsda, dsda_tics, compat[d.name] = dsda_ms(env, tmp, d.file, shim, d.wad)
                sl_tics, sl_cpu, sl_wall, _ = sightline_timedemo(binary, d, args.size, 1)
                tics[d.name] = (dsda_tics, sl_tics)
                runs[d.name].append({"dsda": dsda, "sl": sl_wall, "sl cpu": sl_cpu})
                print(f"  {d.name} ({d.map}, {dsda_tics} tics in dsda-doom, {sl_tics} in Sightline): "
                      f"dsda-doom {dsda:.3f}, Sightline {sl_wall:.3f} wall ms per frame", file=sys.stderr)
    n = args.rounds
    lines = [
        f"| demo | map | tics | dsda-doom's compatibility | dsda-doom wall ms/frame | Sightline wall ms/frame "
        "| dsda-doom / Sightline | Sightline CPU ms/frame |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for d in demos:
        med = {k: statistics.median(run[k] for run in runs[d.name]) for k in ("dsda", "sl", "sl cpu")}
        t = tics[d.name]
        lines.append(f"| {d.name} | {d.map} | {t[0] if t[0] == t[1] else f'{t[0]} (Sightline {t[1]})'} "
                     f"| {compat[d.name]} | {med['dsda']:.3f} | {med['sl']:.3f} "
                     f"| **{med['dsda'] / med['sl']:.2f}x** | {med['sl cpu']:.3f} |")
    totals = []
    for r in range(n):
        totals.append(tuple(
            sum(runs[d.name][r][k] * tics[d.name][i] for d in demos) / sum(tics[d.name][i] for d in demos)
            for k, i in (("dsda", 0), ("sl", 1), ("sl cpu", 1))))
    med = [statistics.median(t[i] for t in totals) for i in range(3)]
    ratios = [t[0] / t[1] for t in totals]
    lines.append(f"| all eight | | {sum(tics[d.name][0] for d in demos)} | | {med[0]:.3f} | {med[1]:.3f} "
                 f"| **{statistics.median(ratios):.2f}x** | {med[2]:.3f} |")
    lines.append("")
    lines.append(f"dsda-doom software at {args.size} (window reported focused, "
                 f"{'melt on' if args.melt else 'melt off'}) against Sightline at {args.size}, one thread, "
                 f"wall time per frame of the whole game (tics and rendering). Figures are medians of {n} round(s); "
                 "the total ratio is the median of the rounds' total ratios: "
                 + ", ".join(f"{x:.2f}x" for x in ratios) + ". dsda-doom picks each demo's compatibility "
                 "itself and may desync; a desynced demo still plays, and is timed over, every tic.")
    lines.append("")
    lines.append(load_line(loads))
    report(lines, args.out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--size", default="1920x1080")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--out", type=Path)
    parser.add_argument("--melt", action="store_true", help="leave dsda-doom's screen melt on (in the timed stretch)")
    parser.add_argument("--tour", action="store_true", help="the older E1M4 tour comparison instead")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("--rounds must be at least 1")
    (tour if args.tour else demos)(args)


if __name__ == "__main__":
    main()

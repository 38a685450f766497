#!/usr/bin/env python3
"""Frame time on Freedoom's E1M4 tour before and after issue 12, in one run.

Two builds of `sightline`: BASE (the commit before the issue, 4738a02, which
plays only imported RON maps) and HEAD. Each imports E1M4 with its own
importer (`sightline import freedoom1.wad --map E1M4 -o DIR`); HEAD also
tours the map straight from the WAD (`freedoom1.wad:E1M4`), as a player
would open it. All three tours must have the same poses and show the same
things:

- BASE's importer keeps only the things of the middle skill in single
  player; HEAD's keeps them all and draws (and tours) those of skill 3:
  the same things, in the same order (checked here).
- BASE refuses a pose exactly on a line (issue 12, point 5, changed that),
  so its tour skips things standing on one. Those things are moved a
  quarter unit off the line, up and right, in both imported maps (listed
  when run); the WAD tour keeps them where they are.

Then `sightline bench tour MAP --size WxH --threads N --json` runs for each
of BASE, HEAD (imported) and HEAD (WAD), interleaved, ROUNDS times per
configuration, the order rotating each round; the medians of the per-run
medians and the head/base ratios are printed as a markdown table. Last, the
player start and a sample of tour poses are captured with both builds
(`sightline capture MAP --pose X,Y,A --size WxH -o F.png`) and the PNGs
compared pixel by pixel (ImageMagick's `compare -metric AE`).

Usage: scripts/tour-before-after.py --base-bin B --head-bin H [--rounds N] [--wad PATH] [--out DIR]
"""

import argparse
import json
import re
import statistics
import subprocess
from pathlib import Path

CONFIGS = [((320, 200), 1, 3), ((1920, 1080), 1, 1), ((1920, 1080), 2, 1)]  # size, threads, passes
MARKERS = {"player2_start", "player3_start", "player4_start", "deathmatch_start", "teleport_destination"}
NUDGE = 0.25


def run(cmd):
    return subprocess.run([str(c) for c in cmd], check=True, capture_output=True, text=True).stdout


def parse_map(path):
    """Vertices, lines (from, to) and things (kind, x, y, skills, multiplayer) of a RON map as `import` writes it."""
    s = Path(path).read_text()
    vs = s[s.index("vertices:") : s.index("sectors:")]
    vertices = [(float(a), float(b)) for a, b in re.findall(r"\((-?[0-9.]+), (-?[0-9.]+)\)", vs)]
    ls = s[s.index("lines:") : s.index("things:")]
    lines = [(int(f), int(t)) for f, t in re.findall(r"Line\(\s*from: (\d+),\s*to: (\d+),", ls)]
    things = []
    for m in re.finditer(r"Thing\((.*?)\n        \)", s[s.index("things:") :], re.S):
        body = m.group(1)
        skills = re.search(r"skills: \[([^\]]*)\]", body)
        things.append(
            {
                "kind": re.search(r'kind: "([^"]*)"', body).group(1),
                "x": float(re.search(r"x: (-?[0-9.]+)", body).group(1)),
                "y": float(re.search(r"y: (-?[0-9.]+)", body).group(1)),
                "skills": [k.strip() for k in skills.group(1).split(",")] if skills else ["Easy", "Medium", "Hard"],
                "multiplayer": "multiplayer: true" in body,
            }
        )
    return vertices, lines, things


def on_a_line(vertices, lines, p):
    for f, t in lines:
        (ax, ay), (bx, by) = vertices[f], vertices[t]
        cross = (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)
        if cross == 0 and min(ax, bx) <= p[0] <= max(ax, bx) and min(ay, by) <= p[1] <= max(ay, by):
            return True
    return False


def nudge(path, points, out):
    """Writes `path` with the things at `points` moved NUDGE up and right."""
    s = Path(path).read_text()
    i = s.index("things:")
    head, tail = s[:i], s[i:]
    for x, y in points:
        old = f"x: {x},\n            y: {y},"
        new = f"x: {x + NUDGE},\n            y: {y + NUDGE},"
        assert old in tail, (path, x, y)
        tail = tail.replace(old, new)
    Path(out).write_text(head + tail)


def prepare(base_bin, head_bin, wad, out):
    base_dir, head_dir = out / "base", out / "head"
    run([base_bin, "import", wad, "--map", "E1M4", "-o", base_dir])
    run([head_bin, "import", wad, "--map", "E1M4", "-o", head_dir])
    bv, bl, base_things = parse_map(base_dir / "e1m4.ron")
    _, _, head_things = parse_map(head_dir / "e1m4.ron")
    drawn = [t for t in head_things if t["kind"] not in MARKERS and "Medium" in t["skills"] and not t["multiplayer"]]
    same = [(t["x"], t["y"]) for t in base_things] == [(t["x"], t["y"]) for t in drawn]
    print(f"things: base {len(base_things)}, head {len(head_things)} of which {len(drawn)} at skill 3 (player start included); same positions in the same order: {same}")
    assert same, "the two importers keep different things"
    stuck = [(t["x"], t["y"]) for t in base_things if on_a_line(bv, bl, (t["x"], t["y"]))]
    print(f"things exactly on a line, moved {NUDGE} up and right in both imported maps: {stuck}")
    nudge(base_dir / "e1m4.ron", stuck, base_dir / "e1m4-tour.ron")
    nudge(head_dir / "e1m4.ron", stuck, head_dir / "e1m4-tour.ron")
    return {
        "base": (base_bin, base_dir / "e1m4-tour.ron"),
        "head": (head_bin, head_dir / "e1m4-tour.ron"),
        "head-wad": (head_bin, f"{wad}:E1M4"),
    }, base_things, stuck


def tour(binary, map_, size, threads, passes):
    out = run([binary, "bench", "tour", map_, "--size", f"{size[0]}x{size[1]}", "--threads", threads, "--repeat", passes, "--json"])
    poses = int(re.search(r"\((\d+) poses", out).group(1))
    return json.loads(out.strip().splitlines()[-1]), poses


def differing_pixels(a, b):
    """Pixels that differ in any channel (ImageMagick's absolute error count, no fuzz)."""
    r = subprocess.run(["compare", "-metric", "AE", str(a), str(b), "null:"], capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    return int(float(r.stderr.split()[0]))


def compare_frames(maps, things, stuck, out, size):
    """The player start (its own angle) and every 37th thing (none on a line) facing 0 and 135 degrees."""
    poses = [(things[0]["x"], things[0]["y"], 90.0)]
    poses += [(t["x"], t["y"], a) for t in things[1::37] if (t["x"], t["y"]) not in stuck for a in (0.0, 135.0)]
    rows = []
    for x, y, a in poses:
        pngs = {}
        for name, (binary, map_) in maps.items():
            png = out / f"{name}-{x}-{y}-{a}-{size[0]}x{size[1]}.png"
            run([binary, "capture", map_, "--pose", f"{x},{y},{a}", "--size", f"{size[0]}x{size[1]}", "-o", png])
            pngs[name] = png
        rows.append(((x, y, a), differing_pixels(pngs["base"], pngs["head"]), differing_pixels(pngs["base"], pngs["head-wad"])))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--base-bin", required=True, type=Path)
    ap.add_argument("--head-bin", required=True, type=Path)
    ap.add_argument("--wad", default="/usr/share/games/doom/freedoom1.wad")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out", type=Path, default=Path("/tmp/tour-before-after"))
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    maps, things, stuck = prepare(args.base_bin, args.head_bin, args.wad, args.out)
    names = list(maps)
    medians = {}
    for size, threads, passes in CONFIGS:
        key = (size, threads)
        medians[key] = {n: [] for n in names}
        for r in range(args.rounds):
            order = names[r % len(names) :] + names[: r % len(names)]
            for name in order:
                binary, map_ = maps[name]
                result, poses = tour(binary, map_, size, threads, passes)
                medians[key][name].append(result["median_ms"])
                print(f"{size[0]}x{size[1]} t{threads} round {r} {name}: {poses} poses, median {result['median_ms']:.4f} ms", flush=True)
    print("\n| size, threads | base ms | head (imported) ms | head (WAD) ms | head / base | head (WAD) / base |")
    print("|---|---:|---:|---:|---:|---:|")
    for (size, threads), m in medians.items():
        b, h, w = (statistics.median(m[n]) for n in names)
        print(f"| {size[0]}x{size[1]}, {threads} | {b:.4f} | {h:.4f} | {w:.4f} | {h / b:.3f} | {w / b:.3f} |")
    print("\nper-run medians (ms):")
    for (size, threads), m in medians.items():
        for n in names:
            print(f"  {size[0]}x{size[1]} t{threads} {n}: {', '.join(f'{v:.4f}' for v in m[n])}")
    for size in [(320, 200), (1920, 1080)]:
        rows = compare_frames(maps, things, stuck, args.out, size)
        print(f"\npixels differing at {size[0]}x{size[1]} (of {size[0] * size[1]}), base against head (imported) and head (WAD):")
        for pose, h, w in rows:
            print(f"  pose {pose}: {h}, {w}")


if __name__ == "__main__":
    main()

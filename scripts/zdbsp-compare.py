#!/usr/bin/env python3
"""Compare Sightline's BSP splitters with ZDBSP and with a WAD's shipped nodes.

For one Doom WAD (default: Freedoom's freedoom1.wad) this

  (a) runs ZDBSP with its defaults on the whole WAD, RUNS times, and takes the
      median wall clock; then reads each map's SEGS, SSECTORS and NODES back
      out of ZDBSP's output WAD;
  (b) reads the same lumps from the input WAD (the nodes it shipped with);
  (c) builds `sightline` (cargo build --release), imports every map to RON in
      a temporary directory, and compiles each map with each of our splitters
      (`sightline compile --json`), RUNS times, interleaved with the ZDBSP runs
      so that a busy machine slows every builder alike. Our time is the median
      over runs of the summed `build_ms` (the tree build alone, as ZDBSP's
      figure is its whole process: reading, nodes, blockmap, reject, writing);
      the wall clock of each whole compile loop (process start, RON parsing,
      writing) is reported beside it.

Extra segs are `segs / sides_in - 1`, each builder against its own input:
ZDBSP and the shipped nodes count one side per sidedef of each LINEDEF
(1 + (left sidedef != 0xFFFF)); our importer drops lines that draw and block
nothing (same sector on both sides, no middle texture), so our sides_in is
smaller, and our figure is against that.

Depth is the number of internal nodes on the longest root-to-leaf path, as
`BuildStats::depth` counts it.

Usage:
  scripts/zdbsp-compare.py [--wad FILE] [--runs 3] [--seeds 1,2,3]
                           [--splitters cost,random,...] [--out FILE]
Standard library only. Needs `zdbsp` and `cargo` on PATH.
"""

import argparse
import json
import os
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT_WAD = "/usr/share/games/doom/freedoom1.wad"
MAP_LUMPS = {
    "THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES",
    "SECTORS", "REJECT", "BLOCKMAP", "BEHAVIOR", "SCRIPTS",
}


# --- WAD reading -----------------------------------------------------------

def read_wad(path):
    """Returns {MAPNAME: {LUMP: bytes}} for every map in the WAD, in WAD order."""
    data = Path(path).read_bytes()
    magic, count, directory = struct.unpack_from("<4sii", data, 0)
    if magic not in (b"IWAD", b"PWAD"):
        sys.exit(f"{path}: not a WAD (magic {magic!r})")
    lumps = []
    for i in range(count):
        offset, size, name = struct.unpack_from("<ii8s", data, directory + 16 * i)
        name = name.split(b"\0")[0].decode("ascii", "replace").upper()
        lumps.append((name, data[offset:offset + size]))
    maps = {}
    i = 0
    while i < len(lumps):
        name = lumps[i][0]
        if i + 1 < len(lumps) and lumps[i + 1][0] == "THINGS":
            parts = {}
            j = i + 1
            while j < len(lumps) and lumps[j][0] in MAP_LUMPS:
                parts[lumps[j][0]] = lumps[j][1]
                j += 1
            maps[name] = parts
            i = j
        else:
            i += 1
    return maps


def sides_in(linedefs):
    """One side per linedef plus one per left sidedef."""
    n = 0
    for k in range(0, len(linedefs) - len(linedefs) % 14, 14):
        left = struct.unpack_from("<H", linedefs, k + 12)[0]
        n += 1 + (left != 0xFFFF)
    return n


def tree_depth(children, leaf_bit, root):
    """Internal nodes on the longest root-to-leaf path; children[i] = (right, left)."""
    if not children:
        return 0
    depth = 0
    stack = [(root, 1)]
    while stack:
        node, d = stack.pop()
        depth = max(depth, d)
        for child in children[node]:
            if not child & leaf_bit:
                stack.append((child, d + 1))
    return depth


def node_figures(parts):
    """(segs, nodes, leaves, depth) of a map's node lumps, vanilla or ZDBSP's XNOD."""
    nodes = parts.get("NODES", b"")
    if nodes[:4] in (b"XNOD", b"ZNOD"):
        if nodes[:4] == b"ZNOD":
            import zlib
            nodes = b"XNOD" + zlib.decompress(nodes[4:])
        return xnod_figures(nodes)
    segs = len(parts.get("SEGS", b"")) // 12
    leaves = len(parts.get("SSECTORS", b"")) // 4
    count = len(nodes) // 28
    children = [struct.unpack_from("<HH", nodes, 28 * i + 24) for i in range(count)]
    return segs, count, leaves, tree_depth(children, 0x8000, count - 1)


def xnod_figures(data):
    """ZDBSP's extended nodes (written when a map overflows the vanilla limits)."""
    pos = 4
    _orig, new = struct.unpack_from("<II", data, pos)
    pos += 8 + 8 * new
    (leaves,) = struct.unpack_from("<I", data, pos)
    pos += 4 + 4 * leaves
    (segs,) = struct.unpack_from("<I", data, pos)
    pos += 4 + 11 * segs
    (count,) = struct.unpack_from("<I", data, pos)
    pos += 4
    children = [struct.unpack_from("<II", data, pos + 32 * i + 24) for i in range(count)]
    return segs, count, leaves, tree_depth(children, 0x80000000, count - 1)


def wad_rows(wad):
    rows = {}
    for name, parts in read_wad(wad).items():
        segs, nodes, leaves, depth = node_figures(parts)
        rows[name.lower()] = {
            "sides_in": sides_in(parts.get("LINEDEFS", b"")),
            "sides_out": segs, "nodes": nodes, "leaves": leaves, "depth": depth,
        }
    return rows


# --- running things --------------------------------------------------------

def run_quiet(cmd, **kw):
    return subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, **kw)


def sightline_binary():
    """Builds the release binary and returns its path in cargo's target dir."""
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=REPO, check=True)
    meta = subprocess.run(["cargo", "metadata", "--format-version", "1", "--no-deps"],
                          cwd=REPO, check=True, capture_output=True, text=True)
    binary = Path(json.loads(meta.stdout)["target_directory"]) / "release" / "sightline"
    if not binary.exists():
        sys.exit(f"{binary}: not built")
    return binary


def time_zdbsp(wad, out, options=()):
    started = time.perf_counter()
    run_quiet(["zdbsp", *options, "-o", str(out), str(wad)])
    return time.perf_counter() - started


def compile_all(binary, maps, splitter, seed, out):
    """One loop over every map: {map: stats}, and the loop's wall clock in s."""
    stats = {}
    started = time.perf_counter()
    for path in maps:
        cmd = [str(binary), "compile", str(path), "-o", str(out), "--splitter", splitter,
               "--seed", str(seed), "--json"]
        done = subprocess.run(cmd, check=True, capture_output=True, text=True)
        stats[path.stem] = json.loads(done.stdout.strip().splitlines()[-1])
    return stats, time.perf_counter() - started


# --- report ----------------------------------------------------------------

def extra(rows):
    s_in = sum(r["sides_in"] for r in rows.values())
    s_out = sum(r["sides_out"] for r in rows.values())
    return 100.0 * (s_out / s_in - 1.0) if s_in else 0.0


def per_map_table(title, rows, time_unit):
    lines = [f"### {title}", "",
             f"| map | sides_in | sides_out | extra % | nodes | depth | build {time_unit} |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for name in sorted(rows):
        r = rows[name]
        t = "" if r.get("time") is None else f"{r['time']:.1f}"
        lines.append(f"| {name} | {r['sides_in']} | {r['sides_out']} | "
                     f"{100.0 * (r['sides_out'] / r['sides_in'] - 1.0):.1f} | {r['nodes']} | "
                     f"{r['depth']} | {t} |")
    times = [r["time"] for r in rows.values() if r.get("time") is not None]
    total_t = f"{sum(times):.0f}" if times else ""
    lines.append(f"| **total** | {sum(r['sides_in'] for r in rows.values())} | "
                 f"{sum(r['sides_out'] for r in rows.values())} | {extra(rows):.1f} | "
                 f"{sum(r['nodes'] for r in rows.values())} | "
                 f"{max((r['depth'] for r in rows.values()), default=0)} | {total_t} |")
    lines.append("")
    return lines


def side_by_side(everyone):
    """One row per map: each builder's extra %, then each of ours' build ms."""
    ours = [(n, rows) for n, rows in everyone if any(r.get("time") is not None for r in rows.values())]
    head = ["map"] + [n for n, _ in everyone] + [f"{n} ms" for n, _ in ours]
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * (len(head) - 1)]
    maps = sorted(set.intersection(*(set(rows) for _, rows in everyone)))
    for m in maps:
        cells = [f"{100.0 * (rows[m]['sides_out'] / rows[m]['sides_in'] - 1.0):.1f}" for _, rows in everyone]
        cells += [f"{rows[m]['time']:.1f}" for _, rows in ours]
        lines.append(f"| {m} | " + " | ".join(cells) + " |")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--wad", default=DEFAULT_WAD)
    ap.add_argument("--runs", type=int, default=3, help="runs of each builder; medians are reported")
    ap.add_argument("--splitters", default="cost,random",
                    help="our splitters, comma-separated; random runs once per seed")
    ap.add_argument("--seeds", default="1,2,3", help="seeds of the random splitter")
    ap.add_argument("--out", default=None, help="markdown report (default: zdbsp-compare-WADNAME.md here)")
    args = ap.parse_args()

    wad = Path(args.wad)
    if not wad.exists():
        sys.exit(f"{wad}: no such WAD")
    if shutil.which("zdbsp") is None:
        sys.exit("zdbsp is not on PATH (Debian: apt install zdbsp)")
    out_md = Path(args.out or f"zdbsp-compare-{wad.stem}.md")
    binary = sightline_binary()
    seeds = [int(s) for s in args.seeds.split(",") if s]
    builders = []
    for s in args.splitters.split(","):
        builders += [(s, seed) for seed in seeds] if s == "random" else [(s, 0)]

    with tempfile.TemporaryDirectory(prefix="zdbsp-compare-") as tmp:
        tmp = Path(tmp)
        run_quiet([str(binary), "import", str(wad), "--map", "all", "-o", str(tmp / "maps")])
        maps = sorted((tmp / "maps").glob("*.ron"))
        if not maps:
            sys.exit(f"{wad}: the importer wrote no maps")
        zd_times, zd_nodes_times, our = [], [], {b: [] for b in builders}
        for run in range(args.runs):
            print(f"run {run + 1}/{args.runs}", file=sys.stderr)
            zd_times.append(time_zdbsp(wad, tmp / "zdbsp.wad"))
            # Without blockmap (-b) and leaving the reject as it was (-E):
            # nearly all that is left is reading, the nodes, and writing.
            zd_nodes_times.append(time_zdbsp(wad, tmp / "zdbsp-nodes.wad", ("-b", "-E")))
            for b in builders:
                our[b].append(compile_all(binary, maps, b[0], b[1], tmp / "out.slbsp"))
        zdbsp_rows = wad_rows(tmp / "zdbsp.wad")
    shipped_rows = wad_rows(wad)

    summary = ["| builder | sides_in | sides_out | extra % | nodes | max depth | time ms (median) | wall ms (median) |",
               "|---|---:|---:|---:|---:|---:|---:|---:|"]

    def summary_row(name, rows, t_ms, wall_ms):
        t = "" if t_ms is None else f"{t_ms:.0f}"
        w = "" if wall_ms is None else f"{wall_ms:.0f}"
        summary.append(f"| {name} | {sum(r['sides_in'] for r in rows.values())} | "
                       f"{sum(r['sides_out'] for r in rows.values())} | {extra(rows):.1f} | "
                       f"{sum(r['nodes'] for r in rows.values())} | "
                       f"{max(r['depth'] for r in rows.values())} | {t} | {w} |")

    everyone = [("zdbsp", zdbsp_rows), ("shipped", shipped_rows)]
    zd_ms = 1e3 * statistics.median(zd_times)
    summary_row("zdbsp (defaults, whole process)", zdbsp_rows, zd_ms, zd_ms)
    zd_nodes_ms = 1e3 * statistics.median(zd_nodes_times)
    summary_row("zdbsp -b -E (no blockmap or reject)", zdbsp_rows, zd_nodes_ms, zd_nodes_ms)
    summary_row("shipped nodes", shipped_rows, None, None)
    details = []
    details += per_map_table("zdbsp", zdbsp_rows, "")
    details += per_map_table("shipped nodes", shipped_rows, "")
    random_extras = []
    for (splitter, seed), runs in our.items():
        name = splitter if splitter != "random" else f"random seed {seed}"
        rows = {}
        for m in runs[0][0]:
            first = runs[0][0][m]
            rows[m] = {k: first[k] for k in ("sides_in", "sides_out", "nodes", "leaves", "depth")}
            rows[m]["time"] = statistics.median(r[0][m]["build_ms"] for r in runs)
        total_ms = statistics.median(sum(s["build_ms"] for s in r[0].values()) for r in runs)
        wall_ms = 1e3 * statistics.median(r[1] for r in runs)
        summary_row(f"sightline {name}", rows, total_ms, wall_ms)
        everyone.append((name, rows))
        details += per_map_table(f"sightline {name}", rows, "ms")
        if splitter == "random":
            random_extras.append(extra(rows))

    head = [f"# BSP builders on {wad.name}", "",
            f"{len(maps)} maps; medians of {args.runs} interleaved runs. ZDBSP's time is its whole",
            "process on the whole WAD (nodes, blockmap, reject, I/O; with `-b -E` it builds no",
            "blockmap and keeps the reject, same nodes); ours is the summed `build_ms`",
            "(tree build only), with the wall clock of the whole compile loop (one process per map,",
            "RON parsing, file writing) beside it. Extra % is segs / sides_in - 1 against each",
            "builder's own input: our importer drops lines that draw and block nothing, so our",
            "sides_in is smaller than the WAD's.", ""]
    text = head + summary + [""]
    if random_extras:
        text += [f"random autopartition, mean extra over {len(random_extras)} seeds: "
                 f"{statistics.mean(random_extras):.1f} %", ""]
    text += ["## Per map", "", "Extra segs, % (ours against our sides_in), and build ms of ours:", ""]
    text += side_by_side(everyone) + [""] + details
    report = "\n".join(text)
    out_md.write_text(report + "\n")
    print(report)
    print(f"written to {out_md}", file=sys.stderr)


if __name__ == "__main__":
    main()

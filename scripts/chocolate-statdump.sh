#!/usr/bin/env bash
# Plays vanilla Doom demos in Chocolate Doom, headless, and keeps what its
# intermission showed for every level each demo completed: Chocolate's
# -statdump text (kills, items, secrets, time; engine/src/play/statdump.rs
# reads it). This is how a demo Sightline recorded is checked against
# vanilla Doom. The tests do the same run through tests/chocolate.rs.
#
# Usage: bash scripts/chocolate-statdump.sh [-o OUTDIR] [--file PWAD]... IWAD DEMO.lmp...
#   -o OUTDIR       write <demo>.statdump.txt there instead of beside each demo
#   --file PWAD     a PWAD the demos play on (Chocolate's -file); repeatable
#   CHOCOLATE_DOOM  the binary (default: chocolate-doom on PATH, else
#                   /usr/games/chocolate-doom, where Debian's package puts it)
#
# Each demo gets <demo>.statdump.txt only when Chocolate played it to its
# end and it completed at least one level; an older one is removed first.
# Exit status: 0 when every demo did; 1 when any did not (each is named);
# 2 for bad usage or no chocolate-doom.
#
# How Chocolate runs (Chocolate Doom 3.0.0, Debian 12):
#   -timedemo    plays as fast as it can, where -playdemo plays in real time
#                (35 tics a second); the game is the same. At the demo's end
#                it exits through I_Error, status 255, after printing "timed N
#                gametics" to stderr; -statdump is written on that path too
#                (it is registered with I_AtExit(StatDump, true)).
#   -nodraw      skips the rendering; SDL's dummy video and audio drivers
#                stand in for a display and a sound card, so no X server.
#   -window      without it Chocolate sleeps startup_delay (1 s) after
#                setting a full-screen mode: 1.1 s a demo instead of 0.15 s.
#   -nogui       I_Error prints instead of opening a message box.
#   HOME         a scratch one, so the default.cfg Chocolate writes and any
#                user config stay apart; XDG_* are unset for the same reason.
#   cwd          a scratch one, and the demo passed by its absolute path:
#                Chocolate looks for a demo in the cwd first.
#   the demo     a copy named sldemo.lmp: Chocolate adds the file as a lump
#                named after it, loaded last, so a demo called MAP01.lmp or
#                E1M1.lmp would be found as the map ("W_LumpLength: 3659 >=
#                numlumps").
set -euo pipefail

usage() {
    sed -n 's/^# \{0,1\}//; 8,17p' "$0" >&2
    exit 2
}

outdir=""
files=()
while [ $# -gt 0 ]; do
    case "$1" in
        -o) [ $# -ge 2 ] || usage; outdir="$2"; shift 2 ;;
        --file) [ $# -ge 2 ] || usage; files+=("$(realpath -e "$2")"); shift 2 ;;
        -h | --help) usage ;;
        --) shift; break ;;
        -*) echo "unknown option $1" >&2; usage ;;
        *) break ;;
    esac
done
[ $# -ge 2 ] || usage
iwad="$(realpath -e "$1" 2>/dev/null)" || { echo "$1: no such IWAD" >&2; exit 2; }
shift

binary="${CHOCOLATE_DOOM:-}"
if [ -z "$binary" ]; then
    binary="$(command -v chocolate-doom || true)"
    [ -n "$binary" ] || [ ! -x /usr/games/chocolate-doom ] || binary=/usr/games/chocolate-doom
fi
if [ -z "$binary" ] || [ ! -x "$binary" ]; then
    if [ -n "${CHOCOLATE_DOOM:-}" ]; then
        echo "CHOCOLATE_DOOM=$CHOCOLATE_DOOM is not an executable" >&2
    else
        echo "chocolate-doom not found on PATH or in /usr/games: apt-get install chocolate-doom," \
            "or set CHOCOLATE_DOOM to the binary" >&2
    fi
    exit 2
fi
if [ -n "$outdir" ]; then
    mkdir -p "$outdir"
    outdir="$(realpath -e "$outdir")"
fi

scratch="$(mktemp -d "${TMPDIR:-/tmp}/chocolate-statdump.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/home"
file_args=()
[ ${#files[@]} -eq 0 ] || file_args=(-file "${files[@]}")

failed=()
declare -A written
for given in "$@"; do
    name="$(basename "$given")"
    if ! demo="$(realpath -e "$given" 2>/dev/null)"; then
        echo "$given: FAILED: no such file" >&2
        failed+=("$given"); continue
    fi
    out="${outdir:-$(dirname "$demo")}/${name%.*}.statdump.txt"
    if [ -n "${written[$out]:-}" ]; then
        echo "$given: FAILED: $out was just written for ${written[$out]}" >&2
        failed+=("$given"); continue
    fi
    rm -f "$out" "$scratch/statdump.txt"
    cp "$demo" "$scratch/sldemo.lmp"
    start=$EPOCHREALTIME
    status=0
    (cd "$scratch" && env -u XDG_CONFIG_HOME -u XDG_DATA_HOME HOME="$scratch/home" \
        SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy \
        timeout "${CHOCOLATE_TIMEOUT:-600}" "$binary" -iwad "$iwad" "${file_args[@]}" -timedemo "$scratch/sldemo.lmp" \
        -nodraw -window -nogui -nosound -nomusic -statdump "$scratch/statdump.txt") \
        >"$scratch/stdout.txt" 2>"$scratch/stderr.txt" || status=$?
    seconds="$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }')"
    gametics="$(sed -n 's/^timed \([0-9]*\) gametics.*/\1/p' "$scratch/stderr.txt")"
    if [ -z "$gametics" ]; then
        echo "$given: FAILED: chocolate-doom stopped before the demo's end (exit status $status, ${seconds} s); its stderr:" >&2
        sed 's/^/    /' "$scratch/stderr.txt" >&2
        failed+=("$given"); continue
    fi
    levels="$(sed -n 's/^Statistics captured for \([0-9]*\) level(s)$/\1/p' "$scratch/stdout.txt")"
    if [ ! -f "$scratch/statdump.txt" ] || [ -z "$levels" ]; then
        echo "$given: FAILED: played to its end ($gametics gametics, ${seconds} s) but chocolate-doom wrote no statdump" >&2
        failed+=("$given"); continue
    fi
    if [ "$levels" -eq 0 ]; then
        echo "$given: FAILED: the demo ended without completing a level ($gametics gametics, ${seconds} s)" >&2
        failed+=("$given"); continue
    fi
    mv "$scratch/statdump.txt" "$out"
    written[$out]="$given"
    # The name under each banner, and the time line, for one line a level.
    summary="$(awk '/^=+$/ { banner = !banner; next } banner { name = $0 }
                    /^Time: / { sub(/^Time: /, ""); printf "%s%s %s", sep, name, $0; sep = ", " }' "$out")"
    echo "$given: $levels level(s) [$summary], $gametics gametics, ${seconds} s -> $out"
done

if [ ${#failed[@]} -gt 0 ]; then
    echo "${#failed[@]} of $# demo(s) failed: ${failed[*]}" >&2
    exit 1
fi

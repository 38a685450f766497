#!/usr/bin/env bash
# Reference tic dumps of vanilla Doom demos, made by Chocolate Doom.
#
# Builds Debian's chocolate-doom source with scripts/chocolate-dump.patch
# (which, given CHOCOLATE_TIC_DUMP=<file>, writes one line of game state after
# every tic of a demo in which the level ran), then plays the eight vanilla
# demos of Debian's Freedoom IWADs (freedoom1.wad and freedoom2.wad, DEMO1 to
# DEMO4) with -timedemo and writes <iwad>-<LUMP>.txt for each. The format is
# specified in tests/fixtures/demo-dumps/README.md.
#
# Usage: bash scripts/chocolate-demo-dumps.sh [OUTDIR]
#   OUTDIR                  where the dumps go (default tests/fixtures/demo-dumps)
#   CHOCOLATE_DUMP_SCRATCH  build directory (default ${TMPDIR:-/tmp}/chocolate-demo-dumps);
#                           an existing build there is reused
#
# On Debian 12 as root (or with sudo): adds deb-src to the Types of
# /etc/apt/sources.list.d/debian.sources, installs chocolate-doom's build
# dependencies and freedoom, and fetches the source with apt-get source. The
# patched binary stays in the scratch directory; nothing is installed from it.
set -euo pipefail

repo="$(cd "$(dirname "$0")/.." && pwd)"
patch_file="$repo/scripts/chocolate-dump.patch"
outdir="$(realpath -m "${1:-$repo/tests/fixtures/demo-dumps}")"
scratch="$(realpath -m "${CHOCOLATE_DUMP_SCRATCH:-${TMPDIR:-/tmp}/chocolate-demo-dumps}")"
wads=/usr/share/games/doom
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
start=$SECONDS

echo "== apt: deb-src, build dependencies, freedoom"
sources=/etc/apt/sources.list.d/debian.sources
if [ -f "$sources" ]; then
    # Every "Types:" line without deb-src gets it; lines that have it are left.
    if grep -E '^Types:' "$sources" | grep -qv 'deb-src'; then
        $sudo sed -i -E '/^Types:/{/deb-src/!s/[[:space:]]*$/ deb-src/}' "$sources"
        echo "added deb-src to $sources"
    fi
else
    echo "note: no $sources; apt-get source needs deb-src entries from elsewhere" >&2
fi
$sudo apt-get update -q
$sudo env DEBIAN_FRONTEND=noninteractive apt-get build-dep -y -q chocolate-doom
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends --no-upgrade \
    freedoom dpkg-dev patch

echo "== source and build in $scratch"
mkdir -p "$scratch"
# A source tree patched with another version of the patch is thrown away.
if [ -f "$scratch/applied.patch" ] && ! cmp -s "$scratch/applied.patch" "$patch_file"; then
    echo "the patch changed since the last build: unpacking the source again"
    rm -rf "$scratch"/chocolate-doom-*/ "$scratch/applied.patch"
fi
src="$(find "$scratch" -maxdepth 1 -type d -name 'chocolate-doom-*' | sort | head -1)"
if [ -z "$src" ]; then
    (cd "$scratch" && apt-get source -q chocolate-doom)
    src="$(find "$scratch" -maxdepth 1 -type d -name 'chocolate-doom-*' | sort | head -1)"
    patch -p1 -d "$src" <"$patch_file"
    cp "$patch_file" "$scratch/applied.patch"
fi
source_version="$(dpkg-parsechangelog -l "$src/debian/changelog" -S Version)"
(
    cd "$src"
    if [ ! -f Makefile ]; then
        # Debian's compiler flags (debian/rules asks for hardening=+all).
        export DEB_BUILD_MAINT_OPTIONS=hardening=+all
        autoreconf -fi
        CFLAGS="$(dpkg-buildflags --get CFLAGS)" \
            CPPFLAGS="$(dpkg-buildflags --get CPPFLAGS)" \
            LDFLAGS="$(dpkg-buildflags --get LDFLAGS)" \
            ./configure
    fi
    # Only what chocolate-doom links: the three helper libraries, the Doom
    # library and the binary (not heretic, hexen, strife, setup or docs).
    for dir in textscreen opl pcsound src/doom; do
        make -j2 -C "$dir" >/dev/null
    done
    make -j2 -C src chocolate-doom >/dev/null
) >"$scratch/build.log" 2>&1 || { tail -30 "$scratch/build.log" >&2; exit 1; }
binary="$src/src/chocolate-doom"
echo "built $binary (chocolate-doom source $source_version, $((SECONDS - start)) s so far)"

echo "== dumps into $outdir"
mkdir -p "$outdir" "$scratch/home" "$scratch/run"

# dump IWAD DEMO OUT NAME: plays DEMO (a lump name, or a file's path) of
# IWAD in the patched Chocolate, its tic dump to OUT; sets $timed to the
# gametics it reports. -timedemo ends the program through I_Error at the
# demo's end (exit status 255), after printing "timed N gametics". A scratch
# HOME keeps any user config out; the cwd is a scratch directory as
# Chocolate looks for <lump>.lmp there first.
dump() {
    local iwad=$1 demo=$2 out=$3 name=$4 status=0
    rm -f "$out.tmp"
    (cd "$scratch/run" && env -u XDG_DATA_HOME -u XDG_CONFIG_HOME \
        HOME="$scratch/home" SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy \
        CHOCOLATE_TIC_DUMP="$out.tmp" \
        timeout 600 "$binary" -iwad "$wads/$iwad.wad" -timedemo "$demo" \
        -nogui -nosound -nomusic -nodraw) >"$scratch/run/$name.log" 2>&1 || status=$?
    timed="$(sed -n 's/^timed \([0-9]*\) gametics.*/\1/p' "$scratch/run/$name.log")"
    if [ -z "$timed" ] || [ ! -s "$out.tmp" ]; then
        cat "$scratch/run/$name.log" >&2
        echo "$name: no timedemo report or no dump (exit status $status)" >&2
        exit 1
    fi
    mv "$out.tmp" "$out"
}

for iwad in freedoom1 freedoom2; do
    for lump in DEMO1 DEMO2 DEMO3 DEMO4; do
        out="$outdir/$iwad-$lump.txt"
        dump "$iwad" "$lump" "$out" "$iwad-$lump"
        tics="$(grep -vc '^#' "$out")"
        read -r first _ < <(grep -v '^#' "$out" | head -1)
        read -r last _ < <(tail -1 "$out")
        level="$(head -1 "$out" | grep -o 'gameversion=[^ ]*\|skill=[^ ]*\|episode=[^ ]*\|map=[^ ]*' | tr '\n' ' ')"
        health="$(tail -1 "$out" | sed -E 's/.* p0=([^,]*,){6}([^,]*),.*/\2/')"
        echo "$iwad $lump: $tics tics dumped (gametic $first..$last), timedemo: $timed gametics; ${level}last tic's p0 health $health; $(du -k "$out" | cut -f1) KiB"
        if [ "$tics" != "$timed" ]; then
            echo "  note: $((timed - tics)) of the $timed tics played were not level tics (intermission or finale)"
        fi
    done
done
# Our own recordings kept beside the dumps (a game across an intermission,
# recorded by `sightline autoplay --levels N --record`), each with its IWAD
# named in its file name (<iwad>-<what>.lmp). Chocolate looks for a demo in
# the cwd first and adds it as a lump named after the file, so each plays as
# a copy named sldemo.lmp.
for lmp in "$repo"/tests/fixtures/demo-dumps/*.lmp; do
    [ -e "$lmp" ] || continue
    name="$(basename "$lmp" .lmp)"
    iwad="${name%%-*}"
    out="$outdir/$name.txt"
    cp "$lmp" "$scratch/run/sldemo.lmp"
    dump "$iwad" "$scratch/run/sldemo.lmp" "$out" "$name"
    tics="$(grep -vc '^#' "$out")"
    echo "$name: $tics level tics dumped of $timed gametics ($((timed - tics)) between levels); $(du -k "$out" | cut -f1) KiB"
done
echo "chocolate-doom source $source_version, freedoom $(dpkg-query -W -f='${Version}' freedoom); $((SECONDS - start)) s in all"

#!/usr/bin/env bash
# Fetches the scenario files ViZDoom 1.3.2 ships (the .cfg files and their
# WADs, from the wheel's vizdoom/scenarios/) into DIR, default
# target/vizdoom/scenarios, and prints DIR. The scenario tests read them from
# SIGHTLINE_VIZDOOM_DIR:
#
#   SIGHTLINE_VIZDOOM_DIR=$(scripts/vizdoom-scenarios.sh) cargo test --release -p sightline-engine scenario
#
# Needs pip and unzip. Only the wheel for this machine's Python is fetched
# (--no-deps); the scenario files are the same in every wheel of a release.
set -euo pipefail

dir=${1:-target/vizdoom/scenarios}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

python3 -m pip download vizdoom==1.3.2 --no-deps --only-binary=:all: -d "$tmp" >&2
wheel=$(find "$tmp" -name 'vizdoom-1.3.2-*.whl' | head -n 1)
if [[ -z $wheel ]]; then
    echo "vizdoom-scenarios.sh: pip fetched no vizdoom 1.3.2 wheel for this Python" >&2
    exit 1
fi
unzip -o -q "$wheel" 'vizdoom/scenarios/*' -d "$tmp/unpacked"
mkdir -p "$dir"
cp "$tmp"/unpacked/vizdoom/scenarios/* "$dir"/
cd "$dir" && pwd

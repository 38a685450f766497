#!/usr/bin/env bash
# The long suites: the tests too long for the README's test command, which
# lists them as ignored ("long suite ..."). CI runs them after it.
#
#   the Freedoom batch: every map of both IWADs autoplayed without monsters,
#     and `check` agreeing with the bot (tests/autopilot.rs)
#   the statdump round trips: the bot's exits with monsters on the first nine
#     maps of each IWAD, played again in Chocolate Doom (tests/autopilot_lmp.rs)
#   every Freedoom map imported, compiled, rendered and played (tests/freedoom.rs)
#   144 more generated puzzles (tests/puzzles.rs)
#
#   scripts/long-suites.sh [TEST FILTER...]
#
# They need Freedoom's WADs (apt-get install freedoom, or SIGHTLINE_DOOM_DIR)
# and Chocolate Doom (apt-get install chocolate-doom); missing ones fail the
# build or the test here instead of skipping. About 15 minutes on two quiet
# cores.
set -euo pipefail
cd "$(dirname "$0")/.."
export SIGHTLINE_REQUIRE_FREEDOOM=1 SIGHTLINE_REQUIRE_CHOCOLATE=1
cargo test --workspace --release --test autopilot --test autopilot_lmp --test freedoom --test puzzles -- --ignored "$@"

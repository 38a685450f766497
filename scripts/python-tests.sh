#!/usr/bin/env bash
# The Python package's suite: builds the wheel from python/ (maturin, through
# pip), installs it in a fresh virtual environment with what the tests need,
# and runs them (python/tests). ViZDoom's scenarios come from
# SIGHTLINE_VIZDOOM_DIR, else scripts/vizdoom-scenarios.sh fetches them.
#
#   scripts/python-tests.sh [PYTEST ARGS...]
#
# The environment is made anew in target/pyenv each run, so a stale install
# never hides a broken build. Needs python3 with venv and pip.
set -euo pipefail
cd "$(dirname "$0")/.."

env_dir=target/pyenv
rm -rf "$env_dir"
python3 -m venv "$env_dir"
py="$env_dir/bin/python"
"$py" -m pip install --quiet --upgrade pip
"$py" -m pip install --quiet "./python[test]"
if [[ -z ${SIGHTLINE_VIZDOOM_DIR:-} ]]; then
    SIGHTLINE_VIZDOOM_DIR="$(scripts/vizdoom-scenarios.sh)"
    export SIGHTLINE_VIZDOOM_DIR
fi
# Run from outside the source tree, so `import sightline` is the installed
# package and not python/sightline.
here=$(pwd)
cd "$env_dir"
"$here/$py" -m pytest -p no:cacheprovider -q "$here/python/tests" "$@"

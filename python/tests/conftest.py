"""Fixtures for the Python tests: ViZDoom's scenarios (from the vizdoom
wheel, see scripts/vizdoom-scenarios.sh) and Freedoom's IWAD. A missing
fixture skips the tests that need it, saying why; with
SIGHTLINE_REQUIRE_VIZDOOM set (as .ci/run sets it) it fails them instead."""

import os

import pytest

import sightline


def _required() -> bool:
    return os.environ.get("SIGHTLINE_REQUIRE_VIZDOOM", "") not in ("", "0")


@pytest.fixture(scope="session")
def scenarios() -> str:
    if not sightline.scenarios_path:
        why = "ViZDoom's scenarios are not here: set SIGHTLINE_VIZDOOM_DIR or run scripts/vizdoom-scenarios.sh"
        if _required():
            pytest.fail(f"SIGHTLINE_REQUIRE_VIZDOOM is set but {why}")
        pytest.skip(why)
    return sightline.scenarios_path


@pytest.fixture
def basic_cfg(scenarios) -> str:
    return os.path.join(scenarios, "basic.cfg")

"""Fixtures of the verticalChannel tests."""

import pytest

from channelTestRuns import RUNS, run_smoke


@pytest.fixture(scope="session")
def smoke_runs(foam_env):
    """The smoke runs, serial (1) and on 2 ranks (2), once per session."""
    tmp = RUNS / "test_verticalChannel"
    return {n: run_smoke(tmp, n) for n in (1, 2)}

"""Settings every test module shares.

Hypothesis runs derandomized (the examples follow from each test's own code, not from a random seed)
and without its example database: a property test passes or fails the same way on every run and
every machine, so `make test` on a clean clone cannot fail at random. Inputs a property once found
are kept as `@example`s beside the test.
"""

from __future__ import annotations

import os
from collections.abc import Iterator

import pytest
import sharedcache
from hypothesis import settings

settings.register_profile("cantools-od", derandomize=True, database=None)
settings.load_profile("cantools-od")


@pytest.fixture(scope="session", autouse=True)
def shared_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """One folder for the whole run (every pytest-xdist worker's base temporary folder is in the run's), where the
    peers' readings of the same bytes are kept once for every module and process (tests/sharedcache.py)."""
    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base
    previous = os.environ.get(sharedcache.ENV)
    os.environ[sharedcache.ENV] = str(root / "shared-cache")
    yield
    if previous is None:
        del os.environ[sharedcache.ENV]
    else:
        os.environ[sharedcache.ENV] = previous

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


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_node_collection_finished(node: object, ids: list[str]) -> None:
    """Under `--dist loadgroup` (make test) a test with an xdist_group mark carries its group in its node ID, which
    is how pytest-xdist keeps a group's tests, and so the module fixture they share, on one worker. pytest 9.2 with
    pytest-xdist 3.8 leaves the IDs as they are without a word (pytest-xdist issue 1386): each such fixture is then
    made on every worker that runs one of its tests (the Rust corpus crate compiled twice, the peer matrix judged
    twice). When no ID that a worker collected has one though their modules declare groups, stop rather than run so (a
    selection of modules without groups runs as it is)."""
    config = getattr(node, "config", None)
    if config is None or config.getoption("dist", None) != "loadgroup" or not ids:
        return
    if not any("@" in nodeid.rpartition("]")[2] for nodeid in ids) and _declare_groups(config, ids):
        pytest.exit(
            f"pytest-xdist --dist loadgroup groups no test with pytest {pytest.__version__}: install the versions "
            "pyproject.toml asks for (make test does)",
            returncode=3,
        )


def _declare_groups(config: pytest.Config, ids: list[str]) -> bool:
    """Whether a module of these tests declares an xdist_group (the controller does not collect: it has IDs only)."""
    modules = {nodeid.split("::", 1)[0] for nodeid in ids}
    return any("xdist_group" in (config.rootpath / module).read_text(encoding="utf-8") for module in modules)

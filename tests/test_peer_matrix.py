"""The peer-reader matrix over the whole corpus: what `fmt`, `convert` (EDS -> DCF with a node-ID) and `lint --fix`
write reads in python-canopen as the original does, and lely's dcfchk accepts every output of a file it accepted.

The rules behind it are by value kind (docs/portability.md). There is no exception: where python-canopen reads the
original otherwise than CiA 306 means it (a name it does not find, a signed value in two's-complement hex), ours keeps
the spelling, so that it reads ours alike; lint says what to change (EDS091, DIA018, EDS032).
"""

from __future__ import annotations

import pytest
from peermatrix import FileResult, Judgement, judge, judge_all, real_probes

from support import corpus_devices

# Its tests share one module fixture: under pytest-xdist they run on one worker, which makes it once.
pytestmark = pytest.mark.xdist_group("peer_matrix")


@pytest.fixture(scope="module")
def matrix(tmp_path_factory: pytest.TempPathFactory) -> dict[str, FileResult]:
    files = corpus_devices()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    return {r.name: r for r in judge_all(files, tmp_path_factory.mktemp("peers"), full=False)}


def _judgements(matrix: dict[str, FileResult], output: str) -> list[tuple[str, str, Judgement]]:
    return [(name, peer, j) for name, r in matrix.items() for (out, peer), j in r.judgements.items() if out == output]


@pytest.mark.parametrize("output", ["fmt", "convert-dcf", "lint-fix"])
def test_dcfchk_accepts_every_output_of_a_file_it_accepted(matrix: dict[str, FileResult], output: str) -> None:
    accepted = [(name, j) for name, peer, j in _judgements(matrix, output) if peer == "dcfchk" and j.before is None]
    assert accepted, "dcfchk accepted no original: the check would prove nothing"
    assert [f"{name}: {j.after}" for name, j in accepted if j.after is not None] == []


@pytest.mark.parametrize("output", ["fmt", "convert-dcf", "lint-fix"])
def test_python_canopen_reads_every_output_as_the_original(matrix: dict[str, FileResult], output: str) -> None:
    changed: list[str] = []
    read = 0
    for name, peer, j in _judgements(matrix, output):
        if peer == "dcfchk" or j.before is not None:
            continue
        read += 1
        if j.after is not None:
            changed.append(f"{name} ({peer}): python-canopen read the original but not ours: {j.after}")
            continue
        changed += [f"{name} ({peer}): {d}" for d in j.differences]
    assert read > 50
    assert changed == []
    if output == "lint-fix":  # a safe fix changes nothing python-canopen reads, not even the entry it fixes
        assert [str(d) for _, peer, j in _judgements(matrix, output) if peer != "dcfchk" for d in j.intended] == []


@pytest.fixture(scope="module")
def real_matrix(tmp_path_factory: pytest.TempPathFactory) -> list[FileResult]:
    folder = tmp_path_factory.mktemp("real")
    return [judge(path, folder / path.stem) for path in real_probes(folder / "probes")]


@pytest.mark.parametrize("output", ["fmt", "convert-dcf", "lint-fix"])
def test_real_values_read_alike_in_every_output(real_matrix: list[FileResult], output: str) -> None:
    """REAL32/REAL64 defaults and limits written as IEEE bit patterns (HighLimit=0xFFFF) and as decimals: both
    peers read every output as they read the original (python-canopen reads such a limit as the integer 65535,
    lely as the pattern), and dcfchk accepts every output of a probe it accepted."""
    accepted = 0
    for result in real_matrix:
        for (out, peer), j in result.judgements.items():
            if out != output:
                continue
            if peer == "dcfchk":
                accepted += j.before is None
                assert j.before is not None or j.after is None, f"{result.name}: dcfchk: {j.after}"
                continue
            assert (j.before, j.after) == (None, None), f"{result.name} ({peer}): {j.before} / {j.after}"
            assert [str(d) for d in j.differences] == [], f"{result.name} ({peer})"
    assert accepted >= 3, "dcfchk accepted too few probes for the check to prove anything"

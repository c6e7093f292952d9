"""The peer-reader matrix over the whole corpus: what `fmt`, `convert` (EDS -> DCF with a node-ID) and `lint --fix`
write reads in python-canopen as the original does, and lely's dcfchk accepts every output of a file it accepted.

The rules behind it are by value kind (docs/portability.md); the few files where python-canopen reads the original
wrongly by CiA 306 are listed below, each with why, and there it must read ours the CiA 306 way.
"""

from __future__ import annotations

import pytest
from peermatrix import Difference, FileResult, Judgement, judge, judge_all, real_probes

from support import corpus_devices

# Its tests share one module fixture: under pytest-xdist they run on one worker, which makes it once.
pytestmark = pytest.mark.xdist_group("peer_matrix")

# python-canopen reads the default of a signed type written in hex as an unsigned number; CiA 306 (value
# definitions: a hex number is the bit pattern of the type) makes it the two's complement. Ours writes the
# signed value in decimal, which python-canopen reads right.
SIGNED_HEX = "signed-hex"
# The original spells the commissioning section or its NodeID key otherwise than python-canopen looks for
# (it is case-sensitive and knows one spelling), so without a given node-ID it finds none and reads no value
# from $NODEID formulas; ours spells them as CiA 306 does, so it reads the node-ID the file states.
NODE_ID_SPELLING = "node-id-spelling"

EXCEPTIONS: dict[str, tuple[str, str]] = {
    "maxon__epos2_347717.eds": (SIGNED_HEX, "60C0h INTEGER16 0xFFFF (-1), 60C2h sub2 INTEGER8 0xFD (-3)"),
    "sevcon-gen4__Gen4.eds": (SIGNED_HEX, "2870h sub3/sub7 INTEGER16 0xFF9C (-100)"),
    "trinamic__TMCM-1270.eds": (SIGNED_HEX, "607Dh sub1 INTEGER32 0x80000001, 60C2h sub2 INTEGER8 0xFD (-3)"),
    "oresat__c3.dcf": (NODE_ID_SPELLING, "[DeviceCommissioning] NodeId=1"),
    "technosoft__ISD860.dcf": (NODE_ID_SPELLING, "[DeviceCommissioning] NodeId=0"),
}

_SIGNED_BITS = {0x02: 8, 0x03: 16, 0x04: 32, 0x10: 24, 0x12: 40, 0x13: 48, 0x14: 56, 0x15: 64}


def _explained(rule: str, peer: str, d: Difference, data_type: object) -> bool:
    if rule == SIGNED_HEX:
        bits = _SIGNED_BITS.get(data_type) if isinstance(data_type, int) else None
        return (
            d.field in ("default", "value")
            and bits is not None
            and isinstance(d.before, int)
            and d.after == d.before - (1 << bits)
        )
    return rule == NODE_ID_SPELLING and "no node-ID" in peer and d.before is None and isinstance(d.after, int)


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
    unexplained: list[str] = []
    explained: set[str] = set()
    read = 0
    for name, peer, j in _judgements(matrix, output):
        if peer == "dcfchk" or j.before is not None:
            continue
        read += 1
        if j.after is not None:
            unexplained.append(f"{name} ({peer}): python-canopen read the original but not ours: {j.after}")
            continue
        rule = EXCEPTIONS.get(name, ("", ""))[0]
        for d in j.differences:
            if _explained(rule, peer, d, _data_type(matrix, name, d)):
                explained.add(name)
            else:
                unexplained.append(f"{name} ({peer}): {d}")
    assert read > 50
    assert unexplained == []
    if output == "lint-fix":  # a safe fix changes nothing python-canopen reads, not even the entry it fixes
        assert [str(d) for _, peer, j in _judgements(matrix, output) if peer != "dcfchk" for d in j.intended] == []
    if output == "fmt":  # the list stays minimal: every file in it needs its exception
        assert explained == set(EXCEPTIONS)


def _data_type(matrix: dict[str, FileResult], name: str, d: Difference) -> object:
    return matrix[name].data_types.get(d.key)


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

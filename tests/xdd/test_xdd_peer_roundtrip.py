"""Every corpus EDS/DCF through XDD (a DCF through XDC) and back: python-canopen, the judge, reads the same
entries as from the file in canonical form, but for objects `convert` names as not kept (a signed value the EDS
wrote as two's-complement hex comes back as the negative number). An entry python-canopen reads more of after the round
trip than before (it cannot read a REAL ParameterValue written as a bit pattern), or reads without the quotes
that delimit a string in lely's dialect, is no loss."""

from __future__ import annotations

import configparser
from pathlib import Path

import pytest
from xddkit import peer_differences, peer_entries

from cantools_od import dumps, load, loads
from cantools_od.api import Format
from cantools_od.losses import losses
from cantools_od.sniff import NotADeviceDescription

from support import corpus_files, file_params


@pytest.mark.parametrize("path", file_params(corpus_files(), "../shared/eds-corpus is absent"))
def test_corpus_files_read_alike_after_xml(path: Path, tmp_path: Path) -> None:
    ini: Format = "dcf" if path.suffix.lower() == ".dcf" else "eds"
    xml: Format = "xdc" if ini == "dcf" else "xdd"
    try:
        device = load(path)
    except NotADeviceDescription as error:
        pytest.skip(f"not read as a device description: {error}")
    reference = tmp_path / f"reference.{ini}"
    reference.write_bytes(dumps(device, ini, "canonical"))
    back = tmp_path / f"back.{ini}"
    written = loads(dumps(device, xml), fmt=xml)
    back.write_bytes(dumps(written, ini))
    said = " ".join(losses(device, written, xml))
    try:
        peer_entries(path, tmp_path)
    except Exception as error:  # the judge cannot read the file itself: nothing to compare with
        pytest.skip(f"python-canopen cannot read {path.name}: {error}")
    try:
        unsaid = [line for line in peer_differences(reference, back, misread_before=True) if line[:4] not in said]
    except configparser.NoOptionError as error:  # an object python-canopen cannot read at all: said, or a finding
        unsaid = [] if error.section[:4] in said else [str(error)]
    assert unsaid == []

"""`model.plain`, the model as plain data without pydantic's serializer: the same as `model_dump` on all real
material, and what keeps reading, checking and writing an EDS free of building any class's schema."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from cantools_od import load
from cantools_od.model.plain import plain
from cantools_od.sniff import NotADeviceDescription

from support import shared_files

REAL = shared_files((".eds", ".dcf", ".xdd", ".xdc"))


@pytest.mark.skipif(not REAL, reason="../shared is absent")
def test_plain_is_model_dump_on_every_real_file() -> None:
    compared = 0
    for path in REAL:
        try:
            device = load(path)
        except NotADeviceDescription:
            continue
        assert plain(device, ("diagnostics",)) == device.model_dump(exclude={"diagnostics"}), path
        for obj in device.objects.values():
            assert plain(obj, ("origin",)) == obj.model_dump(exclude={"origin"}), (path, obj.index)
        compared += 1
    assert compared > 200


_NO_SCHEMA = """
import sys
from cantools_od import dumps, load
from cantools_od.lint import LintOptions, lint
from cantools_od.lint.config import load_selection
device = load(sys.argv[1])
lint(device, LintOptions(), load_selection(None))
dumps(device, style="canonical")
dumps(device)
print("pydantic.plugin._loader" in sys.modules)
"""


def test_reading_checking_and_writing_an_eds_builds_no_schema(tmp_path: Path) -> None:
    """The first validation or dump in a process builds the class's schema and loads pydantic's plugins (about
    30 ms at every start of a command): the reader, the rules and the EDS writer make and compare models without."""
    device = tmp_path / "compact.eds"  # CompactSubObj and CompactPDO: implied sub-objects and PDOs; no [FileInfo]
    device.write_text(
        "[DeviceInfo]\nVendorName=x\nNrOfRXPDO=1\nNrOfTXPDO=1\nCompactPDO=0x3F\n"
        "[2000]\nParameterName=Table\nObjectType=0x8\nDataType=0x0007\nAccessType=rw\nPDOMapping=0\n"
        "CompactSubObj=3\nDefaultValue=1\n[2000Name]\nNrOfEntries=1\n2=Second\n"
    )
    ran = subprocess.run([sys.executable, "-c", _NO_SCHEMA, str(device)], capture_output=True, text=True, check=True)
    assert ran.stdout == "False\n", ran.stderr

"""The application of CANopenDemo's demo device, for the test device of test_can_bus.py.

The OD of demoDevice gives some entries no data (`.dataOrig = NULL`, in CANopenEditor's OD.c as in ours): the
demo's application serves them through OD extensions. CO_identificators.c serves 1008h, 1009h and 100Ah and sets
the identity (1018h); objectAccessOD.c serves the record 2120h (its sub-index 5, an average computed on read);
domainDemo.c the DOMAIN 2122h. The test device is built the way the demo's authors build it for Linux: these
sources, their Linux target's headers (CO_ident_defs.h, peripheral.h: no hardware), compiled where they lie.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import cast

import mirrors
from cnokit import DEMO, HERE

from cantools_od.model import Device

REPO = "CANopenNode/CANopenDemo"
COMMIT = "1f16f496cf9bec459d0c86307572eac7cdbc2ebd"  # the commit ../shared/third_party/CANopenDemo-demo is from
SOURCES = ["demo/CO_application.c", "demo/CO_identificators.c", "demo/objectAccessOD.c", "demo/domainDemo.c"]
HEADERS = ["demo/CO_identificators.h", "demo/objectAccessOD.h", "demo/domainDemo.h",
           "demo/linux/CO_ident_defs.h", "demo/linux/peripheral.h"]  # fmt: skip
IDENTITY = 0x1018


@dataclass(frozen=True)
class Application:
    """What build_device adds to the stack: sources, include folders, and the define that makes device_main.c
    call them."""

    sources: tuple[Path, ...]
    includes: tuple[Path, ...]
    define: str
    ident_defs: Path  # the target's CO_ident_defs.h: what 1008h-100Ah and 1018h will answer


def demo_application(work: Path) -> Application:
    """The whole application (CO_application.c with its hooks), from the snapshot of CANopenDemo, extracted into
    `work`; the calling test is skipped when the snapshot is absent."""
    root = work / "CANopenDemo"
    mirrors.materialize(REPO, COMMIT, SOURCES + HEADERS, root)
    includes = (root / "demo", root / "demo" / "linux", HERE / "demoapp")  # demoapp: CO_application.h
    return Application(tuple(root / s for s in SOURCES), includes, "-DDEVICE_APPLICATION",
                       root / "demo" / "linux" / "CO_ident_defs.h")  # fmt: skip


def identificators(work: Path, device: Device) -> Application:
    """CO_identificators.c alone, read in place from ../shared, with a CO_ident_defs.h of ours in `work` (the
    demo's are in its target folders, which ../shared does not hold): the identity `device` describes."""
    identity = device.objects[IDENTITY].subs
    numbers = {name: identity[sub].default for sub, name in
               ((1, "VENDOR_ID"), (2, "PRODUCT_CODE"), (3, "REVISION_NUMBER"), (4, "SERIAL_NUMBER"))}  # fmt: skip
    assert all(isinstance(value, int) for value in numbers.values()), numbers
    lines = [f"#define CO_IDENTITY_{name} 0x{cast(int, value):08X}" for name, value in numbers.items()]
    lines += ["#define CO_BITRATE_INITIAL 125", "#define CO_NODE_ID_INITIAL 10",
              f'#define CO_DEVICE_NAME "{device.device_info.product_name}"', '#define CO_HW_VERSION "hw from the test"',
              '#define CO_SW_VERSION "sw from the test"']  # fmt: skip
    work.mkdir(parents=True, exist_ok=True)
    ident_defs = work / "CO_ident_defs.h"
    ident_defs.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return Application((DEMO / "CO_identificators.c",), (work, DEMO), "-DDEVICE_IDENTIFICATORS", ident_defs)


def ident_string(ident_defs: Path, name: str) -> bytes:
    """A string a CO_ident_defs.h defines (CO_DEVICE_NAME ...), as the device sends it."""
    for line in ident_defs.read_text(encoding="utf-8").splitlines():
        part = line.split(maxsplit=2)
        if part[:2] == ["#define", name]:
            return part[2].strip('"').encode()
    raise AssertionError(f"{ident_defs} defines no {name}")

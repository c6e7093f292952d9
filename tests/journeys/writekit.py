"""A small project as a user has one, for the tests of what commands write (docs/outputs.md): two device
descriptions and the pin file of one, a bus description naming both, a vendor table, a file `fmt` changes and
one `lint --fix` changes; and the checks of a folder before and after a command."""

from __future__ import annotations

import hashlib
import os
import stat
from pathlib import Path

from support import EXAMPLES

BUS = "master:\n  node_id: 1\ndrive:\n  node_id: 2\n  dcf: drive.eds\nio:\n  node_id: 3\n  dcf: io.eds\n"
TABLE = "Index,Sub,Name,Type,Access\n0x2000,0,Speed,UNSIGNED16,rw\n"
DRIVE = (EXAMPLES / "cia402_drive.eds").read_bytes()
UNFORMATTED = (EXAMPLES / "io_device.eds").read_bytes().replace(b"DataType=0x0007", b"DataType=7")
FIXABLE = (
    b"[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x80+$NODEID\n"
)
HAND_WRITTEN = b"/* written by hand: not to be replaced */\n"


def project(folder: Path) -> Path:
    """The project's files in `folder` (made when missing); `folder`."""
    from cantools_od import load
    from cantools_od.identifiers import assign

    folder.mkdir(parents=True, exist_ok=True)
    (folder / "drive.eds").write_bytes(DRIVE)
    (folder / "io.eds").write_bytes((EXAMPLES / "io_device.eds").read_bytes())
    (folder / "drive.ids.toml").write_text(assign(load(folder / "drive.eds")).to_toml())
    (folder / "bus.yml").write_text(BUS)
    (folder / "table.csv").write_text(TABLE)
    (folder / "unformatted.eds").write_bytes(UNFORMATTED)
    (folder / "emcy.eds").write_bytes(FIXABLE)
    return folder


def state(folder: Path) -> dict[str, tuple[str, int]]:
    """Every file under `folder`: relative path → (sha256 of its bytes, mode); a symbolic link by its target's name."""
    found: dict[str, tuple[str, int]] = {}
    for top, _, names in os.walk(folder):
        for name in names:
            path = Path(top, name)
            relative = path.relative_to(folder).as_posix()
            if path.is_symlink():
                found[relative] = (f"-> {os.readlink(path)}", 0)
                continue
            mode = stat.S_IMODE(path.lstat().st_mode)
            try:
                found[relative] = (hashlib.sha256(path.read_bytes()).hexdigest(), mode)
            except OSError:
                found[relative] = ("unreadable", mode)
    return found


def changed(before: dict[str, tuple[str, int]], after: dict[str, tuple[str, int]]) -> set[str]:
    """The files changed in bytes or mode, or removed, between two states (new files are not changes)."""
    return {name for name, held in before.items() if after.get(name) != held}

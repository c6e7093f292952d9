"""CANopenNode's EDS conventions: stack metadata kept as comment lines in object sections.

CANopenEditor's EDS export writes the storage group of every object and sub-object as
`;StorageLocation=<group>` above its keys; older CANopenNode (v1-v3) EDS files also write
`;TPDODetectCos=1` for objects whose change requests a TPDO. Both become typed
`CanopenNodeInfo` fields, so nothing downstream reads comments.
"""

from __future__ import annotations

import re

from ..model import CanopenNodeInfo, Device, Variable

_SETTING = re.compile(r";\s*(StorageLocation|TPDODetectCos)\s*=\s*(\S*)\s*$", re.IGNORECASE)


def _settings(var: Variable) -> dict[str, str]:
    found: dict[str, str] = {}
    for lines in var.comments.values():
        for line in lines:
            match = _SETTING.match(line)
            if match:
                found.setdefault(match[1].lower(), match[2])
    return found


def _fill(var: Variable) -> None:
    settings = _settings(var)
    if not settings:
        return
    info = var.canopennode or CanopenNodeInfo()
    if settings.get("storagelocation") and info.storage_group is None:
        info.storage_group = settings["storagelocation"]
    if "tpdodetectcos" in settings and info.flags_pdo is None:
        info.flags_pdo = settings["tpdodetectcos"].strip() not in ("", "0", "false")
    var.canopennode = info


def read_canopennode_comments(device: Device) -> None:
    """Fill `canopennode` of every object and sub-object from its CANopenNode comment lines."""
    for obj in device.objects.values():
        _fill(obj)
        for sub in obj.subs.values():
            _fill(sub)

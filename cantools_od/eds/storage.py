"""CANopenNode's storage group in an EDS: the `;StorageLocation=` comment CANopenEditor writes.

An EDS has no key for it, so CANopenEditor (and this writer) keep it as a comment
line right after ObjectType; reading it fills CanopenNodeInfo.storage_group.
"""

from __future__ import annotations

from ..canopennode.info import STORAGE_LOCATION_PREFIX
from ..model import CanopenNodeInfo, Device, Variable


def written_group(var: Variable) -> str | None:
    for lines in var.comments.values():
        for line in lines:
            if line.startswith(STORAGE_LOCATION_PREFIX):
                return line[len(STORAGE_LOCATION_PREFIX) :].strip()
    return None


def read_storage_groups(device: Device) -> None:
    """Fill storage_group from the comment, for every object and sub-object that has one."""
    for obj in device.objects.values():
        for var in (obj, *obj.subs.values()):
            if not var.comments:
                continue
            group = written_group(var)
            if group:
                info = var.canopennode or CanopenNodeInfo.model_construct()
                info.storage_group = group
                var.canopennode = info


def storage_comments(var: Variable, keys: list[str]) -> dict[str, list[str]]:
    """The section's comments, with the storage group's line added when the model has one the text lacks."""
    comments = dict(var.comments)
    group = var.canopennode.storage_group if var.canopennode is not None else None
    if not group or written_group(var) is not None or not keys:
        return comments
    after = keys.index("ObjectType") + 1 if "ObjectType" in keys and keys[-1] != "ObjectType" else 0
    key = keys[after]
    comments[key] = [f"{STORAGE_LOCATION_PREFIX}{group}", *comments.get(key, [])]
    return comments

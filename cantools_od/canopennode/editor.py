"""How CANopenEditor reads a project and writes its OD (libEDSsharp, CanOpenNodeExporter_V4.cs), where CiA 306/311
leave it open: PDO attribute bits from the PDOmapping word, defaults CiA 306 cannot read, ARRAY elements typed by
their ARRAY, the C names of display names. The generator follows these so that a project moves without change.
"""

from __future__ import annotations

import re
import sys
import unicodedata
from collections.abc import Sequence
from enum import StrEnum
from typing import Any, Protocol

from ..model.datatypes import DOMAIN, DataType, ValueKind

_WORD = re.compile(r"[A-Za-z0-9_]+")


# What the profile's functions read of an entry, an object and a device: the model's classes have it, and this module,
# which model/objects.py imports for CanopenNodeInfo, need not import them back.
class Mappable(Protocol):
    @property
    def access(self) -> StrEnum | None: ...

    @property
    def stated_pdo_mapping(self) -> str | None: ...

    @property
    def pdo_mapping(self) -> bool | None: ...

    def pdo_mapping_kind(self) -> str | None: ...


class Typed(Protocol):
    @property
    def data_type(self) -> int | None: ...


class Owner(Typed, Protocol):
    @property
    def kind(self) -> int: ...

    @property
    def dtype(self) -> DataType | None: ...


class Types(Protocol):
    def entry_type(self, var: Any, obj: Any) -> DataType | None: ...


def sdo_directions(access: str | None) -> str:
    """The ODA_SDO_* bits of an access type: "R" (ro, const), "W" (wo), "RW" (rw, rwr, rww) or ""."""
    if access is None:
        return ""
    return {"ro": "R", "const": "R", "wo": "W"}.get(access, "RW")


def pdo_directions(word: str | None, access: str | None) -> str:
    """The ODA_*PDO bits ("T", "R", "TR" or "") CANopenEditor gives a PDOmapping word and an access type.

    An explicit direction (RPDO, or the access rww) wins, then TPDO (or rwr); optional and default
    allow both directions whatever the access; no allows none.
    """
    if word == "RPDO" or access == "rww":
        return "R"
    if word == "TPDO" or access == "rwr":
        return "T"
    return "TR" if word in ("optional", "default") else ""


def editor_pdo_word(stated: str | None, mappable: bool | None) -> str:
    """The PDOmapping word CANopenEditor reads: an XDD's own, else an EDS's PDOMapping=1 as optional."""
    return stated if stated is not None else ("optional" if mappable else "no")


def pdo_bits_pair(var: Mappable) -> tuple[str, str]:
    """An entry's ODA_*PDO directions, ours and CANopenEditor's.

    They differ only on an EDS's PDOMapping=1 on a ro/const or wo entry: CANopenEditor reads it as
    `optional` and allows both directions; CiA 301 maps a read-only entry into TPDOs only and a
    write-only one into RPDOs only, so we keep the direction the access allows (CANopenEditor's own
    EDS export writes ro with PDOMapping=1 for its TPDO-only entries).
    """
    access = var.access.value if var.access else None
    ours = pdo_directions(var.pdo_mapping_kind(), access)
    return ours, pdo_directions(editor_pdo_word(var.stated_pdo_mapping, var.pdo_mapping), access)


def editor_octets(text: str) -> bytes | None:
    """An OCTET_STRING default as CANopenEditor reads it: hex bytes of one or two digits between blanks ("0",
    "1 2 A"), which CiA 306's even-length hex does not cover; None when the text is not of that form."""
    tokens = text.split()
    if not tokens or not all(len(t) <= 2 and all(c in "0123456789abcdefABCDEF" for c in t) for t in tokens):
        return None
    return bytes(int(t, 16) for t in tokens)


_C_FLOAT = re.compile(r"[+-]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fF]")


def editor_real(text: str) -> float | None:
    """A REAL default written as a C float literal ("0.0f"), which CANopenEditor copies into OD.c as it is."""
    stripped = text.strip()
    return float(stripped[:-1]) if _C_FLOAT.fullmatch(stripped) else None


def editor_integer(text: str) -> int | None:
    """An integer as CANopenEditor reads it where the file's own type did not say how (an ARRAY element with
    DataType 0, whose ARRAY gives the type): 0x hex (U and L dropped), a leading 0 octal, else decimal."""
    stripped = text.strip()
    if re.fullmatch(r"0[xX][0-9A-Fa-f]+[uUlL]*", stripped):
        return int(stripped.rstrip("uUlL"), 16)
    if re.fullmatch(r"0[0-7]+", stripped):
        return int(stripped, 8)
    return int(stripped) if re.fullmatch(r"-?\d+", stripped) else None


def editor_reads(dtype: DataType, text: str) -> bool:
    """Whether CANopenEditor takes a default that CiA 306 cannot read: any DOMAIN default (it ignores them),
    short hex octets of an OCTET_STRING (`0`, `1 2 A`), a C float literal of a REAL (`0.0f`), an integer of an
    entry typed only by its ARRAY."""
    if dtype.index == DOMAIN.index:
        return True
    if dtype.kind is ValueKind.OCTETS:
        return editor_octets(text) is not None
    if dtype.kind in (ValueKind.UNSIGNED, ValueKind.SIGNED):
        return editor_integer(text) is not None
    return dtype.kind is ValueKind.REAL and editor_real(text) is not None


def editor_entry_type(device: Types, var: Typed, obj: Owner) -> DataType | None:
    """The entry's type as CANopenEditor takes it: its own, else, for an ARRAY element whose DataType is 0 or
    missing, the ARRAY's (old CANopenEditor projects write `dataType="0000"` on the elements)."""
    dtype = device.entry_type(var, obj)
    if dtype is None and var is not obj and obj.kind == 0x8 and not var.data_type:
        return obj.dtype
    return dtype


def entry_has_memory(length: int, has_value: bool, textual: bool) -> bool:
    """CANopenEditor's storage rule for one entry (Get_dataProperties, Prepare_var, Prepare_rec): memory where it
    has a value, or where it is a string or octet string of some capacity (`CO_stringLengthMin`); a DOMAIN, of
    length 0, never. Without memory `dataOrig` is NULL and the application serves the entry (OD_extension_init)."""
    return length > 0 and (has_value or textual)


def array_has_memory(elements: Sequence[bool]) -> bool:
    """CANopenEditor's storage rule for an ARRAY's elements (Prepare_arr): one C array, which exists when the first
    element has memory by `entry_has_memory`, whatever the others say. Sub-index 0 is judged on its own."""
    return bool(elements) and elements[0]


# --- names --------------------------------------------------------------------------------------


def c_name(name: str) -> str:
    """CANopenEditor's spelling of a display name (v4.1 and later): camelCase words, '-' as '_', '_'
    between capitals, '_' before a leading digit.

    "COB-ID SYNC message" → COB_ID_SYNCMessage, "Highest sub-index supported" →
    highestSub_indexSupported, "Variable NV Int32" → variableNV_Int32, "Trigger input x8" →
    triggerInputX8. Application code written
    against CANopenEditor's OD.h (OD_PERSIST_COMM.x1018_identity.vendor_ID) keeps compiling.
    """
    folded = unicodedata.normalize("NFKD", name).encode("ascii", "ignore").decode("ascii")
    out, last = "", ""
    for word in _WORD.findall(folded.replace("-", "_")):
        if last.isupper() and word[0].isupper():
            out += "_"
        last = word[-1]
        if len(word) > 1 and word[0].isalpha():
            word = word[0].upper() + word[1:]
        out += word
    if out[:1].isdigit():
        out = "_" + out
    elif len(out) > 1 and out[0].isalpha() and out[1].islower():
        out = out[0].lower() + out[1:]
    elif len(out) == 1:
        out = out.lower()
    return sys.intern(out)  # members repeat from object to object (sub1, highestSub_indexSupported)

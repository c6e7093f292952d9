"""The code registry: every code cantools-od can print, once, with its family and kebab-case name.

Like ruff's `codes.rs`, this table is the one list of codes: a family's module declares what each
code means (`rule()` for a check, `declare()` for a code reported while reading, importing or
generating: severity, summary, documentation), and this table says which codes exist, which family
owns them and what they are called. A test fails when the two disagree. Adding a code is one
line here plus its declaration in the family's module, with a failing and a fixed example (see
`exampleset` for what an example can say), which tests/test_rule_docs.py runs.

`--select`/`--ignore` take codes, code prefixes (`PDO`, `EDS03`) and family names (`cobid`).
"""

from __future__ import annotations

import importlib
from functools import cache
from typing import NamedTuple

from ..model import Severity
from .rules import RULES, Rule


class Family(NamedTuple):
    module: str  # the module of cantools_od.lint that declares the family's codes
    title: str
    refs: str = ""  # the sections of the standards the family checks


# Families in the order the linter runs them; each is imported explicitly by `load()`.
FAMILIES: dict[str, Family] = {
    "reader": Family("reader", "Reported while reading an EDS/DCF", "CiA 306 §4 (file structure, value syntax §4.3)"),
    "xdd": Family("xdd", "Reported while reading an XDD/XDC", "CiA 311"),
    "syntax": Family("syntax", "File structure: sections, keys, lines", "CiA 306 §4, [Comments] §4.6.5"),
    "objects": Family("objects", "Object and sub-object sections", "CiA 306 §4.6.3; CiA 301 data types"),
    "dcf": Family("dcf", "DCF additions and the module concept", "CiA 306 §5, §6"),
    "objlists": Family(
        "objlists",
        "[MandatoryObjects], [OptionalObjects], [ManufacturerObjects]",
        "CiA 306 object lists; CiA 301 index areas",
    ),
    "values": Family(
        "values", "Values and limits against their data types", "CiA 306 §4.3, §4.6.3; CiA 301 data types"
    ),
    "identity": Family(
        "identity", "Mandatory objects and [DeviceInfo] against the dictionary", "CiA 306 [DeviceInfo]; CiA 301 §7.5.2"
    ),
    "pdo": Family("pdo", "PDO records and mappings", "CiA 301 §7.2.2, §7.4.8, §7.5.2.35-38; CiA 306 §4.6.3.4.1"),
    "cobid": Family("cobid", "COB-IDs and PDO communication parameters", "CiA 301 §7.2, §7.3, §7.5.2.35/37"),
    "network": Family("network", "Several nodes of one network (lint --network)", "CiA 301 §7.2, §7.3"),
    "portability": Family("portability", "What peer tools read differently (dialects)", "CiA 306 §4"),
    "standard": Family(
        "standard", "CiA 301/302 standard objects (and CiA 402 ones) against their definitions", "CiA 301 §7.5; CiA 402"
    ),
    "canopennode": Family(
        "canopennode",
        "What the CANopenNode v4 stack needs (lint --profile canopennode)",
        "CiA 301 §7.4 (object dictionary), §7.5.2 (the communication objects the stack implements)",
    ),
    "probe": Family(
        "probe",
        "Reported by probe: a live device against its description",
        "CiA 301 §7.2.4 (SDO), §7.5.2 (communication objects)",
    ),
    "import": Family(
        "tool", "Reported by import-table", "CiA 301 §7.4 (object dictionary entries); CiA 306 §4.6.3 (their keys)"
    ),
    "gen": Family("tool", "Reported by gen", "CiA 301 §7.4.8 (PDO mapping), §7.5.2.35-38 (PDO parameters)"),
    "lint": Family("tool", "Reported by the linter about itself", "CiA 306 §4 (the file the rules read)"),
}

# code -> kebab-case name, per family.
NAMES: dict[str, dict[str, str]] = {
    "reader": {
        "EDS000": "not-a-device-description",
        "JSN001": "not-a-model",
        "EDS002": "duplicate-section-or-key",
        "EDS030": "value-invalid-for-type",
        "EDS032": "non-portable-value-form",
        "EDS033": "non-portable-nodeid-formula",
        "EDS100": "not-utf8",
        "EDS101": "line-not-an-entry",
        "EDS102": "unclosed-section-header",
        "EDS103": "sub-object-without-object",
        "EDS104": "bad-compact-section",
    },
    "xdd": {
        "XDD001": "xml-not-well-formed",
        "XDD002": "xml-entities-or-external-references",
        "XDD003": "xml-too-large-or-deep",
        "XDD004": "not-cia-311",
        "XDD005": "cia-311-namespace",
        "XDD006": "required-attribute-missing",
        "XDD007": "unreadable-value",
        "XDD008": "duplicate-index-or-unique-id",
        "XDD009": "unique-id-ref-dangling",
        "XDD010": "unknown-element",
        "XDD011": "unknown-attribute",
    },
    "syntax": {
        "EDS001": "line-too-long",
        "EDS091": "name-peers-do-not-find",
        "EDS003": "unknown-key",
        "EDS004": "unknown-section",
        "EDS005": "name-too-long",
        "EDS006": "date-time-form",
        "EDS007": "eds-version-missing",
        "EDS008": "eds-version-not-4-0",
        "EDS009": "mandatory-section-missing",
        "EDS090": "comments-line-count",
    },
    "objects": {
        "EDS020": "mandatory-key-missing",
        "EDS021": "sub-number-mismatch",
        "EDS022": "compact-sub-obj-misused",
        "EDS023": "obj-flags-reserved-bits",
        "EDS024": "key-not-allowed-for-object-type",
        "EDS025": "sub-index-0-not-unsigned8",
        "EDS026": "sub-index-0-below-highest",
        "EDS027": "sub-index-ffh-described",
        "EDS028": "array-element-types-differ",
        "EDS080": "data-type-undefined",
        "EDS081": "object-type-outside-type-area",
    },
    "dcf": {
        "EDS050": "upload-download-file-access",
        "EDS051": "upload-download-file-not-domain",
        "EDS052": "dcf-key-in-eds",
        "EDS060": "dcf-without-node-id",
        "EDS062": "node-id-out-of-range",
        "EDS063": "node-id-unconfigured",
        "EDS064": "const-parameter-value-differs",
        "EDS070": "module-sections-inconsistent",
    },
    "objlists": {
        "EDS010": "listed-object-missing",
        "EDS012": "object-not-listed",
        "EDS013": "object-in-wrong-list",
        "EDS014": "supported-objects-mismatch",
        "EDS015": "object-list-numbering",
        "EDS016": "object-listed-twice",
        "EDS017": "object-outside-list-area",
        "EDS018": "data-type-listed",
        "EDS019": "object-list-missing",
    },
    "values": {
        "EDS031": "low-limit-above-high-limit",
        "EDS034": "value-outside-type-range",
        "EDS035": "default-outside-limits",
        "EDS036": "limits-on-non-numeric-type",
        "EDS037": "nodeid-in-non-integer",
        "EDS038": "visible-string-not-printable",
        "EDS039": "real-not-finite",
        "EDS061": "parameter-value-outside-limits",
    },
    "identity": {
        "EDS011": "mandatory-object-missing",
        "EDS040": "identity-mismatch",
        "EDS041": "pdo-count-mismatch",
        "EDS042": "static-mapping-writable",
        "EDS043": "baud-rate-unsupported",
        "EDS044": "no-baud-rate",
        "EDS045": "serial-number-mismatch",
        "EDS046": "granularity-above-64",
    },
    "pdo": {
        "PDO001": "pdo-record-unpaired",
        "PDO002": "pdo-record-not-record",
        "PDO040": "mapping-count-invalid",
        "PDO041": "mapping-hole",
        "PDO042": "mapped-object-missing",
        "PDO043": "mapped-object-not-mappable",
        "PDO044": "mapped-access-direction",
        "PDO045": "mapping-length-mismatch",
        "PDO046": "pdo-longer-than-frame",
        "PDO048": "mapping-off-granularity",
        "PDO049": "object-mapped-twice",
        "PDO050": "dummy-entry-not-a-type",
        "PDO051": "dummy-entry-in-tpdo",
        "PDO052": "mapped-var-sub-index",
        "PDO053": "mapping-length-msb-set",
        "PDO054": "object-in-several-rpdos",
        "PDO060": "pdo-mandatory-sub-missing",
        "PDO062": "dummy-entry-not-enabled",
        "PDO064": "mapping-sub-object-type",
    },
    "cobid": {
        "COB001": "cob-id-high-bits-in-11-bit",
        "COB004": "pdo-restricted-can-id",
        "COB005": "pdo-on-service-can-id",
        "COB006": "default-cob-id-not-predefined",
        "COB007": "pdo-5-plus-valid-by-default",
        "COB009": "producers-share-can-id",
        "COB010": "rpdos-share-can-id",
        "COB012": "default-sdo-server-cob-id-changed",
        "COB013": "rpdo-on-own-can-id",
        "PDO010": "comm-sub0-below-highest",
        "PDO011": "rpdo-inhibit-or-sync-start",
        "PDO012": "comm-sub-object-type",
        "PDO013": "comm-parameter-mappable",
        "PDO020": "transmission-type-reserved",
        "PDO021": "rpdo-rtr-transmission-type",
        "PDO023": "event-tpdo-without-timer",
        "PDO024": "sync-start-not-cyclic",
        "PDO032": "event-timer-ignored",
        "PDO033": "event-timer-below-inhibit",
    },
    "network": {
        "COB011": "network-conflict",
    },
    "portability": {
        "DIA001": "dummy-usage-incomplete",
        "DIA002": "quoted-string-outside-lely",
        "DIA003": "real-as-bit-pattern",
        "DIA004": "compact-sub-obj-on-record",
        "DIA005": "deftype-or-defstruct",
        "DIA006": "canopennode-comments",
        "DIA007": "text-not-ascii",
        "DIA008": "custom-data-type",
        "DIA009": "record-sub-names-repeat",
        "DIA010": "python-canopen-key",
        "DIA011": "reserved-device-info-key",
        "DIA012": "module-concept-sections",
        "DIA013": "time-value",
        "DIA014": "nodeid-in-limit",
        "DIA015": "empty-pdo-mapping",
        "DIA016": "obj-flags-set",
        "DIA017": "comment-character-in-text",
        "DIA018": "key-spelling",
        "DIA019": "empty-device-info-number",
        "DIA020": "octal-device-info-number",
        "DIA021": "comments-key-case",
    },
    "probe": {
        "PRB001": "missing-on-device",
        "PRB002": "length-differs-on-device",
        "PRB003": "read-refused-by-device",
        "PRB004": "identity-differs-on-device",
        "PRB005": "value-differs-on-device",
        "PRB006": "communication-value-differs-on-device",
        "PRB007": "write-refused-by-device",
        "PRB008": "no-answer-from-device",
    },
    "import": {
        "IMP001": "source-unreadable",
        "IMP002": "no-table-found",
        "IMP003": "overrides-invalid",
        "IMP004": "delimited-file-malformed",
        "IMP010": "cell-not-understood",
        "IMP011": "index-not-understood",
        "IMP012": "sub-index-not-understood",
        "IMP013": "index-range-unresolved",
        "IMP020": "conflict-by-policy",
        "IMP031": "type-or-access-unknown",
        "IMP032": "sub-index-ffh-dropped",
        "IMP040": "override-unused",
        "IMP050": "value-does-not-fit",
        "IMP051": "cob-id-made-node-relative",
    },
    "gen": {
        "GEN001": "cannot-generate",
    },
    "lint": {
        "LNT001": "rule-failed",
    },
    "standard": {
        "STD001": "standard-object-type",
        "STD002": "standard-array-or-record",
        "STD003": "standard-data-type",
        "STD004": "standard-access-type",
        "STD005": "standard-pdo-mapping",
        "STD006": "standard-value",
        "STD007": "standard-default-mapping",
    },
    "canopennode": {
        "CNO001": "type-stack-cannot-hold",
        "CNO002": "sub0-not-unsigned8",
        "CNO003": "array-elements-differ",
        "CNO004": "array-gaps-or-empty",
        "CNO005": "required-object-missing",
        "CNO006": "count-label-out-of-limits",
        "CNO007": "default-stack-cannot-store",
        "CNO008": "nodeid-not-added-by-stack",
        "CNO009": "writable-string-without-memory",
        "CNO010": "pdo-bits-differ-from-canopeneditor",
    },
}


class Code(NamedTuple):
    """One registered code: its declaration (severity, summary, documentation) and its place here."""

    code: str
    family: str
    name: str
    rule: Rule

    @property
    def severity(self) -> Severity:
        return self.rule.severity

    @property
    def summary(self) -> str:
        return self.rule.summary


@cache
def load() -> None:
    """Import every family's module, so that every code is declared (no import has side effects elsewhere)."""
    for family in dict.fromkeys(f.module for f in FAMILIES.values()):
        importlib.import_module(f"{__package__}.{family}")


def family_of(code: str) -> str | None:
    return next((family for family, names in NAMES.items() if code in names), None)


def codes() -> dict[str, Code]:
    """Every registered code with its declaration, in code order."""
    load()
    found = {
        code: Code(code, family, name, RULES[code])
        for family, names in NAMES.items()
        for code, name in names.items()
        if code in RULES
    }
    return dict(sorted(found.items()))


def find(selector: str) -> Code | None:
    """A code by its code (`PDO045`) or its name (`mapping-length-mismatch`)."""
    table = codes()
    wanted = selector.strip()
    found = table.get(wanted.upper())
    return found or next((c for c in table.values() if c.name == wanted.lower()), None)


def matches(selector: str, code: str) -> bool:
    """Whether a --select/--ignore entry covers a code: a family name, a code prefix, or the code's kebab-case name."""
    family = family_of(code)
    if family is None:
        return code.startswith(selector.upper())
    wanted = selector.lower()
    return code.startswith(selector.upper()) or family == wanted or NAMES[family][code] == wanted

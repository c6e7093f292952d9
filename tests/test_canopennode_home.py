"""CANopenNode in one home: no module outside `cantools_od/canopennode/` spells a fact of the stack or of
CANopenEditor's projects.

The facts are the identifying spellings the home itself defines: CANopenEditor's `CO_*` properties, the EDS
`;StorageLocation=` comment, the storage group `PERSIST_COMM`, the `ODA_*` attribute and `ODT_*` object-type
names, `OD_CNT_` and the count labels that are not plain words (`HB_CONS`, `SDO_SRV`), the `CO_CONFIG_*`
switches, the `.canopennode.toml` suffix. So the list cannot go stale: a fact added to the home is looked for
everywhere else at once. A module that needs one imports it; what the other layers keep is their work (the CNO
rules, the view, the C layout in templates/canopennode).

The sweep reads string literals, f-string parts included. Docstrings, comments and the text of rules
(`@rule(...)`: description, examples, fix advice) and rule-example builders (`ex.*(...)`) are documentation.
"""

from __future__ import annotations

import ast

from test_one_home import example_calls

from cantools_od.canopennode import info, overrides, profile

from support import ROOT

PACKAGE = ROOT / "cantools_od"
HOME = "canopennode/"

FACTS = frozenset(
    {
        *info.PROPERTIES,
        *info.EDS_COMMENT_KEYS,
        info.STORAGE_LOCATION,
        info.DETECT_COS,
        profile.PERSIST_COMM,
        profile.ATTRIBUTE_PREFIX,
        *profile.SDO_ATTRIBUTES.values(),
        *profile.PDO_ATTRIBUTES.values(),
        *profile.SRDO_ATTRIBUTES.values(),
        profile.MULTIBYTE_ATTRIBUTE,
        profile.STRING_ATTRIBUTE,
        *(name for pair in profile.OBJECT_TYPES.values() for name in pair),
        profile.COUNT_PREFIX,
        *(label for label in profile.COUNT_LABELS if "_" in label),  # HB_CONS, SDO_SRV: not NMT, EM, SYNC
        profile.SWITCH_PREFIX,
        *profile.STACK_FLAGS,
        *profile.STACK_DEFAULTS,
        overrides.SUFFIX,
    }
)

# Modules outside the home that may spell a fact, each with its reason.
ALLOWED: dict[str, str] = {}


def _documentation(tree: ast.AST) -> set[int]:
    """ids of the string constants that document: docstrings, and all inside `@rule(...)` and `ex.*(...)`."""
    skipped = example_calls(tree)
    for node in ast.walk(tree):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):  # a docstring, of a field too
            skipped.add(id(node.value))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "rule":
            skipped.update(id(sub) for sub in ast.walk(node))
    return skipped


def misplaced(relative: str, source: str) -> list[str]:
    """`file:line: 'fact'` for every CANopenNode fact a string literal spells outside the home."""
    if relative.startswith(HOME) or relative in ALLOWED:
        return []
    tree = ast.parse(source)
    documentation = _documentation(tree)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in documentation:
            for fact in sorted(fact for fact in FACTS if fact in node.value):
                found.append(f"cantools_od/{relative}:{node.lineno}: {fact!r}")
    return found


def test_canopennode_facts_live_in_their_home() -> None:
    found = [
        line
        for path in sorted(PACKAGE.rglob("*.py"))
        for line in misplaced(path.relative_to(PACKAGE).as_posix(), path.read_text(encoding="utf-8"))
    ]
    assert not found, "CANopenNode facts outside cantools_od/canopennode/:\n" + "\n".join(found)


def test_the_facts_are_read_from_the_home() -> None:
    """The list is the home's own, not empty, and holds what a reader, a rule and a renderer each use."""
    assert {"CO_disabled", "CO_storageGroup", "CO_countLabel", "CO_flagsPDO", ";StorageLocation"} <= FACTS
    assert {"PERSIST_COMM", "ODA_SDO_RW", "ODT_ARR", "OD_CNT_", "CO_CONFIG_HB_CONS", ".canopennode.toml"} <= FACTS


PROBE = '''"""Docstrings may name CO_storageGroup and ODA_TPDO."""
GROUP = "PERSIST_COMM"  # a stray copy


def read(name: str) -> bool:
    """CO_disabled is documentation here."""
    return name == "CO_disabled" or name.startswith(f"{name};StorageLocation=")


@rule("CNO999", W, "title", "doc naming OD_CNT_NMT", "[2000]\\n;StorageLocation=RAM")
def example() -> None:
    ex.record(0x2000, "CO_flagsPDO")
'''


def test_the_sweep_finds_a_stray_spelling() -> None:
    """The sweep is not blind: literals outside the home are caught, f-string parts too; the home itself,
    docstrings, rule texts and rule examples are not."""
    found = [line.split(": ", 1)[1] for line in misplaced("xdd/probe.py", PROBE)]
    assert found == ["'PERSIST_COMM'", "'CO_disabled'", "';StorageLocation'", "'StorageLocation'"]
    assert misplaced("canopennode/probe.py", PROBE) == []

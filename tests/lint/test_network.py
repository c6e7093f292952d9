"""Network rule COB011 (cantools_od/lint/network.py): several DCFs checked as one network."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

from lintkit import VALUE_COLUMN, at, comm, dcf, load, mapping, section, var, where

from cantools_od.lint import Finding, LintOptions
from cantools_od.lint.network import lint_network
from cantools_od.model import Severity

from support import ROOT, cli_command

STATUS = var(0x6041, "Statusword", 0x0006, "ro")
POSITION = var(0x6064, "Position actual value", 0x0004, "ro")
SENDER = (comm(0x1800, "$NODEID+0x180"), mapping(0x1A00, "0x60410010", "0x60640020"), STATUS, POSITION)
WORD = var(0x2000, "Remote status", 0x0006, "rw")
LONG = var(0x2001, "Remote position", 0x0004, "rw")


def receiver(*entries: str, cob: str = "0x00000181") -> tuple[str, ...]:
    return comm(0x1400, cob), mapping(0x1600, *entries), WORD, LONG


def network(*texts: str, options: LintOptions | None = None) -> list[Finding]:
    devices = [load(text, f"{'abc'[n]}.dcf") for n, text in enumerate(texts)]
    return [f for f in lint_network(devices, options or LintOptions()) if f.code == "COB011"]


def located(found: Finding) -> tuple[str, int, int]:
    return (found.location.file, *at(found))


def test_a_consistent_network_has_no_findings() -> None:
    assert network(dcf(1, *SENDER), dcf(2, *receiver("0x20000010", "0x20010020"))) == []


def test_dummy_entries_skip_what_the_receiver_ignores() -> None:
    assert network(dcf(1, *SENDER), dcf(2, *receiver("0x00060010", "0x20010020"))) == []


def test_shared_node_id() -> None:
    second = dcf(1, *receiver("0x20000010", "0x20010020"))
    (found,) = network(dcf(1, *SENDER), second)
    assert found.message == "node-ID 1 is also the node-ID of a.dcf"
    assert found.severity is Severity.ERROR
    assert located(found) == ("b.dcf", where(second, "DeviceComissioning", "NodeID"), 1)


def test_node_without_node_id_is_a_warning() -> None:
    second = dcf(None, *receiver("0x20000010", "0x20010020"))
    (found,) = network(dcf(1, *SENDER), second)
    assert found.severity is Severity.WARNING
    assert found.message == "no node-ID (1-127): its $NODEID COB-IDs are not checked"
    assert located(found) == ("b.dcf", where(second, "DeviceComissioning"), 1)


def test_two_nodes_produce_one_can_id() -> None:
    second = dcf(2, comm(0x1800, "0x00000181"), mapping(0x1A00, "0x60410010"), STATUS)
    (found,) = network(dcf(1, *SENDER), second)
    assert found.message == "TPDO1 sends CAN-ID 181h, which a.dcf (TPDO1) sends too"
    assert located(found) == ("b.dcf", where(second, "1800sub1", "DefaultValue"), VALUE_COLUMN)


def test_rpdo_without_producer() -> None:
    second = dcf(2, *receiver("0x20000010", "0x20010020", cob="0x00000190"))
    (found,) = network(dcf(1, *SENDER), second)
    assert found.severity is Severity.WARNING
    assert found.message == "RPDO1 receives CAN-ID 190h, which no node of the network sends"
    assert located(found) == ("b.dcf", where(second, "1400sub1", "DefaultValue"), VALUE_COLUMN)


def test_rpdo_on_another_nodes_emcy() -> None:
    emcy = section("1014", ParameterName="COB-ID EMCY", DataType="0x0007", AccessType="rw", DefaultValue="$NODEID+0x80")
    second = dcf(2, *receiver("0x20000010", "0x20010020", cob="0x00000081"))
    (found,) = network(dcf(1, *SENDER, emcy), second)
    assert found.message == "RPDO1 receives CAN-ID 081h, which is a.dcf's EMCY"
    assert located(found) == ("b.dcf", where(second, "1400sub1", "DefaultValue"), VALUE_COLUMN)


def test_layout_total_length_differs() -> None:
    second = dcf(2, *receiver("0x20000010"))
    (found,) = network(dcf(1, *SENDER), second)
    assert found.message == "RPDO1 maps 16 bits, but a.dcf TPDO1 sends 48 bits"
    assert located(found) == ("b.dcf", where(second, "1600sub0", "DefaultValue"), VALUE_COLUMN)


def test_layout_entries_do_not_line_up() -> None:
    second = dcf(2, *receiver("0x20010020", "0x20000010"))
    (found,) = network(dcf(1, *SENDER), second)
    assert found.message == (
        "RPDO1 maps 2001sub0 at bits 0-31, but a.dcf TPDO1 does not (it sends 6041sub0 at bits 0-15)"
    )
    assert found.severity is Severity.ERROR
    assert located(found) == ("b.dcf", where(second, "1600sub1", "DefaultValue"), VALUE_COLUMN)


def test_layout_types_differ() -> None:
    unsigned = var(0x2002, "Remote position, unsigned", 0x0007, "rw")
    second = dcf(2, *receiver("0x20000010", "0x20020020"), unsigned)
    (found,) = network(dcf(1, *SENDER), second)
    assert found.severity is Severity.WARNING
    assert found.message == "RPDO1 receives 2002sub0 as UNSIGNED32, but a.dcf TPDO1 sends 6064sub0 as INTEGER32"
    assert located(found) == ("b.dcf", where(second, "1600sub2", "DefaultValue"), VALUE_COLUMN)


def test_two_sync_producers() -> None:
    third = dcf(3, sync=True)
    found = network(dcf(1, *SENDER, sync=True), dcf(2, *receiver("0x20000010", "0x20010020")), third)
    assert [(f.message, located(f)) for f in found] == [
        (
            "SYNC producer (1005h bit 30), but a.dcf produces SYNC too",
            ("c.dcf", where(third, "1005", "DefaultValue"), 14),
        )
    ]


def test_cli_network_exit_code_and_location(tmp_path: Path) -> None:
    first, second = dcf(1, *SENDER), dcf(2, comm(0x1800, "0x00000181"), mapping(0x1A00, "0x60410010"), STATUS)
    (tmp_path / "a.dcf").write_text(first)
    (tmp_path / "b.dcf").write_text(second)
    base = [*cli_command(), "lint", "--select", "COB011", "a.dcf", "b.dcf"]
    path = os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])
    env = {**os.environ, "PYTHONPATH": path}  # the files' folder is the working directory, not the project
    alone = subprocess.run(base, capture_output=True, text=True, cwd=tmp_path, env=env, timeout=120)
    assert alone.returncode == 0, alone.stdout + alone.stderr
    together = subprocess.run([*base, "--network"], capture_output=True, text=True, cwd=tmp_path, env=env, timeout=120)
    assert together.returncode == 1, together.stdout + together.stderr
    line = where(second, "1800sub1", "DefaultValue")
    expected = f"b.dcf:{line}:{VALUE_COLUMN}: error: TPDO1 sends CAN-ID 181h, which a.dcf (TPDO1) sends too [COB011]"
    assert expected in together.stdout.splitlines()


def test_network_findings_honour_suppression_comments() -> None:
    from cantools_od.lint.runner import lint_network as filtered

    second = dcf(2, *receiver("0x20000010", "0x20010020", cob="0x00000190"))
    quiet = second.replace("[1400sub1]", "; cantools-od: ignore COB011\n[1400sub1]")
    devices = [load(dcf(1, *SENDER), "a.dcf"), load(second, "b.dcf")]
    assert [f.code for f in filtered(devices, LintOptions())] == ["COB011"]
    devices = [load(dcf(1, *SENDER), "a.dcf"), load(quiet, "b.dcf")]
    assert filtered(devices, LintOptions()) == []

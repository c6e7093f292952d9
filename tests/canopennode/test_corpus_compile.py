"""Every corpus file the canopennode profile accepts compiles, as C and as C++, with the real stack."""

from __future__ import annotations

import re
from pathlib import Path

from cnokit import STACK, STACK_DEFAULTS, WARNINGS, includes, load_accepted, parallel, run, stack, write_od

from cantools_od.api import load
from cantools_od.lint.canopennode import profile_findings
from cantools_od.sniff import NotADeviceDescription

from support import corpus_files


def test_every_accepted_corpus_file_compiles_with_gcc_and_gxx(tmp_path: Path) -> None:
    stack()
    files = corpus_files()
    if not files:
        import pytest

        pytest.skip("../shared/eds-corpus is absent")
    devices, refused = load_accepted(files)
    print(f"\n{len(devices)} of {len(files)} accepted; refused: {refused}")
    assert len(devices) >= 15, refused  # the sweep must exercise a real share of the corpus
    # One translation unit per compiler: OD0.c ... ODn.c have their own prefixes, so they coexist.
    names = []
    for n, device in enumerate(devices):
        write_od(device, tmp_path, f"OD{n}")
        names.append(f"OD{n}")
    (tmp_path / "all.c").write_text("".join(f'#include "{name}.c"\n' for name in names))
    calls = "".join(f"    total += {name}->size;\n" for name in names)
    headers = "".join(f'#include "{name}.h"\n' for name in names)
    (tmp_path / "main.c").write_text(
        f"#include <stdio.h>\n{headers}int main(void) {{\n    unsigned long total = 0;\n{calls}"
        '    printf("%lu\\n", total);\n    return total == 0;\n}\n'
    )
    interface = str(STACK / "301" / "CO_ODinterface.c")
    jobs = [
        ["gcc", *WARNINGS, *includes(tmp_path), "-c", "all.c", "-o", "all_c.o"],
        ["g++", "-x", "c++", *WARNINGS, *includes(tmp_path), "-c", "all.c", "-o", "all_cxx.o"],
        ["gcc", *WARNINGS, *includes(tmp_path), "-c", interface, "-o", "interface.o"],
        ["gcc", *WARNINGS, *includes(tmp_path), "-c", "main.c", "-o", "main.o"],
    ]
    parallel(lambda job: run(job, cwd=tmp_path), jobs)
    for od in ("all_c.o", "all_cxx.o"):  # both link with the stack's C code and list every object
        run(["g++", "-o", f"{od}.exe", od, "interface.o", "main.o"], cwd=tmp_path)
        objects = sum(len([o for o in d.objects.values() if o.kind.value in (2, 7, 8, 9)]) for d in devices)
        assert run([str(tmp_path / f"{od}.exe")]).stdout.strip() == str(objects)


def test_profile_refuses_only_what_no_configuration_builds_and_reads_defaults_as_canopeneditor() -> None:
    """Without a declared stack configuration, the switched objects (1003h, 1014h, 1016h, 1006h, SRDO) are never
    a reason to refuse; with the stack's defaults declared, fewer files pass; CNO007 never fires on a DOMAIN."""
    from cantools_od.model.datatypes import DOMAIN

    files = corpus_files()
    if not files:
        import pytest

        pytest.skip("../shared/eds-corpus is absent")
    undeclared, _ = load_accepted(files)
    defaults, _ = load_accepted(files, STACK_DEFAULTS)
    assert {d.source for d in defaults} < {d.source for d in undeclared}
    domain_findings = []
    for path in files:
        try:
            device = load(str(path))
        except NotADeviceDescription:
            continue
        for finding in profile_findings(device):
            if finding.code == "CNO005" and finding.severity.value == "error":
                assert re.match(r"no object counts as (NMT|EM|HB_PROD) \(", finding.message), finding
            if finding.code == "CNO007":
                index = int(finding.message[:4], 16)
                obj = device.objects[index]
                sub = finding.message.split(" ")[1].rstrip(":")
                var = obj.subs[int(sub[3:], 16)] if sub.startswith("sub") else obj
                dtype = device.entry_type(var, obj)
                domain_findings += [finding.message] if dtype is not None and dtype.index == DOMAIN.index else []
    assert domain_findings == []

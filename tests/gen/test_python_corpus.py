"""Every real file of ../shared/eds-corpus through `cantools-od gen -t python -t markdown --keep-going`, in-process:
an importable module whose `object_dictionary()` equals `to_canopen` of what errors did not leave out, and a valid
Markdown document naming every object (type definitions included); or, for a file that is no device description,
a refusal with exit code 2 (EDS000). Never a traceback."""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path
from typing import Any

import pytest
from pykit import check_markdown, check_markdown_lines, import_file, run_gen

from cantools_od import load, to_canopen
from cantools_od.eds.where import damaged_objects
from cantools_od.render.escape import markdown_text
from cantools_od.views.partial import unfit_values, without

from support import corpus_files


def _od(od: Any) -> dict[tuple[int, int], tuple[Any, ...]]:
    found: dict[tuple[int, int], tuple[Any, ...]] = {}
    for index in od:
        obj = od[index]
        for var in [obj] if not hasattr(obj, "subindices") else [obj[sub] for sub in obj]:
            found[index, var.subindex] = (type(obj).__name__, obj.name, var.name, var.data_type, var.access_type)
            found[index, var.subindex] += (var.default, var.value, var.relative, var.min, var.max, var.pdo_mappable)
    return found


def _sweep(path: Path, folder: Path, parse: bool) -> str:
    """'generated', 'generated in part' or 'refused'; raises AssertionError on anything else."""
    result = run_gen(path, "-t", "python", "-t", "markdown", "-o", folder, "--name", "generated", "--keep-going")
    assert result.exception is None or isinstance(result.exception, SystemExit), result.exc_info
    assert "Traceback" not in result.output
    module_file, document = folder / "generated.py", folder / "generated.md"
    if not module_file.exists():
        assert result.exit_code == 2 and "[EDS000]" in result.output, result.output
        assert not document.exists()
        return "refused"
    assert result.exit_code == 0, result.output
    whole = load(path)
    # what --keep-going leaves out: objects with errors, and values no generated code can spell (GEN001)
    device = without(whole, set(damaged_objects(whole)) | set(unfit_values(whole)))
    module = import_file(module_file)
    assert _od(module.object_dictionary()) == _od(to_canopen(device, device.node_id))
    for name, cls in vars(module).items():
        if name[:4] in ("Rpdo", "Tpdo") and name[4:].isdigit():
            zero = cls()
            assert cls.unpack(zero.pack()) == zero and len(zero.pack()) == cls.SIZE
            assert [f.name for f in dataclasses.fields(cls)] == [f.name for f in cls._LAYOUT]
    text = document.read_text(encoding="utf-8")
    if parse:  # markdown-it-py takes most of the sweep's time: every fourth document, the rest line by line
        check_markdown(text)
    else:
        check_markdown_lines(text)
    indices = {index for index, obj in device.objects.items() if obj.kind.name not in ("NULL", "DEFTYPE")}
    for index in indices:
        shown = markdown_text(device.objects[index].name)
        tag = f'<a id="{index:04X}"></a>'
        heading = f"### {tag}Object {index:04X}h: {shown}\n" if shown else f"### {tag}Object {index:04X}h\n"
        assert f"\n{heading}" in text and f"](#{index:04X})" in text
        assert hasattr(module, f"INDEX_{module_identifier(module, index)}")
    types = text.partition("\n## Type definitions\n")[2]
    for index in device.objects.keys() - indices:  # NULL and DEFTYPE objects: in the table of type definitions
        assert f'\n| <a id="{index:04X}"></a>{index:04X}h | ' in types, f"{index:04X}h is not in the Markdown reference"
    return "generated in part" if device is not whole else "generated"


def module_identifier(module: Any, index: int) -> str:
    names = [name for name, value in vars(module).items() if name.startswith("INDEX_") and value == index]
    assert len(names) == 1, (index, names)
    return names[0][len("INDEX_") :]


def test_corpus_sweep(tmp_path: Path) -> None:
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    start = time.perf_counter()
    counts: dict[str, int] = {}
    failures: list[str] = []
    for number, path in enumerate(files):
        folder = tmp_path / f"{number:03d}"
        try:
            outcome = _sweep(path, folder, parse=number % 4 == 0)
        except AssertionError as error:
            failures.append(f"{path.name}: {str(error)[:2000]}")
            continue
        counts[outcome] = counts.get(outcome, 0) + 1
    elapsed = time.perf_counter() - start
    summary = ", ".join(f"{count} {outcome}" for outcome, count in sorted(counts.items()))
    print(f"\ncorpus: {len(files)} files in {elapsed:.1f} s: {summary}, {len(failures)} failed")
    assert not failures, "\n".join(failures)
    assert counts.get("generated", 0) + counts.get("generated in part", 0) >= len(files) - 1

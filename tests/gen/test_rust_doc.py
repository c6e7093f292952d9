"""`cargo doc` of generated Rust is warning-free (`RUSTDOCFLAGS=-D warnings`): names and texts from an
EDS are Markdown to rustdoc, so brackets, HTML-like tags, emphasis, backticks and URLs in them must
reach the documentation as the text they are, not as links, tags or broken markup."""

from __future__ import annotations

from pathlib import Path

from rustkit import EXAMPLES, Record, cargo, eds_text, render_rust, require, var, write_crate

MARKDOWN_NAMES = [
    "Speed [rpm]",
    "Limit [0..100] %",
    "See [Speed] and [`x`](y)",
    "Gain <b>high</b> <br>",
    "Value `unclosed",
    "*Bold* _em_ **strong** ~~gone~~",
    "Docs at https://example.com/od and www.example.com",
    "# Heading | pipe | cell",
    "Back\\slash & ampersand &amp; &lt;",
    "Trailing backslash \\",
    "1. Ordered",
    "> Quote",
    "    indented code",
]


def test_cargo_doc_is_warning_free(tmp_path: Path) -> None:
    require("cargo", "rustc")
    objects: dict[int, dict[str, str] | Record] = {
        0x2000 + n: var(name, 0x0006, "1") for n, name in enumerate(MARKDOWN_NAMES)
    }
    objects[0x2100] = Record(
        "Record [with] <tags>", [var("Highest sub-index [max]", 0x0005, "2", "ro", False)]
        + [var(name, 0x0005, "1") for name in ("Entry [1]", "Entry <2>")]
    )  # fmt: skip
    eds = tmp_path / "markdown.eds"
    eds.write_text(eds_text("markdown.eds", objects, {}, "Device [x] <y> `z`"), encoding="utf-8")
    modules = {
        "markdown": render_rust(eds, "markdown")[1],
        "io_device": render_rust(EXAMPLES / "io_device.eds", "io_device")[1],
        "cia402_drive": render_rust(EXAMPLES / "cia402_drive.eds", "cia402_drive")[1],
    }
    crate = write_crate(tmp_path / "crate", "rust_doc_tests", modules, {})
    result = cargo(crate, "doc", "--no-deps", "--lib", env={"RUSTDOCFLAGS": "-D warnings"})
    assert result.returncode == 0, result.stderr[-8000:]
    assert "warning:" not in result.stderr, result.stderr[-8000:]

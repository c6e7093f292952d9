"""The XML layer under the XDD reader (cantools_od/xdd/safe.py, xmltext.py): where a broken file is reported,
what reading imports, and escaping that writes what the standard library's XML writer writes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from xml.sax.saxutils import escape as sax_escape
from xml.sax.saxutils import quoteattr as sax_quoteattr

from hypothesis import given
from hypothesis import strategies as st
from xddkit import MANDATORY, document

from cantools_od import api
from cantools_od.xdd.xmltext import escape, quoteattr

_MORE = st.sampled_from([None, {"\n": "&#10;", "\r": "&#13;"}, {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}])
_TEXT = st.text(alphabet=st.sampled_from(list("ab &<>\"'\n\r\t;#é€")), max_size=40)


@given(_TEXT, _MORE)
def test_escaping_is_the_standard_librarys(text: str, more: dict[str, str] | None) -> None:
    assert escape(text, more) == sax_escape(text, more or {})
    assert quoteattr(text, more) == sax_quoteattr(text, more or {})


def test_a_truncated_file_is_reported_where_it_ends() -> None:
    """expat finds most damage only at the end of the input; the diagnostic points there, not at line 1."""
    data = document(MANDATORY).encode()
    cut = data[: data.rindex(b"</")]  # the closing tags of the document are missing
    device = api.loads(cut, source="cut.xdd")
    [diagnostic] = device.diagnostics
    assert diagnostic.code == "XDD001"
    assert diagnostic.location.line == cut.count(b"\n") + 1, diagnostic


def test_reading_an_xdd_imports_no_network_or_mail_modules(tmp_path: Path) -> None:
    """The XML driver once pulled in urllib.request, http, email and ssl: a fifth of reading a large file."""
    path = tmp_path / "device.xdd"
    path.write_text(document(MANDATORY))
    code = (
        "import sys; from cantools_od import api\n"
        "device = api.load(sys.argv[1])\n"
        "assert device.objects and not device.diagnostics, device.diagnostics\n"
        "print(sorted(m for m in ('urllib.request', 'http.client', 'email', 'ssl', 'xml.sax') if m in sys.modules))"
    )
    shown = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True, check=True)
    assert shown.stdout.strip() == "[]", shown.stdout + shown.stderr

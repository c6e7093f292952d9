"""When the server checks an edited document: an edit after a quiet spell at once, the edits of a burst (typing,
a paste in steps) once they pause for DEBOUNCE, so that a single edit is not kept waiting for edits that never come."""

from __future__ import annotations

import asyncio

import pytest

from cantools_od.lsp.app import build
from cantools_od.lsp.document import Encoding
from cantools_od.lsp.server import DEBOUNCE, Open


@pytest.mark.asyncio
async def test_a_single_edit_is_checked_at_once_and_a_burst_when_it_pauses() -> None:
    server, uri = build(), "file:///device.eds"
    state = server.open[uri] = Open(Encoding())
    loop = asyncio.get_running_loop()
    delays = []
    for _ in range(3):  # three edits in a row: the first alone so far, the others within DEBOUNCE of it
        server.edited(uri)
        assert state.pending is not None
        delays.append(state.pending.when() - loop.time())
    state.pending.cancel()
    assert delays[0] <= 0.001
    assert all(DEBOUNCE - 0.05 <= delay <= DEBOUNCE for delay in delays[1:])
    state.changed -= DEBOUNCE  # a quiet spell after the last edit (its check has started: nothing pending)
    state.pending = None
    server.edited(uri)
    assert state.pending is not None and state.pending.when() - loop.time() <= 0.001
    state.pending.cancel()

"""Python's cyclic garbage collector, paused around work that makes many objects which outlive it.

The model and a check's walks are acyclic: reference counting frees them. A collector pass over them only costs
time, and a full pass over a large device is the costliest: `lint` of a 16 MB file spent a fifth of its time in
three such passes."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


def pause() -> bool:
    """Stop the collector; whether this call stopped it (and so `resume` should start it again)."""
    if not gc.isenabled():
        return False
    gc.disable()
    return True


def resume() -> None:
    """Start the collector again. Every object made meanwhile still counts as young: the first allocation after
    `enable` would walk them all. Freezing and unfreezing moves them to the oldest generation without a walk (not
    when the program froze objects of its own: unfreezing would release those too)."""
    if not gc.get_freeze_count():
        gc.freeze()
        gc.unfreeze()
    gc.enable()


@contextmanager
def paused() -> Iterator[None]:
    stopped = pause()
    try:
        yield
    finally:
        if stopped:
            resume()

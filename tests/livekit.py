"""What the live tests share: a TPDO a master sees after its SYNC."""

from __future__ import annotations

import threading
from typing import Any

import canopen


def received_on_sync(network: canopen.Network, pdo: Any, timeout: float = 2.0) -> bool:
    """Send SYNC; whether `pdo` (a python-canopen PdoMap) arrives after it. The frame may arrive before a
    `wait_for_reception` would start waiting, so the reception is watched from before the SYNC."""
    arrived = threading.Event()
    pdo.add_callback(lambda _: arrived.set())
    network.sync.transmit()
    return arrived.wait(timeout)

"""What a change of a PDO's transmission type or timing does on the bus (CiA 301 §7.2.2, §7.5.2.35/36).

A master configured for the old file expects the old traffic: a TPDO that is now sent on SYNC never comes
on a bus without SYNC; one that is now sent every 100 ms adds bus load; an RPDO's event timer is a deadline.
Each is `wire` with what changes on the bus, unless the traffic stays the same.
"""

from __future__ import annotations

from ..model.cia301.pdo import EVENT_TIMER_SUB, INHIBIT_SUB
from .records import Impact

SYNC_CYCLIC_LAST = 240
RTR_SYNC, RTR_EVENT = 252, 253
EVENT_TYPES = (254, 255)


def _ordinal(number: int) -> str:
    suffix = "th" if 10 <= number % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(number % 10, "th")
    return f"{number}{suffix}"


def _when(direction: str, value: int) -> str:
    """When the PDO goes on the bus (TPDO) or takes effect (RPDO)."""
    if direction == "rx":
        if value <= SYNC_CYCLIC_LAST:
            return "applied at the next SYNC"
        return "applied on arrival" if value in EVENT_TYPES else "reserved"
    if value == 0:
        return "sent on the SYNC after a change"
    if value == 1:
        return "sent on every SYNC"
    if value <= SYNC_CYCLIC_LAST:
        return f"sent on every {_ordinal(value)} SYNC"
    if value == RTR_SYNC:
        return "sent on request (RTR), sampled at SYNC"
    if value == RTR_EVENT:
        return "sent on request (RTR)"
    if value in EVENT_TYPES:
        return "sent on change"
    return "reserved"


def transmission_effect(direction: str, old: int | None, new: int | None) -> tuple[Impact, str]:
    """`wire` when the PDO is sent (or applied) at other times; value when only the kind of event changes."""
    if old is None or new is None:
        return Impact.VALUE, "stated on one side only"
    before, after = _when(direction, old), _when(direction, new)
    if before == after:
        if old in EVENT_TYPES and new in EVENT_TYPES:
            return Impact.VALUE, "event-driven on both sides: the event is manufacturer- (254) or profile-defined (255)"
        return Impact.VALUE, f"{after} on both sides"
    return Impact.BREAKING, f"{after} instead of {before.removeprefix('sent ').removeprefix('applied ')}"


def _ms(value: int, scale: int) -> str:
    return f"{value * scale / 1000:g} ms"


def timing_effect(direction: str, transmission: int | None, sub: int, old: int, new: int) -> tuple[Impact, str]:
    """What an inhibit time (100 µs), event timer (ms) or SYNC start value change does to the traffic."""
    event_driven = transmission is None or transmission in EVENT_TYPES
    if sub == EVENT_TIMER_SUB and direction == "rx":
        if not new:
            return Impact.BREAKING, "no longer a deadline: a missing RPDO goes unnoticed"
        return Impact.BREAKING, f"an RPDO not received within {new} ms is now an error" + (
            f" (was {old} ms)" if old else ""
        )
    if direction == "rx":
        return Impact.VALUE, "not used by an RPDO"
    if sub == EVENT_TIMER_SUB:
        if not event_driven:
            return Impact.VALUE, "not used by a synchronous TPDO"
        if not new:
            return Impact.BREAKING, f"no longer sent every {old} ms, only on change"
        return Impact.BREAKING, f"now every {new} ms" + (f" instead of every {old} ms" if old else ", also on change")
    if sub == INHIBIT_SUB:
        if not event_driven:
            return Impact.VALUE, "not used by a synchronous TPDO"
        if not new:
            return Impact.BREAKING, f"no longer held back: sent on every change (was at most every {_ms(old, 100)})"
        return Impact.BREAKING, f"now at most every {_ms(new, 100)}" + (
            f" instead of every {_ms(old, 100)}" if old else ", where it was sent on every change"
        )
    if transmission is not None and 1 <= transmission <= SYNC_CYCLIC_LAST:
        return (
            Impact.BREAKING,
            f"first sent when the SYNC counter is {new}" if new else "no longer waits for a SYNC counter value",
        )
    return Impact.VALUE, "used by a cyclic synchronous TPDO only"

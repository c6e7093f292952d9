"""Numbers in generated prose."""

from __future__ import annotations


def count(number: int, noun: str) -> str:
    """`1 bit`, `0 bits`, `2 sub-objects`: the noun in the singular for exactly one."""
    return f"{number} {noun}" if number == 1 else f"{number} {noun}s"

"""Text of one entry → typed value, with notes on anything unusual.

Integers are read by a small tokenizer (an optional "-", then operands joined by operators)
unless they are a plain decimal or hex number; results are cached by text, since real files
repeat the same few values thousands of times.
"""

from __future__ import annotations

import re
import struct
from functools import lru_cache
from typing import NamedTuple

from ..model import NodeIdExpr, RawValue, Severity, TimeValue, Value, ValueKind
from ..model.assemble import construct
from .keys import MAX_DIGITS


class Note(NamedTuple):
    """Something unusual about a value's text: a diagnostic for the reader to place."""

    code: str
    severity: Severity
    message: str
    # How an XDD reader takes the note: the same, milder (a form only lely refuses: lely reads no XDD) or not at
    # all (hex bytes separated by blanks: CANopenEditor's own XDD spelling of OCTET_STRING values).
    in_xdd: Severity | None = None
    silent_in_xdd: bool = False


class Parsed(NamedTuple):
    value: Value | None
    notes: tuple[Note, ...] = ()
    comment: str | None = None  # an inline comment cut off the value


_PLAIN_INT = re.compile(r"-?(?:0[xX][0-9a-fA-F]+|[1-9][0-9]*|0)\Z")
_HEX_BYTES = re.compile(r"(?:[0-9a-fA-F]{2})*\Z")
_INLINE_COMMENT = re.compile(r"[ \t]+[;#]")
_SUFFIX = re.compile(r"[uUlL]+\Z")


# An integer expression: blanks, then terms. A number is hex, octal (a leading 0) or decimal, each
# with an optional C suffix; "-" before the first operand negates it, between operands it subtracts.
_BLANKS = re.compile(r"[ \t]+")
_TERM = re.compile(
    r"(?P<NODEID>(?i:\$nodeid))"
    r"|(?P<NUMBER>(?:0[xX][0-9a-fA-F]+|0[0-9]+|[0-9]+)(?:[uU]?[lL]{1,2}|[lL]{1,2}[uU]|[uU])?)"
    r"|(?P<OP>[-+*/])"
)


def _after_blanks(text: str, position: int) -> int:
    blanks = _BLANKS.match(text, position)
    return position if blanks is None else blanks.end()


def _terms(text: str) -> list[tuple[str, str]]:
    """(MINUS | OP | NODEID | NUMBER, text) of an expression `-? operand (op operand)*`; raises ValueError."""
    found: list[tuple[str, str]] = []
    position = _after_blanks(text, 0)
    while position < len(text):
        match = _TERM.match(text, position)
        if match is None:
            raise ValueError(f"{text!r} is not a number")
        kind = match.lastgroup or ""
        operand_due = not found or found[-1][0] in ("MINUS", "OP")
        if kind == "OP" and not found and match.group() == "-":
            kind = "MINUS"
        elif (kind == "OP") == operand_due:  # an operator where an operand is due, or two operands in a row
            raise ValueError(f"{text!r} is not a number")
        found.append((kind, match.group()))
        position = _after_blanks(text, match.end())
    if not found or found[-1][0] in ("MINUS", "OP"):
        raise ValueError(f"{text!r} is not a number")
    return found


def _too_long(text: str) -> ValueError:
    return ValueError(f"a number of {len(text)} characters; no data type holds one so long")


def _number(token: str) -> tuple[int, list[Note]]:
    if len(token) > MAX_DIGITS:
        raise _too_long(token)
    notes: list[Note] = []
    digits = _SUFFIX.sub("", token)  # u and l are no hex digits, so this is safe for hex too
    if digits != token:
        notes.append(Note("EDS032", Severity.WARNING, f"C suffix in {token!r} is not CiA 306 syntax"))
    if digits[:2].lower() == "0x":
        return int(digits, 16), notes
    if len(digits) > 1 and digits[0] == "0":
        if any(c in "89" for c in digits):
            raise ValueError(f"{token!r} is not a valid octal number")
        notes.append(
            Note(
                "EDS032",
                Severity.WARNING,
                f"{token!r} is octal ({int(digits, 8)}) per CiA 306; python-canopen reads it differently",
            )
        )
        return int(digits, 8), notes
    return int(digits), notes


def _parse_integer_expr(text: str) -> tuple[int | NodeIdExpr, list[Note]]:
    notes: list[Note] = []
    total = 0
    nodeid_at: int | None = None
    sign = 1
    operands = 0
    for kind, token in _terms(text):
        if kind == "MINUS":
            sign = -1
        elif kind == "OP":
            if token in "*/":
                raise ValueError(f"{text!r}: only + may combine terms")
            sign = 1 if token == "+" else -1
        elif kind == "NODEID":
            if nodeid_at is not None or sign < 0:
                raise ValueError(f"{text!r}: $NODEID may appear once and only be added")
            nodeid_at = operands
            operands += 1
        else:
            value, number_notes = _number(token)
            notes.extend(number_notes)
            total += sign * value
            operands += 1
    if nodeid_at is None:
        if operands > 1:
            raise ValueError(f"{text!r}: arithmetic is allowed only with $NODEID")
        return total, notes
    if nodeid_at > 0:
        message = f"{text!r}: $NODEID should come first ($NODEID+n); lely rejects this form"
        notes.append(Note("EDS033", Severity.ERROR, message, in_xdd=Severity.WARNING))
    elif operands > 2:
        message = f"{text!r}: python-canopen reads no value and lely rejects it"
        notes.append(Note("EDS033", Severity.ERROR, message, in_xdd=Severity.WARNING))
    elif "-" in text:
        notes.append(Note("EDS033", Severity.ERROR, f"{text!r}: $NODEID may only be added to"))
    if text.count("$") == 1 and "$NODEID" not in text:
        notes.append(Note("EDS033", Severity.WARNING, f"{text!r}: write $NODEID in upper case"))
    return construct(NodeIdExpr, {"offset": total, "text": text}), notes


def parse_int(text: str) -> tuple[int | NodeIdExpr, list[Note]]:
    """An integer or `$NODEID` sum; raises ValueError when it is neither."""
    if _PLAIN_INT.match(text):
        if len(text) > MAX_DIGITS:
            raise _too_long(text)
        return int(text, 0), []
    return _parse_integer_expr(text)


_NUMBERS = (ValueKind.UNSIGNED, ValueKind.SIGNED, ValueKind.REAL, ValueKind.BOOL, ValueKind.TIME)
_LONGEST_NUMBER = 255  # CiA 306's longest line; a number never needs as much


@lru_cache(maxsize=65536)
def parse_value(text: str, kind: ValueKind | None, bits: int | None, type_name: str) -> Parsed:
    """Read `text` as a value of the given kind. Never raises."""
    if text == "":
        return Parsed(None)
    if len(text) > _LONGEST_NUMBER and kind in _NUMBERS:  # quoted in no message: it may be megabytes
        why = f"a value of {len(text)} characters; no {type_name} is written so long"
        return Parsed(construct(RawValue, {"text": text}), (Note("EDS030", Severity.ERROR, why),))
    try:
        return _parse(text, kind, bits, type_name)
    except ValueError as error:
        cut = _INLINE_COMMENT.search(text)
        if cut is not None and kind not in (ValueKind.STRING, ValueKind.UNICODE, None):
            head, comment = text[: cut.start()], text[cut.end() - 1 :]
            retry = parse_value(head, kind, bits, type_name)
            if not isinstance(retry.value, RawValue):
                note = Note(
                    "EDS032",
                    Severity.WARNING,
                    f"inline comment {comment!r} after the value; CiA 306 has none, tools disagree on it",
                )
                return Parsed(retry.value, (*retry.notes, note), comment)
        if type_name == "DOMAIN" and text in ("0", "0x0", "0x00"):  # CANopenNode's "empty" DOMAIN
            why = f"{text!r} for DOMAIN: CANopenNode's way to say empty; other tools reject it"
            return Parsed(construct(RawValue, {"text": text}), (Note("EDS030", Severity.WARNING, why),))
        return Parsed(
            construct(RawValue, {"text": text}), (Note("EDS030", Severity.ERROR, f"{error} for {type_name}"),)
        )


def _parse(text: str, kind: ValueKind | None, bits: int | None, type_name: str) -> Parsed:
    if kind is ValueKind.UNSIGNED or kind is ValueKind.SIGNED:
        number, notes = parse_int(text)
        if (
            kind is ValueKind.SIGNED
            and isinstance(number, int)
            and bits is not None
            and text.lstrip()[:2].lower() == "0x"
            and (1 << (bits - 1)) <= number < (1 << bits)
        ):
            notes.append(
                Note(
                    "EDS032",
                    Severity.WARNING,
                    f"{text!r} read as two's complement ({number - (1 << bits)}); lely reads it as overflow",
                )
            )
            number -= 1 << bits
        return Parsed(number, tuple(notes))
    if kind is ValueKind.BOOL:
        number, notes = parse_int(text)
        if number not in (0, 1):
            raise ValueError(f"{text!r} is not 0 or 1")
        return Parsed(bool(number), tuple(notes))
    if kind is ValueKind.REAL:
        return Parsed(_parse_real(text, bits or 32))
    if kind is ValueKind.OCTETS:
        compact = text.replace(" ", "")
        if not _HEX_BYTES.match(compact):
            raise ValueError(f"{text!r} is not hex byte pairs")
        blanks: tuple[Note, ...] = ()
        if compact != text:
            blanks = (Note("EDS032", Severity.WARNING, "hex bytes separated by blanks", silent_in_xdd=True),)
        return Parsed(bytes.fromhex(compact), blanks)
    if kind is ValueKind.TIME:
        parts = text.split()
        if len(parts) == 2:
            days, _ = parse_int(parts[0])
            ms, _ = parse_int(parts[1])
            if isinstance(days, int) and isinstance(ms, int):
                return Parsed(construct(TimeValue, {"days": days, "ms": ms}))
        number, notes = parse_int(text)
        if not isinstance(number, int):
            raise ValueError(f"{text!r} is not a time value")
        return Parsed(TimeValue.from_bits(number), tuple(notes))
    if kind is ValueKind.STRING or kind is ValueKind.UNICODE:
        return Parsed(text)
    return Parsed(construct(RawValue, {"text": text}))  # records and unknown types: no value syntax


def _parse_real(text: str, bits: int) -> float:
    if text.lstrip("-")[:2].lower() == "0x":
        pattern = int(text, 16)
        if not 0 <= pattern < 1 << bits:
            raise ValueError(f"{text!r} is not a {bits}-bit pattern")
        fmt = "<f" if bits == 32 else "<d"
        return float(struct.unpack(fmt, pattern.to_bytes(bits // 8, "little"))[0])
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{text!r} is not a real number") from None
    if bits != 32:
        return value
    try:
        return float(struct.unpack("<f", struct.pack("<f", value))[0])
    except OverflowError:
        raise ValueError(f"{text!r} is beyond the REAL32 range") from None


def format_real(value: float, bits: int, as_bits: bool) -> str:
    """REAL text: IEEE bit pattern (lely) or the shortest decimal that reads back."""
    if as_bits:
        fmt = "<f" if bits == 32 else "<d"
        return f"0x{int.from_bytes(struct.pack(fmt, value), 'little'):0{bits // 4}X}"
    if bits == 32:
        for digits in range(1, 10):
            text = f"{value:.{digits}g}"
            try:
                if struct.unpack("<f", struct.pack("<f", float(text)))[0] == value:
                    return _decimal(text)
            except OverflowError:  # rounded up past the largest REAL32
                continue
    return _decimal(repr(value))


def _decimal(text: str) -> str:
    return text if any(c in text for c in ".eEn") else text + ".0"

"""Messages the server cannot take: a JSON-RPC error the client can read, and one line in the log, never a
traceback. A request whose parameters do not fit its method gets "invalid params" (-32602), text that is no
JSON "parse error" (-32700, without an id: the id cannot be read)."""

from __future__ import annotations

import json
import logging
import sys
from collections.abc import Callable
from typing import Any

from pygls.exceptions import JsonRpcException, JsonRpcInvalidParams, JsonRpcInvalidRequest, JsonRpcParseError
from pygls.protocol import LanguageServerProtocol

PREFIX = "cantools-od lsp: "


def say(line: str) -> None:
    """One line on stderr, which editors keep as the server's log."""
    print(PREFIX + line, file=sys.stderr, flush=True)


class _Rejected:
    """A message already answered with an error (or, for a notification, logged), or passed on."""


_REJECTED = _Rejected()


class OdProtocol(LanguageServerProtocol):
    divert: Callable[[dict[str, Any]], object] | None = None
    """Takes a message that another process serves (process.py), before pygls reads it: None when taken, else
    the message for this server (a stand-in for a large message replaced by the whole)."""

    def structure_message(self, data: dict[str, Any]) -> Any:
        if "jsonrpc" not in data:  # a part of a message: pygls builds the message from its parts
            return data
        if self.divert is not None:
            kept = self.divert(data)
            if kept is None:
                return _REJECTED
            if not isinstance(kept, dict) or "jsonrpc" not in kept:  # decoded whole: a JSON value, no message
                return kept
            data = kept
        try:
            return super().structure_message(data)
        except JsonRpcException:
            method = data.get("method")
            self._reject(data, f"invalid parameters for {method!r}" if method else "a message that is no request")
            return _REJECTED

    def _reject(self, data: object, reason: str) -> None:
        message_id = data.get("id") if isinstance(data, dict) else None
        if isinstance(message_id, (int, str)) and not isinstance(message_id, bool):
            method = data.get("method") if isinstance(data, dict) else None
            error = JsonRpcInvalidParams(reason) if method else JsonRpcInvalidRequest(reason)
            self._send_response(message_id, error=error.to_response_error())
        say(f"{reason} (id {message_id!r}): answered with an error" if message_id is not None else f"{reason}: ignored")

    def handle_message(self, message: Any) -> None:
        if message is _REJECTED:
            return
        if not hasattr(message, "jsonrpc"):  # JSON, but no JSON-RPC message (a list, a number, an object without it)
            self._reject(message, "not a JSON-RPC 2.0 message")
            return
        super().handle_message(message)

    def parse_error(self, error: Exception) -> None:
        """Text that is no JSON: answered as JSON-RPC says (id null)."""
        code = JsonRpcParseError.CODE
        self._send_data({"jsonrpc": "2.0", "id": None, "error": {"code": code, "message": f"not JSON: {error}"}})


class OneLine(logging.Formatter):
    """pygls's log records as one line each: the first line of the message, the error's type and text."""

    def format(self, record: logging.LogRecord) -> str:
        text = record.getMessage().split("\n", 1)[0]
        if record.exc_info and record.exc_info[1] is not None:
            error = record.exc_info[1]
            text += f": {type(error).__name__}: {str(error).splitlines()[0] if str(error) else ''}"
        return PREFIX + text


def log_in_one_line() -> None:
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(OneLine())
    logging.basicConfig(level=logging.ERROR, handlers=[handler], force=True)


def is_parse_error(error: Exception) -> bool:
    return isinstance(error, (json.JSONDecodeError, UnicodeDecodeError))

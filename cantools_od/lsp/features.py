"""The request handlers: each asks the document's last analysis and one feature module."""

from __future__ import annotations

import asyncio
import functools
import inspect
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar, cast

from lsprotocol import types

from . import actions, completion, formatting, hover, navigation, outline
from .rpc import say
from .where import Index

if TYPE_CHECKING:
    from ..model import Device, Location
    from .positions import Lines
    from .server import OdServer, Open


H = TypeVar("H", bound=Callable[..., Any])
WORKSPACE_SYMBOLS = 500
"""At most this many objects answer a workspace symbol search (the open documents' objects, in order)."""


def guarded(handler: H) -> H:
    """A request answers nothing rather than fail: the server logs one line and stays up."""

    def failed(error: Exception) -> None:
        say(f"{handler.__name__}: {type(error).__name__}: {error}")

    if inspect.iscoroutinefunction(handler):

        @functools.wraps(handler)
        async def wait(*args: Any) -> Any:
            try:
                return await handler(*args)
            except asyncio.CancelledError:  # $/cancelRequest: pygls answers "request cancelled"
                raise
            except RuntimeError as error:
                if "shutdown" in str(error):  # the document was closed meanwhile: as if cancelled
                    raise asyncio.CancelledError() from None
                failed(error)
                return None
            except Exception as error:
                failed(error)
                return None

        return cast(H, wait)

    @functools.wraps(handler)
    def run(*args: Any) -> Any:
        try:
            return handler(*args)
        except Exception as error:
            failed(error)
            return None

    return cast(H, run)


def _index(state: Open, device: Device) -> Index:
    found = state.cache.get("index")
    if not isinstance(found, Index) or found.device is not device:
        found = state.cache["index"] = Index(device)
    return found


def _location(uri: str, lines: Lines, where: Location) -> types.Location:
    return types.Location(uri, lines.rest_of_line(where.line, where.column))


def _device(ls: OdServer, uri: str) -> tuple[Device, Lines, Open] | None:
    found = ls.current(uri)
    if found is None or found[0].device is None:
        return None
    return found[0].device, found[1], found[2]


def register(server: OdServer) -> None:
    _reading(server)
    _navigation(server)
    _editing(server)


def _reading(server: OdServer) -> None:
    """Hover, outline and completion."""

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    @guarded
    def on_hover(ls: OdServer, params: types.HoverParams) -> types.Hover | None:
        found = _device(ls, params.text_document.uri)
        if found is None:
            return None
        device, lines, state = found
        spot = _index(state, device).at(*lines.model(params.position))
        text = hover.describe(device, spot, ls.options.node_id) if spot is not None else None
        if text is None or spot is None:
            return None
        return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, text), lines.whole_line(spot.line))

    _outline_and_completion(server)


def _navigation(server: OdServer) -> None:
    """Definition and references."""

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    @guarded
    def on_definition(ls: OdServer, params: types.DefinitionParams) -> types.Location | None:
        uri = params.text_document.uri
        found = _device(ls, uri)
        if found is None:
            return None
        device, lines, state = found
        ref = navigation.id_ref_at(
            lines.line(params.position.line), lines.column(params.position.line, params.position.character)
        )
        if ref is not None:
            target = navigation.parameter_element(state.encoding.bytes(lines.text), device.source, ref)
            return _location(uri, lines, target) if target is not None else None
        spot = _index(state, device).at(*lines.model(params.position))
        where = navigation.definition(device, spot) if spot is not None else None
        return _location(uri, lines, where) if where is not None else None

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    @guarded
    def on_references(ls: OdServer, params: types.ReferenceParams) -> list[types.Location] | None:
        uri = params.text_document.uri
        found = _device(ls, uri)
        if found is None:
            return None
        device, lines, state = found
        number = params.position.line
        unique_id = navigation.id_at(lines.line(number), lines.column(number, params.position.character))
        if unique_id is not None:
            users = navigation.id_ref_users([lines.line(n) for n in range(len(lines))], unique_id)
            return [types.Location(uri, lines.rest_of_line(line + 1, column + 1)) for line, column in users]
        spot = _index(state, device).at(*lines.model(params.position))
        return [_location(uri, lines, where) for where in navigation.references(device, spot)] if spot else []


def _editing(server: OdServer) -> None:
    """Code actions and formatting."""

    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION,
        types.CodeActionOptions(
            code_action_kinds=[types.CodeActionKind.QuickFix, types.CodeActionKind.SourceFixAll], resolve_provider=True
        ),
    )
    @guarded
    async def on_code_action(ls: OdServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
        uri = params.text_document.uri
        found = ls.current(uri)
        if found is None or found[0].device is None:
            return None
        analysis, _, state = found
        span = (params.range.start.line + 1, params.range.end.line + 1)
        offered = actions.code_actions(uri, analysis, span, list(params.context.diagnostics))
        if ls.resolves or not offered:
            return offered
        resolved = []
        for action in offered:  # a client that cannot resolve gets each edit now
            try:
                resolved.append(await ls.in_worker(uri, actions.resolve, action, analysis, state.encoding, ls.options))
            except actions.NotFixed as reason:
                say(f"{uri}: {reason}")
        return resolved

    @server.feature(types.CODE_ACTION_RESOLVE)
    @guarded
    async def on_resolve(ls: OdServer, action: types.CodeAction) -> types.CodeAction:
        wanted = actions.wanted(action)
        found = ls.current(wanted[0]) if wanted is not None else None
        if wanted is None or found is None:
            return action
        analysis, _, state = found
        try:
            return await ls.in_worker(wanted[0], actions.resolve, action, analysis, state.encoding, ls.options)
        except actions.NotFixed as reason:
            ls.window_show_message(types.ShowMessageParams(types.MessageType.Warning, f"cantools-od: {reason}"))
            return action

    async def _format(ls: OdServer, uri: str, within: types.Range | None) -> list[types.TextEdit] | None:
        found = ls.current(uri)
        if found is None:
            return None
        analysis, _, state = found
        try:
            return await ls.in_worker(uri, formatting.format_edits, uri, analysis, state.encoding, within)
        except formatting.NotFormatted as reason:
            message = f"cantools-od: {reason}"
            if within is None or not state.told:  # format on paste asks at every paste: say it once
                state.told = within is not None
                ls.window_show_message(types.ShowMessageParams(types.MessageType.Warning, message))
            ls.window_log_message(types.LogMessageParams(types.MessageType.Info, message))
            return []

    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    @guarded
    async def on_formatting(ls: OdServer, params: types.DocumentFormattingParams) -> list[types.TextEdit] | None:
        return await _format(ls, params.text_document.uri, None)

    @server.feature(types.TEXT_DOCUMENT_RANGE_FORMATTING)
    @guarded
    async def on_range_formatting(
        ls: OdServer, params: types.DocumentRangeFormattingParams
    ) -> list[types.TextEdit] | None:
        return await _format(ls, params.text_document.uri, params.range)


def _outline_and_completion(server: OdServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    @guarded
    async def on_symbols(ls: OdServer, params: types.DocumentSymbolParams) -> list[types.DocumentSymbol] | None:
        uri = params.text_document.uri
        found = _device(ls, uri)
        if found is None:
            return None
        device, lines, state = found

        def symbols() -> list[types.DocumentSymbol]:
            return outline.symbols(device, _index(state, device), lines)

        return await ls.in_worker(uri, symbols)

    @server.feature(types.WORKSPACE_SYMBOL)
    @guarded
    async def on_workspace_symbols(ls: OdServer, params: types.WorkspaceSymbolParams) -> list[types.WorkspaceSymbol]:
        found: list[types.WorkspaceSymbol] = []
        for uri in list(ls.open):
            current = _device(ls, uri)
            if current is not None and len(found) < WORKSPACE_SYMBOLS:
                device, lines, state = current
                left = WORKSPACE_SYMBOLS - len(found)
                found += outline.workspace_symbols(uri, device, _index(state, device), lines, params.query, left)
        for item in await ls.children.symbols(params.query):  # those of the documents served by other processes
            if len(found) < WORKSPACE_SYMBOLS:
                found.append(ls.protocol._converter.structure(item, types.WorkspaceSymbol))
        return found

    @server.feature(types.TEXT_DOCUMENT_FOLDING_RANGE)
    @guarded
    async def on_folding(ls: OdServer, params: types.FoldingRangeParams) -> list[types.FoldingRange] | None:
        uri = params.text_document.uri
        found = _device(ls, uri)
        if found is None:
            return None
        device, lines, state = found
        return await ls.in_worker(uri, lambda: outline.folding(device, _index(state, device), lines))

    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=["=", "["]))
    @guarded
    def on_completion(ls: OdServer, params: types.CompletionParams) -> types.CompletionList | None:
        uri = params.text_document.uri
        found = ls.current(uri)
        if found is None:
            return None
        analysis, _, state = found
        device = analysis.device
        if device is not None and device.file_format != "eds":
            return None
        document = ls.workspace.get_text_document(uri)
        number = params.position.line
        lines = document.lines
        text = lines[number] if number < len(lines) else ""
        column = document.position_codec.position_from_client_units(lines, params.position).character
        before, after = text[:column], text[column:]
        index = _index(state, device) if device is not None else None
        present = set(device.objects) if device is not None else set()
        items = completion.complete(index, before, number + 1, present, after)
        return types.CompletionList(is_incomplete=False, items=items)

"""rcssserver's message syntax: S-expressions of symbols, numbers and quoted strings.

Every message the server sends a client is one S-expression, ``(head item ...)``, each item
a symbol (``play_on``, ``l``), a number (``-12.5``, ``1e-05``), a double-quoted string
(``"HELIOS"``, a team name in a ``see``; a ``say`` message in a ``hear``) or a nested list.
:func:`parse` turns the text into nested Python lists of ``str`` tokens (quoted strings
keep their quotes, so ``'"HELIOS"'`` and ``HELIOS`` stay distinct); the parsers of
:mod:`rcss_bridge.messages` and :mod:`rcss_bridge.params` give the tokens their types.

``hear`` messages of players carry free text (an unquoted ``say`` is passed on as said, with
spaces and parentheses); :mod:`rcss_bridge.messages` reads those before tokenising.
"""

from __future__ import annotations

import re

from rcss_bridge.errors import ProtocolError

Expr = list["Expr | str"]
"""A parsed S-expression: its items, each a token (``str``) or a nested expression."""

_TOKEN = re.compile(r'\s*(?:(\()|(\))|("(?:[^"\\]|\\.)*")|([^\s()"]+))')
"""One token: an opening or closing parenthesis, a quoted string or a bare word."""


def parse(text: str) -> Expr:
    """The S-expression ``text`` (one message; a trailing NUL byte and whitespace are ignored)
    as nested lists; a :class:`ProtocolError` quoting the text when it is not one balanced
    expression."""
    body = text.rstrip("\0 \n\r\t")
    stack: list[Expr] = []
    result: Expr | None = None
    position = 0
    end = len(body)
    while position < end:
        match = _TOKEN.match(body, position)
        if match is None:
            if body[position:].strip() == "":
                break
            raise ProtocolError(f"unreadable server message at character {position}: {_excerpt(text)}")
        position = match.end()
        opening, closing, quoted, word = match.groups()
        if opening:
            if result is not None:
                raise ProtocolError(f"text after the end of a server message: {_excerpt(text)}")
            child: Expr = []
            if stack:
                stack[-1].append(child)
            stack.append(child)
        elif closing:
            if not stack:
                raise ProtocolError(f"unbalanced ')' in a server message: {_excerpt(text)}")
            finished = stack.pop()
            if not stack:
                result = finished
        else:
            if not stack:
                raise ProtocolError(f"a token outside parentheses in a server message: {_excerpt(text)}")
            stack[-1].append(quoted or word)
    if stack or result is None:
        raise ProtocolError(f"unbalanced '(' in a server message: {_excerpt(text)}")
    return result


def head(text: str) -> str:
    """The first word of a message, ``"see"`` for ``(see 12 ...)``, without parsing the rest
    (empty when the text does not start with ``(``)."""
    body = text.lstrip()
    if not body.startswith("("):
        return ""
    stop = 1
    while stop < len(body) and body[stop] not in " ()\0":
        stop += 1
    return body[1:stop]


def unquote(token: str) -> str:
    """A quoted string token's text (``'"HELIOS"'`` -> ``HELIOS``); a bare word unchanged."""
    if len(token) >= 2 and token[0] == token[-1] == '"':
        return token[1:-1].replace('\\"', '"')
    return token


def number(token: "Expr | str", what: str) -> float:
    """``token`` as a float; a :class:`ProtocolError` naming ``what`` when it is not a number."""
    try:
        return float(token)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ProtocolError(f"{what}: expected a number, got {token!r}") from None


def integer(token: "Expr | str", what: str) -> int:
    """``token`` as an int (``"3"`` or ``"3.0"``); a :class:`ProtocolError` naming ``what`` otherwise."""
    value = number(token, what)
    if value != int(value):
        raise ProtocolError(f"{what}: expected a whole number, got {token!r}")
    return int(value)


def _excerpt(text: str, limit: int = 80) -> str:
    """The start of ``text`` for an error message."""
    clean = text.rstrip("\0")
    return repr(clean if len(clean) <= limit else clean[:limit] + "...")

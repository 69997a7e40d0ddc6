"""Text a client sends: refuse what cannot be stored or echoed (lone UTF-16 surrogates).

JSON's ``\\ud800`` escape decodes (with the standard library) to a Python string holding a
lone surrogate: it cannot be encoded as UTF-8, so storing it or echoing it in a response
fails later, far from the request that brought it. These helpers find and refuse it at
the door, naming the field.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from app.kinematics.errors import InvalidInputError

_SURROGATE = re.compile("[\ud800-\udfff]")

#: What the error says about a lone surrogate.
SURROGATE_REASON = "must be valid Unicode text (a lone UTF-16 surrogate such as \\ud800 is not)"


def has_surrogate(text: str) -> bool:
    """Whether ``text`` holds a lone surrogate code point (U+D800–U+DFFF)."""
    return _SURROGATE.search(text) is not None


def check_text(value: str, field: str) -> str:
    """``value`` unchanged, or :class:`InvalidInputError` naming ``field`` if it has a surrogate."""
    if has_surrogate(value):
        raise InvalidInputError(SURROGATE_REASON, field)
    return value


def find_surrogate(obj: Any, path: str = "") -> str | None:
    """The dotted path of the first string (value or key) holding a surrogate, else ``None``.

    Walks decoded JSON (dicts, lists, strings); ``path`` is the prefix (``""``: the body).
    """
    stack: list[tuple[Any, str]] = [(obj, path)]
    while stack:
        item, where = stack.pop()
        if isinstance(item, str):
            if has_surrogate(item):
                return where or "body"
        elif isinstance(item, Mapping):
            for key, value in item.items():
                sub = f"{where}.{key}" if where else str(key)
                if isinstance(key, str) and has_surrogate(key):
                    return where or "body"
                stack.append((value, sub))
        elif isinstance(item, list | tuple):
            stack.extend((v, f"{where}.{i}" if where else str(i)) for i, v in enumerate(item))
    return None


def printable(text: str) -> str:
    """``text`` with each lone surrogate replaced by U+FFFD (safe to encode as UTF-8)."""
    if not has_surrogate(text):
        return text
    return text.encode("utf-16", "surrogatepass").decode("utf-16", "replace")

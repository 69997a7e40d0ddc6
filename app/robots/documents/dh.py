"""DH table documents sent by clients (JSON or YAML), checked before and by dh2urdf.

The YAML screen (:func:`_screen_yaml`) runs before the pure-Python table parser: it bounds
nesting depth and the number of parse events and refuses aliases. dh2urdf then validates
the table (:meth:`dh2urdf.DHTable.from_text`); its errors become core errors naming the
field in the API's dotted form (``joints.2.lower``).
"""

from __future__ import annotations

import logging
from typing import Literal

import yaml

from app.kinematics.errors import InvalidInputError
from dh2urdf import DHError, DHTable

log = logging.getLogger("denavit.documents")

#: Most rows a user-supplied DH table may have.
MAX_DH_JOINTS = 64
#: Largest DH table document (bytes): tables are small, and YAML parsing is slow.
MAX_DH_DOCUMENT_BYTES = 256 * 1024
#: Deepest nesting a DH document may have (a table needs 3 levels).
MAX_DOCUMENT_DEPTH = 16
#: Most YAML parse events a DH document may have (64 rows of 10 fields need ~1,400).
MAX_YAML_EVENTS = 20_000


def dh_field(path: str | None, prefix: str = "") -> str:
    """A dh2urdf field path (``joints[2].lower``) in the API's dotted form (``joints.2.lower``)."""
    dotted = (path or "").replace("[", ".").replace("]", "").strip(".")
    if prefix:
        return f"{prefix}.{dotted}" if dotted else prefix
    return dotted or "body"


def dh_error(exc: DHError, prefix: str = "") -> InvalidInputError:
    """The core error (HTTP 422) for a dh2urdf validation error, naming the field."""
    return InvalidInputError(exc.reason, dh_field(exc.field, prefix))


class MalformedDocumentError(InvalidInputError):
    """The document is not JSON or YAML at all (the API answers 400)."""


def _max_bracket_depth(text: str) -> int:
    """Deepest nesting of ``[``/``{`` in ``text`` (quotes ignored: an upper bound)."""
    depth = deepest = 0
    for char in text:
        if char in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif char in "]}" and depth:
            depth -= 1
    return deepest


def _screen_yaml(text: str) -> None:
    """Cheap checks before the (pure-Python, slow) table parser sees a YAML document.

    PyYAML's scanner is quadratic in flow nesting depth and a DH table is small and
    shallow, so the document is refused when it nests deeper than
    :data:`MAX_DOCUMENT_DEPTH`, has more than :data:`MAX_YAML_EVENTS` parse events (read with
    libyaml when available), or uses aliases (``*name``, which let a small body expand
    enormously).
    """
    if _max_bracket_depth(text) > MAX_DOCUMENT_DEPTH:
        raise MalformedDocumentError(
            f"invalid YAML: nested deeper than {MAX_DOCUMENT_DEPTH} levels", "body"
        )
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    depth = events = 0
    try:
        for event in yaml.parse(text, Loader=loader):
            events += 1
            if isinstance(event, yaml.AliasEvent):
                line = event.start_mark.line + 1 if event.start_mark else "?"
                raise InvalidInputError(
                    f"YAML aliases are not accepted (alias *{event.anchor} on line {line}); "
                    "write the values out",
                    "body",
                )
            if isinstance(event, yaml.CollectionStartEvent):
                depth += 1
                if depth > MAX_DOCUMENT_DEPTH:
                    raise MalformedDocumentError(
                        f"invalid YAML: nested deeper than {MAX_DOCUMENT_DEPTH} levels", "body"
                    )
            elif isinstance(event, yaml.CollectionEndEvent):
                depth -= 1
            if events > MAX_YAML_EVENTS:
                raise InvalidInputError(
                    f"too many YAML values for a DH table (more than {MAX_YAML_EVENTS})", "body"
                )
    except yaml.YAMLError:
        return  # syntax errors are reported by the table parser, with their position
    except RecursionError:
        raise MalformedDocumentError("invalid YAML: nested too deeply", "body") from None


def parse_dh_document(text: str, fmt: Literal["json", "yaml"]) -> DHTable:
    """Validate a DH table document (JSON or YAML text) and convert it to SI.

    Raises
    ------
    MalformedDocumentError
        The text is not JSON/YAML (or uses YAML aliases, or nests absurdly deep).
    InvalidInputError
        A field is wrong; ``field`` is its dotted path (``joints.2.lower``).
    """
    if fmt == "yaml":
        _screen_yaml(text)
    try:
        table = DHTable.from_text(text, fmt)
    except DHError as exc:
        if exc.field is None and exc.reason.startswith(("invalid JSON", "invalid YAML")):
            raise MalformedDocumentError(exc.reason, "body") from None
        raise dh_error(exc) from None
    except RecursionError:
        raise MalformedDocumentError(f"invalid {fmt.upper()}: nested too deeply", "body") from None
    except (TypeError, KeyError, AttributeError) as exc:  # a value of a type dh2urdf missed
        log.warning("dh2urdf raised %r instead of DHError", exc)
        raise InvalidInputError(f"not a valid DH table ({exc})", "body") from None
    if table.dof > MAX_DH_JOINTS:
        raise InvalidInputError(f"at most {MAX_DH_JOINTS} rows, got {table.dof}", "joints")
    return table

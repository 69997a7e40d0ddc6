"""Expanding a client's ``.urdf.xacro`` into URDF text, confined to its package.

The expansion runs in a bounded child process of its own (:mod:`app.robots.documents.sandbox`,
task ``xacro`` of :mod:`app.robots.documents.xacro_child`): wall-clock time (killed after
``timeout_s``), CPU time, address space (``memory_bytes`` over what it uses at start), no
file writes, no new processes; its answer is read up to ``max_output_chars``. Inside it,
xacro reads files only from the package, which it sees at ``/package``
(:data:`~app.robots.documents.xacro_child.VIRTUAL_ROOT`), sees no environment variable, and
evaluates only checked expressions (see the child's module). A typical expansion costs the
child's start (about 0.2-0.4 s: Python and the xacro import) plus the expansion itself.

The arguments (``xacro_args``) are strings; JSON numbers and booleans are accepted and
written as xacro would read them (``0.1``, ``true``).
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from pathlib import Path

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.manifests import package_names
from app.robots.documents.sandbox import ChildLimits, run_child

#: Default bounds of one expansion (the route passes the settings
#: ``DENAVIT_XACRO_TIMEOUT_S``, ``DENAVIT_XACRO_MEMORY_BYTES``, ``DENAVIT_XACRO_MAX_OUTPUT_CHARS``).
XACRO_TIMEOUT_S = 20.0
XACRO_MEMORY_BYTES = 512 * 1024 * 1024
XACRO_MAX_OUTPUT_CHARS = 8 * 1024 * 1024


@dataclass(frozen=True, slots=True)
class XacroLimits:
    """The bounds of one expansion (``DENAVIT_XACRO_*``), passed to :func:`expand_xacro`."""

    timeout_s: float = XACRO_TIMEOUT_S
    memory_bytes: int = XACRO_MEMORY_BYTES
    max_output_chars: int = XACRO_MAX_OUTPUT_CHARS


#: At most this many ``xacro_args``, names and values of at most this many characters.
MAX_ARGS = 256
MAX_ARG_CHARS = 4096
_ARG_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_.\-]{0,127}$")


def _arg_value(name: str, value: object, args_field: str = "xacro_args") -> str:
    field = f"{args_field}.{name}"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        text = str(value)
    elif isinstance(value, float):
        if not math.isfinite(value):
            raise InvalidInputError("must be a finite number", field)
        text = repr(value)
    elif isinstance(value, str):
        text = value
    else:
        raise InvalidInputError(
            f"must be a string, number or boolean, not {type(value).__name__}", field
        )
    if len(text) > MAX_ARG_CHARS:
        raise InvalidInputError(f"longer than {MAX_ARG_CHARS} characters", field)
    if any(ord(c) < 32 and c not in "\t\n\r" or 0xD800 <= ord(c) < 0xE000 for c in text):
        raise InvalidInputError("must not contain control characters or surrogates", field)
    return text


def check_xacro_args(args: object, field: str = "xacro_args") -> dict[str, str]:
    """The xacro arguments ``args`` as strings, or :class:`InvalidInputError` naming the bad
    one (``field`` or ``<field>.<name>``: ``xacro_args``, or ``srdf_xacro_args``)."""
    if not isinstance(args, Mapping):
        raise InvalidInputError("must be an object of argument names to values", field)
    if len(args) > MAX_ARGS:
        raise InvalidInputError(f"more than {MAX_ARGS} arguments", field)
    out = {}
    for name, value in args.items():
        if not isinstance(name, str) or not _ARG_NAME.match(name):
            raise InvalidInputError(
                f"argument name {str(name)[:60]!r} is not a xacro name "
                "(letters, digits, '_', '.', '-'; at most 128 characters)",
                field,
            )
        out[name] = _arg_value(name, value, field)
    return out


def _renamed(exc: InvalidInputError, field: str, args_field: str) -> InvalidInputError:
    """``exc`` naming ``field`` for ``description`` and ``args_field`` for ``xacro_args``
    (an SRDF given as xacro: fields ``srdf`` and ``srdf_xacro_args``)."""
    name = exc.field or "description"
    if name == "description":
        name = field
    elif name.startswith("xacro_args"):
        name = args_field + name[len("xacro_args") :]
    return InvalidInputError(exc.message.replace("xacro_args", args_field), name)


def _description_path(root: Path, description: str) -> Path:
    path = Path(description)
    if path.is_absolute() or ".." in path.parts or not description.strip():
        raise InvalidInputError(
            f"{description[:200]!r} must be a relative path inside the package", "description"
        )
    real = Path(os.path.realpath(root / path))
    if Path(os.path.realpath(root)) not in real.parents or not real.is_file():
        raise InvalidInputError(
            f"{description[:200]!r}: no such file in the package", "description"
        )
    return path


def expand_xacro(
    root: Path,
    description: str,
    args: Mapping[str, str],
    limits: XmlLimits,
    *,
    packages: Mapping[str, str] | None = None,
    timeout_s: float = XACRO_TIMEOUT_S,
    memory_bytes: int = XACRO_MEMORY_BYTES,
    max_output_chars: int = XACRO_MAX_OUTPUT_CHARS,
    field: str = "description",
    args_field: str = "xacro_args",
) -> str:
    """The URDF (or SRDF) text of the xacro file ``root / description`` expanded with
    ``args``.

    Parameters
    ----------
    root
        The unpacked package: every file read must resolve (symlinks followed) inside it.
    description
        The xacro file's path relative to ``root``.
    args
        Values of the document's ``<xacro:arg>``s (strings; numbers and booleans are
        written as text).
    limits
        XML limits applied to every file read and to the result.
    packages
        The names ``$(find <pkg>)`` knows: package name → its folder relative to ``root``,
        as :func:`app.robots.documents.manifests.package_names` gives them (read from ``root``
        when not given).
    timeout_s, memory_bytes, max_output_chars
        Bounds of the child process: wall-clock time, address space it may add, length
        of the expanded document.
    field, args_field
        The request fields refusals name for the document and for its arguments.

    Raises
    ------
    InvalidInputError
        Field ``field`` (message naming the file, relative to ``root``, and the line), or
        ``args_field`` / ``<args_field>.<name>`` for the arguments (``archive`` for an
        unreadable ``package.xml`` when ``packages`` is not given).
    """
    try:
        return _expand(
            root, description, args, limits, packages, timeout_s, memory_bytes, max_output_chars
        )
    except InvalidInputError as exc:
        raise _renamed(exc, field, args_field) from None


def _expand(
    root: Path,
    description: str,
    args: Mapping[str, str],
    limits: XmlLimits,
    packages: Mapping[str, str] | None,
    timeout_s: float,
    memory_bytes: int,
    max_output_chars: int,
) -> str:
    """:func:`expand_xacro`, its refusals naming ``description`` and ``xacro_args``."""
    checked_args = check_xacro_args(args)
    path = _description_path(root, description)
    if packages is None:
        packages = package_names(root, limits)
    request = {
        "root": os.path.realpath(root),
        "description": path.as_posix(),
        "args": checked_args,
        "packages": dict(packages),
        "limits": asdict(limits),
        "max_output_chars": int(max_output_chars),
    }
    bounds = ChildLimits(
        timeout_s,
        memory_bytes,
        4 * max_output_chars + 1024,
        "DENAVIT_XACRO_TIMEOUT_S",
        "DENAVIT_XACRO_MEMORY_BYTES",
    )
    urdf = run_child("xacro", request, bounds, field="description", what="xacro expansion")
    if not isinstance(urdf, str):  # pragma: no cover - the child answers a document
        raise InvalidInputError("xacro expansion gave no document", "description")
    try:
        parse_literal_xml(urdf, "description", limits)
    except InvalidInputError as exc:
        raise InvalidInputError(f"the expanded document: {exc.message}", "description") from None
    return urdf

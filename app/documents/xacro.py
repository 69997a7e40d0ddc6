"""Expanding a client's ``.urdf.xacro`` into URDF text, confined to its package.

The expansion runs in a child process of its own (:mod:`app.documents.xacro_child`),
started with ``python -I -B`` and an empty environment, which dies with the thread that
waits for it (``PR_SET_PDEATHSIG``, as :mod:`app.kinematics.procwatch` does for
reachability builds) and is bounded: wall-clock time (killed after ``timeout_s``), CPU
time, address space (``memory_bytes`` over what it uses at start), no file writes, no new
processes; its answer is read up to ``max_output_chars``. Inside it, xacro reads files
only from the package, sees no environment variable, and evaluates only checked
expressions (see the child's module). A typical expansion costs the child's start (about
0.2-0.4 s: Python and the xacro import) plus the expansion itself.

The arguments (``xacro_args``) are strings; JSON numbers and booleans are accepted and
written as xacro would read them (``0.1``, ``true``).
"""

from __future__ import annotations

import json
import math
import os
import re
import selectors
import subprocess
import sys
import time
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from pathlib import Path

import app
from app.documents.manifests import package_names
from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml

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
_CHILD = "from app.documents.xacro_child import main; main({pid})"


def _arg_value(name: str, value: object) -> str:
    field = f"xacro_args.{name}"
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


def check_xacro_args(args: object) -> dict[str, str]:
    """The ``xacro_args`` as strings, or :class:`InvalidInputError` naming the bad one."""
    if not isinstance(args, Mapping):
        raise InvalidInputError("must be an object of argument names to values", "xacro_args")
    if len(args) > MAX_ARGS:
        raise InvalidInputError(f"more than {MAX_ARGS} arguments", "xacro_args")
    out = {}
    for name, value in args.items():
        if not isinstance(name, str) or not _ARG_NAME.match(name):
            raise InvalidInputError(
                f"argument name {str(name)[:60]!r} is not a xacro name "
                "(letters, digits, '_', '.', '-'; at most 128 characters)",
                "xacro_args",
            )
        out[name] = _arg_value(name, value)
    return out


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


def _run_child(request: dict[str, object], timeout_s: float, max_output: int) -> dict[str, str]:
    """Run the child with ``request`` and return its answer (bounded in time and size)."""
    path = str(Path(app.__file__).parent.parent)
    code = f"import sys; sys.path.insert(0, {path!r}); {_CHILD.format(pid=os.getpid())}"
    proc = subprocess.Popen(
        [sys.executable, "-I", "-B", "-c", code],  # isolated, writes no bytecode
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env={},
        cwd="/",
        close_fds=True,
    )
    try:
        assert proc.stdin is not None and proc.stdout is not None
        proc.stdin.write(json.dumps(request).encode("utf-8"))
        proc.stdin.close()
        chunks: list[bytes] = []
        size = 0
        deadline = time.monotonic() + timeout_s
        with selectors.DefaultSelector() as sel:
            sel.register(proc.stdout, selectors.EVENT_READ)
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise InvalidInputError(
                        f"xacro expansion took longer than {timeout_s:g} s "
                        "(DENAVIT_XACRO_TIMEOUT_S)",
                        "description",
                    )
                if not sel.select(left):
                    continue
                data = os.read(proc.stdout.fileno(), 1 << 16)
                if not data:
                    break
                chunks.append(data)
                size += len(data)
                if size > max_output:
                    raise InvalidInputError(
                        f"the expanded URDF is larger than {max_output} bytes "
                        "(DENAVIT_XACRO_MAX_OUTPUT_CHARS)",
                        "description",
                    )
        proc.wait(timeout=max(1.0, deadline - time.monotonic()))
    except subprocess.TimeoutExpired:
        raise InvalidInputError("xacro expansion did not finish", "description") from None
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        if proc.stdout is not None:
            proc.stdout.close()
    try:
        answer = json.loads(b"".join(chunks))
    except ValueError:
        answer = None
    if not isinstance(answer, dict):
        raise InvalidInputError(
            "xacro expansion failed: it exceeded its memory or CPU limits "
            f"(exit status {proc.returncode}; DENAVIT_XACRO_MEMORY_BYTES)",
            "description",
        )
    return answer


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
) -> str:
    """The URDF text of the xacro file ``root / description`` expanded with ``args``.

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
        as :func:`app.documents.manifests.package_names` gives them (read from ``root``
        when not given).
    timeout_s, memory_bytes, max_output_chars
        Bounds of the child process: wall-clock time, address space it may add, length
        of the expanded document.

    Raises
    ------
    InvalidInputError
        Field ``description`` (message naming the file, relative to ``root``, and the
        line), or ``xacro_args`` / ``xacro_args.<name>`` for the arguments (``archive``
        for an unreadable ``package.xml`` when ``packages`` is not given).
    """
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
        "memory_bytes": int(memory_bytes),
        "cpu_s": math.ceil(1.5 * timeout_s) + 1,  # a backstop: the wall-clock timeout rules
        "max_output_chars": int(max_output_chars),
    }
    answer = _run_child(request, timeout_s, 4 * max_output_chars + 1024)
    if "error" in answer:
        field = answer.get("field")
        raise InvalidInputError(
            str(answer["error"]), field if field in ("description", "xacro_args") else "description"
        )
    urdf = answer.get("urdf")
    if not isinstance(urdf, str):  # pragma: no cover - the child always answers one of both
        raise InvalidInputError("xacro expansion gave no document", "description")
    try:
        parse_literal_xml(urdf, "description", limits)
    except InvalidInputError as exc:
        raise InvalidInputError(f"the expanded URDF: {exc.message}", "description") from None
    return urdf

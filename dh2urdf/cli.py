"""Command line: ``dh2urdf TABLE.{yaml,yml,json} [-o robot.urdf]``.

Reads a DH table, validates it and writes the URDF to stdout or ``-o FILE``. Any problem
with the input (missing or unreadable file, bad YAML/JSON, invalid table, bad arguments)
is reported as one line ``dh2urdf: error: <file>: <field>: <reason>`` on stderr with exit
status 2; failing to write the output gives exit status 1. Never a traceback.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import NoReturn

# Import submodules, not the package: works even where ``dh2urdf`` resolves as a namespace.
from dh2urdf.errors import DHError
from dh2urdf.loaders import format_for_path
from dh2urdf.table import DHTable
from dh2urdf.urdf import to_urdf

__all__ = ["main", "EXIT_OK", "EXIT_OUTPUT_ERROR", "EXIT_INPUT_ERROR"]

PROG = "dh2urdf"
EXIT_OK = 0
EXIT_OUTPUT_ERROR = 1
EXIT_INPUT_ERROR = 2


class _UsageError(Exception):
    """Raised instead of argparse's print-usage-and-exit."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        raise _UsageError(message)


def _parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog=PROG,
        description=(
            "Convert a Denavit-Hartenberg table (YAML or JSON) to URDF. Links dh_0..dh_n are "
            "the DH frames, 'tool' the TCP, 'world' the root; output in SI units."
        ),
        epilog="Exit status: 0 ok, 1 output could not be written, 2 bad input or arguments.",
    )
    p.add_argument("table", help="DH table file (.yaml, .yml or .json); '-' reads stdin")
    p.add_argument("-o", "--output", metavar="FILE", help="write the URDF here instead of stdout")
    p.add_argument(
        "--format",
        choices=("yaml", "json"),
        help="input format (default: from the file extension; yaml for stdin)",
    )
    return p


def _error(message: str) -> None:
    print(f"{PROG}: error: {message}", file=sys.stderr)


def _load(source: str, fmt: str | None) -> DHTable:
    if source == "-":
        return DHTable.from_text(sys.stdin.read(), fmt or "yaml")
    path = Path(source)
    fmt = fmt or format_for_path(path)
    try:
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise DHError(None, f"not UTF-8 text ({exc.reason} at byte {exc.start})") from exc
    return DHTable.from_text(text, fmt)  # type: ignore[arg-type]


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (0, 1 or 2).

    Parameters
    ----------
    argv : sequence of str, optional
        Arguments without the program name (default: ``sys.argv[1:]``).
    """
    try:
        args = _parser().parse_args(argv)
    except _UsageError as exc:
        _error(f"{exc} (see '{PROG} --help')")
        return EXIT_INPUT_ERROR
    except SystemExit as exc:  # --help
        return int(exc.code or 0)

    source = "<stdin>" if args.table == "-" else args.table
    try:
        table = _load(args.table, args.format)
        text = to_urdf(table)
    except DHError as exc:
        _error(f"{source}: {exc}")
        return EXIT_INPUT_ERROR
    except OSError as exc:
        _error(f"{source}: cannot read: {exc.strerror or exc}")
        return EXIT_INPUT_ERROR
    except RecursionError:
        _error(f"{source}: document nested too deeply")
        return EXIT_INPUT_ERROR

    if args.output is None or args.output == "-":
        sys.stdout.write(text)
        sys.stdout.flush()
        return EXIT_OK
    try:
        Path(args.output).write_text(text, encoding="utf-8")
    except OSError as exc:
        _error(f"{args.output}: cannot write: {exc.strerror or exc}")
        return EXIT_OUTPUT_ERROR
    return EXIT_OK

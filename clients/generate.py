"""Generate the Python client package (clients/python/denavit_client) from docs/openapi.json.

``make clients`` runs ``python clients/generate.py`` (and openapi-typescript for
clients/typescript); ``--check`` generates into a temporary directory and exits 1 naming
every file that differs from the committed package (tests/clients checks it).

How the package is made:

- openapi-python-client, at the version pinned in the development lock, with the committed
  configuration clients/python/generator.yaml (package name, the content types it cannot
  read by their own name: XML text is text, the PNG heat map is a file), ``--meta none``:
  the package only, its metadata is the hand-written clients/python/pyproject.toml.
- From the document with one change: an operation whose ``security`` admits anonymous
  access (an empty requirement ``{}``: the bearer token is needed only when the service runs
  with ``DENAVIT_API_TOKEN`` set) is given no ``security``. The generator has no notion of
  optional security (any ``security`` makes the operation demand an ``AuthenticatedClient``),
  so without this a write operation would not accept a plain ``Client`` with no token.
  ``denavit_client.session.connect`` gives the right client for a token or none.
- Formatted by the project's ruff (its pyproject.toml), not the generator's hooks, so the
  committed files are what ``ruff format`` keeps.
- The hand-written modules (:data:`HAND_WRITTEN`) live in the same package; generating
  never touches them.
"""

from __future__ import annotations

import argparse
import copy
import filecmp
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
DOCUMENT = ROOT / "docs" / "openapi.json"
CLIENT = ROOT / "clients" / "python"
CONFIG = CLIENT / "generator.yaml"
PACKAGE = "denavit_client"
#: Modules of the package written by hand (paths inside it): never generated, never removed.
HAND_WRITTEN = frozenset({"session.py", "arrays.py", "stream.py", "py.typed"})
METHODS = ("get", "put", "post", "delete", "options", "head", "patch", "trace")


def generator_document(document: dict[str, Any]) -> dict[str, Any]:
    """``document`` with no ``security`` on operations that admit anonymous access.

    Parameters
    ----------
    document
        The OpenAPI document (not changed).

    Returns
    -------
    dict
        A copy in which every operation whose ``security`` list holds an empty requirement
        (``{}``: the token is optional) has its ``security`` removed.
    """
    out = copy.deepcopy(document)
    for item in out.get("paths", {}).values():
        for method in METHODS:
            op = item.get(method)
            if isinstance(op, dict) and {} in op.get("security", []):
                del op["security"]
    return out


def _run(cmd: list[str], cwd: Path) -> None:
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{done.stdout}{done.stderr}")


def generate(out: Path, document: dict[str, Any] | None = None) -> str:
    """Generate the package into ``out`` (a new directory); returns the generator's output.

    Parameters
    ----------
    out
        Directory to create, the package's own folder (``.../denavit_client``).
    document
        The OpenAPI document; by default docs/openapi.json.
    """
    bin_dir = Path(sys.executable).parent
    if document is None:
        document = json.loads(DOCUMENT.read_text())
    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "openapi.json"
        spec.write_text(json.dumps(generator_document(document)))
        done = subprocess.run(
            [
                str(bin_dir / "openapi-python-client"),
                "generate",
                "--path",
                str(spec),
                "--config",
                str(CONFIG),
                "--meta",
                "none",
                "--output-path",
                str(out),
            ],
            env={**os.environ, "PATH": f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"},
            capture_output=True,
            text=True,
        )
    if done.returncode != 0:
        raise SystemExit(f"openapi-python-client failed:\n{done.stdout}{done.stderr}")
    ruff = [sys.executable, "-m", "ruff"]
    config = ["--no-cache", "--config", str(ROOT / "pyproject.toml")]
    _run([*ruff, "check", ".", "--fix-only", "--quiet", *config], out)
    _run([*ruff, "format", ".", "--quiet", *config], out)
    return done.stdout + done.stderr


def _files(folder: Path) -> set[str]:
    """The package's generated files under ``folder`` (relative, POSIX), caches excluded."""
    return {
        p.relative_to(folder).as_posix()
        for p in folder.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
    } - HAND_WRITTEN


def differences(fresh: Path, committed: Path) -> list[str]:
    """Files that differ between a fresh generation and the committed package (missing on
    either side, or another content)."""
    a, b = _files(fresh), _files(committed)
    return sorted(
        (a ^ b) | {name for name in a & b if not filecmp.cmp(fresh / name, committed / name, False)}
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--check", action="store_true", help="compare with the committed package, change nothing"
    )
    args = parser.parse_args(argv)
    committed = CLIENT / PACKAGE
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / PACKAGE
        log = generate(fresh)
        if args.check:
            changed = differences(fresh, committed)
            if changed:
                print("clients/python is out of date (run `make clients`):", *changed, sep="\n  ")
                return 1
            return 0
        for name in _files(committed):
            (committed / name).unlink()
        for name in sorted(_files(fresh)):
            (committed / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(fresh / name, committed / name)
        for folder in sorted(committed.rglob("*"), reverse=True):
            if folder.is_dir() and not any(folder.iterdir()):
                folder.rmdir()
    warnings = [w.strip().splitlines()[0] for w in log.split("WARNING parsing")[1:]]
    for warning in warnings:
        print("generator warning:", warning)
    return 0


if __name__ == "__main__":
    sys.exit(main())

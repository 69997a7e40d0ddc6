"""The hash-locked requirement files (`make lock`) and a reader of them, shared by the lock
tests (tests/test_lock.py) and the runtime-lock serving test
(tests/test_runtime_lock_serves.py)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RUNTIME = ROOT / "requirements.lock"
DEV = ROOT / "requirements-dev.lock"


def canonical(name: str) -> str:
    """PEP 503 normalised project name."""
    return re.sub(r"[-_.]+", "-", name).lower()


def parse_lock(path: Path) -> dict[str, tuple[str, list[str]]]:
    """{name: (version, [sha256 hashes])} of a `uv pip compile --generate-hashes` file."""
    entries: dict[str, tuple[str, list[str]]] = {}
    current: str | None = None
    for line in path.read_text().splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        requirement = re.match(r"^([A-Za-z0-9_.-]+)==([^\s;\\]+)", line)
        if requirement:
            current = canonical(requirement[1])
            assert current not in entries, f"{path.name}: {current} twice"
            entries[current] = (requirement[2], [])
        else:
            assert not line[0].isalnum(), f"{path.name}: unpinned line {line!r}"
            assert current is not None, f"{path.name}: {line!r} before any requirement"
            entries[current][1].extend(re.findall(r"--hash=sha256:([0-9a-f]{64})", line))
    return entries


def parse_via(path: Path) -> dict[str, set[str]]:
    """{name: names of the locked packages that require it} from the ``# via`` annotations of
    a `uv pip compile --annotation-style line` file (``-c``/``-r`` sources and
    ``denavit (pyproject.toml)`` left out)."""
    via: dict[str, set[str]] = {}
    current: str | None = None
    for line in path.read_text().splitlines():
        requirement = re.match(r"^([A-Za-z0-9_.-]+)==", line)
        if requirement:
            current = canonical(requirement[1])
            via[current] = set()
        elif current and line.strip().startswith("# via "):
            for source in line.strip()[len("# via ") :].split(","):
                source = source.strip()
                if re.fullmatch(r"[A-Za-z0-9_.-]+", source):
                    via[current].add(canonical(source))
    return via

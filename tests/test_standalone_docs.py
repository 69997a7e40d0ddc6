"""The repository stands on its own: no tracked text refers to files outside it or to
work-tracking numbers.

A reader of a clone has nothing but the clone: a note kept beside the repository (the
workplace's domain notes, a ``shared`` folder next to the checkout) or a tracker's item
number ("issue" and a number) explains nothing to them. Such a reference is replaced by the
content itself or by a page inside the repository (docs/*.md). Third-party files kept as
they were published (tests/corpus/, app/static/vendor/) are not ours to edit and are not
read.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: Third-party files, kept byte for byte as published.
THIRD_PARTY = ("tests/corpus/", "app/static/vendor/")
#: What points outside the repository. Spelled in pieces, so this file does not match itself.
OUTSIDE = re.compile(
    "|".join(
        [
            r"\bDOMAIN" + r"\.md\b",  # the workplace's domain notes
            r"\.\./" + r"shared\b",  # the folder beside the checkout
            r"\bissue" + r"s?\s*#?\s*\d+",  # a tracker's item: the word, then its number
        ]
    ),
    re.IGNORECASE,
)
SKIPPED_DIRS = {".git", ".venv", "__pycache__", ".pytest_cache", ".ruff_cache", "node_modules"}


def tracked_files() -> list[str]:
    """The repository's files (``git ls-files``; a walk of the tree without git)."""
    try:
        out = subprocess.run(
            ["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True, timeout=60
        ).stdout
        return sorted(name for name in out.decode().split("\0") if name)
    except (OSError, subprocess.SubprocessError):
        return sorted(
            str(p.relative_to(ROOT))
            for p in ROOT.rglob("*")
            if p.is_file() and not SKIPPED_DIRS.intersection(p.relative_to(ROOT).parts)
        )


def outside_references(text: str) -> list[tuple[int, str]]:
    """``(line number, matched text)`` of each reference to something outside the repository."""
    return [(text.count("\n", 0, m.start()) + 1, m.group(0)) for m in OUTSIDE.finditer(text)]


def _text(path: Path) -> str | None:
    data = path.read_bytes()
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def test_no_tracked_text_refers_outside_the_repository() -> None:
    found = []
    for name in tracked_files():
        path = ROOT / name
        if name.startswith(THIRD_PARTY) or not path.is_file():
            continue
        text = _text(path)
        if text is None:  # binary (images, meshes)
            continue
        found += [f"{name}:{line}: {match!r}" for line, match in outside_references(text)]
    assert not found, "references outside the repository:\n" + "\n".join(found)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("see DOMAIN" + ".md for the frames", "DOMAIN" + ".md"),
        ("copied from ../" + "shared/notes", "../" + "shared"),
        ("measured for issue" + " 12", "issue" + " 12"),
        ("Issues" + " 12/14", "Issues" + " 12"),
        ("(issue" + " #3)", "issue" + " #3"),
    ],
)
def test_the_reader_finds_each_kind(text: str, match: str) -> None:
    """The check above would pass on a reader that finds nothing: show it finds each kind."""
    assert outside_references(f"first line\n{text}\n") == [(2, match)]


@pytest.mark.parametrize(
    "text",
    [
        "the issue's reference",
        "a known issue in uvicorn",
        "DOMAINS = 2",
        "../shared_lib",
        "tissue 4",
    ],
)
def test_ordinary_words_are_not_references(text: str) -> None:
    assert outside_references(text) == []

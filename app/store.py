"""User-added data on disk (robots, scenes, maps) under ``DENAVIT_DATA_DIR``.

Writes are atomic: the bytes go to a temporary file in the same directory, are fsynced,
and the file is renamed over its target (then the directory is fsynced), so a reader or a
crash sees either the old file or the new one, never half of one.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

TMP_PREFIX = ".tmp-"


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (temp file, fsync, rename, fsync dir)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=TMP_PREFIX, dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    dir_fd = os.open(path.parent, os.O_RDONLY)
    try:
        os.fsync(dir_fd)
    finally:
        os.close(dir_fd)


def remove_stale_temporaries(root: Path) -> int:
    """Delete temporary files a crash left behind under ``root``; returns how many."""
    count = 0
    if root.is_dir():
        for tmp in root.rglob(TMP_PREFIX + "*"):
            tmp.unlink(missing_ok=True)
            count += 1
    return count

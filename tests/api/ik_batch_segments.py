"""The shared memory segments of batch IK (:mod:`app.workers.shared_segment`) this test
process created and did not unlink."""

from __future__ import annotations

import os
from pathlib import Path

from app.workers.shared_segment import PREFIX

#: Where Linux shows POSIX shared memory segments.
SHM = Path("/dev/shm")


def leftover_segments() -> list[str]:
    """Names of this process's batch segments still in :data:`SHM`."""
    return sorted(p.name for p in SHM.glob(f"{PREFIX}{os.getpid()}-*"))

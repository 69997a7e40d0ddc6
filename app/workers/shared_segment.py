"""Shared memory segments between a caller and its worker processes (POSIX ``shm``).

The caller :func:`create` s a segment for one piece of work (a batch of IK targets and their
answers, :mod:`app.workers.ik_batch`); it is always unlinked when the ``with`` block ends,
however it ends (answers read, an error, cancellation, a dead worker), and the caller's
``multiprocessing`` resource tracker unlinks it should the caller itself be killed. Workers
map it by name (:func:`map_segment`; :func:`still_there` tells whether the caller has
unlinked it) without registering it anywhere: the segment is the caller's alone to unlink
(the standard library's ``SharedMemory(name)`` would register it with the
tracker again, which then reports a leak or unlinks it behind the caller's back).

Names start with :data:`PREFIX` and the caller's PID (``/dev/shm/<name>`` on Linux), so a
test can check that none is left behind.
"""

from __future__ import annotations

import _posixshmem  # the standard library's own POSIX shm binding (what SharedMemory uses)
import contextlib
import mmap
import os
import secrets
import traceback
from collections.abc import Iterator
from multiprocessing import shared_memory

#: Every segment's name starts with this, then the creating process's PID.
PREFIX = "denavit-ikb-"


@contextlib.contextmanager
def create(size: int) -> Iterator[shared_memory.SharedMemory]:
    """A new segment of ``size`` bytes (> 0, zero-filled), unlinked when the block ends.

    Views made on ``segment.buf`` must be released (no NumPy array left on them) before the
    block ends, else the mapping stays until they are collected (the segment's name is
    unlinked either way); on an exception, the locals of the finished frames it went
    through are cleared, so views held only there go first."""
    name = f"{PREFIX}{os.getpid()}-{secrets.token_hex(8)}"
    segment = shared_memory.SharedMemory(name=name, create=True, size=size)
    try:
        yield segment
    except BaseException as exc:
        traceback.clear_frames(exc.__traceback__)  # the views in the finished frames go
        raise
    finally:
        try:
            segment.close()
        except BufferError:  # a view still exported (an error mid-read): freed when collected
            pass
        segment.unlink()


def map_segment(name: str) -> mmap.mmap:
    """The segment ``name`` mapped read-write in this process, for the caller to close (not
    registered with any resource tracker; never unlinked here).

    Raises
    ------
    FileNotFoundError
        The segment is gone (its creator has unlinked it).
    """
    fd = _posixshmem.shm_open("/" + name, os.O_RDWR, mode=0o600)
    try:
        return mmap.mmap(fd, os.fstat(fd).st_size)
    finally:
        os.close(fd)


def still_there(name: str) -> bool:
    """Whether the segment ``name`` still has its name (its creator has not unlinked it):
    a mapping kept from before says nothing about that."""
    try:
        fd = _posixshmem.shm_open("/" + name, os.O_RDONLY, mode=0o600)
    except FileNotFoundError:
        return False
    os.close(fd)
    return True

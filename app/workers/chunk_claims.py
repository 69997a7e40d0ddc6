"""The chunks of a batch, claimed one after the other by worker processes from a control
block in the batch's shared segment (:mod:`app.workers.ik_batch`).

A batch is cut into chunks of consecutive rows (guided sizes, :func:`ik_batch.chunk_sizes`),
and each worker is handed one *drain* of the batch: a task that claims the next unclaimed
chunk, solves it, and claims again until none is left, the batch is cancelled or the pool
stops. The caller submits one drain per worker instead of one task per chunk, so what a
chunk costs to hand out is a claim under a lock (~2 µs), not a round trip through the
executor (~0.3 ms of the caller's CPU and ~0.15 ms of the worker's, docs/benchmarks.md);
and the chunks still go to whichever worker is free first, so the workers run out of work
together.

The block is int64 words, after the batch's targets, answers and recipe::

    CLAIMED  chunks claimed so far (the next chunk to claim)
    READY    chunks whose targets the caller has written (it writes them as the workers start)
    CANCEL   1 once the caller withdraws the batch (cancelled, the pool stopping)
    SOLVED   rows whose answers are written
    started  one word per drain: 1 once that drain has claimed work (a drain that starts after
             every chunk was claimed claims nothing; the caller need not wait for it)
    done     one word per chunk: 1 once its answers are written
    bounds   chunk k is rows bounds[k] … bounds[k + 1] − 1

Every read and write of the block is made holding one ``multiprocessing`` lock shared by the
caller and the pool's workers (given to each worker as it starts): the lock's acquire and
release order the writes of targets and answers before and after them between processes on
any architecture, so a worker reads a chunk's targets only after the caller has written them,
and the caller reads a chunk's answers only after the worker has written them.
"""

from __future__ import annotations

import time
from typing import Protocol

import numpy as np

CLAIMED, READY, CANCEL, SOLVED = range(4)
_HEAD = 4
#: How often (s) a worker that has claimed a chunk whose targets are not written yet looks
#: again (only at a batch's start: the caller writes ~1 µs of targets per row).
READY_POLL_S = 0.0002


class Lock(Protocol):
    """A lock shared with the workers (``multiprocessing`` or, in one process, ``threading``)."""

    def __enter__(self) -> object: ...
    def __exit__(self, *exc: object) -> None: ...


class ControlBlock:
    """Views on a batch's control block of ``chunks`` chunks and ``drains`` drains at
    ``offset`` of ``buffer``; every method holds ``lock`` while it touches the block."""

    __slots__ = ("chunks", "drains", "_words", "_lock")

    def __init__(
        self, buffer: memoryview, offset: int, chunks: int, drains: int, lock: Lock
    ) -> None:
        self.chunks = chunks
        self.drains = drains
        count = self.nbytes(chunks, drains) // 8
        self._words = np.frombuffer(buffer, dtype=np.int64, count=count, offset=offset)
        self._lock = lock

    @staticmethod
    def nbytes(chunks: int, drains: int) -> int:
        """Bytes of a block of ``chunks`` chunks and ``drains`` drains."""
        return 8 * (_HEAD + drains + chunks + chunks + 1)

    def _started(self) -> np.ndarray:
        return self._words[_HEAD : _HEAD + self.drains]

    def _done(self) -> np.ndarray:
        at = _HEAD + self.drains
        return self._words[at : at + self.chunks]

    def bounds(self) -> np.ndarray:
        """The chunks' row bounds (chunks + 1 words)."""
        return self._words[_HEAD + self.drains + self.chunks :]

    def release(self) -> None:
        """Drop the views on the buffer (before the segment is closed)."""
        self._words = np.empty(0, dtype=np.int64)

    # the caller's side

    def lay_out(self, sizes: list[int]) -> None:
        """A new block: chunks of ``sizes`` rows, nothing claimed, written or solved."""
        with self._lock:
            self._words[:] = 0
            self.bounds()[1:] = np.cumsum(sizes)

    def publish(self, ready: int) -> None:
        """The targets of the first ``ready`` chunks are written."""
        with self._lock:
            self._words[READY] = ready

    def cancel(self) -> None:
        """Withdraw the batch: no drain claims another chunk."""
        with self._lock:
            self._words[CANCEL] = 1

    def progress(self) -> tuple[int, np.ndarray, np.ndarray]:
        """Rows solved, which drains have claimed work, which chunks are done (copies)."""
        with self._lock:
            return int(self._words[SOLVED]), self._started().copy(), self._done().copy()

    # a worker's side

    def start(self, drain: int) -> bool:
        """Drain ``drain`` begins: whether there is a chunk left to claim (then it is marked
        started, and the caller waits for its answer)."""
        with self._lock:
            if self._words[CLAIMED] >= self.chunks or self._words[CANCEL]:
                return False
            self._started()[drain] = 1
            return True

    def claim(self) -> int | None:
        """The next chunk, once its targets are written; None when every chunk is claimed or
        the batch is withdrawn."""
        with self._lock:
            k = int(self._words[CLAIMED])
            if k >= self.chunks or self._words[CANCEL]:
                return None
            self._words[CLAIMED] = k + 1
        while True:
            with self._lock:
                if self._words[CANCEL]:
                    return None
                if self._words[READY] > k:
                    return k
            time.sleep(READY_POLL_S)

    def finish(self, k: int) -> None:
        """Chunk ``k``'s answers are written."""
        with self._lock:
            rows = self.bounds()
            self._words[SOLVED] += rows[k + 1] - rows[k]
            self._done()[k] = 1

"""This process's metric values, in prometheus_client's multiprocess files, written fast.

The files are the library's: ``<prefix>_<pid>.db`` (prefix ``counter``, ``histogram`` or
``gauge_livesum``) in a directory, each a :class:`prometheus_client.mmap_dict.MmapedDict`
(entries: the JSON key of :func:`prometheus_client.mmap_dict.mmap_key`, then two float64,
the value and a timestamp, 8-byte aligned), read and summed on a scrape by
:class:`prometheus_client.multiprocess.MultiProcessCollector`.

Why not the library's ``Counter``/``Histogram``/``Gauge`` objects, which write the same
files: in multiprocess mode they cost about 8.3 µs per request for the five values a request
changes (a lock, ``os.getpid()`` and a 16-byte pack per value, the histogram's bucket scan),
against about 1.7 µs for the writer here (docs/benchmarks.md, "Metrics by prometheus_client").
Here an entry is created once through ``MmapedDict`` (so the format is the library's), and
each later update is one aligned float64 store through a memoryview of the mapping: a
:class:`Slot`. A file that grows is mapped anew by ``MmapedDict`` without unmapping the old
mapping, so a slot taken earlier still writes into the same file.
"""

from __future__ import annotations

import os
from pathlib import Path

from prometheus_client.mmap_dict import MmapedDict

#: The files a process writes (``gauge_livesum``: summed over live processes only).
PREFIXES = ("counter", "histogram", "gauge_livesum")


class Slot:
    """One value of a file: ``view[index]`` (float64). ``add`` is one aligned store; the
    caller serialises read-modify-writes of one slot."""

    __slots__ = ("view", "index")

    def __init__(self, view: memoryview, index: int) -> None:
        self.view = view
        self.index = index

    def add(self, amount: float) -> None:
        """Add ``amount`` to the value."""
        self.view[self.index] += amount

    def get(self) -> float:
        """The value now."""
        return self.view[self.index]


class ValueFiles:
    """This process's value files in ``directory``; ``None``: values go nowhere (a process
    that can write no file records nothing, instead of failing its requests).

    :meth:`slot` is not thread-safe (the caller serialises it); :meth:`Slot.add` may run in
    any thread (one store).
    """

    def __init__(self, directory: Path | None) -> None:
        self.directory = directory
        self._dicts: dict[str, MmapedDict] = {}
        self._slots: dict[tuple[str, str], Slot] = {}
        self._views: dict[str, tuple[object, memoryview]] = {}  # prefix → (mapping, view)
        self._scratch = memoryview(bytearray(8)).cast("d")

    def _dict(self, prefix: str) -> MmapedDict:
        found = self._dicts.get(prefix)
        if found is None:
            assert self.directory is not None
            path = self.directory / f"{prefix}_{os.getpid()}.db"
            found = self._dicts[prefix] = MmapedDict(str(path))
        return found

    def slot(self, prefix: str, key: str) -> Slot:
        """The value named ``key`` (:func:`~prometheus_client.mmap_dict.mmap_key`) of the
        ``prefix`` file, created zero on first use (an existing entry keeps its value)."""
        known = self._slots.get((prefix, key))
        if known is not None:
            return known
        if self.directory is None:
            return Slot(self._scratch, 0)
        d = self._dict(prefix)
        d.read_value(key)  # creates the entry (the library's format); may remap the file
        position = d._positions[key]  # byte offset of the value (8-aligned)
        mapping, view = self._views.get(prefix, (None, self._scratch))
        if mapping is not d._m:  # first use, or the file grew and was mapped anew
            mapping, view = d._m, memoryview(d._m).cast("d")
            self._views[prefix] = (mapping, view)
        slot = self._slots[(prefix, key)] = Slot(view, position // 8)
        return slot

    def snapshot(self) -> dict[tuple[str, str], float]:
        """Every value this process created, as it is now: (prefix, key) → value."""
        return {k: s.get() for k, s in self._slots.items()}

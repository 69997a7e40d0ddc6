"""Metric values shared by the worker processes of one service: one memory-mapped file each.

Every worker process keeps its counters in a file of its own, ``<pid>-<start>.db``, in the
service instance's directory (:func:`instance_directory`), mapped into memory: recording a
request is a few stores into the mapping (no system call, no file lock). A scrape, in
whichever worker answers it, reads every file of the directory and sums them, so each
scrape reports the service's total. Files of workers that have died stay in the directory
(uvicorn starts a replacement): their counters are still summed and totals never go down
while the service runs; gauges (requests in flight) are summed over live processes only.

File layout (native byte order)::

    header   uint32 used (bytes in use, header included), uint32 MAGIC
    entry*   uint32 key length, uint32 value count, key (UTF-8 JSON) padded to 8 bytes,
             value count float64

A writer appends an entry (key and zeroed values) before it raises ``used``; values are
8-byte aligned, so a reader sees each value whole (one aligned store) and never an entry
half-written. The file grows by doubling (rarely: 64 KiB hold a few hundred keys).

The directory of a service instance is keyed by the process that owns the workers (the
uvicorn supervisor with ``--workers`` > 1, else the serving process itself): its pid, its
start time and the pid namespace, under ``<tmp>/denavit-metrics-<uid>/``. A restarted
service gets a new directory (Prometheus sees a counter reset, as for any restart); the
directories of services that no longer run are removed when a new one starts.
"""

from __future__ import annotations

import contextlib
import mmap
import multiprocessing
import os
import resource
import shutil
import stat
import struct
import tempfile
from dataclasses import dataclass
from pathlib import Path

MAGIC = 0x314E4544  # b"DEN1"
_HEADER = struct.Struct("=II")
_ENTRY = struct.Struct("=II")
INITIAL_SIZE = 64 * 1024


def _pad8(n: int) -> int:
    return (n + 7) & ~7


# --------------------------------------------------------------------------------------------
# Processes


def _proc_stat(pid: int) -> list[str] | None:
    """Fields of ``/proc/<pid>/stat`` after the command name (state first), or ``None``."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            text = f.read().decode("ascii", "replace")
    except OSError:
        return None
    return text[text.rfind(")") + 2 :].split()


def process_start(pid: int) -> int:
    """Start time of process ``pid`` in clock ticks after boot (0 where /proc is missing)."""
    fields = _proc_stat(pid)
    try:
        return int(fields[19]) if fields else 0
    except (IndexError, ValueError):
        return 0


def pid_namespace() -> int:
    """Identity of this process's pid namespace (0 where it cannot be read)."""
    try:
        return os.stat("/proc/self/ns/pid").st_ino
    except OSError:
        return 0


def process_alive(pid: int, start: int) -> bool:
    """Whether process ``pid`` runs (not a zombie) and, when ``start`` is known, is the one
    that started then (a pid reused by another process is not)."""
    fields = _proc_stat(pid)
    if fields is None:
        if os.path.isdir("/proc/self"):
            return False
        try:
            os.kill(pid, 0)  # no /proc: existence is all that can be checked
        except ProcessLookupError:
            return False
        except PermissionError:
            return True
        return True
    if fields[0] in {"Z", "X"}:
        return False
    return not start or process_start(pid) == start


@dataclass(frozen=True)
class ProcessStats:
    """Resident memory (bytes) and CPU time (s) of a process, read from /proc."""

    resident_bytes: int
    cpu_seconds: float


def process_stats(pid: int) -> ProcessStats | None:
    """Resident memory and CPU time of ``pid`` from /proc (``None`` if unavailable)."""
    fields = _proc_stat(pid)
    try:
        with open(f"/proc/{pid}/statm", "rb") as f:
            pages = int(f.read().split()[1])
        assert fields is not None
        ticks = int(fields[11]) + int(fields[12])  # utime + stime
    except (OSError, ValueError, IndexError, AssertionError):
        return None
    return ProcessStats(pages * os.sysconf("SC_PAGE_SIZE"), ticks / os.sysconf("SC_CLK_TCK"))


def resident_memory_bytes() -> int:
    """Current resident set size of this process (bytes; peak RSS where /proc is missing)."""
    try:
        with open("/proc/self/statm", "rb") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def cpu_seconds() -> float:
    """User and system CPU time of this process (s)."""
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


# --------------------------------------------------------------------------------------------
# Instance directory


def base_directory() -> Path:
    """``<tmp>/denavit-metrics-<uid>``: where the service instances' directories live."""
    uid = os.getuid() if hasattr(os, "getuid") else 0
    return Path(tempfile.gettempdir()) / f"denavit-metrics-{uid}"


def _private_dir(path: Path) -> None:
    """Create ``path`` (mode 0700) or accept it if it is our own real directory."""
    with contextlib.suppress(FileExistsError):
        path.mkdir(mode=0o700)
    st = path.lstat()
    if not stat.S_ISDIR(st.st_mode) or (hasattr(os, "getuid") and st.st_uid != os.getuid()):
        raise OSError(f"{path} is not a directory of this user")


def instance_directory(base: Path | None = None) -> Path:
    """The directory shared by the worker processes of this service instance (created).

    The instance is the process that owns the workers: the parent of a ``multiprocessing``
    child (uvicorn's supervisor with ``--workers`` > 1, or its reloader), else this process.
    Directories of other instances in this pid namespace whose owner has stopped are
    removed.
    """
    base = base or base_directory()
    parent = multiprocessing.parent_process()
    owner = parent.pid if parent is not None and parent.pid is not None else os.getpid()
    ns = pid_namespace()
    _private_dir(base)
    path = base / f"{ns}-{owner}-{process_start(owner)}"
    remove_stale_instances(base, ns, keep=path.name)
    _private_dir(path)
    return path


def remove_stale_instances(base: Path, ns: int, keep: str = "") -> int:
    """Remove the instance directories of ``ns`` whose owner process has stopped."""
    removed = 0
    try:
        names = os.listdir(base)
    except OSError:
        return 0
    for name in names:
        parts = name.split("-")
        if name == keep or len(parts) != 3 or not all(p.isdigit() for p in parts):
            continue
        if int(parts[0]) != ns or process_alive(int(parts[1]), int(parts[2])):
            continue
        shutil.rmtree(base / name, ignore_errors=True)
        removed += 1
    return removed


# --------------------------------------------------------------------------------------------
# Writing


class ValueFile:
    """This process's values: named slots of float64 in a memory-mapped file (an unlinked
    one, private to the process, when ``path`` is ``None``).

    :meth:`slot` is not thread-safe (the caller serialises it). Writing :attr:`values` is
    safe from any thread at any time: when the file grows, :attr:`values` becomes a view of
    a new, larger mapping, and the old mappings stay valid views of the same file, so a
    write through a view fetched earlier is never lost nor refused.
    """

    def __init__(self, path: Path | None = None, size: int = INITIAL_SIZE) -> None:
        self.path = path
        if path is not None:
            flags = os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0)
            self._fd = os.open(path, flags | getattr(os, "O_CLOEXEC", 0), 0o600)
        elif hasattr(os, "memfd_create"):
            self._fd = os.memfd_create("denavit-metrics")
        else:  # pragma: no cover - not Linux
            with tempfile.TemporaryFile() as f:
                self._fd = os.dup(f.fileno())
        os.ftruncate(self._fd, size)
        self._size = size
        self._mm = mmap.mmap(self._fd, size)
        self._retired: list[tuple[mmap.mmap, memoryview]] = []
        self._used = _HEADER.size
        _HEADER.pack_into(self._mm, 0, self._used, MAGIC)
        self.values = memoryview(self._mm).cast("d")
        #: Key → (index of its first value in :attr:`values`, number of values).
        self.slots: dict[str, tuple[int, int]] = {}

    def slot(self, key: str, count: int = 1) -> int:
        """Index in :attr:`values` of the first of ``count`` values named ``key`` (created,
        zero, on first use; the same ``count`` must be given every time)."""
        known = self.slots.get(key)
        if known is not None:
            return known[0]
        raw = key.encode()
        start = self._used
        values_at = start + _ENTRY.size + _pad8(len(raw))
        end = values_at + 8 * count
        if end > self._size:
            self._grow(max(2 * self._size, _pad8(end)))
        mm = self._mm
        _ENTRY.pack_into(mm, start, len(raw), count)
        mm[start + _ENTRY.size : start + _ENTRY.size + len(raw)] = raw
        # The values are zero already (a file extended by ftruncate reads as zeros).
        self._used = end
        _HEADER.pack_into(mm, 0, end, MAGIC)  # publish the entry: readers stop at `used`
        self.slots[key] = (values_at // 8, count)
        return values_at // 8

    def _grow(self, size: int) -> None:
        os.ftruncate(self._fd, size)
        new = mmap.mmap(self._fd, size)
        self._retired.append((self._mm, self.values))
        self._mm, self._size = new, size
        self.values = memoryview(new).cast("d")

    def snapshot(self) -> dict[str, list[float]]:
        """Every key with its values (this process's, as they are now)."""
        return {key: self.values[i : i + n].tolist() for key, (i, n) in self.slots.items()}


# --------------------------------------------------------------------------------------------
# Reading


def read_values(path: Path) -> dict[str, list[float]]:
    """Every entry of a value file, as another process sees it now ({} if unreadable)."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_CLOEXEC", 0))
    except OSError:
        return {}
    try:
        for _ in range(5):  # the file may grow between fstat and reading `used`
            size = os.fstat(fd).st_size
            if size < _HEADER.size:
                return {}
            with mmap.mmap(fd, size, access=mmap.ACCESS_READ) as mm:
                used, magic = _HEADER.unpack_from(mm, 0)
                if magic != MAGIC:
                    return {}
                if used > size:
                    continue
                return _parse(mm, used)
        return {}
    except (OSError, ValueError):
        return {}
    finally:
        os.close(fd)


def _parse(mm: mmap.mmap, used: int) -> dict[str, list[float]]:
    out: dict[str, list[float]] = {}
    pos = _HEADER.size
    with memoryview(mm) as view:
        while pos + _ENTRY.size <= used:
            klen, count = _ENTRY.unpack_from(mm, pos)
            key_at = pos + _ENTRY.size
            values_at = key_at + _pad8(klen)
            end = values_at + 8 * count
            if end > used:
                break
            key = bytes(view[key_at : key_at + klen]).decode("utf-8", "replace")
            with view[values_at:end] as raw, raw.cast("d") as values:
                out[key] = values.tolist()
            pos = end
    return out


@dataclass(frozen=True)
class ProcessValues:
    """One worker's value file as read by a scrape."""

    pid: int
    start: int
    alive: bool
    values: dict[str, list[float]]


def read_directory(directory: Path) -> list[ProcessValues]:
    """Every worker file of an instance directory, with whether its process still runs."""
    out = []
    try:
        names = sorted(os.listdir(directory))
    except OSError:
        return out
    for name in names:
        stem, dot, ext = name.partition(".")
        parts = stem.split("-")
        if ext != "db" or not dot or len(parts) != 2 or not all(p.isdigit() for p in parts):
            continue
        pid, start = int(parts[0]), int(parts[1])
        alive = process_alive(pid, start)
        out.append(ProcessValues(pid, start, alive, read_values(directory / name)))
    return out


def process_lines(live: list[ProcessValues], start_key: str) -> list[str]:
    """``process_*`` metrics of each live worker, labelled by ``pid`` (its start time is
    the value ``start_key`` of its file)."""
    memory, cpu, start = [], [], []
    for proc in sorted(live, key=lambda p: p.pid):
        if proc.pid == os.getpid():
            stats: ProcessStats | None = ProcessStats(resident_memory_bytes(), cpu_seconds())
        else:
            stats = process_stats(proc.pid)
        label = f'{{pid="{proc.pid}"}}'
        if stats is not None:
            memory.append(f"process_resident_memory_bytes{label} {stats.resident_bytes}")
            cpu.append(f"process_cpu_seconds_total{label} {stats.cpu_seconds!r}")
        started = proc.values.get(start_key)
        if started:
            start.append(f"process_start_time_seconds{label} {started[0]!r}")
    return [
        "# HELP process_resident_memory_bytes Resident memory size in bytes, per worker.",
        "# TYPE process_resident_memory_bytes gauge",
        *memory,
        "# HELP process_cpu_seconds_total User and system CPU time spent in seconds, per worker.",
        "# TYPE process_cpu_seconds_total counter",
        *cpu,
        "# HELP process_start_time_seconds Start time of the process (Unix time, s), per worker.",
        "# TYPE process_start_time_seconds gauge",
        *start,
    ]

"""The worker processes of one service, as its metrics see them: where they keep their files,
which of them still run, and their ``process_*`` metrics.

Every worker process of a service instance writes its values into prometheus_client's
multiprocess files (``counter_<pid>.db``, ``histogram_<pid>.db``, ``gauge_livesum_<pid>.db``;
:mod:`app.operations.metrics_files`) in one directory, the instance directory
(:func:`instance_directory`): ``PROMETHEUS_MULTIPROC_DIR`` of the library. A scrape sums
them with :class:`prometheus_client.multiprocess.MultiProcessCollector`. Besides, each worker
leaves a marker ``<pid>-<start>.worker`` (:func:`register_worker`; ``start`` is its start
time in clock ticks after boot), so that a scrape knows every worker that ever recorded,
tells a live worker from a dead one whose pid was reused, and calls the library's
:func:`~prometheus_client.multiprocess.mark_process_dead` for the dead ones (their
``livesum`` gauge files go; their counters stay in the sums).

The instance directory is keyed by the process that owns the workers (the uvicorn
supervisor with ``--workers`` > 1, else the serving process itself): its pid, its start
time and the pid namespace, under ``$PROMETHEUS_MULTIPROC_DIR`` when it is set, else under
``<tmp>/denavit-metrics-<uid>/``. A restarted service gets a new, empty directory
(Prometheus sees a counter reset, as for any restart); the directories of services that
no longer run are removed when a new one starts.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import shutil
import stat
import tempfile
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from prometheus_client.metrics_core import CounterMetricFamily, GaugeMetricFamily, Metric
from prometheus_client.multiprocess import mark_process_dead
from prometheus_client.process_collector import ProcessCollector

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


# --------------------------------------------------------------------------------------------
# Instance directory


def base_directory() -> Path:
    """Where the service instances' directories live: ``$PROMETHEUS_MULTIPROC_DIR`` when it
    is set (the library's variable: a tmpfs is best), else ``<tmp>/denavit-metrics-<uid>``."""
    configured = os.environ.get("PROMETHEUS_MULTIPROC_DIR")
    if configured:
        return Path(configured)
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
    removed, so a new instance starts from an empty directory.
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
# Workers of an instance


@dataclass(frozen=True)
class Worker:
    """A process that recorded into an instance directory (its marker file)."""

    pid: int
    start: int
    alive: bool


def register_worker(directory: Path) -> None:
    """Leave this process's marker in ``directory`` and drop the ``live*`` gauge files a
    dead process with the same pid may have left (they would be read as this process's)."""
    pid = os.getpid()
    mark_process_dead(pid, str(directory))
    (directory / f"{pid}-{process_start(pid)}.worker").touch()


def workers(directory: Path) -> list[Worker]:
    """Every worker that registered in ``directory``, by pid, with whether it still runs."""
    out = []
    try:
        names = sorted(os.listdir(directory))
    except OSError:
        return out
    for name in names:
        stem, dot, ext = name.partition(".")
        parts = stem.split("-")
        if ext != "worker" or not dot or len(parts) != 2 or not all(p.isdigit() for p in parts):
            continue
        pid, start = int(parts[0]), int(parts[1])
        out.append(Worker(pid, start, process_alive(pid, start)))
    return out


def mark_dead_workers(directory: Path, found: Iterable[Worker]) -> None:
    """prometheus_client's ``mark_process_dead`` for each dead worker (its ``livesum``
    gauges leave the sums; counters stay), unless a live worker now has its pid."""
    found = list(found)
    live = {w.pid for w in found if w.alive}
    for w in found:
        if not w.alive and w.pid not in live:
            mark_process_dead(w.pid, str(directory))


class WorkersCollector:
    """A prometheus_client collector: the workers summed in a scrape, the one answering it,
    and resident memory, CPU time and start time of each live worker (``pid`` label; read
    from /proc by the library's :class:`~prometheus_client.process_collector.ProcessCollector`).

    Parameters
    ----------
    found
        The instance's workers (:func:`workers`); this process is added if it is missing
        (metrics not shared).
    """

    def __init__(self, found: list[Worker]) -> None:
        me = os.getpid()
        if not any(w.pid == me and w.alive for w in found):
            found = [*found, Worker(me, process_start(me), True)]
        self.found = found

    def collect(self) -> Iterable[Metric]:
        live = sorted((w for w in self.found if w.alive), key=lambda w: w.pid)
        workers = GaugeMetricFamily(
            "denavit_worker_processes",
            "Worker processes whose counters are summed here.",
            labels=["state"],
        )
        workers.add_metric(["live"], len(live))
        workers.add_metric(["exited"], len(self.found) - len(live))
        info = GaugeMetricFamily(
            "denavit_process_info", "The worker process answering this scrape.", labels=["pid"]
        )
        info.add_metric([str(os.getpid())], 1)
        memory = GaugeMetricFamily(
            "process_resident_memory_bytes",
            "Resident memory size in bytes, per worker.",
            labels=["pid"],
        )
        cpu = CounterMetricFamily(
            "process_cpu_seconds_total",
            "User and system CPU time spent in seconds, per worker.",
            labels=["pid"],
        )
        start = GaugeMetricFamily(
            "process_start_time_seconds",
            "Start time of the process (Unix time, s), per worker.",
            labels=["pid"],
        )
        families = {
            "process_resident_memory_bytes": memory,
            "process_cpu_seconds": cpu,
            "process_start_time_seconds": start,
        }
        for w in live:
            process = ProcessCollector(pid=lambda pid=w.pid: pid, registry=None)
            for family in process.collect():
                ours = families.get(family.name)
                if ours is not None and family.samples:
                    ours.add_metric([str(w.pid)], family.samples[0].value)
        return [workers, info, memory, cpu, start]

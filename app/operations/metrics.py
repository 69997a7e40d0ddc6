"""Prometheus metrics of the service, summed over its worker processes by prometheus_client.

``GET /metrics`` (Prometheus text format 0.0.4) renders :data:`METRICS`: request counts by
method, route template and status, latency histograms by method and route template,
requests in flight, IK outcomes (:func:`record_ik`), and per worker (``pid`` label)
resident memory, CPU time and start time.

The service runs prometheus_client's multiprocess mode: each worker process writes its
values into the library's per-process files (``counter_<pid>.db``, ...) in the service
instance's directory (``PROMETHEUS_MULTIPROC_DIR`` of the library;
:func:`~app.operations.metrics_workers.instance_directory`, shared when the application
starts, on the ASGI lifespan), and every scrape, whichever worker answers it, sums the files
of all the workers with :class:`~prometheus_client.multiprocess.MultiProcessCollector`,
dead workers included, so totals never go down while the service runs. The requests in
flight are a ``livesum`` gauge: a dead worker's leave the sum
(:func:`~prometheus_client.multiprocess.mark_process_dead`, called by the scrape). The text
is the library's :func:`~prometheus_client.exposition.generate_latest`.

Recording does not go through the library's ``Counter``/``Histogram`` objects, which cost
about 7 µs more per request in multiprocess mode, but writes the same files directly
(:mod:`app.operations.metrics_files`): a few float64 stores under a lock, no system call.
"""

from __future__ import annotations

import logging
import os
import shutil
import tempfile
import threading
import weakref
from bisect import bisect_left
from pathlib import Path

from prometheus_client import CollectorRegistry, generate_latest
from prometheus_client.mmap_dict import mmap_key
from prometheus_client.multiprocess import MultiProcessCollector
from prometheus_client.utils import floatToGoString

from app.operations.metrics_files import Slot, ValueFiles
from app.operations.metrics_workers import (
    WorkersCollector,
    instance_directory,
    mark_dead_workers,
    register_worker,
    workers,
)

#: Upper bounds (s) of the latency histogram buckets (``+Inf`` is implicit).
LATENCY_BUCKETS: tuple[float, ...] = (
    0.0005,
    0.001,
    0.0025,
    0.005,
    0.01,
    0.025,
    0.05,
    0.1,
    0.25,
    0.5,
    1.0,
    2.5,
    5.0,
    10.0,
    30.0,
)

# The families: (metric name, help); the names and help texts are part of the files' keys.
REQUESTS = ("denavit_http_requests", "HTTP requests by method, route template, status.")
LATENCY = ("denavit_http_request_duration_seconds", "HTTP request latency (s).")
IN_FLIGHT = ("denavit_http_requests_in_flight", "HTTP requests being handled (live workers).")
IK = ("denavit_ik_requests", "IK solves by outcome.")

_LE = [floatToGoString(b) for b in (*LATENCY_BUCKETS, float("inf"))]
_log = logging.getLogger("denavit")


class _RouteStats:
    """The slots of one (method, route template): its latency buckets (not cumulative; the
    scrape accumulates them), its latency sum, and a count per status."""

    __slots__ = ("buckets", "sum", "statuses")

    def __init__(self, buckets: list[Slot], total: Slot) -> None:
        self.buckets = buckets
        self.sum = total
        self.statuses: dict[int, Slot] = {}


class Metrics:
    """Request counters and latency histograms, rendered as Prometheus text.

    Values live in prometheus_client's multiprocess files
    (:class:`~app.operations.metrics_files.ValueFiles`): of a private temporary directory
    (made on first use) until :meth:`share`, then of the service instance's directory,
    which a scrape sums over every worker process (dead ones included for counters, live
    ones only for the requests in flight).
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._files: ValueFiles | None = None
        self._private: weakref.finalize | None = None
        self._directory: Path | None = None
        self._routes: dict[tuple[str, str], _RouteStats] = {}
        self._in_flight: Slot | None = None
        self._ik: dict[bool, Slot] = {}
        self._pid = os.getpid()
        _AT_FORK.add(self)

    @property
    def directory(self) -> Path | None:
        """The instance directory the values are shared in (``None``: process-local)."""
        return self._directory

    def share(self, directory: Path | None = None) -> Path:
        """Keep this process's values in the instance directory from now on (default:
        :func:`~app.operations.metrics_workers.instance_directory`), so that a scrape in any
        worker of the instance sums them. Values recorded so far are carried over.
        Idempotent; raises ``OSError`` when the directory or a file cannot be made. One
        object per process may share a directory (the files are named by pid)."""
        with self._lock:
            if self._directory is not None:
                return self._directory
            directory = directory or instance_directory()
            register_worker(directory)
            new = ValueFiles(directory)
            if self._files is not None:
                for (prefix, key), value in self._files.snapshot().items():
                    new.slot(prefix, key).add(value)
            self._use(new)
            self._directory = directory
            if self._private is not None:
                self._private()  # the private directory is not needed any more
                self._private = None
            return directory

    def _use(self, files: ValueFiles) -> None:
        """Record into ``files`` from now on (lock held)."""
        self._files = files
        self._routes = {}
        self._ik = {ok: files.slot("counter", _ik_key(ok)) for ok in (True, False)}
        self._in_flight = files.slot("gauge_livesum", _IN_FLIGHT_KEY)

    def _open(self) -> ValueFiles:
        """The files recorded into: a private directory's until :meth:`share`."""
        files = self._files
        if files is not None:
            return files
        with self._lock:
            if self._files is None:
                try:
                    private = tempfile.mkdtemp(prefix="denavit-metrics-local-")
                except OSError as exc:
                    _log.warning("metrics are not recorded: no temporary directory (%s)", exc)
                    self._use(ValueFiles(None))
                else:
                    self._private = weakref.finalize(self, shutil.rmtree, private, True)
                    self._use(ValueFiles(Path(private)))
            assert self._files is not None
            return self._files

    def _after_fork(self) -> None:
        """In a forked child: stop writing into the parent's files. The child's values go
        nowhere (no file: a child that leaves by ``os._exit`` would leave it behind); the
        service's children (batch IK, reachability builds) record nothing."""
        self._lock = threading.Lock()
        if os.getpid() != self._pid:
            if self._private is not None:
                self._private.detach()  # the parent's directory: not the child's to remove
                self._private = None
            self._directory = None
            self._use(ValueFiles(None))
        self._pid = os.getpid()

    def enter(self) -> None:
        """One more request in flight (no lock: called on the event loop thread, like
        :meth:`finish`; one store)."""
        slot = self._in_flight
        if slot is None:
            self._open()
            slot = self._in_flight
            assert slot is not None
        slot.view[slot.index] += 1.0

    def finish(self, method: str, route: str, status: int, seconds: float) -> None:
        """A request leaves flight: one less in flight, and :meth:`observe` it."""
        files = self._files or self._open()
        with self._lock:
            slot = self._in_flight
            assert slot is not None
            slot.view[slot.index] -= 1.0
            self._observe(files, method, route, status, seconds)

    def observe(self, method: str, route: str, status: int, seconds: float) -> None:
        """Count one request of ``route`` (a path template) that took ``seconds``."""
        files = self._files or self._open()
        with self._lock:
            self._observe(files, method, route, status, seconds)

    def _observe(
        self, files: ValueFiles, method: str, route: str, status: int, seconds: float
    ) -> None:
        if files is not self._files:  # shared meanwhile
            files = self._files
            assert files is not None
        stats = self._routes.get((method, route))
        if stats is None:
            stats = self._routes[(method, route)] = _RouteStats(
                [files.slot("histogram", k) for k in _bucket_keys(method, route)],
                files.slot("histogram", _sum_key(method, route)),
            )
        slot = stats.statuses.get(status)
        if slot is None:
            key = _status_key(method, route, status)
            slot = stats.statuses[status] = files.slot("counter", key)
        slot.view[slot.index] += 1.0
        slot = stats.buckets[bisect_left(LATENCY_BUCKETS, seconds)]
        slot.view[slot.index] += 1.0
        slot = stats.sum
        slot.view[slot.index] += seconds

    def record_ik(self, success: bool) -> None:
        """Count one IK solve by outcome."""
        self._open()
        with self._lock:
            self._ik[bool(success)].add(1.0)

    def render(self) -> bytes:
        """The Prometheus text exposition (format 0.0.4) of the instance's worker processes:
        their files summed by ``MultiProcessCollector``, and the workers themselves
        (:class:`~app.operations.metrics_workers.WorkersCollector`)."""
        files = self._open()
        registry = CollectorRegistry(auto_describe=False)
        found = []
        if self._directory is not None:
            found = workers(self._directory)
            mark_dead_workers(self._directory, found)
        if files.directory is not None and files.directory.is_dir():  # (removed by hand?)
            MultiProcessCollector(registry, path=str(files.directory))
        registry.register(WorkersCollector(found))
        return generate_latest(registry)


def _status_key(method: str, route: str, status: int) -> str:
    name, help_text = REQUESTS
    labels = ["method", "route", "status"]
    return mmap_key(name, name + "_total", labels, [method, route, str(status)], help_text)


def _bucket_keys(method: str, route: str) -> list[str]:
    name, help_text = LATENCY
    labels = ["method", "route", "le"]
    return [mmap_key(name, name + "_bucket", labels, [method, route, le], help_text) for le in _LE]


def _sum_key(method: str, route: str) -> str:
    name, help_text = LATENCY
    return mmap_key(name, name + "_sum", ["method", "route"], [method, route], help_text)


def _ik_key(success: bool) -> str:
    name, help_text = IK
    result = "success" if success else "failure"
    return mmap_key(name, name + "_total", ["result"], [result], help_text)


_IN_FLIGHT_KEY = mmap_key(IN_FLIGHT[0], IN_FLIGHT[0], [], [], IN_FLIGHT[1])


class _ForkHooks:
    """Metrics objects to detach from their parent's files in a forked child."""

    def __init__(self) -> None:
        self._refs: list[weakref.ref[Metrics]] = []
        if hasattr(os, "register_at_fork"):
            os.register_at_fork(after_in_child=self._after_fork)

    def add(self, metrics: Metrics) -> None:
        self._refs = [r for r in self._refs if r() is not None]
        self._refs.append(weakref.ref(metrics))

    def _after_fork(self) -> None:
        for ref in self._refs:
            metrics = ref()
            if metrics is not None:
                metrics._after_fork()


_AT_FORK = _ForkHooks()

#: The process's metrics (every app in the process shares them).
METRICS = Metrics()


def record_ik(success: bool) -> None:
    """Count one IK solve (``success``: a solution within tolerance was found).

    Thread-safe: call it from the route or from the work pool.
    """
    METRICS.record_ik(success)

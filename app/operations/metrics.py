"""Prometheus metrics of the service, summed over its worker processes.

``GET /metrics`` (Prometheus text format 0.0.4) renders :data:`METRICS`: request counts by
method, route template and status, latency histograms by method and route template,
requests in flight, IK outcomes (:func:`record_ik`), and per worker (``pid`` label)
resident memory and CPU time. Each worker records into a memory-mapped file of its own,
shared by the service's workers (:mod:`app.operations.metrics_shm`; set up when the application
starts, on the ASGI lifespan): every scrape, whichever worker answers it, sums the counters
of all the workers, including workers that have died, so totals never go down while the
service runs. Updates are a few memory-mapped values under a lock (no system call).
"""

from __future__ import annotations

import os
import threading
import time
import weakref
from bisect import bisect_left
from pathlib import Path
from typing import Any

import orjson

from app.operations.metrics_shm import (
    ProcessValues,
    ValueFile,
    instance_directory,
    process_lines,
    process_start,
    read_directory,
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


_NB = len(LATENCY_BUCKETS) + 1  # histogram buckets, +Inf included
_IN_FLIGHT = orjson.dumps(["g", "in_flight"]).decode()
_START = orjson.dumps(["g", "start"]).decode()
_IK = {ok: orjson.dumps(["ik", "success" if ok else "failure"]).decode() for ok in (True, False)}


class _RouteStats:
    """Value indices of one (method, route template): ``base`` .. ``base + _NB - 1`` the
    latency buckets, ``base + _NB`` the latency sum; ``statuses`` maps status → count."""

    __slots__ = ("method", "route", "base", "statuses")

    def __init__(self, method: str, route: str, base: int) -> None:
        self.method = method
        self.route = route
        self.base = base
        self.statuses: dict[int, int] = {}


class Metrics:
    """Request counters and latency histograms, rendered as Prometheus text.

    Values live in a :class:`~app.operations.metrics_shm.ValueFile`: anonymous memory until
    :meth:`share`, then a memory-mapped file of the service instance's directory, which a
    scrape sums over every worker process (dead ones included for counters, live ones only
    for gauges). Recording is a few stores under a lock, with no system call.
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._file = ValueFile()
        self._routes: dict[tuple[str, str], _RouteStats] = {}
        self._directory: Path | None = None
        self._pid = os.getpid()
        self.started = time.time()
        self._index_fixed()
        self._file.values[self._start] = self.started
        _AT_FORK.add(self)

    def _index_fixed(self) -> None:
        f = self._file
        self._in_flight = f.slot(_IN_FLIGHT)
        self._start = f.slot(_START)
        self._ik = {ok: f.slot(key) for ok, key in _IK.items()}

    @property
    def directory(self) -> Path | None:
        """The instance directory the values are shared in (``None``: process-local)."""
        return self._directory

    def share(self, directory: Path | None = None) -> Path:
        """Keep this process's values in ``<directory>/<pid>-<start>.db`` from now on
        (default directory: :func:`~app.operations.metrics_shm.instance_directory`), so that a
        scrape
        in any worker of the instance sums them. Values recorded so far are carried over.
        Idempotent; raises ``OSError`` when the file cannot be created."""
        with self._lock:
            if self._directory is not None:
                return self._directory
            directory = directory or instance_directory()
            self._switch(ValueFile(directory / f"{os.getpid()}-{process_start(os.getpid())}.db"))
            self._directory = directory
            return directory

    def _switch(self, new: ValueFile) -> None:
        """Copy every value into ``new`` and use it (lock held). The old file is not closed:
        a request entering in another thread meanwhile writes into it harmlessly."""
        old = self._file
        for key, values in old.snapshot().items():
            i = new.slot(key, len(values))
            for k, v in enumerate(values):
                new.values[i + k] = v
        self._file = new
        self._index_fixed()
        for (method, route), stats in self._routes.items():
            stats.base = new.slots[_route_key(method, route)][0]
            for status in stats.statuses:
                stats.statuses[status] = new.slots[_status_key(method, route, status)][0]

    def _after_fork(self) -> None:
        """In a forked child: stop writing into the parent's file (values stay readable)."""
        self._lock = threading.Lock()
        if self._directory is not None and os.getpid() != self._pid:
            self._switch(ValueFile())
            self._directory = None
        self._pid = os.getpid()

    def _route_stats(self, method: str, route: str) -> _RouteStats:
        stats = self._routes[(method, route)] = _RouteStats(
            method, route, self._file.slot(_route_key(method, route), _NB + 1)
        )
        return stats

    def enter(self) -> None:
        """One more request in flight (no lock: called on the event loop thread, like
        :meth:`finish`; writing :attr:`ValueFile.values` is safe from any thread)."""
        self._file.values[self._in_flight] += 1.0

    def finish(self, method: str, route: str, status: int, seconds: float) -> None:
        """A request leaves flight: one less in flight, and :meth:`observe` it."""
        with self._lock:
            self._file.values[self._in_flight] -= 1.0
            self._observe(method, route, status, seconds)

    def observe(self, method: str, route: str, status: int, seconds: float) -> None:
        """Count one request of ``route`` (a path template) that took ``seconds``."""
        with self._lock:
            self._observe(method, route, status, seconds)

    def _observe(self, method: str, route: str, status: int, seconds: float) -> None:
        stats = self._routes.get((method, route)) or self._route_stats(method, route)
        i = stats.statuses.get(status)
        if i is None:
            i = stats.statuses[status] = self._file.slot(_status_key(method, route, status))
        values = self._file.values
        values[i] += 1.0
        values[stats.base + bisect_left(LATENCY_BUCKETS, seconds)] += 1.0
        values[stats.base + _NB] += seconds

    def record_ik(self, success: bool) -> None:
        """Count one IK solve by outcome."""
        with self._lock:
            self._file.values[self._ik[bool(success)]] += 1.0

    def _processes(self) -> list[ProcessValues]:
        directory = self._directory
        procs = [] if directory is None else read_directory(directory)
        if not any(p.pid == os.getpid() for p in procs):  # process-local, or file removed
            with self._lock:
                procs.append(ProcessValues(os.getpid(), 0, True, self._file.snapshot()))
        return procs

    def render(self) -> bytes:
        """The Prometheus text exposition (format 0.0.4), summed over the instance's
        worker processes (see :mod:`app.operations.metrics_shm`)."""
        procs = self._processes()
        totals: dict[tuple[Any, ...], list[float]] = {}
        in_flight = 0.0
        for proc in procs:
            for key, values in proc.values.items():
                parsed = tuple(orjson.loads(key))
                if parsed[0] == "g":
                    if parsed == ("g", "in_flight") and proc.alive:
                        in_flight += values[0]
                    continue
                total = totals.get(parsed)
                if total is None:
                    totals[parsed] = list(values)
                elif len(total) == len(values):
                    totals[parsed] = [a + b for a, b in zip(total, values, strict=True)]
        out: list[str] = [
            "# HELP denavit_http_requests_total HTTP requests by method, route template, status.",
            "# TYPE denavit_http_requests_total counter",
        ]
        for key in sorted(k for k in totals if k[0] == "s"):
            _, method, route, status = key
            labels = _labels(method=method, route=route, status=str(status))
            out.append(f"denavit_http_requests_total{labels} {int(totals[key][0])}")
        out += [
            "# HELP denavit_http_request_duration_seconds HTTP request latency (s).",
            "# TYPE denavit_http_request_duration_seconds histogram",
        ]
        for key in sorted(k for k in totals if k[0] == "h"):
            _, method, route = key
            values = totals[key]
            if len(values) != _NB + 1:
                continue
            cumulative = 0
            for bound, n in zip((*LATENCY_BUCKETS, float("inf")), values, strict=False):
                cumulative += int(n)
                le = "+Inf" if bound == float("inf") else repr(bound)
                labels = _labels(method=method, route=route, le=le)
                out.append(f"denavit_http_request_duration_seconds_bucket{labels} {cumulative}")
            labels = _labels(method=method, route=route)
            out.append(f"denavit_http_request_duration_seconds_sum{labels} {values[_NB]!r}")
            out.append(f"denavit_http_request_duration_seconds_count{labels} {cumulative}")
        ik = {r: int(totals.get(("ik", r), [0.0])[0]) for r in ("success", "failure")}
        live = [p for p in procs if p.alive]
        out += [
            "# HELP denavit_http_requests_in_flight HTTP requests being handled (live workers).",
            "# TYPE denavit_http_requests_in_flight gauge",
            f"denavit_http_requests_in_flight {int(in_flight)}",
            "# HELP denavit_ik_requests_total IK solves by outcome.",
            "# TYPE denavit_ik_requests_total counter",
            f'denavit_ik_requests_total{{result="success"}} {ik["success"]}',
            f'denavit_ik_requests_total{{result="failure"}} {ik["failure"]}',
            "# HELP denavit_worker_processes Worker processes whose counters are summed here.",
            "# TYPE denavit_worker_processes gauge",
            f'denavit_worker_processes{{state="live"}} {len(live)}',
            f'denavit_worker_processes{{state="exited"}} {len(procs) - len(live)}',
            "# HELP denavit_process_info The worker process answering this scrape.",
            "# TYPE denavit_process_info gauge",
            f'denavit_process_info{{pid="{os.getpid()}"}} 1',
        ]
        out += process_lines(live, _START)
        return ("\n".join(out) + "\n").encode()


def _route_key(method: str, route: str) -> str:
    return orjson.dumps(["h", method, route]).decode()


def _status_key(method: str, route: str, status: int) -> str:
    return orjson.dumps(["s", method, route, status]).decode()


def _escape(value: str) -> str:
    return value.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")


def _labels(**labels: str) -> str:
    return "{" + ",".join(f'{k}="{_escape(v)}"' for k, v in labels.items()) + "}"


class _ForkHooks:
    """Metrics objects to detach from their parent's file in a forked child."""

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

"""/metrics sums the counters of every worker process of the service (prometheus_client's
multiprocess files, app.operations.metrics_files and metrics_workers): a live 2-worker
server, where every scrape must report the service's totals, whichever worker answers, and
never less than before (a killed worker's counters included); and the files themselves,
written here and read by the library."""

from __future__ import annotations

import asyncio
import os
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import httpx
from prometheus_client.mmap_dict import MmapedDict

from app.middleware.observability import ObservabilityMiddleware
from app.operations.metrics import Metrics
from app.operations.metrics_files import ValueFiles
from app.operations.metrics_workers import (
    instance_directory,
    mark_dead_workers,
    pid_namespace,
    process_start,
    register_worker,
    remove_stale_instances,
    workers,
)
from tests.helpers import ROOT, parse_metrics, serve

ROBOTS_200 = 'denavit_http_requests_total{method="GET",route="/robots",status="200"}'
ROBOTS_COUNT = 'denavit_http_request_duration_seconds_count{method="GET",route="/robots"}'
SCRAPES_200 = 'denavit_http_requests_total{method="GET",route="/metrics",status="200"}'


def scrape(url: str) -> tuple[int, dict[str, float]]:
    """One scrape on a new connection: (pid of the answering worker, samples)."""
    with httpx.Client(timeout=30) as client:
        r = client.get(url + "/metrics")
    assert r.status_code == 200, r.text
    samples = parse_metrics(r.text)
    pids = [k for k in samples if k.startswith("denavit_process_info{")]
    assert len(pids) == 1, pids
    return int(pids[0].split('"')[1]), samples


def counters(samples: dict[str, float]) -> dict[str, float]:
    """The samples of counter and histogram families (which must never decrease)."""
    return {
        k: v
        for k, v in samples.items()
        if k.startswith(("denavit_http_request", "denavit_ik_requests_total"))
        and not k.startswith("denavit_http_requests_in_flight")
    }


def assert_not_decreasing(before: dict[str, float], after: dict[str, float]) -> None:
    went_down = {k: (v, after.get(k, 0.0)) for k, v in before.items() if after.get(k, 0.0) < v}
    assert not went_down, went_down


def scrape_thread(url: str, n: int) -> list[tuple[int, dict[str, float]]]:
    """``n`` scrapes one after another, each on a new connection; every scrape must count
    the scrapes this thread completed before it and no counter may go down."""
    seen: list[tuple[int, dict[str, float]]] = []
    for i in range(n):
        pid, samples = scrape(url)
        assert samples.get(SCRAPES_200, 0) >= i  # earlier scrapes of this thread, at least
        if seen:
            assert_not_decreasing(counters(seen[-1][1]), counters(samples))
        seen.append((pid, samples))
    return seen


def test_every_scrape_of_two_workers_reports_the_service_total(tmp_path) -> None:
    n = 60
    with serve(tmp_path / "data", "--workers", "2") as server:
        url = server.url
        with ThreadPoolExecutor(max_workers=4) as pool:
            # new connections: the kernel hands them to both workers
            codes = list(pool.map(lambda _: httpx.get(url + "/robots", timeout=30), range(n)))
            assert [c.status_code for c in codes] == [200] * n
            runs = list(pool.map(lambda _: scrape_thread(url, 25), range(4)))
        answered = {pid for run in runs for pid, _ in run}
        for _ in range(400):  # both workers must have answered (new connections, bounded)
            if len(answered) == 2:
                break
            answered.add(scrape(url)[0])
        assert len(answered) == 2, answered
        for run in runs:
            for pid, samples in run:
                assert samples[ROBOTS_200] == n, (pid, samples[ROBOTS_200])
                assert samples[ROBOTS_COUNT] == n
                assert samples['denavit_worker_processes{state="live"}'] >= 1
                assert samples["denavit_http_requests_in_flight"] >= 1  # this scrape

        # A killed worker's counters stay in the totals; the supervisor replaces it.
        high = {}
        for run in runs:
            for _, samples in run:
                high = {k: max(v, high.get(k, 0.0)) for k, v in counters(samples).items()}
        victim = next(iter(answered))
        os.kill(victim, signal.SIGKILL)
        end = time.monotonic() + 120
        while True:
            pid, samples = scrape(url)
            assert_not_decreasing(high, counters(samples))
            assert samples[ROBOTS_200] == n
            replaced = samples['denavit_worker_processes{state="live"}'] == 2
            if replaced and samples['denavit_worker_processes{state="exited"}'] >= 1:
                break
            assert time.monotonic() < end, "the killed worker was not replaced"
            time.sleep(0.1)
        for run in [scrape_thread(url, 10)]:
            for pid, samples in run:
                assert pid != victim
                assert samples[ROBOTS_200] == n
                assert_not_decreasing(high, counters(samples))


# ---------------------------------------------------------------------------------------------
# In process


def _reaped_pid() -> int:
    """The pid of a process that has exited and been reaped."""
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_a_request_is_counted_before_its_last_byte_is_sent() -> None:
    """A client that has the whole response can scrape at once (on another worker) and
    must find its request counted."""
    metrics = Metrics()
    seen: list[int] = []

    class Route:
        path = "/r"

    async def app(scope: dict[str, Any], receive: Any, send: Any) -> None:
        scope["route"] = Route()
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": b"a", "more_body": True})
        await send({"type": "http.response.body", "body": b"b"})

    async def send(message: dict[str, Any]) -> None:
        if message["type"] == "http.response.body":
            text = metrics.render().decode()
            key = 'denavit_http_requests_total{method="GET",route="/r",status="200"}'
            seen.append(int(parse_metrics(text).get(key, 0)))

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": b""}

    scope = {"type": "http", "method": "GET", "path": "/r", "headers": []}
    middleware = ObservabilityMiddleware(app, access_log=False, metrics=metrics)
    asyncio.run(middleware(scope, receive, send))
    assert seen == [0, 1]  # not after the first part, before the last one


def _values(path: Path) -> dict[str, float]:
    """Key → value of one value file, read by prometheus_client's own reader."""
    return {k: v for k, v, _, _ in MmapedDict.read_all_values_from_file(str(path))}


def test_values_written_here_are_read_by_the_library_also_after_the_file_grows(
    tmp_path,
) -> None:
    files = ValueFiles(tmp_path)
    early = files.slot("counter", '["first"]')  # a slot taken before the file grows
    keys = [f'["key", {i}, "{"x" * 60}"]' for i in range(20_000)]  # > 1 MiB of entries
    for i, key in enumerate(keys):
        files.slot("counter", key).add(float(i))
    path = tmp_path / f"counter_{os.getpid()}.db"
    assert path.stat().st_size > 1 << 20  # the library's initial size: it grew
    early.add(7.0)  # writes through a view of the first mapping land in the same file
    got = _values(path)
    assert got['["first"]'] == 7.0
    assert [got[k] for k in keys] == [float(i) for i in range(20_000)]
    assert files.snapshot() == {("counter", k): v for k, v in got.items()}


_DEAD_WORKER = """
import sys
from pathlib import Path
from app.operations.metrics import Metrics
m = Metrics()
m.share(Path(sys.argv[1]))
for _ in range(4):
    m.observe("GET", "/x", 200, 0.002)
m.observe("GET", "/x", 500, 0.002)
m.record_ik(True)
m.record_ik(True)
for _ in range(3):
    m.enter()  # it dies with 3 requests in flight
"""


def test_scrape_sums_live_and_dead_workers_but_gauges_only_live(tmp_path) -> None:
    dead = subprocess.run([sys.executable, "-c", _DEAD_WORKER, str(tmp_path)], cwd=ROOT)
    assert dead.returncode == 0  # it has exited and been reaped
    dead_pid = next(w.pid for w in workers(tmp_path))
    me = Metrics()
    me.share(tmp_path)
    me.observe("GET", "/x", 200, 0.002)
    me.record_ik(True)
    me.enter()
    samples = parse_metrics(me.render().decode())
    assert samples['denavit_http_requests_total{method="GET",route="/x",status="200"}'] == 5
    assert samples['denavit_http_requests_total{method="GET",route="/x",status="500"}'] == 1
    assert samples['denavit_http_request_duration_seconds_count{method="GET",route="/x"}'] == 6
    assert samples['denavit_ik_requests_total{result="success"}'] == 3
    assert samples["denavit_http_requests_in_flight"] == 1
    assert samples['denavit_worker_processes{state="live"}'] == 1
    assert samples['denavit_worker_processes{state="exited"}'] == 1
    assert f'process_resident_memory_bytes{{pid="{os.getpid()}"}}' in samples
    assert not any(f'pid="{dead_pid}"' in k for k in samples)
    assert {w.alive for w in workers(tmp_path)} == {True, False}


def test_a_dead_workers_pid_reused_by_a_live_one_keeps_the_live_ones_gauge(tmp_path) -> None:
    """Markers carry the start time: the dead process that had this pid is told apart from
    this one, and marking it dead must not drop this process's requests in flight."""
    me = Metrics()
    me.share(tmp_path)
    (tmp_path / f"{os.getpid()}-12345.worker").touch()  # an earlier process with this pid
    me.enter()
    found = workers(tmp_path)
    assert sorted(w.alive for w in found) == [False, True]
    mark_dead_workers(tmp_path, found)
    samples = parse_metrics(me.render().decode())
    assert samples["denavit_http_requests_in_flight"] == 1
    assert samples['denavit_worker_processes{state="exited"}'] == 1


def test_a_worker_with_a_dead_ones_pid_starts_with_nothing_in_flight(tmp_path) -> None:
    """A dead process with this pid left 3 requests in flight in its ``livesum`` file: a new
    worker must not count them as its own."""
    stale = MmapedDict(str(tmp_path / f"gauge_livesum_{os.getpid()}.db"))
    key = '["denavit_http_requests_in_flight", "denavit_http_requests_in_flight", {}, '
    key += '"HTTP requests being handled (live workers)."]'
    stale.write_value(key, 3.0, 0.0)
    stale.close()
    register_worker(tmp_path)
    me = Metrics()
    me.share(tmp_path)
    assert parse_metrics(me.render().decode())["denavit_http_requests_in_flight"] == 0


def test_directories_of_stopped_services_are_removed(tmp_path) -> None:
    ns = pid_namespace()
    mine = f"{ns}-{os.getpid()}-{process_start(os.getpid())}"
    stopped = f"{ns}-{_reaped_pid()}-12345"
    other_namespace = f"{ns + 1}-{_reaped_pid()}-12345"
    for name in (mine, stopped, other_namespace, "unrelated"):
        (tmp_path / name).mkdir()
    assert remove_stale_instances(tmp_path, ns) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [mine, other_namespace, "unrelated"]
    )


def test_a_forked_child_does_not_write_into_its_parents_files(tmp_path) -> None:
    me = Metrics()
    me.share(tmp_path)
    me.observe("GET", "/x", 200, 0.002)
    before = sorted(p.name for p in tmp_path.iterdir())
    pid = os.fork()
    if pid == 0:  # the child: count 10 requests, then leave without clean-up
        try:
            for _ in range(10):
                me.enter()
                me.finish("GET", "/x", 200, 0.002)
        finally:
            os._exit(0)
    os.waitpid(pid, 0)
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    got = _values(tmp_path / f"counter_{os.getpid()}.db")
    assert [v for k, v in got.items() if '"/x"' in k] == [1.0]
    samples = parse_metrics(me.render().decode())
    assert samples['denavit_http_requests_total{method="GET",route="/x",status="200"}'] == 1
    assert samples["denavit_http_requests_in_flight"] == 0


def test_the_instance_directory_lives_under_prometheus_multiproc_dir(tmp_path, monkeypatch) -> None:
    """The library's variable names the base; each start of a service gets its own,
    empty, directory in it (named after the owner process: here this one)."""
    monkeypatch.setenv("PROMETHEUS_MULTIPROC_DIR", str(tmp_path / "prom"))
    path = instance_directory()
    assert path.parent == tmp_path / "prom"
    assert path.name == f"{pid_namespace()}-{os.getpid()}-{process_start(os.getpid())}"
    assert list(path.iterdir()) == []

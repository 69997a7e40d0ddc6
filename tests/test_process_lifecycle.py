"""Processes die with their parent: kill -9 of the uvicorn worker that owns a reachability
build, or of the uvicorn supervisor, leaves no process behind (forkserver, build
processes, resource tracker, workers), checked in the process table (/proc)."""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import time

import httpx
import pytest

from tests.helpers import Server, descendants, proc_stat, serve

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="walks /proc for the process tree"
)

BASE = "/robots/planar2/reachability"
#: A build that runs for minutes with a process per core (cancelled or killed long before).
LONG_BUILD = {
    "voxel_size": 0.05,
    "bounds": {"min": [-2, -2, -0.025], "max": [2, 2, 0.025]},
    "orientation_divisions": 0,
    "samples": 500_000_000,
}
#: How long the former descendants may take to go (generous: a loaded machine is slow).
GONE_WITHIN_S = 30.0


def parent(pid: int) -> int:
    """The parent pid of ``pid`` (0 if it does not exist)."""
    stat = proc_stat(pid)
    return stat[1] if stat else 0


def running(pid: int) -> bool:
    """Whether ``pid`` is in the process table and not a zombie (or dead)."""
    stat = proc_stat(pid)
    return stat is not None and stat[0] not in {"Z", "X"}


def cmdline(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            return f.read().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return ""


def start_long_build(server: Server) -> tuple[int, set[int]]:
    """Post :data:`LONG_BUILD`; once its build processes run, the pid of the worker that owns
    the job (the server process, or the worker with a forkserver child whose build processes
    run) and that worker's descendants (forkserver, build processes...)."""
    r = httpx.post(server.url + BASE, json=LONG_BUILD, timeout=30)
    assert r.status_code == 202, r.text
    end = time.monotonic() + 120
    while True:
        tree = {server.proc.pid} | descendants(server.proc.pid)
        for owner in sorted(tree):
            forkservers = [p for p in tree if "forkserver" in cmdline(p) and parent(p) == owner]
            if forkservers and descendants(forkservers[0]):
                return owner, descendants(owner)
        assert time.monotonic() < end, f"the build processes did not start: {tree}"
        time.sleep(0.1)


def wait_gone(pids: set[int]) -> set[int]:
    """Poll until none of ``pids`` runs (or :data:`GONE_WITHIN_S`); the ones still running."""
    end = time.monotonic() + GONE_WITHIN_S
    while (left := {p for p in pids if running(p)}) and time.monotonic() < end:
        time.sleep(0.1)
    return left


def kill_all(pids: set[int]) -> None:
    """Clean up after a failed check: the test must not leave orphans either."""
    for pid in pids:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)


@pytest.mark.parametrize("workers", [1, 2])
def test_killing_the_build_owner_leaves_no_process(tmp_path, workers) -> None:
    data = tmp_path / "data"
    args = ("--workers", "2") if workers == 2 else ()
    with serve(data, *args) as server:
        url, pid = server.url, server.proc.pid
        owner, tree = start_long_build(server)
        assert owner == pid if workers == 1 else owner in descendants(pid)
        os.kill(owner, signal.SIGKILL)
        left = wait_gone(tree)
        kill_all(left)
        assert not left, [(p, cmdline(p)) for p in left]
        if workers == 2:  # the supervisor replaced the worker: the service still answers
            assert httpx.get(url + "/health", timeout=30).status_code == 200


def test_killing_the_supervisor_leaves_no_process(tmp_path) -> None:
    data = tmp_path / "data"
    with serve(data, "--workers", "2") as server:
        master = server.proc.pid
        start_long_build(server)
        tree = descendants(master)
        assert len(tree) >= 4  # 2 workers, a forkserver, build processes
        os.kill(master, signal.SIGKILL)
        left = wait_gone(tree)
        kill_all(left)
        assert not left, [(p, cmdline(p)) for p in left]

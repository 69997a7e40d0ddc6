"""What test modules share: problem answers, live servers, metrics text, the guarded routes.

- :func:`problem`: assert an RFC 9457 problem+json answer (status, field) and return it.
- :func:`free_port` and :func:`serve`: a real server (``uvicorn`` with arguments such as
  ``--workers 2``, or ``python -m app``, the entry of ``make run`` and the image) on a free
  loopback port, stopped by its PID afterwards; :func:`make_app_with_a_bug` is a test-only
  application factory for it (``uvicorn --factory``).
- :func:`poll_live`: GET a live server's job until a condition holds.
- :func:`parse_metrics`: Prometheus text exposition → samples.
- :func:`fk_target`: the wire IK target of a frame at a configuration (FK in the test).
- :func:`write_routes`: the routes guarded by the write token.

Threads that talk to a live server each open their own ``httpx.Client``.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from urllib.parse import urlsplit

import httpx
import numpy as np
import orjson
from fastapi import FastAPI
from fastapi.routing import APIRoute, iter_route_contexts

from app.api.security import require_token
from app.kinematics.fk import forward_kinematics
from app.kinematics.rotations import matrix_to_quaternion
from app.main import create_app

ROOT = Path(__file__).resolve().parents[1]


def problem(resp: httpx.Response, status: int, field: str | None = None) -> dict:
    """Assert an RFC 9457 problem answer with ``status`` (and ``field``); its body.

    The body must have the standard members, its own ``status``, and (when ``field`` is
    given) name the field both in ``field`` and in ``detail``.
    """
    assert resp.status_code == status, resp.text
    assert resp.headers["content-type"].startswith("application/problem+json")
    body = resp.json()
    assert {"type", "title", "status", "detail"} <= body.keys(), body
    assert body["status"] == status, body
    if field is not None:
        assert body["field"] == field, body
        assert field in body["detail"], body
    return body


# ------------------------------------------------------------------------- live servers
def free_port() -> int:
    """A TCP port free on 127.0.0.1 now (the OS's choice)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """A live server process: its base URL, process, log file (stderr and stdout) and data
    directory."""

    def __init__(self, proc: subprocess.Popen[bytes], url: str, log: Path, data_dir: Path) -> None:
        self.proc, self.url, self.log, self.data_dir = proc, url, log, data_dir

    def log_lines(self) -> list[dict]:
        """The JSON lines logged so far (other lines skipped)."""
        out = []
        for line in self.log.read_text().splitlines():
            with contextlib.suppress(orjson.JSONDecodeError):
                out.append(orjson.loads(line))
        return out


@contextlib.contextmanager
def serve(
    data_dir: Path,
    *uvicorn_args: str,
    app: str = "app.main:app",
    env: dict[str, str] | None = None,
    settings: dict[str, str] | None = None,
    timeout: float = 90,
) -> Iterator[Server]:
    """Run a server on a free loopback port until ``/health`` answers; stop it after.

    Parameters
    ----------
    data_dir
        ``DENAVIT_DATA_DIR`` of the server.
    uvicorn_args
        Extra ``uvicorn`` arguments (``"--workers", "2"``; ``"--factory"`` with ``app``
        naming a factory such as ``tests.helpers:make_app_with_a_bug``).
    app
        The ASGI app (or factory) uvicorn serves.
    env
        Extra environment variables.
    settings
        When given, run ``python -m app`` instead (the entry of ``make run`` and the
        image), configured only by ``DENAVIT_*`` variables: these (``{"workers": "1"}``
        → ``DENAVIT_WORKERS=1``) plus host, port and data directory; the caller's own
        ``DENAVIT_*`` variables are dropped.
    timeout
        Seconds the server may take to answer ``/health``.

    The server is stopped through its PID (SIGTERM, then SIGKILL after 30 s) unless the
    test already stopped it.
    """
    port = free_port()
    if settings is None:
        cmd = [sys.executable, "-m", "uvicorn", app, "--host", "127.0.0.1",
               "--port", str(port), "--no-access-log", *uvicorn_args]  # fmt: skip
        full_env = {**os.environ, "DENAVIT_DATA_DIR": str(data_dir), **(env or {})}
    else:
        assert not uvicorn_args, "python -m app takes its settings from DENAVIT_*"
        cmd = [sys.executable, "-m", "app"]
        full_env = {k: v for k, v in os.environ.items() if not k.upper().startswith("DENAVIT_")}
        full_env |= {"DENAVIT_HOST": "127.0.0.1", "DENAVIT_PORT": str(port)}
        full_env |= {"DENAVIT_DATA_DIR": str(data_dir), **(env or {})}
        full_env |= {f"DENAVIT_{k.upper()}": v for k, v in settings.items()}
    # The server logs one JSON line per request: into a file, as an unread pipe would fill up.
    log_path = Path(tempfile.mkdtemp(prefix="denavit-server-")) / "server.log"
    with open(log_path, "wb") as log:
        proc = subprocess.Popen(cmd, cwd=ROOT, env=full_env, stderr=log, stdout=log)
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + timeout
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"server exited {proc.returncode}: {log_path.read_text()}")
            with contextlib.suppress(httpx.TransportError):
                if httpx.get(url + "/health", timeout=2).status_code == 200:
                    break
            if time.monotonic() > deadline:
                raise RuntimeError(f"server did not start: {log_path.read_text()[-3000:]}")
            time.sleep(0.1)
        yield Server(proc, url, log_path, Path(data_dir))
    finally:
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()


def worker_pids(server: Server) -> list[int]:
    """The PIDs of a multi-worker server's uvicorn workers (the supervisor's children that
    run the app; not multiprocessing's resource tracker), sorted."""
    pids = []
    for pid in descendants(server.proc.pid):
        stat = proc_stat(pid)
        try:
            cmdline = Path(f"/proc/{pid}/cmdline").read_bytes()
        except OSError:
            continue
        if stat is not None and stat[1] == server.proc.pid and b"resource_tracker" not in cmdline:
            pids.append(pid)
    return sorted(pids)


def worker_rss_mb(pid: int) -> float:
    """Resident memory of process ``pid`` (MiB), from /proc/<pid>/status."""
    status = Path(f"/proc/{pid}/status").read_text()
    return int(status.split("VmRSS:")[1].split()[0]) / 1024


def make_app_with_a_bug() -> FastAPI:
    """The service plus ``GET /test/bug``, which raises an unexpected exception.

    A test-only application factory for a live server (``uvicorn --factory``), never
    imported by the service: the real API has no way to trigger a bug on purpose.
    """
    app = create_app()

    @app.get("/test/bug", include_in_schema=False)
    async def bug() -> None:
        raise RuntimeError("a bug, on purpose")

    return app


# ---------------------------------------------------------------------- metrics, routes
_SAMPLE = re.compile(
    r'^([a-zA-Z_:][a-zA-Z0-9_:]*)(\{(?:[a-zA-Z_]\w*="(?:[^"\\]|\\.)*",?)*\})? (\S+)$'
)


def parse_metrics(text: str) -> dict[str, float]:
    """Sample name with labels → value; every line must be a comment or a valid sample."""
    samples = {}
    for line in text.splitlines():
        if line.startswith("# HELP ") or line.startswith("# TYPE "):
            continue
        m = _SAMPLE.match(line)
        assert m, f"not Prometheus text: {line!r}"
        samples[m[1] + (m[2] or "")] = float(m[3])
    return samples


def _uses(dependant, fn) -> bool:
    return any(d.call is fn or _uses(d, fn) for d in dependant.dependencies)


def api_routes(app: FastAPI) -> list[tuple[str, APIRoute]]:
    """(full path template, route) of every documented API route."""
    return [
        (rc.path, rc.original_route)
        for rc in iter_route_contexts(app.routes)
        if isinstance(rc.original_route, APIRoute) and rc.original_route.include_in_schema
    ]


def write_routes(app: FastAPI) -> list[tuple[str, str, APIRoute]]:
    """(method, path, route) of every route guarded by ``require_token``."""
    return [
        (m, path, r)
        for path, r in api_routes(app)
        if _uses(r.dependant, require_token)
        for m in sorted(r.methods)
    ]


def send_and_hang_up(url: str, path: str, body: dict) -> None:
    """Send a whole request on a raw connection, then close it without reading the answer."""
    parts = urlsplit(url)
    payload = json.dumps(body).encode()
    head = (
        f"POST {path} HTTP/1.1\r\nHost: {parts.hostname}\r\n"
        f"Content-Type: application/json\r\nContent-Length: {len(payload)}\r\n\r\n"
    ).encode()
    with socket.create_connection((parts.hostname, parts.port), timeout=10) as s:
        s.sendall(head + payload)
        time.sleep(0.2)  # let the server read it and hand it to the pool


def poll_live(url: str, until, timeout: float = 60.0) -> dict:
    """GET ``url`` until ``until(job)`` holds (60 s: a loaded machine is slow, never wrong)."""
    end = time.monotonic() + timeout
    while True:
        r = httpx.get(url, timeout=10)
        assert r.status_code == 200, r.text
        if until(job := r.json()):
            return job
        assert time.monotonic() < end, job
        time.sleep(0.05)


def fk_target(registry, q, robot_id: str, frame: str) -> dict:
    """The wire target of ``frame`` at configuration ``q`` (position and quaternion)."""
    T = forward_kinematics(registry.get(robot_id), np.array(q), [frame])[frame]
    return {"position": T[:3, 3].tolist(), "orientation": matrix_to_quaternion(T[:3, :3]).tolist()}


def proc_stat(pid: int) -> tuple[str, int] | None:
    """State letter and parent pid of ``pid`` (``None`` if it does not exist)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            text = f.read().decode("ascii", "replace")
    except OSError:
        return None
    fields = text[text.rfind(")") + 2 :].split()
    return fields[0], int(fields[1])


def descendants(pid: int) -> set[int]:
    """Every process below ``pid`` in the process tree (children, their children...)."""
    children: dict[int, list[int]] = {}
    for name in os.listdir("/proc"):
        if name.isdigit() and (stat := proc_stat(int(name))) is not None:
            children.setdefault(stat[1], []).append(int(name))
    out: set[int] = set()
    todo = [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            if child not in out:
                out.add(child)
                todo.append(child)
    return out

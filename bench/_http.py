"""Helpers of the HTTP benchmarks: a server on loopback, a load generator, RSS sampling.

Only loopback addresses are used (127.0.0.1). Load generator: ``wrk`` (Debian package
``wrk``; installed with apt-get when missing and possible), else a small asyncio HTTP/1.1
keep-alive client (:func:`python_load`), slower but dependency-free.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import httpx

ROOT = Path(__file__).resolve().parents[1]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@dataclass
class Server:
    proc: subprocess.Popen[bytes]
    url: str

    def pids(self) -> list[int]:
        """The server process and its children (uvicorn workers)."""
        out = [self.proc.pid]
        with contextlib.suppress(OSError):
            children = Path(f"/proc/{self.proc.pid}/task/{self.proc.pid}/children").read_text()
            out += [int(p) for p in children.split()]
        return out

    def rss_bytes(self) -> int:
        total = 0
        for pid in self.pids():
            with contextlib.suppress(OSError, ValueError, IndexError):
                pages = int(Path(f"/proc/{pid}/statm").read_text().split()[1])
                total += pages * os.sysconf("SC_PAGE_SIZE")
        return total


@contextlib.contextmanager
def serve(code: str | None = None, **settings: str) -> Iterator[Server]:
    """Run Denavit (``python -m app``), or ``python -c code``, on a free loopback port.

    ``settings`` become ``DENAVIT_*`` variables (``workers="2"``...). ``code`` may use the
    same variables (it is given the port in DENAVIT_PORT).
    """
    port = free_port()
    env = {k: v for k, v in os.environ.items() if not k.upper().startswith("DENAVIT_")}
    data = tempfile.mkdtemp(prefix="denavit-bench-")
    env |= {"DENAVIT_HOST": "127.0.0.1", "DENAVIT_PORT": str(port), "DENAVIT_DATA_DIR": data}
    env |= {f"DENAVIT_{k.upper()}": v for k, v in settings.items()}
    cmd = [sys.executable, "-m", "app"] if code is None else [sys.executable, "-c", code]
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)  # fmt: skip
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 90
        while True:
            if proc.poll() is not None:
                raise RuntimeError(f"server exited with {proc.returncode}")
            with contextlib.suppress(httpx.TransportError):
                if httpx.get(url + "/health", timeout=2).status_code == 200:
                    break
            if time.monotonic() > deadline:
                raise RuntimeError("server did not start")
            time.sleep(0.1)
        yield Server(proc, url)
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        shutil.rmtree(data, ignore_errors=True)


@dataclass
class LoadResult:
    tool: str
    requests: int
    seconds: float
    rps: float
    p50_ms: float
    p99_ms: float
    errors: int
    rss_mb: list[float] = field(default_factory=list)


def ensure_wrk() -> str | None:
    """Path of wrk; tries ``apt-get install -y wrk`` once when it is missing (root only)."""
    found = shutil.which("wrk")
    if found or os.geteuid() != 0 or not shutil.which("apt-get"):
        return found
    with contextlib.suppress(subprocess.SubprocessError, OSError):
        subprocess.run(["apt-get", "install", "-y", "-qq", "wrk"], capture_output=True,
                       timeout=300, check=False)  # fmt: skip
    return shutil.which("wrk")


_UNITS = {"us": 1e-3, "ms": 1.0, "s": 1e3, "m": 60e3}


def _ms(text: str) -> float:
    m = re.fullmatch(r"([\d.]+)(us|ms|s|m)", text)
    assert m, text
    return float(m[1]) * _UNITS[m[2]]


def wrk_load(
    wrk: str, url: str, body: bytes, seconds: float, connections: int, threads: int = 1
) -> LoadResult:
    """POST ``body`` (JSON) to ``url`` with wrk for ``seconds``."""
    with tempfile.NamedTemporaryFile("w", suffix=".lua", delete=False) as f:
        f.write('wrk.method = "POST"\nwrk.headers["Content-Type"] = "application/json"\n')
        f.write(f"wrk.body = [==[{body.decode()}]==]\n")
        script = f.name
    try:
        done = subprocess.run(
            [wrk, f"-t{threads}", f"-c{connections}", f"-d{max(1, round(seconds))}s",
             "--latency", "--timeout", "30s", "-s", script, url],
            capture_output=True, text=True, timeout=seconds + 120, check=True,
        )  # fmt: skip
    finally:
        os.unlink(script)
    out = done.stdout
    total = re.search(r"(\d+) requests in ([\d.]+)(\w+)", out)
    rps = float(re.search(r"Requests/sec:\s+([\d.]+)", out)[1])
    p50 = _ms(re.search(r"\s50%\s+(\S+)", out)[1])
    p99 = _ms(re.search(r"\s99%\s+(\S+)", out)[1])
    non2xx = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
    sock = re.search(r"Socket errors: connect (\d+), read (\d+), write (\d+), timeout (\d+)", out)
    errors = (int(non2xx[1]) if non2xx else 0) + (sum(map(int, sock.groups())) if sock else 0)
    secs = float(total[2]) * {"s": 1.0, "ms": 1e-3, "m": 60.0}.get(total[3], 1.0)
    return LoadResult("wrk", int(total[1]), secs, rps, p50, p99, errors)


def python_load(url: str, body: bytes, seconds: float, connections: int) -> LoadResult:
    """The same measurement with an asyncio HTTP/1.1 keep-alive client (no wrk)."""
    m = re.fullmatch(r"http://([\d.]+):(\d+)(/.*)", url)
    host, port, path = m[1], int(m[2]), m[3]
    request = (
        f"POST {path} HTTP/1.1\r\nHost: {host}:{port}\r\nContent-Type: application/json\r\n"
        f"Content-Length: {len(body)}\r\n\r\n"
    ).encode() + body
    latencies: list[float] = []
    errors = 0

    async def one(stop: float) -> None:
        nonlocal errors
        reader, writer = await asyncio.open_connection(host, port)
        try:
            while time.perf_counter() < stop:
                t0 = time.perf_counter()
                writer.write(request)
                head = await reader.readuntil(b"\r\n\r\n")
                status = int(head.split(b" ", 2)[1])
                length = int(re.search(rb"(?i)content-length: (\d+)", head)[1])
                await reader.readexactly(length)
                latencies.append(time.perf_counter() - t0)
                errors += status >= 300
        finally:
            writer.close()

    async def run() -> float:
        t0 = time.perf_counter()
        await asyncio.gather(*(one(t0 + seconds) for _ in range(connections)))
        return time.perf_counter() - t0

    elapsed = asyncio.run(run())
    lat = sorted(latencies)
    pick = lambda q: lat[min(len(lat) - 1, int(q * len(lat)))] * 1e3  # noqa: E731
    return LoadResult("python", len(lat), elapsed, len(lat) / elapsed, pick(0.5), pick(0.99),
                      errors)  # fmt: skip


def load(url: str, body: bytes, seconds: float, connections: int) -> LoadResult:
    """wrk when available, else :func:`python_load`."""
    wrk = ensure_wrk()
    if wrk:
        return wrk_load(wrk, url, body, seconds, connections)
    return python_load(url, body, seconds, connections)


@contextlib.contextmanager
def sample_rss(server: Server, every: float = 1.0) -> Iterator[list[tuple[float, int]]]:
    """(seconds since start, RSS bytes of the server and its workers), sampled in a thread."""
    samples: list[tuple[float, int]] = []
    stop = threading.Event()
    t0 = time.perf_counter()

    def loop() -> None:
        while not stop.is_set():
            samples.append((time.perf_counter() - t0, server.rss_bytes()))
            stop.wait(every)

    thread = threading.Thread(target=loop, daemon=True)
    thread.start()
    try:
        yield samples
    finally:
        stop.set()
        thread.join()

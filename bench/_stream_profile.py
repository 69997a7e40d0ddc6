"""Where a one-at-a-time binary IK round trip goes, and the floors below the service.

Printed by ``python -m bench stream`` after its tables:

- :func:`profile`: the service with :mod:`bench._stream_stamps` (timestamps at each stage,
  on the clock the client shares), binary IK frames one at a time from
  :class:`bench._ws.BlockingWebSocket`; per stage, the median and mean gap (µs) from the
  previous stage, the first from the client's send and the last to its receive;
- :func:`floors`: what the transports cost with no work, same client and loop: a bare
  uvicorn + Starlette WebSocket echo with the service's uvicorn options, and a raw TCP
  echo (a uvloop ``asyncio.Protocol``, 72-byte messages: the size of a binary IK frame),
  alternating message by message; and the same WebSocket echo through each client the
  service's table uses (the blocking one, the ``websockets`` sync client with its reader
  thread, the ``websockets`` asyncio client on the standard event loop, the Python client's
  :class:`denavit_client.stream.CallingThreadWebSocket`): what each client
  adds to a round trip, whatever the server does.
"""

from __future__ import annotations

import asyncio
import bisect
import json
import os
import socket
import tempfile
import time

import numpy as np
import orjson
from denavit_client.stream import CallingThreadWebSocket
from websockets.asyncio.client import connect as aio_connect
from websockets.sync.client import connect

from bench._http import serve
from bench._stream_stamps import SERVER_CODE, STAGES
from bench._ws import BlockingWebSocket

ECHO_CODE = """
import asyncio, os, threading, uvicorn, uvloop
from starlette.applications import Starlette
from starlette.responses import PlainTextResponse
from starlette.routing import Route, WebSocketRoute
from app.__main__ import server_options
from app.operations.settings import get_settings

async def echo(ws):
    await ws.accept()
    while True:
        m = await ws.receive()
        if m["type"] == "websocket.disconnect":
            return
        await ws.send_bytes(m["bytes"])

class Echo(asyncio.Protocol):
    def connection_made(self, transport):
        self.transport = transport
    def data_received(self, data):
        self.transport.write(data)

def tcp():
    loop = uvloop.new_event_loop()
    server = loop.run_until_complete(loop.create_server(
        Echo, "127.0.0.1", int(os.environ["BENCH_TCP_ECHO_PORT"])))
    loop.run_forever()

threading.Thread(target=tcp, daemon=True).start()
app = Starlette(routes=[Route("/health", lambda r: PlainTextResponse("ok")),
                        WebSocketRoute("/echo", echo)])
options = server_options(get_settings())
options.pop("http")  # the bounded protocol's 431 page needs the service's modules only
uvicorn.run(app, **options)
"""


def _percentiles(us: list[float]) -> str:
    a = np.array(us)
    return f"{np.median(a):.1f} / {np.percentile(a, 99):.1f}"


def profile(robot_id: str, q: list[float], pose_target: dict, targets: list, n: int) -> None:
    """The stages of ``n`` binary IK round trips on ``robot_id`` (after 50 unrecorded)."""
    fd, path = tempfile.mkstemp(prefix="stream-stamps-", suffix=".json")
    os.close(fd)
    os.environ["BENCH_STREAM_STAMPS"] = path
    sent: list[tuple[int, int]] = []
    try:
        with serve(code=SERVER_CODE) as server:
            port = int(server.url.rsplit(":", 1)[1])
            ws = BlockingWebSocket("127.0.0.1", port, f"/robots/{robot_id}/stream")
            ws.send(orjson.dumps({"id": 0, "op": "ik", "seed": q, "target": pose_target}).decode())
            assert orjson.loads(ws.recv())["success"]
            for i, (p, o) in enumerate(targets[: n + 50]):
                frame = np.array([3.0, float(i), *p, *o], "<f8").tobytes()
                t0 = time.perf_counter_ns()
                ws.send(frame)
                ws.recv()
                sent.append((t0, time.perf_counter_ns()))
            ws.close()
        with open(path) as f:
            stamps = json.load(f)
    finally:
        os.unlink(path)
        os.environ.pop("BENCH_STREAM_STAMPS", None)
    times = [t for _, t in stamps]
    gaps: dict[int, list[float]] = {k: [] for k in range(len(STAGES) + 1)}
    total = []
    for t0, t1 in sent[50:]:
        inside = stamps[bisect.bisect_left(times, t0) : bisect.bisect_right(times, t1)]
        seen: dict[int, int] = {}
        for stage, t in inside:
            seen.setdefault(stage, t)
        if any(stage not in seen for stage in range(len(STAGES) - 1)):
            continue  # (the "written" stamp may fall after the client's receive: not used)
        last = t0
        for stage in range(len(STAGES) - 1):  # up to "ASGI send entered"
            gaps[stage].append((seen[stage] - last) / 1e3)
            last = seen[stage]
        gaps[len(STAGES)].append((t1 - last) / 1e3)
        total.append((t1 - t0) / 1e3)
    print(f"\nOne binary IK round trip on {robot_id}, stage by stage ({len(total)} round trips, "
          f"blocking client; load average {os.getloadavg()[0]:.1f})\n")  # fmt: skip
    print("| from → to | median (µs) | mean (µs) |")
    print("|---|---:|---:|")
    names = ["client send", *STAGES[:-1], "client has the answer"]
    order = [*range(len(STAGES) - 1), len(STAGES)]
    for k, stage in enumerate(order):
        us = np.array(gaps[stage])
        print(f"| {names[k]} → {names[k + 1]} | {np.median(us):.1f} | {us.mean():.1f} |")
    t = np.array(total)
    print(f"| **round trip** | **{np.median(t):.1f}** | **{t.mean():.1f}** |")


async def _aio_echo(aws, frame: bytes) -> float:
    t0 = time.perf_counter_ns()
    await aws.send(frame)
    await aws.recv()
    return (time.perf_counter_ns() - t0) / 1e3


def floors(n: int) -> None:
    """A WebSocket echo through uvicorn + Starlette and a raw TCP echo, same client; then
    the WebSocket echo through each of the three clients, alternating."""
    tcp_port = _free_port()
    os.environ["BENCH_TCP_ECHO_PORT"] = str(tcp_port)
    frame = bytes(72)
    ws_us: list[float] = []
    tcp_us: list[float] = []
    clients: dict[str, list[float]] = {
        "blocking": [], "websockets sync": [], "asyncio": [], "calling thread": []
    }  # fmt: skip
    try:
        with serve(code=ECHO_CODE) as server:
            port = int(server.url.rsplit(":", 1)[1])
            ws = BlockingWebSocket("127.0.0.1", port, "/echo")
            tcp = socket.create_connection(("127.0.0.1", tcp_port))
            tcp.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            for i in range(n + 50):
                t0 = time.perf_counter_ns()
                ws.send(frame)
                ws.recv()
                t1 = time.perf_counter_ns()
                tcp.sendall(frame)
                got = b""
                while len(got) < len(frame):
                    got += tcp.recv(4096)
                t2 = time.perf_counter_ns()
                if i >= 50:
                    ws_us.append((t1 - t0) / 1e3)
                    tcp_us.append((t2 - t1) / 1e3)
            tcp.close()
            url = f"ws://127.0.0.1:{port}/echo"
            loop = asyncio.new_event_loop()
            aws = loop.run_until_complete(aio_connect(url, compression=None, proxy=None))
            own = CallingThreadWebSocket(url)
            with connect(url, compression=None, proxy=None) as sync:
                for i in range(n + 50):
                    t0 = time.perf_counter_ns()
                    ws.send(frame)
                    ws.recv()
                    t1 = time.perf_counter_ns()
                    sync.send(frame)
                    sync.recv()
                    t2 = time.perf_counter_ns()
                    t_aio = loop.run_until_complete(_aio_echo(aws, frame))
                    t3 = time.perf_counter_ns()
                    own.send(frame)
                    own.recv()
                    t4 = time.perf_counter_ns()
                    if i >= 50:
                        clients["blocking"].append((t1 - t0) / 1e3)
                        clients["websockets sync"].append((t2 - t1) / 1e3)
                        clients["asyncio"].append(t_aio)
                        clients["calling thread"].append((t4 - t3) / 1e3)
            own.close()
            loop.run_until_complete(aws.close())
            loop.close()
            ws.close()
    finally:
        os.environ.pop("BENCH_TCP_ECHO_PORT", None)
    print(f"\nFloors, 72-byte messages one at a time ({n} each, alternating, blocking client)\n")
    print("| echo | median / p99 (µs) |")
    print("|---|---:|")
    print(
        f"| uvicorn + Starlette WebSocket (the service's uvicorn options) | {_percentiles(ws_us)} |"
    )
    print(f"| raw TCP (uvloop protocol) | {_percentiles(tcp_us)} |")
    print(f"\nThe same WebSocket echo through each client ({n} each, alternating)\n")
    print("| client | median / p99 (µs) | over the blocking client (medians, µs) |")
    print("|---|---:|---:|")
    base = float(np.median(clients["blocking"]))
    names = {
        "blocking": "blocking (`bench._ws`, the calling thread reads)",
        "websockets sync": "`websockets` sync client (reader thread)",
        "asyncio": "`websockets` asyncio client (standard event loop)",
        "calling thread": "`denavit_client.stream.CallingThreadWebSocket` (`websockets`' "
        "sans-I/O protocol, the calling thread reads)",
    }
    for key, us in clients.items():
        extra = float(np.median(us)) - base
        print(f"| {names[key]} | {_percentiles(us)} | {extra:+.1f} |")


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]

"""What an IK request costs over HTTP beyond its solve, against an FK request.

``python -m bench ik_http`` prints one markdown table (docs/benchmarks.md, "IK over HTTP"):
for UR5 (closed form) and Panda, side by side in one run,

- **live**: a real server (``python -m app``, 1 uvicorn worker, access log on, as deployed)
  on 127.0.0.1, one keep-alive ``httpx`` client, sequential requests: median round trip of
  POST /fk (one configuration), of POST /ik (the pose of that configuration, default budget),
  the median ``solve_time_ms`` the server reports, and **IK − solve − FK**: what IK costs
  beyond its own solve and an FK request's round trip (target ≤ 0.1 ms);
- **in process**: the same requests through the ASGI app called directly (no socket, no
  client), in CPU time of the calling thread (``time.thread_time``), so load from other
  processes does not count; trimmed mean (the slowest 10 % dropped).

FK and IK requests alternate one by one so load hits both alike. ``DENAVIT_BENCH_N``
requests of each (default 2000).
"""

from __future__ import annotations

import asyncio
import os
import statistics
import tempfile
import time
from pathlib import Path

import httpx
import orjson

from bench._http import serve

N = int(os.environ.get("DENAVIT_BENCH_N", "2000"))
JSON = {"content-type": "application/json"}
ROBOTS = {
    "ur5": [0.3, -1.1, 1.4, -0.6, 1.2, 0.4],
    "panda": [0.2, -0.5, 0.1, -2.0, 0.3, 1.6, 0.6, 0.02],
}


def pose_target(pose: dict) -> dict:
    """The IK target of an FK answer's pose (position and quaternion)."""
    return {"position": pose["position"], "orientation": pose["orientation"]}


def _ik_body(pose: dict) -> bytes:
    return orjson.dumps({"target": pose_target(pose)})


def _trimmed_ms(values: list[float]) -> float:
    kept = sorted(values)[: max(1, int(len(values) * 0.9))]
    return statistics.fmean(kept) * 1e3


def live() -> dict[str, tuple[float, float, float]]:
    """Robot → (FK, IK, solve) medians in ms, on a live server."""
    out = {}
    with serve(workers="1") as server, httpx.Client(base_url=server.url, timeout=120) as c:
        for robot_id, q in ROBOTS.items():
            fk = orjson.dumps({"q": q})
            pose = next(iter(c.post(f"/robots/{robot_id}/fk", content=fk, headers=JSON)
                             .json()["poses"].values()))  # fmt: skip
            ik = _ik_body(pose)
            for _ in range(50):  # warm-up: kernels compiled, caches filled
                c.post(f"/robots/{robot_id}/ik", content=ik, headers=JSON).raise_for_status()
            fks, iks, solves = [], [], []
            for _ in range(N):
                t = time.perf_counter()
                c.post(f"/robots/{robot_id}/fk", content=fk, headers=JSON)
                fks.append(time.perf_counter() - t)
                t = time.perf_counter()
                r = c.post(f"/robots/{robot_id}/ik", content=ik, headers=JSON)
                iks.append(time.perf_counter() - t)
                solves.append(r.json()["solve_time_ms"])
            m = statistics.median
            out[robot_id] = (m(fks) * 1e3, m(iks) * 1e3, m(solves))
    return out


def in_process() -> dict[str, tuple[float, float, float]]:
    """Robot → (FK, IK, solve) in CPU ms per request, the ASGI app called directly."""
    from app.main import create_app
    from app.operations.settings import Settings

    app = create_app(Settings(data_dir=Path(tempfile.mkdtemp(prefix="denavit-bench-"))))

    async def call(path: str, body: bytes) -> bytes:
        sent = False

        async def receive() -> dict:
            nonlocal sent
            if not sent:
                sent = True
                return {"type": "http.request", "body": body, "more_body": False}
            await asyncio.sleep(3600)
            return {"type": "http.disconnect"}

        chunks: list[bytes] = []

        async def send(message: dict) -> None:
            if message["type"] == "http.response.body":
                chunks.append(message.get("body", b""))

        headers = [(b"content-type", b"application/json"), (b"host", b"bench"),
                   (b"content-length", str(len(body)).encode())]  # fmt: skip
        scope = {"type": "http", "asgi": {"version": "3.0"}, "http_version": "1.1",
                 "method": "POST", "scheme": "http", "path": path, "raw_path": path.encode(),
                 "query_string": b"", "root_path": "", "headers": headers,
                 "client": ("127.0.0.1", 1), "server": ("127.0.0.1", 80), "state": {}}  # fmt: skip
        await app(scope, receive, send)
        return b"".join(chunks)

    async def run() -> dict[str, tuple[float, float, float]]:
        out = {}
        async with app.router.lifespan_context(app):
            for robot_id, q in ROBOTS.items():
                fk = orjson.dumps({"q": q})
                pose = next(iter(orjson.loads(await call(f"/robots/{robot_id}/fk", fk))
                                 ["poses"].values()))  # fmt: skip
                ik = _ik_body(pose)
                for _ in range(50):
                    await call(f"/robots/{robot_id}/ik", ik)
                fks, iks, solves = [], [], []
                for _ in range(N):
                    t = time.thread_time()
                    await call(f"/robots/{robot_id}/fk", fk)
                    fks.append(time.thread_time() - t)
                    t = time.thread_time()
                    r = await call(f"/robots/{robot_id}/ik", ik)
                    iks.append(time.thread_time() - t)
                    solves.append(orjson.loads(r)["solve_time_ms"] * 1e-3)
                out[robot_id] = (_trimmed_ms(fks), _trimmed_ms(iks), _trimmed_ms(solves))
        return out

    return asyncio.run(run())


def main() -> None:
    rows = [("live, wall median", live()), ("in process, CPU", in_process())]
    print(f"\nIK over HTTP beyond its solve ({N} FK and IK requests each, alternating)\n")
    print("| robot | measured | FK round trip (ms) | IK round trip (ms) | solve_time_ms | "
          "IK − solve − FK (ms) |")  # fmt: skip
    print("|---|---|---:|---:|---:|---:|")
    for robot_id in ROBOTS:
        for label, table in rows:
            fk, ik, solve = table[robot_id]
            print(f"| {robot_id} | {label} | {fk:.3f} | {ik:.3f} | {solve:.3f} | "
                  f"{ik - solve - fk:+.3f} |")  # fmt: skip


if __name__ == "__main__":
    main()

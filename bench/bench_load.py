"""Load test: FK, IK and collision checks at saturation, memory watched.

``python -m bench load`` starts ``python -m app`` on 127.0.0.1 with the image's worker
count (``DENAVIT_WORKERS=2``), then drives each endpoint with wrk (64 connections; the
asyncio fallback client when wrk is unavailable) for ``DENAVIT_LOAD_SECONDS`` (default 60)
seconds, one after the other. For each it prints requests/s, p50/p99 latency, the error
count (non-2xx answers and socket errors; must be 0) and the resident memory of the server
processes (parent + workers), sampled every second: the mean of the first 10 s against the
mean of the last 10 s (growth must stay within noise: under 5 %).

Requests (Panda): FK at the "ready" configuration; IK of a reachable pose (the FK pose of
a configuration near "ready"), default 5 ms budget; self-collision check (meshes) at
"ready".
"""

from __future__ import annotations

import os
import time

import httpx
import orjson

from bench._http import ensure_wrk, load, sample_rss, serve

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
CONNECTIONS = 64
WINDOW = 10.0  # s, for the memory comparison


def requests_under_test(url: str) -> list[tuple[str, str, bytes]]:
    """(name, path, JSON body); the IK target is an FK pose, so it is reachable."""
    q = [v + 0.1 for v in READY[:7]] + [0.02]
    pose = httpx.post(f"{url}/robots/panda/fk", json={"q": q}, timeout=60).json()
    target = next(iter(pose["poses"].values()))
    ik = {"target": {"position": target["position"], "orientation": target["orientation"]}}
    return [
        ("FK", "/robots/panda/fk", orjson.dumps({"q": READY})),
        ("IK", "/robots/panda/ik", orjson.dumps({**ik, "seed": READY})),
        ("collisions", "/robots/panda/collisions", orjson.dumps({"q": READY})),
    ]


def main() -> None:
    seconds = float(os.environ.get("DENAVIT_LOAD_SECONDS", "60"))
    workers = os.environ.get("DENAVIT_LOAD_WORKERS", "2")
    tool = "wrk" if ensure_wrk() else "python asyncio client (wrk unavailable)"
    print(f"machine: {os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {tool}, {CONNECTIONS} "
          f"connections, {seconds:g} s per endpoint; python -m app, {workers} workers")  # fmt: skip
    print("\n| endpoint | requests/s | p50 ms | p99 ms | errors | RSS first 10 s (MB) "
          "| RSS last 10 s (MB) | growth |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|")
    with serve(workers=workers, access_log="true") as server:
        cases = requests_under_test(server.url)
        for _, path, body in cases:  # every worker builds its models before the clock runs
            load(server.url + path, body, 2.0, CONNECTIONS)
        for name, path, body in cases:
            with sample_rss(server) as samples:
                result = load(server.url + path, body, seconds, CONNECTIONS)
            end = samples[-1][0]
            first = [rss for t, rss in samples if t <= min(WINDOW, end / 2)]
            last = [rss for t, rss in samples if t >= max(end - WINDOW, end / 2)]
            mb_first = sum(first) / len(first) / 1e6
            mb_last = sum(last) / len(last) / 1e6
            growth = 100 * (mb_last / mb_first - 1)
            print(f"| {name} `POST {path}` | {result.rps:.0f} | {result.p50_ms:.2f} | "
                  f"{result.p99_ms:.2f} | {result.errors} | {mb_first:.1f} | {mb_last:.1f} | "
                  f"{growth:+.1f} % |", flush=True)  # fmt: skip
            assert result.errors == 0, f"{name}: {result.errors} errors"
            assert growth < 5.0, f"{name}: memory grew {growth:.1f} %"


if __name__ == "__main__":
    main()

"""Forward kinematics over HTTP against its ceilings, side by side in one run.

``python -m bench fk`` prints two markdown tables (docs/benchmarks.md, "Forward kinematics
over HTTP"):

1. Single-pose FK requests/s (POST /robots/panda/fk, Panda, 8 joints, default frame) on a
   real uvicorn server on 127.0.0.1 with one worker, loaded by wrk (16 connections), against
   the ceiling of the same stack: a bench-only async FastAPI endpoint that validates the
   same body with the same model (``FKRequest``) and echoes it (``stack_echo_app``: Denavit's
   app, middleware included, plus the echo route). Also: the echo on a bare FastAPI app (no
   middleware), on Denavit's routes without the middleware (so the middleware's cost is
   isolated from route matching), FK and echo with the access log off, and FK on uvicorn's
   pure-Python asyncio loop + h11 parser. Target: FK ≥ 0.8× the echo; a last line prints
   the target, the echo's and FK's requests/s, the ratio and "met" or "NOT met".
2. Batch FK poses/s (POST /robots/panda/fk/batch, 10 000 configurations) against raw
   in-process Pinocchio in a Python loop (``forwardKinematics`` + ``updateFramePlacement``
   per configuration, the placement's translation and rotation copied out). Target ≥ 0.25×.

Rows are measured in interleaved rounds (best of ``DENAVIT_BENCH_ROUNDS``, default 2) so
load from other processes hits them alike; ``DENAVIT_BENCH_SECONDS`` (default 8) per run.
"""

from __future__ import annotations

import contextlib
import os
import time

import httpx
import numpy as np
import orjson
import pinocchio as pin
from fastapi import FastAPI

from app.api.responses import ORJSONResponse
from app.api.schemas.common import RobotId
from app.api.schemas.fk import FKRequest
from app.robots.registry import Registry
from bench._http import ensure_wrk, load, serve

READY = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785, 0.02]
FK_BODY = orjson.dumps({"q": READY})
JSON = {"content-type": "application/json"}
CONNECTIONS = 16
BATCH = 10_000


def _echo_route(app: FastAPI) -> FastAPI:
    @app.post("/bench/{robot_id}/echo", include_in_schema=False)
    async def echo(robot_id: RobotId, body: FKRequest) -> ORJSONResponse:
        """Validate the FK body with the FK model and send it back."""
        return ORJSONResponse({"robot_id": robot_id, **body.model_dump(exclude_none=True)})

    return app


def stack_echo_app() -> FastAPI:
    """Denavit's app (settings, middleware, error handlers) plus the echo route."""
    from app.main import create_app

    return _echo_route(create_app())


def routes_echo_app() -> FastAPI:
    """Denavit's app and the echo route, without the middleware (its cost, isolated)."""
    app = stack_echo_app()
    app.user_middleware = []
    return app


def bare_echo_app() -> FastAPI:
    """A bare FastAPI app with only the echo route and /health (no middleware)."""
    app = FastAPI()

    @app.get("/health")
    async def health() -> ORJSONResponse:
        return ORJSONResponse({"status": "ok"})

    return _echo_route(app)


def _uvicorn(target: str, factory: bool = True, **overrides: str) -> str:
    """``python -c`` code: uvicorn with the options of ``python -m app`` (and overrides)."""
    return (
        "import uvicorn\n"
        "from app.__main__ import server_options\n"
        "from app.operations.settings import get_settings\n"
        f"opts = {{**server_options(get_settings()), **{overrides!r}}}\n"
        f"uvicorn.run({target!r}, factory={factory}, **opts)\n"
    )


def single_pose(seconds: float, rounds: int) -> list[tuple[str, str, float, float, float]]:
    """(row, url path, best requests/s, p50 ms, p99 ms) for each configuration."""
    rows = [
        ("echo, bare FastAPI (no middleware)", _uvicorn("bench.bench_fk:bare_echo_app"), {},
         "/bench/panda/echo"),
        ("echo, Denavit routes, no middleware", _uvicorn("bench.bench_fk:routes_echo_app"), {},
         "/bench/panda/echo"),
        ("echo, Denavit stack (the ceiling)", _uvicorn("bench.bench_fk:stack_echo_app"), {},
         "/bench/panda/echo"),
        ("echo, Denavit stack, access log off", _uvicorn("bench.bench_fk:stack_echo_app"),
         {"access_log": "false"}, "/bench/panda/echo"),
        ("FK, Denavit (python -m app)", None, {}, "/robots/panda/fk"),
        ("FK, access log off", None, {"access_log": "false"}, "/robots/panda/fk"),
        ("FK, asyncio loop + h11", _uvicorn("app.main:app", False, loop="asyncio", http="h11"), {},
         "/robots/panda/fk"),
    ]  # fmt: skip
    best: dict[str, tuple[float, float, float]] = {}
    with contextlib.ExitStack() as stack:
        servers = [stack.enter_context(serve(code, **env)) for _, code, env, _ in rows]
        for server, (_, _, _, path) in zip(servers, rows, strict=True):
            check = httpx.post(server.url + path, content=FK_BODY, headers=JSON)
            assert check.status_code == 200, check.text
            load(server.url + path, FK_BODY, 1.0, CONNECTIONS)  # warm-up
        for _ in range(rounds):
            for server, (name, _, _, path) in zip(servers, rows, strict=True):
                r = load(server.url + path, FK_BODY, seconds, CONNECTIONS)
                assert r.errors == 0, (name, r)
                if r.rps > best.get(name, (0.0,))[0]:
                    best[name] = (r.rps, r.p50_ms, r.p99_ms)
    return [(name, path, *best[name]) for name, _, _, path in rows]


def raw_pinocchio_poses_per_s(qs: np.ndarray, repeats: int = 3) -> float:
    """Poses/s of Pinocchio FK in a Python loop (translation and rotation copied out)."""
    robot = Registry().get("panda")
    model, data = robot.model, robot.model.createData()
    fid = model.getFrameId(robot.ee_frame)
    qps = [robot.to_pin(q) for q in qs]
    fk, upd = pin.forwardKinematics, pin.updateFramePlacement
    best = 0.0
    for _ in range(repeats):
        t0 = time.perf_counter()
        for qp in qps:
            fk(model, data, qp)
            M = upd(model, data, fid)
            M.translation.copy()
            M.rotation.copy()
        best = max(best, len(qps) / (time.perf_counter() - t0))
    return best


def batch(qs: np.ndarray, repeats: int = 5) -> tuple[float, float, int]:
    """(HTTP poses/s, raw Pinocchio poses/s, body bytes) for the batch of ``qs``."""
    body = orjson.dumps({"configurations": qs.tolist()})
    best_http = 0.0
    with serve() as server, httpx.Client(base_url=server.url, timeout=120) as client:
        client.post("/robots/panda/fk/batch", content=body)  # warm-up
        for _ in range(repeats):
            t0 = time.perf_counter()
            r = client.post(
                "/robots/panda/fk/batch",
                content=body,
                headers={"content-type": "application/json"},
            )
            elapsed = time.perf_counter() - t0
            assert r.status_code == 200 and len(r.json()["positions"]) == len(qs)
            best_http = max(best_http, len(qs) / elapsed)
    return best_http, raw_pinocchio_poses_per_s(qs), len(body)


#: The target: single FK over HTTP at least this fraction of the echo ceiling's requests/s.
TARGET_RATIO = 0.8
#: The ratio recorded before (docs/benchmarks.md, re-run after the hardening, 2026-11-24).
RECORDED_RATIO = 1.06


def target_line(fk_rps: float, echo_rps: float) -> str:
    """The target, its baseline (the echo, measured in the same rounds), the measured ratio
    and whether it is met."""
    ratio = fk_rps / echo_rps
    verdict = "met" if ratio >= TARGET_RATIO else "NOT met"
    return (
        f"Target: single FK over HTTP ≥ {TARGET_RATIO:.2f}× a FastAPI echo with the same "
        f"route table | baseline (echo, Denavit stack, same run): {echo_rps:.0f} requests/s | "
        f"FK: {fk_rps:.0f} requests/s | measured {ratio:.2f}× (recorded before: "
        f"{RECORDED_RATIO:.2f}×) | {verdict}"
    )


def main() -> None:
    seconds = float(os.environ.get("DENAVIT_BENCH_SECONDS", "8"))
    rounds = int(os.environ.get("DENAVIT_BENCH_ROUNDS", "2"))
    tool = "wrk" if ensure_wrk() else "python asyncio client (wrk unavailable)"
    load_avg = os.getloadavg()[0]
    print(f"machine: {os.cpu_count()} cores; load average {load_avg:.1f}; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; load: {tool}, "
          f"{CONNECTIONS} connections, {seconds:g} s per run, best of {rounds}")  # fmt: skip
    print("\n### Single-pose FK, requests/s (uvicorn, 1 worker, loopback)\n")
    print("| server | path | requests/s | p50 ms | p99 ms | vs ceiling |")
    print("|---|---|---|---|---|---|")
    rows = single_pose(seconds, rounds)
    ceiling = next(r for r in rows if "ceiling" in r[0])[2]
    for name, path, rps, p50, p99 in rows:
        print(f"| {name} | {path} | {rps:.0f} | {p50:.2f} | {p99:.2f} | {rps / ceiling:.2f}× |")
    routes = rows[1][2]
    print(f"\nMiddleware cost (echo with vs without Denavit's middleware, same routes): "
          f"{100 * (1 - ceiling / routes):.1f} % of requests/s")  # fmt: skip
    fk = next(r for r in rows if r[1] == "/robots/panda/fk")[2]
    print("\n" + target_line(fk, ceiling))
    robot = Registry().get("panda")
    rng = np.random.default_rng(0)
    lo, hi = np.maximum(robot.lower, -3), np.minimum(robot.upper, 3)
    qs = rng.uniform(lo, hi, size=(BATCH, robot.n))
    http, raw, size = batch(qs)
    print(f"\n### Batch FK, poses/s ({BATCH} Panda configurations, {size / 1e6:.1f} MB body)\n")
    print("| path | poses/s | vs raw |")
    print("|---|---|---|")
    print(f"| raw Pinocchio FK, Python loop, in process | {raw:.0f} | 1.00× |")
    print(f"| POST /robots/panda/fk/batch over HTTP | {http:.0f} | {http / raw:.2f}× |")


if __name__ == "__main__":
    main()

"""Robot store and registry: what adding robots and the cross-worker change check cost.

1. In process: :meth:`RobotStore.token` (the change check: one ``stat`` plus one small read),
   :meth:`Registry.cached` for a built-in robot (no check) and for a user-added one (with
   the check), and FK through both; :meth:`Registry.import_dh` and
   :meth:`Registry.add_urdf` end to end (validation, URDF generation, Pinocchio, fsynced
   atomic write).
2. Over HTTP against a real uvicorn (1 worker): POST /robots/{id}/fk for the built-in
   ``planar3r`` and for the same table imported as a user robot, so the difference is the
   change check; POST /robots/dh + DELETE round trips.
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import httpx
import numpy as np

from app.kinematics.fk import forward_kinematics
from app.robots.registry import Registry
from dh2urdf import DHTable

ROOT = Path(__file__).resolve().parents[1]


def _per_call_us(fn, n: int, repeats: int = 5) -> float:
    """Best of ``repeats`` passes of ``n`` calls, in µs per call."""
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        best = min(best, (time.perf_counter() - t0) / n)
    return best * 1e6


def _table(name: str) -> DHTable:
    doc = DHTable.from_file(ROOT / "robots" / "dh" / "planar3r.yaml").to_dict()
    return DHTable.from_dict({**doc, "name": name})


def in_process() -> list[tuple[str, float]]:
    rows: list[tuple[str, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        reg = Registry(tmp)
        reg.import_dh(_table("mine"))
        reg.get("mine")
        reg.get("planar3r")
        q = np.array([0.3, -0.4, 0.5])
        rows.append(("store.token() (change check)", _per_call_us(reg.store.token, 20_000)))
        rows.append(
            ("cached('planar3r'), built-in", _per_call_us(lambda: reg.cached("planar3r"), 20_000))
        )
        rows.append(
            ("cached('mine'), user robot", _per_call_us(lambda: reg.cached("mine"), 20_000))
        )
        builtin, mine = reg.cached("planar3r"), reg.cached("mine")
        rows.append(
            ("FK tool, built-in (cached + FK)", _per_call_us(
                lambda: forward_kinematics(reg.cached("planar3r") or builtin, q, ["tool"]), 5_000))
        )  # fmt: skip
        rows.append(
            ("FK tool, user robot (cached + FK)", _per_call_us(
                lambda: forward_kinematics(reg.cached("mine") or mine, q, ["tool"]), 5_000))
        )  # fmt: skip
        counter = iter(range(10**6))

        def import_delete() -> None:
            name = f"t{next(counter)}"
            reg.import_dh(_table(name))
            reg.delete(name)

        rows.append(("import_dh + delete (3 rows, fsync)", _per_call_us(import_delete, 20, 3)))
        panda = reg.urdf_text("panda")

        def upload_delete() -> None:
            name = f"u{next(counter)}"
            reg.add_urdf(name, panda)
            reg.delete(name)

        rows.append(("add_urdf + delete (panda URDF)", _per_call_us(upload_delete, 10, 3)))
    return rows


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _rate(fn, seconds: float) -> float:
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        fn()
        n += 1
    return n / (time.perf_counter() - t0)


def over_http(seconds: float = 4.0) -> list[tuple[str, float]]:
    rows: list[tuple[str, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        port = _free_port()
        env = {**os.environ, "DENAVIT_DATA_DIR": tmp, "DENAVIT_ACCESS_LOG": "false"}
        cmd = [sys.executable, "-m", "uvicorn", "app.main:app", "--host", "127.0.0.1",
               "--port", str(port), "--no-access-log", "--log-level", "warning"]  # fmt: skip
        proc = subprocess.Popen(cmd, cwd=ROOT, env=env)
        url = f"http://127.0.0.1:{port}"
        try:
            with httpx.Client(base_url=url, timeout=30) as c:
                for _ in range(300):
                    try:
                        if c.get("/health").status_code == 200:
                            break
                    except httpx.TransportError:
                        time.sleep(0.1)
                doc = {**_table("mine").to_dict()}
                assert c.post("/robots/dh", json=doc).status_code == 201
                body = {"q": [0.3, -0.4, 0.5]}
                for rid in ("planar3r", "mine"):
                    assert c.post(f"/robots/{rid}/fk", json=body).status_code == 200
                rates: dict[str, list[float]] = {"planar3r": [], "mine": []}
                for _ in range(4):  # interleaved rounds: load from other work hits both alike
                    for rid in rates:
                        fk = lambda rid=rid: c.post(f"/robots/{rid}/fk", json=body)  # noqa: E731
                        rates[rid].append(_rate(fk, seconds / 4))
                for rid, label in (("planar3r", "built-in"), ("mine", "user robot")):
                    rows.append((f"POST /robots/{{id}}/fk, {label}", max(rates[rid])))
                counter = iter(range(10**6))

                def round_trip() -> None:
                    name = f"r{next(counter)}"
                    assert c.post("/robots/dh", json={**doc, "name": name}).status_code == 201
                    assert c.delete(f"/robots/{name}").status_code == 204

                rows.append(("POST /robots/dh + DELETE round trips", _rate(round_trip, seconds)))
        finally:
            proc.terminate()
            proc.wait(timeout=20)
    return rows


def main() -> None:
    print("\n### In process (best of 5 passes)\n")
    print("| operation | µs per call |\n|---|---|")
    for label, us in in_process():
        print(f"| {label} | {us:,.1f} |")
    print(
        "\n### Over HTTP (uvicorn, 1 worker, one keep-alive client; "
        "FK: best of 4 interleaved 1 s rounds)\n"
    )
    print("| request | per second |\n|---|---|")
    for label, rate in over_http():
        print(f"| {label} | {rate:,.0f} |")


if __name__ == "__main__":
    main()

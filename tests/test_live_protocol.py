"""HTTP protocol on a live uvicorn server: connections after a 500, SIGTERM mid-request."""

from __future__ import annotations

import re
import signal
import threading
import time
from pathlib import Path

import httpx
import pytest

from tests.helpers import serve


def _local_port(resp: httpx.Response) -> int:
    """The client-side port of the connection that carried ``resp``."""
    return resp.extensions["network_stream"].get_extra_info("client_addr")[1]


def test_a_500_leaves_the_keep_alive_connection_usable(tmp_path: Path) -> None:
    """After an unexpected exception the same connection serves the next request.

    Before: Starlette re-raised after answering and uvicorn closed the connection without
    ``Connection: close``; the client's next request on it met a reset (or, here, httpx
    noticed the close and opened a new connection: another local port).
    """
    app = "tests.helpers:make_app_with_a_bug"
    with serve(tmp_path / "data", "--factory", "--workers", "2", app=app) as server:
        with httpx.Client(base_url=server.url, timeout=60) as client:
            for _ in range(3):
                bug = client.get("/test/bug")
                assert bug.status_code == 500
                assert bug.headers["content-type"] == "application/problem+json"
                assert bug.json()["status"] == 500
                assert bug.headers["x-request-id"]
                assert "close" not in bug.headers.get("connection", "").lower()
                port = _local_port(bug)
                time.sleep(0.2)  # give a closing server time to close (it must not)
                ok = client.get("/robots/ur5")
                assert ok.status_code == 200
                assert _local_port(ok) == port, "the connection was not kept"
            head = client.head("/robots/ur5")  # served by uvicorn: no body, same length
            assert head.status_code == 200 and head.content == b""
            assert head.headers["content-length"] == str(len(ok.content))
            assert _local_port(head) == port


def _in_flight(url: str) -> int:
    text = httpx.get(url + "/metrics", timeout=30).text
    m = re.search(r"^denavit_http_requests_in_flight(?:\{[^}]*\})? (\d+)", text, re.M)
    return int(m.group(1)) if m else 0


def test_sigterm_answers_a_request_cut_off_at_the_graceful_timeout_with_a_503(
    tmp_path: Path,
) -> None:
    """``python -m app`` with a 1 s graceful timeout; an 8 s IK batch is running at SIGTERM.

    The request cannot finish in time: uvicorn cancels it and the client gets a 503
    problem+json with ``Connection: close`` (before: uvicorn's plain-text 500).
    """
    settings = {
        "graceful_timeout_s": "1",
        "workers": "1",  # the /metrics in-flight gauge below is per worker
        "access_log": "false",
    }
    with serve(tmp_path / "data", settings=settings) as server:
        url, proc = server.url, server.proc
        # 8 unreachable targets at 1 s each: the batch runs ~8 s. 1.1 m away: beyond the UR5's
        # reach (~0.95 m) but inside its reach bound (1.24 m), so each is searched to the end.
        far = {"position": [1.1, 0.0, 0.1], "orientation": [0.0, 0.0, 0.0, 1.0]}
        body = {"targets": [far] * 8, "timeout_ms": 1000, "chain_seeds": False}
        result: dict[str, httpx.Response | BaseException] = {}

        def call() -> None:
            try:
                with httpx.Client(timeout=120) as own:
                    result["r"] = own.post(url + "/robots/ur5/ik/batch", json=body)
            except BaseException as exc:  # noqa: BLE001 - reported by the assertion below
                result["r"] = exc

        thread = threading.Thread(target=call)
        thread.start()
        deadline = time.monotonic() + 60
        while _in_flight(url) < 2:  # the batch and this scrape
            assert "r" not in result, f"the batch ended early: {result['r']}"
            assert time.monotonic() < deadline, "the batch never started"
            time.sleep(0.05)
        proc.send_signal(signal.SIGTERM)
        thread.join(timeout=120)
        assert not thread.is_alive()
        resp = result["r"]
        assert isinstance(resp, httpx.Response), resp
        assert resp.status_code == 503, resp.text
        assert resp.headers["content-type"] == "application/problem+json"
        problem = resp.json()
        assert problem["status"] == 503 and "shutting down" in problem["detail"]
        assert resp.headers["connection"] == "close"
        assert int(resp.headers["retry-after"]) >= 1
        assert resp.headers["x-request-id"]
        proc.wait(timeout=120)


@pytest.fixture(autouse=True)
def _no_proxy(monkeypatch: pytest.MonkeyPatch) -> None:
    """Loopback requests must not go through a proxy from the environment."""
    for name in ("HTTP_PROXY", "HTTPS_PROXY", "ALL_PROXY", "http_proxy", "https_proxy"):
        monkeypatch.delenv(name, raising=False)

"""Production behaviour: write protection, body limit, CORS, request ids and JSON logs,
metrics, responsiveness under long work, graceful shutdown on SIGTERM."""

from __future__ import annotations

import contextlib
import hmac
import os
import re
import secrets
import signal
import threading
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import httpx
import orjson
import pytest
from fastapi import Request
from fastapi.testclient import TestClient
from starlette.middleware.base import BaseHTTPMiddleware

from app.api.offload import offload
from app.main import create_app
from app.operations.metrics import METRICS, record_ik
from app.operations.settings import Settings
from tests.helpers import api_routes, parse_metrics, serve, write_routes

ROOT = Path(__file__).resolve().parents[1]
TOKEN = "test-token-0123456789"

# ---------------------------------------------------------------------------------------------
# Helpers


def fill(path: str, robot: str = "panda") -> str:
    """A concrete URL for a path template (robot ids: ``robot``; anything else: 'x')."""
    return re.sub(r"\{(\w+)\}", lambda m: robot if m[1] == "robot_id" else "x", path)


WRITE_VERBS = ("create", "import", "upload", "delete", "build", "cancel", "update", "put", "add")


@pytest.fixture(scope="module")
def guarded_app(tmp_path_factory) -> Iterator[TestClient]:
    data = tmp_path_factory.mktemp("guarded") / "data"
    app = create_app(Settings(data_dir=data, api_token=TOKEN))
    with TestClient(app, raise_server_exceptions=False) as c:
        yield c


# ---------------------------------------------------------------------------------------------
# Write protection


def test_write_routes_are_the_state_changing_ones(app) -> None:
    writes = write_routes(app)
    assert writes, "no route uses require_token"
    schema = app.openapi()["paths"]
    guarded = {(m, p) for m, p, _ in writes}
    for method, path, _ in writes:
        assert method.lower() in schema[path], (method, path)
    for path, route in api_routes(app):
        for method in route.methods:
            changes_state = method in {"PUT", "PATCH", "DELETE"} or (
                method == "POST" and route.name.startswith(WRITE_VERBS)
            )
            if changes_state:
                assert (method, path) in guarded, f"{method} {path} has no token"


@pytest.mark.parametrize(
    "auth",
    [None, "Bearer", "Bearer ", f"Basic {TOKEN}", TOKEN],
    ids=["none", "scheme-only", "empty", "basic", "no-scheme"],
)
def test_write_routes_without_a_bearer_token_are_401(guarded_app, auth) -> None:
    headers = {"authorization": auth} if auth is not None else {}
    for method, path, _ in write_routes(guarded_app.app):
        r = guarded_app.request(method, fill(path), json={}, headers=headers)
        assert r.status_code == 401, (method, path, r.text)
        assert r.headers["www-authenticate"] == "Bearer"
        assert r.headers["content-type"].startswith("application/problem+json")
        assert "authorization" in r.json()["detail"]


@pytest.mark.parametrize("wrong", [TOKEN[:-1], TOKEN + "x", "x" * len(TOKEN), TOKEN.upper()])
def test_write_routes_with_a_wrong_token_are_403(guarded_app, wrong) -> None:
    for method, path, _ in write_routes(guarded_app.app):
        r = guarded_app.request(
            method, fill(path), json={}, headers={"authorization": f"Bearer {wrong}"}
        )
        assert r.status_code == 403, (method, path, r.text)
        assert r.json()["status"] == 403


def test_write_routes_with_the_token_pass_the_guard(guarded_app) -> None:
    for method, path, _ in write_routes(guarded_app.app):
        r = guarded_app.request(
            method,
            fill(path, robot="no_such_robot"),
            json={},
            headers={"authorization": f"bearer {TOKEN}"},
        )
        assert r.status_code not in (401, 403, 500), (method, path, r.text)


def test_reads_and_computations_stay_open(guarded_app) -> None:
    guarded = {(m, p) for m, p, _ in write_routes(guarded_app.app)}
    checked = 0
    for path, route in api_routes(guarded_app.app):
        for method in route.methods:
            if (method, path) in guarded:
                continue
            kwargs = {"json": {}} if method in {"POST", "PUT", "PATCH"} else {}
            r = guarded_app.request(method, fill(path), **kwargs)
            assert r.status_code not in (401, 403, 500), (method, path, r.text)
            checked += 1
    assert checked >= 10


def test_without_a_configured_token_writes_need_none(client, app) -> None:
    for method, path, _ in write_routes(app):
        r = client.request(method, fill(path, robot="no_such_robot"), json={})
        assert r.status_code not in (401, 403, 500), (method, path, r.text)


def test_token_comparison_is_constant_time(guarded_app, monkeypatch) -> None:
    """The guard decides with a constant-time comparison of the presented and expected
    token bytes (not ``==``, whose time leaks the length of the matching prefix)."""
    calls: list[tuple[bytes, bytes]] = []
    verdict: list[bool] = []

    def spy(a, b) -> bool:
        calls.append((bytes(a), bytes(b)))
        return verdict[0] if verdict else real(a, b)

    real = hmac.compare_digest
    monkeypatch.setattr(hmac, "compare_digest", spy)
    monkeypatch.setattr(secrets, "compare_digest", spy)
    url = "/robots/no_such_robot"
    wrong = TOKEN[:-1] + "x"
    assert guarded_app.delete(url, headers={"authorization": f"Bearer {wrong}"}).status_code == 403
    assert calls == [(wrong.encode(), TOKEN.encode())]
    calls.clear()
    assert guarded_app.delete(url, headers={"authorization": f"Bearer {TOKEN}"}).status_code == 404
    assert calls == [(TOKEN.encode(), TOKEN.encode())]
    # the comparison's answer is the guard's verdict
    verdict.append(False)
    assert guarded_app.delete(url, headers={"authorization": f"Bearer {TOKEN}"}).status_code == 403


# ---------------------------------------------------------------------------------------------
# Request body limit (before parsing)


@pytest.fixture
def small_limit(tmp_path) -> Iterator[TestClient]:
    app = create_app(Settings(data_dir=tmp_path / "data", max_body_bytes=1024))
    with TestClient(app, raise_server_exceptions=False) as c:
        yield c


def _assert_413(r: httpx.Response) -> None:
    assert r.status_code == 413, r.text
    assert r.headers["content-type"].startswith("application/problem+json")
    body = r.json()
    assert body["status"] == 413 and body["field"] == "body"
    assert "DENAVIT_MAX_BODY_BYTES" in body["detail"] and "1024" in body["detail"]
    assert r.headers["connection"] == "close"


def test_body_over_the_limit_is_413_before_parsing(small_limit) -> None:
    # Malformed JSON: a parser would say 400; the limit answers first.
    r = small_limit.post(
        "/robots/panda/fk", content=b"{" * 2000, headers={"content-type": "application/json"}
    )
    _assert_413(r)
    assert "2000 bytes" in r.json()["detail"]


def test_chunked_body_over_the_limit_is_413(small_limit) -> None:
    def chunks() -> Iterator[bytes]:
        for _ in range(10):
            yield b" " * 200

    r = small_limit.post(
        "/robots/panda/fk", content=chunks(), headers={"content-type": "application/json"}
    )
    _assert_413(r)


def test_bodies_within_the_limit_pass(small_limit) -> None:
    body = orjson.dumps({"q": [0.0] * 8})
    padded = body + b" " * (1024 - len(body))
    r = small_limit.post(
        "/robots/panda/fk", content=padded, headers={"content-type": "application/json"}
    )
    assert r.status_code == 200, r.text

    def chunks() -> Iterator[bytes]:
        yield padded[:500]
        yield padded[500:]

    r = small_limit.post(
        "/robots/panda/fk", content=chunks(), headers={"content-type": "application/json"}
    )
    assert r.status_code == 200, r.text
    assert r.json()["q"] == [0.0] * 8


# ---------------------------------------------------------------------------------------------
# CORS


def test_cors_is_off_by_default(client) -> None:
    r = client.options(
        "/robots/panda/fk",
        headers={"origin": "https://evil.example", "access-control-request-method": "POST"},
    )
    assert "access-control-allow-origin" not in r.headers
    r = client.get("/robots", headers={"origin": "https://evil.example"})
    assert r.status_code == 200 and "access-control-allow-origin" not in r.headers


def test_cors_allows_only_the_configured_origins(tmp_path) -> None:
    settings = Settings(data_dir=tmp_path / "d", cors_origins=["https://app.example"])
    with TestClient(create_app(settings)) as c:
        ok = c.options(
            "/robots/panda/fk",
            headers={
                "origin": "https://app.example",
                "access-control-request-method": "POST",
                "access-control-request-headers": "authorization, content-type",
            },
        )
        assert ok.status_code == 200
        assert ok.headers["access-control-allow-origin"] == "https://app.example"
        assert "authorization" in ok.headers["access-control-allow-headers"].lower()
        r = c.get("/robots", headers={"origin": "https://app.example"})
        assert r.headers["access-control-allow-origin"] == "https://app.example"
        assert "x-request-id" in r.headers["access-control-expose-headers"].lower()
        bad = c.get("/robots", headers={"origin": "https://evil.example"})
        assert "access-control-allow-origin" not in bad.headers


def test_middleware_is_pure_asgi(app) -> None:
    for m in app.user_middleware:
        assert not (isinstance(m.cls, type) and issubclass(m.cls, BaseHTTPMiddleware)), m


# ---------------------------------------------------------------------------------------------
# Request ids and JSON logs


def test_request_id_is_echoed_or_generated(client) -> None:
    r = client.get("/health", headers={"x-request-id": "abc-123.xyz"})
    assert r.headers["x-request-id"] == "abc-123.xyz"
    generated = {client.get("/health").headers["x-request-id"] for _ in range(3)}
    assert len(generated) == 3
    assert all(re.fullmatch(r"[0-9a-f]{24}", g) for g in generated)
    for bad in ["x" * 129, "has space", "quote\"'", "<script>"]:
        got = client.get("/health", headers={"x-request-id": bad}).headers["x-request-id"]
        assert got != bad and re.fullmatch(r"[0-9a-f]{24}", got)


def test_error_responses_carry_the_request_id(client) -> None:
    for r in [
        client.get("/nowhere", headers={"x-request-id": "rid-404"}),
        client.post("/robots/panda/fk", json={"q": "x"}, headers={"x-request-id": "rid-422"}),
        client.post(
            "/robots/panda/fk",
            content=b"{",
            headers={"x-request-id": "rid-400", "content-type": "application/json"},
        ),
    ]:
        assert r.headers["x-request-id"] == f"rid-{r.status_code}"


def _json_lines(text: str) -> list[dict]:
    out = []
    for line in text.splitlines():
        with contextlib.suppress(orjson.JSONDecodeError):
            doc = orjson.loads(line)
            if isinstance(doc, dict):
                out.append(doc)
    return out


def test_access_log_is_one_json_line_per_request(client, capsys) -> None:
    capsys.readouterr()
    r = client.post("/robots/panda/fk", json={"q": [0.0] * 8}, headers={"x-request-id": "log-1"})
    assert r.status_code == 200
    lines = [d for d in _json_lines(capsys.readouterr().err) if d.get("request_id") == "log-1"]
    access = [d for d in lines if d["logger"] == "denavit.access"]
    assert len(access) == 1
    line = access[0]
    assert line["method"] == "POST" and line["path"] == "/robots/panda/fk"
    assert line["route"] == "/robots/{robot_id}/fk" and line["status"] == 200
    assert line["level"] == "info" and line["duration_ms"] > 0
    assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}\+00:00", line["ts"])


def test_access_log_can_be_turned_off(tmp_path, capsys) -> None:
    with TestClient(create_app(Settings(data_dir=tmp_path / "d", access_log=False))) as c:
        capsys.readouterr()
        c.get("/health", headers={"x-request-id": "quiet"})
        lines = _json_lines(capsys.readouterr().err)
    assert not [d for d in lines if d.get("logger") == "denavit.access"]


def test_logs_inside_a_request_and_in_the_pool_carry_its_id(tmp_path, capsys) -> None:
    import logging

    app = create_app(Settings(data_dir=tmp_path / "d"))
    log = logging.getLogger("denavit.test")

    def work() -> int:
        log.warning("in the pool")
        return 1

    @app.get("/_test/log")
    async def _log(request: Request) -> dict:
        log.warning("on the loop")
        return {"n": await offload(request, work)}

    @app.get("/_test/boom")
    async def _boom() -> dict:
        raise RuntimeError("kaput")

    with TestClient(app, raise_server_exceptions=False) as c:
        capsys.readouterr()
        assert c.get("/_test/log", headers={"x-request-id": "rid-ctx"}).json() == {"n": 1}
        r = c.get("/_test/boom", headers={"x-request-id": "rid-boom"})
        lines = _json_lines(capsys.readouterr().err)
    ours = {d["message"]: d for d in lines if d.get("logger") == "denavit.test"}
    assert ours["on the loop"]["request_id"] == "rid-ctx"
    assert ours["in the pool"]["request_id"] == "rid-ctx"
    assert r.status_code == 500 and r.json()["status"] == 500
    errors = [d for d in lines if d.get("request_id") == "rid-boom" and d["level"] == "error"]
    assert errors and "RuntimeError: kaput" in errors[0]["exc_info"]
    access = [d for d in lines if d.get("request_id") == "rid-boom" and "status" in d]
    assert access[0]["status"] == 500


# ---------------------------------------------------------------------------------------------
# Metrics


def test_metrics_count_requests_per_route_template(client) -> None:
    fk = 'method="POST",route="/robots/{robot_id}/fk"'
    before = parse_metrics(client.get("/metrics").text)
    for rid in ("panda", "ur5", "panda"):
        n = 8 if rid == "panda" else 6
        assert client.post(f"/robots/{rid}/fk", json={"q": [0.0] * n}).status_code == 200
    assert client.post("/robots/panda/fk", json={"q": [0.0]}).status_code == 422
    client.get("/no/such/1")
    client.get("/no/such/2")
    r = client.get("/metrics")
    assert r.headers["content-type"] == "text/plain; version=0.0.4; charset=utf-8"
    after = parse_metrics(r.text)

    def delta(key: str) -> float:
        return after.get(key, 0.0) - before.get(key, 0.0)

    assert delta(f'denavit_http_requests_total{{{fk},status="200"}}') == 3
    assert delta(f'denavit_http_requests_total{{{fk},status="422"}}') == 1
    unmatched = 'denavit_http_requests_total{method="GET",route="unmatched",status="404"}'
    assert delta(unmatched) == 2
    assert not any("/no/such" in k for k in after)
    assert delta(f"denavit_http_request_duration_seconds_count{{{fk}}}") == 4
    buckets = [  # prometheus_client writes labels sorted by name: `le` first
        v
        for k, v in after.items()
        if k.startswith("denavit_http_request_duration_seconds_bucket{le=") and k.endswith(fk + "}")
    ]
    assert len(buckets) == 16 and buckets == sorted(buckets)  # cumulative
    inf = after[f'denavit_http_request_duration_seconds_bucket{{le="+Inf",{fk}}}']
    assert inf == after[f"denavit_http_request_duration_seconds_count{{{fk}}}"]
    assert after[f"denavit_http_request_duration_seconds_sum{{{fk}}}"] > 0
    assert after[f'process_resident_memory_bytes{{pid="{os.getpid()}"}}'] > 10e6
    assert after["denavit_http_requests_in_flight"] == 1  # this scrape
    assert after[f'denavit_process_info{{pid="{os.getpid()}"}}'] == 1


def test_record_ik_counts_outcomes(client) -> None:
    before = parse_metrics(client.get("/metrics").text)
    record_ik(True)
    record_ik(True)
    record_ik(False)
    after = parse_metrics(client.get("/metrics").text)
    ok, bad = (
        'denavit_ik_requests_total{result="success"}',
        'denavit_ik_requests_total{result="failure"}',
    )
    assert after[ok] - before[ok] == 2
    assert after[bad] - before[bad] == 1


def test_metric_label_values_are_escaped() -> None:
    from app.operations.metrics import Metrics

    m = Metrics()
    m.observe("GET", 'a"b\\c\nd', 200, 0.001)
    text = m.render().decode()
    assert 'route="a\\"b\\\\c\\nd"' in text
    parse_metrics(text)
    assert METRICS is not m


# ---------------------------------------------------------------------------------------------
# A live server: responsiveness under long work, graceful shutdown

#: An IK batch that cannot converge: each target takes its whole 1000 ms budget (1.0 m from the
#: panda's shoulder: beyond its reach, ~0.95 m, but inside the reach bound, 1.09 m, that would
#: answer unreachable at once).
SLOW_IK = {"targets": [{"position": [0.0, 1.0, 0.333]}] * 3, "mode": "position", "timeout_ms": 1000}


def test_health_answers_while_long_batches_run(tmp_path) -> None:
    with serve(tmp_path / "data", settings={"access_log": "false"}) as server:
        with ThreadPoolExecutor(max_workers=4) as pool:
            slow = [
                pool.submit(
                    httpx.post, server.url + "/robots/panda/ik/batch", json=SLOW_IK, timeout=120
                )
                for _ in range(4)
            ]
            with httpx.Client(base_url=server.url, timeout=30) as c:
                while c.get("/metrics").text.count("denavit_http_requests_in_flight 5") == 0:
                    assert not any(f.done() for f in slow), [f.result().text for f in slow]
                    time.sleep(0.05)
                health = [c.get("/health") for _ in range(5)]
                still_running = sum(not f.done() for f in slow)
            answers = [f.result() for f in slow]
    assert [h.status_code for h in health] == [200] * 5
    assert still_running >= 1  # /health answered while long work was in flight
    assert [a.status_code for a in answers] == [200] * 4
    assert all(a.json()["solved"] == 0 for a in answers)


def test_sigterm_lets_in_flight_requests_finish(tmp_path) -> None:
    with serve(tmp_path / "data", settings={"graceful_timeout_s": "60"}) as server:
        result: dict[str, httpx.Response] = {}

        def call() -> None:
            result["r"] = httpx.post(
                server.url + "/robots/panda/ik/batch",
                json=SLOW_IK,
                headers={"x-request-id": "in-flight"},
                timeout=120,
            )

        worker = threading.Thread(target=call)
        worker.start()
        while "denavit_http_requests_in_flight 2" not in httpx.get(server.url + "/metrics").text:
            assert worker.is_alive()
            time.sleep(0.05)
        server.proc.send_signal(signal.SIGTERM)
        worker.join(timeout=120)
        code = server.proc.wait(timeout=60)
        lines = server.log_lines()
    assert result["r"].status_code == 200, result["r"].text
    assert len(result["r"].json()["results"]) == 3
    assert code in (0, -signal.SIGTERM)  # uvicorn re-raises the signal after a clean shutdown
    messages = [d["message"] for d in lines]
    assert "denavit stopped" in messages
    done = [d for d in lines if d.get("request_id") == "in-flight" and "status" in d]
    assert done and done[0]["status"] == 200
    # every line the server wrote is JSON
    assert len(lines) == len(server.log.read_text().splitlines())


def test_live_server_refuses_big_bodies(tmp_path) -> None:
    with serve(tmp_path / "data", settings={"max_body_bytes": "4096"}) as server:
        with httpx.Client(base_url=server.url, timeout=30) as c:
            big = c.post(
                "/robots/panda/fk/batch",
                content=b"[" * 1_000_000,
                headers={"content-type": "application/json"},
            )
            assert big.status_code == 413
            assert big.json()["field"] == "body"
            ok = c.post("/robots/panda/fk", json={"q": [0.0] * 8})
            assert ok.status_code == 200

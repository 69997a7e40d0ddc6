"""HTTP protocol contract: malformed bodies, methods (405 ``Allow``, ``HEAD``), in-process.

The live-server side (connections after a 500, SIGTERM mid-request) is in
tests/test_live_protocol.py.
"""

from __future__ import annotations

import re

import pytest
from fastapi.routing import iter_route_contexts
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings

#: Any path parameter gets an existing catalog robot (or a harmless name): the body must be
#: refused before the parameter matters.
_PARAMS = {"robot_id": "ur5"}


def _concrete(template: str) -> str:
    return re.sub(r"\{(\w+)(:\w+)?\}", lambda m: _PARAMS.get(m.group(1), "x"), template)


#: Operations whose body is a multipart form, not JSON: a JSON body is a 415 there.
MULTIPART_ROUTES = {("POST", "/robots/package")}


def _body_routes() -> list[tuple[str, str]]:
    """(method, path) of every documented operation that takes a JSON request body."""
    app = create_app(Settings())
    out = []
    for rc in iter_route_contexts(app.routes):
        if not getattr(rc, "include_in_schema", False):
            continue
        for method in sorted((rc.methods or set()) & {"POST", "PUT", "PATCH"}):
            if (method, rc.path) not in MULTIPART_ROUTES:
                out.append((method, _concrete(rc.path)))
    return out


BODY_ROUTES = _body_routes()


def test_every_body_style_is_covered() -> None:
    """Both decoders are exercised: routes decoding their own body and FastAPI-decoded ones."""
    paths = {p for _, p in BODY_ROUTES}
    assert "/robots/ur5/fk/batch" in paths  # fast path: parse_json (orjson, then json)
    assert "/robots/ur5/fk" in paths  # FastAPI: starlette json.loads + pydantic
    assert "/robots/urdf" in paths and "/robots/dh" in paths  # uploads
    assert len(BODY_ROUTES) >= 15


@pytest.mark.parametrize(("method", "path"), sorted(MULTIPART_ROUTES))
def test_multipart_routes_refuse_json_with_415(client: TestClient, method: str, path: str) -> None:
    resp = client.request(
        method, path, content=b"[[[]]]", headers={"content-type": "application/json"}
    )
    assert resp.status_code == 415, resp.text
    assert resp.json()["field"] == "content-type"


def _deep(depth: int) -> list[bytes]:
    nested = b"[" * depth + b"]" * depth
    return [nested, b'{"q": ' + nested + b"}"]


@pytest.mark.parametrize("depth", [10_000, 100_000])
@pytest.mark.parametrize(("method", "path"), BODY_ROUTES)
def test_deeply_nested_json_is_a_400_naming_the_body(
    client: TestClient, method: str, path: str, depth: int
) -> None:
    for raw in _deep(depth):
        resp = client.request(
            method, path, content=raw, headers={"content-type": "application/json"}
        )
        assert resp.status_code == 400, (method, path, resp.status_code, resp.text[:300])
        assert resp.headers["content-type"] == "application/problem+json"
        body = resp.json()
        assert body["field"] == "body", body
        assert body["detail"].startswith("body: "), body


@pytest.mark.parametrize(("method", "path"), BODY_ROUTES)
def test_non_utf8_body_is_a_400_naming_the_body(client: TestClient, method: str, path: str) -> None:
    resp = client.request(
        method, path, content=b'{"q": "\xff\xfe"}', headers={"content-type": "application/json"}
    )
    assert resp.status_code == 400, (method, path, resp.status_code, resp.text[:300])
    assert resp.json()["field"] == "body"


def test_an_unexpected_exception_is_a_logged_500_problem(
    settings: Settings, caplog: pytest.LogCaptureFixture
) -> None:
    """Answered (with the request id) and logged with its traceback, not re-raised.

    ``TestClient`` re-raises what the application lets escape: before, this test saw the
    ``RuntimeError`` itself (the same escape made uvicorn drop the connection).
    """
    app = create_app(settings)

    @app.get("/test/bug")
    async def bug() -> None:
        raise RuntimeError("a bug, on purpose")

    with TestClient(app) as client:  # raise_server_exceptions=True
        resp = client.get("/test/bug", headers={"x-request-id": "bug-1"})
    assert resp.status_code == 500
    assert resp.headers["content-type"] == "application/problem+json"
    assert resp.headers["x-request-id"] == "bug-1"
    assert resp.json()["detail"] == "internal error"
    [record] = [r for r in caplog.records if r.exc_info and "/test/bug" in r.getMessage()]
    assert isinstance(record.exc_info[1], RuntimeError)


# ------------------------------------------------------------------------ methods, Allow, HEAD
_ALL_METHODS = ("GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS")


def _methods_by_path() -> dict[str, set[str]]:
    """Path template → the methods its routes declare, plus HEAD wherever GET is."""
    app = create_app(Settings())
    out: dict[str, set[str]] = {}
    for rc in iter_route_contexts(app.routes):
        if rc.methods is not None:
            out.setdefault(rc.path, set()).update(rc.methods)
    for methods in out.values():
        if "GET" in methods:
            methods.add("HEAD")
    return out


METHODS_BY_PATH = _methods_by_path()


def test_reserved_paths_are_not_robot_ids() -> None:
    assert METHODS_BY_PATH["/robots/dh"] == METHODS_BY_PATH["/robots/urdf"] == {"POST"}
    assert METHODS_BY_PATH["/robots/{robot_id}"] == {"GET", "HEAD", "DELETE"}
    assert METHODS_BY_PATH["/scenes"] == {"GET", "HEAD", "POST"}


@pytest.mark.parametrize("template", sorted(METHODS_BY_PATH))
def test_every_405_allows_exactly_the_methods_of_its_path(
    client: TestClient, template: str
) -> None:
    expected = METHODS_BY_PATH[template]
    path = _concrete(template)
    for method in sorted(set(_ALL_METHODS) - expected):
        resp = client.request(method, path)
        assert resp.status_code == 405, (method, path, resp.status_code)
        assert resp.headers["content-type"] == "application/problem+json"
        allow = {m.strip() for m in resp.headers["allow"].split(",")}
        assert allow == expected, (method, path)


@pytest.mark.parametrize(
    "template", sorted(t for t, methods in METHODS_BY_PATH.items() if "GET" in methods)
)
def test_head_answers_like_get_without_a_body(client: TestClient, template: str) -> None:
    path = _concrete(template)
    get = client.get(path, follow_redirects=False)
    head = client.head(path, follow_redirects=False)
    assert head.status_code == get.status_code, path
    assert head.content == b"", path
    assert head.headers.get("content-type") == get.headers.get("content-type"), path
    assert head.headers.get("content-length") == get.headers.get("content-length") or (
        template == "/metrics"  # the scrape counts the requests before it: lengths differ
    ), path
    assert get.headers.get("content-length") == str(len(get.content)), path

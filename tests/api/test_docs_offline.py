"""/docs, /redoc and /static from the package: no URL off this server, assets that answer.

The pages themselves are checked in Chromium by tests/browser/test_docs_pages.py; here the
HTML is read as text: every URL in it is relative to this server and answers 200 with the
type its extension says, and ``/static`` serves its files and nothing outside them.
"""

from __future__ import annotations

import asyncio
import re
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.api.static_files import STATIC_DIR
from app.main import create_app
from tests.helpers import ROOT, parse_metrics, problem

PAGES = ["/docs", "/redoc", "/docs/oauth2-redirect"]
ABSOLUTE_URL = re.compile(r"""(?:https?:)?//[^\s"'<>)]+""", re.IGNORECASE)
#: Local URLs a page loads: src/href attributes, Swagger UI's ``url: '...'``, ReDoc's
#: ``spec-url``.
REFERENCED = re.compile(r"""(?:\b(?:src|href|spec-url)="|\burl: ')([^"']+)""")
TYPES = {
    ".js": "text/javascript",
    ".css": "text/css",
    ".png": "image/png",
    ".json": "application/json",
}


def _type_of(url: str) -> str:
    return TYPES[Path(url.split("?")[0]).suffix]


@pytest.mark.parametrize("page", PAGES)
def test_pages_name_no_other_server(client, page: str) -> None:
    r = client.get(page)
    assert r.status_code == 200, r.text
    assert r.headers["content-type"].startswith("text/html")
    # "//host/..." too (scheme-relative); the test client's own host would be allowed.
    urls = ABSOLUTE_URL.findall(r.text)
    foreign = [u for u in urls if not u.split("//")[1].startswith("testserver")]
    assert foreign == [], f"{page} loads from elsewhere: {foreign}"
    assert "googleapis" not in r.text and "jsdelivr" not in r.text


@pytest.mark.parametrize(("page", "expected"), [("/docs", 4), ("/redoc", 3)])
def test_every_asset_a_page_references_answers(client, page: str, expected: int) -> None:
    html = client.get(page).text
    urls = REFERENCED.findall(html)
    assert len(urls) == expected, urls  # script, styles, favicon, the OpenAPI document
    for url in urls:
        assert url.startswith("/"), url
        r = client.get(url)
        assert r.status_code == 200, (url, r.status_code)
        assert r.headers["content-type"].startswith(_type_of(url)), (url, r.headers)
        assert len(r.content) > 0, url
        if url.startswith("/static/"):  # the packaged file, byte for byte
            assert r.content == (STATIC_DIR / url.removeprefix("/static/")).read_bytes(), url


def test_swagger_ui_does_not_call_the_online_validator(client) -> None:
    html = client.get("/docs").text
    assert '"validatorUrl": null' in html


def test_redoc_bundle_fetches_no_logo_from_its_cdn(client) -> None:
    """ReDoc 2 shows Redocly's logo from cdn.redoc.ly: the bundle served has none."""
    html = client.get("/redoc").text
    (script,) = re.findall(r'<script src="([^"]+)"', html)
    served = client.get(script).content
    assert b"cdn.redoc.ly" not in served
    assert b"Redoc" in served and len(served) > 500_000  # the bundle, not a stub


def test_root_path_prefixes_every_url(tmp_path) -> None:
    """Behind a proxy at /denavit, the pages load everything under that prefix."""
    app = create_app()
    with TestClient(app, root_path="/denavit") as c:
        for page in ("/docs", "/redoc"):
            urls = REFERENCED.findall(c.get(page).text)
            assert urls and all(u.startswith("/denavit/") for u in urls), (page, urls)
        assert "window.location.origin + '/denavit/docs/oauth2-redirect'" in c.get("/docs").text


async def _raw_get(app, path: str) -> tuple[int, bytes]:
    """GET ``path`` exactly as given (a client would remove dot segments), straight through
    the ASGI application: its status and body."""
    messages: list[dict] = []
    requests = [{"type": "http.request", "body": b"", "more_body": False}]

    async def receive() -> dict:
        return requests.pop() if requests else {"type": "http.disconnect"}

    async def send(message: dict) -> None:
        messages.append(message)

    scope = {
        "type": "http", "asgi": {"version": "3.0"}, "http_version": "1.1", "method": "GET",
        "scheme": "http", "path": path, "raw_path": path.encode(), "query_string": b"",
        "root_path": "", "headers": [(b"host", b"testserver")],
        "client": ("127.0.0.1", 50000), "server": ("testserver", 80),
    }  # fmt: skip
    await app(scope, receive, send)
    body = b"".join(m.get("body", b"") for m in messages if m["type"] == "http.response.body")
    return messages[0]["status"], body


def test_static_serves_its_files_and_nothing_else(app, client) -> None:
    assert len([r for r in app.routes if getattr(r, "name", None) == "static"]) == 1
    r = client.get("/static/vendor/manifest.json")
    assert r.status_code == 200
    assert r.content == (STATIC_DIR / "vendor" / "manifest.json").read_bytes()
    problem(client.get("/static/vendor/does-not-exist"), 404)
    problem(client.get("/static/vendor/"), 404)  # no directory listings
    problem(client.get("/static/%2e%2e/main.py"), 404)
    problem(client.get("/static/%2e%2e/%2e%2e/app/main.py"), 404)
    source = (ROOT / "app" / "main.py").read_bytes()
    for path in ("/static/../main.py", "/static/vendor/../../main.py", "/static/..%2fmain.py"):
        status, body = asyncio.run(_raw_get(app, path))
        assert status == 404, (path, body)
        assert b"create_app" not in body and body != source


def test_metrics_label_the_pages_and_static_files_by_route(client) -> None:
    """Not ``unmatched`` (the label of requests no route takes): ``/docs``, ``/static``."""

    def counts() -> dict[tuple[str, int], float]:
        samples = parse_metrics(client.get("/metrics").text)
        return {
            (route, status): samples.get(
                f'denavit_http_requests_total{{method="GET",route="{route}",status="{status}"}}',
                0.0,
            )
            for route, status in (("/docs", 200), ("/static", 200), ("/static", 404))
        }

    before = counts()
    client.get("/docs")
    client.get("/static/vendor/manifest.json")
    client.get("/static/vendor/does-not-exist")
    after = counts()
    assert {k: after[k] - before[k] for k in before} == {
        ("/docs", 200): 1,
        ("/static", 200): 1,
        ("/static", 404): 1,
    }

"""/docs (Swagger UI) and /redoc (ReDoc) render the whole API in Chromium, offline.

The ``page`` fixture aborts every request to another host (as a machine without internet
would) and records it: a page that needs a CDN fails here, on its missing operations and on
``tab.external``. The operations rendered are compared with the server's /openapi.json.
"""

from __future__ import annotations

from tests.browser.tools import Tab

METHODS = {"get", "put", "post", "delete", "patch", "head", "options", "trace"}


def _operations(tab: Tab) -> dict[tuple[str, str], str]:
    """(METHOD, path) → operationId of every operation in the server's /openapi.json."""
    spec = tab.http.get("/openapi.json").json()
    return {
        (method.upper(), path): op["operationId"]
        for path, item in spec["paths"].items()
        for method, op in item.items()
        if method in METHODS
    }


def test_swagger_ui_lists_every_operation_offline(page: Tab) -> None:
    expected = _operations(page)
    assert ("POST", "/robots/{robot_id}/fk") in expected
    page.goto("/docs")
    page.page.wait_for_function("document.querySelectorAll('.swagger-ui .opblock').length > 0")
    shown = page.page.evaluate(
        """[...document.querySelectorAll('.swagger-ui .opblock')].map(b => [
            b.querySelector('.opblock-summary-method').textContent.trim(),
            b.querySelector('.opblock-summary-path').getAttribute('data-path'),
        ])"""
    )
    assert len(shown) == len(expected)
    assert {tuple(s) for s in shown} == set(expected)
    title = page.page.locator(".swagger-ui .info .title").inner_text()
    assert title.startswith("Denavit")
    page.shot("docs")
    assert page.external == []
    assert page.errors() == []


def test_redoc_shows_every_operation_offline(page: Tab) -> None:
    expected = _operations(page)
    page.goto("/redoc")
    page.page.wait_for_function(
        "document.querySelectorAll('[data-section-id^=\"operation/\"]').length > 0"
    )
    sections = page.page.evaluate(
        """[...document.querySelectorAll('[data-section-id^="operation/"]')]
            .map(s => s.getAttribute('data-section-id'))"""
    )
    assert len(sections) == len(expected)
    assert {s.removeprefix("operation/") for s in sections} == set(expected.values())
    assert "operation/compute_fk" in sections
    page.shot("redoc")
    assert page.external == []
    assert page.errors() == []

"""The viewer against a server whose write routes are guarded (``DENAVIT_API_TOKEN``).

Reads work without a token; a write from the page (building a reachability map) is
refused with the API's problem shown, until the token is typed into the page's field.
The token travels only in the Authorization header, never in a URL, and is kept nowhere
another script of the origin could read it: not in the field (emptied once read), not in
sessionStorage, localStorage or a cookie. "Clear" forgets it; so does a reload.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from tests.browser.tools import Tab, open_viewer, wait_idle
from tests.helpers import Server, serve

TOKEN = "viewer-test-token-7f3a"


@pytest.fixture(scope="module")
def live(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    """This module's server: write routes need ``Authorization: Bearer TOKEN``."""
    data = tmp_path_factory.mktemp("browser-token-data")
    with serve(data, settings={"workers": "1", "api_token": TOKEN}) as server:
        yield server


def build_in_page(tab: Tab) -> None:
    tab.page.fill("#map-voxel", "0.2")
    tab.page.fill("#map-samples", "3000")
    tab.page.click("#map-build")
    wait_idle(tab)


def test_writes_need_the_token_typed_into_the_page(page: Tab) -> None:
    authorizations: list[str | None] = []
    urls: list[str] = []

    def record(request) -> None:
        urls.append(request.url)
        if request.method == "POST" and request.url.endswith("/reachability"):
            authorizations.append(request.headers.get("authorization"))

    page.page.on("request", record)
    open_viewer(page, "panda")  # reads: no token needed
    assert page.errors() == []

    build_in_page(page)  # without the token: the API's 401 problem, shown
    status = page.page.inner_text("#status")
    assert status.startswith("401: authorization:"), status
    assert page.http.get("/robots/panda/reachability/maps").json()["maps"] == []
    assert authorizations == [None]

    page.page.click("#token-box summary")
    page.page.fill("#token", TOKEN)
    page.page.dispatch_event("#token", "change")
    build_in_page(page)
    page.page.wait_for_function("denavit.panels.reachability.shown !== null && denavit.idle()")
    maps = page.http.get("/robots/panda/reachability/maps").json()["maps"]
    assert len(maps) == 1
    assert page.page.evaluate("denavit.panels.reachability.shown.map_id") == maps[0]["map_id"]
    assert authorizations == [None, f"Bearer {TOKEN}"]
    assert not [u for u in urls if TOKEN in u]
    # Held by the page's script only: the field is empty and says a token is set.
    assert page.page.input_value("#token") == ""
    assert page.page.inner_text("#token-state") == "token set"
    kept = page.page.evaluate(
        """[sessionStorage.length, localStorage.length, document.cookie,
            JSON.stringify({...sessionStorage}), JSON.stringify({...localStorage})]"""
    )
    assert kept[:2] == [0, 0] and TOKEN not in "".join(map(str, kept)), kept
    page.shot("built-map")

    page.page.click("#token-clear")  # forgotten: the next write goes without it
    assert page.page.inner_text("#token-state") == "no token"
    build_in_page(page)
    assert page.page.inner_text("#status").startswith("401: authorization:")
    page.page.fill("#token", TOKEN)
    page.page.dispatch_event("#token", "change")
    page.page.reload()  # a reload asks for the token again
    wait_idle(page)
    assert page.page.text_content("#token-state") == "no token"  # in the closed box
    build_in_page(page)
    assert page.page.inner_text("#status").startswith("401: authorization:")
    assert authorizations == [None, f"Bearer {TOKEN}", None, None]
    assert not [u for u in urls if TOKEN in u]
    # The browser logs the refused requests; nothing else went wrong.
    assert page.page_errors == [] and page.external == []
    assert all("status of 401" in e for e in page.console_errors), page.console_errors

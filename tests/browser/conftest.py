"""Browser tests: Playwright for Python driving Debian's ``chromium`` (not Playwright's own).

Fixtures (module scope: one live server and one browser per test module and xdist worker):

- ``live``: ``python -m app``'s server (:func:`tests.helpers.serve`) on a free port, with
  its own data directory, stopped by PID afterwards.
- ``browser``: headless Chromium at ``DENAVIT_CHROMIUM`` (default ``/usr/bin/chromium``).
  A missing browser fails the tests (``make browser`` installs it); it never skips them.
- ``page``: a fresh context and page per test, wrapped in :class:`tests.browser.tools.Tab`,
  which records console errors, page errors and any request that would leave the machine
  (such requests are aborted: the tests run as if offline). Every Playwright wait and
  action may take :data:`tests.browser.tools.WAIT_MS`.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.browser.tools import CHROMIUM_ARGS, WAIT_MS, Tab
from tests.helpers import Server, serve


@pytest.fixture(scope="module")
def live(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Server]:
    data = tmp_path_factory.mktemp("browser-data")
    with serve(data, settings={"workers": "1"}) as server:
        yield server


@pytest.fixture(scope="module")
def browser() -> Iterator[object]:
    from playwright.sync_api import sync_playwright

    chromium = os.environ.get("DENAVIT_CHROMIUM", "/usr/bin/chromium")
    if not Path(chromium).is_file():
        pytest.fail(f"no Chromium at {chromium}: `make browser` installs Debian's chromium")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=chromium, args=CHROMIUM_ARGS)
        try:
            yield b
        finally:
            b.close()


@pytest.fixture
def page(browser, live: Server, request: pytest.FixtureRequest) -> Iterator[Tab]:
    context = browser.new_context(viewport={"width": 1280, "height": 800})
    context.set_default_timeout(WAIT_MS)  # every wait and action: Chromium renders on the CPU
    try:
        tab = Tab(context.new_page(), live.url, request.node.name)
        with tab.http:  # the test's own API client, closed with the page
            yield tab
    finally:
        context.close()

"""What the browser tests share: Chromium's flags, a page that records errors, screenshots.

Screenshots are test artifacts: ``test-artifacts/browser/<test>-<state>.png`` under the
repository (``DENAVIT_TEST_ARTIFACTS`` to put them elsewhere). Each one must be non-blank:
the standard deviation of its grey levels is at least :data:`MIN_PIXEL_STD`.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from urllib.parse import urlsplit

import httpx
from PIL import Image, ImageStat

ROOT = Path(__file__).resolve().parents[2]

#: Headless, no GPU (WebGL through SwiftShader), and none of Chromium's own background
#: connections (updates, sync, safe browsing), which a closed network refuses.
CHROMIUM_ARGS = [
    "--headless=new",
    "--no-sandbox",
    "--disable-gpu",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
]

MIN_PIXEL_STD = 8.0
LOCAL_HOSTS = {"127.0.0.1", "localhost"}


def artifacts_dir() -> Path:
    path = Path(os.environ.get("DENAVIT_TEST_ARTIFACTS", ROOT / "test-artifacts")) / "browser"
    path.mkdir(parents=True, exist_ok=True)
    return path


def pixel_std(png: Path) -> float:
    """Standard deviation of the grey levels of an image (0 for a blank one)."""
    with Image.open(png) as im:
        return ImageStat.Stat(im.convert("L")).stddev[0]


class Tab:
    """A Playwright page on the live server that records what went wrong.

    ``console_errors`` and ``page_errors`` collect the page's console errors and uncaught
    exceptions; ``external`` every request to a host other than this machine (aborted, so
    the page behaves as it would offline).
    """

    def __init__(self, page, base_url: str, test_name: str) -> None:
        self.page, self.url = page, base_url
        self.name = re.sub(r"[^A-Za-z0-9_.-]+", "_", test_name)
        self.console_errors: list[str] = []
        self.page_errors: list[str] = []
        self.external: list[str] = []
        page.on("console", self._console)
        page.on("pageerror", lambda exc: self.page_errors.append(str(exc)))
        page.route("**/*", self._route)
        self.http = httpx.Client(base_url=base_url, timeout=60)

    def _console(self, msg) -> None:
        if msg.type == "error":
            self.console_errors.append(f"{msg.text} @ {msg.location}")

    def _route(self, route) -> None:
        host = urlsplit(route.request.url).hostname
        if host in LOCAL_HOSTS:
            route.continue_()
        else:
            self.external.append(route.request.url)
            route.abort("internetdisconnected")

    def goto(self, path: str) -> None:
        self.page.goto(self.url + path, wait_until="load")

    def errors(self) -> list[str]:
        """Console errors, page errors and external requests, all in one list."""
        return self.console_errors + self.page_errors + [f"external: {u}" for u in self.external]

    def shot(self, state: str, selector: str | None = None) -> Path:
        """Save a screenshot of the page (or one element) and assert it is not blank."""
        path = artifacts_dir() / f"{self.name}-{state}.png"
        target = self.page.locator(selector) if selector else self.page
        target.screenshot(path=str(path))
        std = pixel_std(path)
        assert std >= MIN_PIXEL_STD, f"{path} looks blank (grey-level std {std:.2f})"
        return path

"""What the browser tests share: Chromium's flags, a page that records errors, screenshots.

The viewer's helpers open a robot and wait until the page is idle (``denavit.idle()``:
loaded, no request in flight), and read what it draws (``framePose``: three.js, root frame)
next to the API's own answers.

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
import numpy as np
import pytest
from PIL import Image, ImageChops, ImageStat

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
#: Playwright's timeout for every wait and action of a test page (the ``page`` fixture):
#: generous, Chromium renders on the CPU and shares 2 cores with the server and other tests.
WAIT_MS = 90_000


def artifacts_dir() -> Path:
    path = Path(os.environ.get("DENAVIT_TEST_ARTIFACTS", ROOT / "test-artifacts")) / "browser"
    path.mkdir(parents=True, exist_ok=True)
    return path


def pixel_std(png: Path) -> float:
    """Standard deviation of the grey levels of an image (0 for a blank one)."""
    with Image.open(png) as im:
        return ImageStat.Stat(im.convert("L")).stddev[0]


def pixels_changed(a: Path, b: Path) -> float:
    """Fraction of the pixels that differ between two screenshots of the same size."""
    with Image.open(a) as im_a, Image.open(b) as im_b:
        diff = ImageChops.difference(im_a.convert("RGB"), im_b.convert("RGB")).convert("L")
        changed = sum(diff.point(lambda v: 255 if v > 16 else 0).histogram()[255:])
        return changed / (diff.width * diff.height)


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


# ------------------------------------------------------------------------- the viewer
#: Bent, well-conditioned configurations, away from the neutrals' stretched elbows.
BENT = {
    "panda": [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.785, 0.0],
    "ur5": [0.3, -1.2, 1.4, -1.6, -1.5, 0.2],
}


def wait_idle(tab: Tab) -> None:
    """Wait until the viewer is loaded and has no request in flight."""
    tab.page.wait_for_function("window.denavit && window.denavit.idle()")


def open_viewer(tab: Tab, robot_id: str) -> dict:
    """Open /viewer/{robot_id}, wait until loaded and idle; the robot's GET /robots/{id}."""
    tab.goto(f"/viewer/{robot_id}")
    wait_idle(tab)
    return tab.http.get(f"/robots/{robot_id}").json()


def set_q(tab: Tab, q: list[float]) -> None:
    """Pose the robot in the page (as its own controls do) and wait until it is idle."""
    tab.page.evaluate("q => denavit.viewer.setQ(q.slice(), 'test')", q)
    wait_idle(tab)


def page_q(tab: Tab) -> list[float]:
    return tab.page.evaluate("denavit.viewer.q")


def rendered_pose(tab: Tab, frame: str) -> dict:
    """The frame's pose as the page draws it (three.js, root frame)."""
    return tab.page.evaluate("f => denavit.viewer.robot.framePose(f)", frame)


def api_fk(tab: Tab, robot_id: str, q: list[float], frame: str) -> dict:
    resp = tab.http.post(f"/robots/{robot_id}/fk", json={"q": q, "frames": [frame]})
    assert resp.status_code == 200, resp.text
    return resp.json()["poses"][frame]


def rotation_angle(qa: list[float], qb: list[float]) -> float:
    """Angle (rad) of the rotation between two unit quaternions [x, y, z, w], well
    conditioned near zero (atan2 of the relative rotation's vector part and scalar)."""
    xa, ya, za, wa = qa
    xb, yb, zb, wb = qb
    # conj(qa) * qb, Hamilton product
    w = wa * wb + xa * xb + ya * yb + za * zb
    v = np.array(
        [
            wa * xb - xa * wb - ya * zb + za * yb,
            wa * yb - ya * wb - za * xb + xa * zb,
            wa * zb - za * wb - xa * yb + ya * xb,
        ]
    )
    return float(2 * np.arctan2(np.linalg.norm(v), abs(w)))


def assert_reaches(answer: dict, reached: dict, target: dict, tol: float = 1e-5) -> None:
    """An IK success holds its contract: the pose reached (FK of the answer's q, computed
    independently of the solver) is within the success tolerance of the target, and the
    errors the answer reports are the true ones."""
    position_error = float(np.linalg.norm(np.subtract(reached["position"], target["position"])))
    angle = rotation_angle(reached["orientation"], target["orientation"])
    assert position_error <= tol, (position_error, answer["position_error"])
    assert angle <= tol, (angle, answer["orientation_error"])
    assert answer["position_error"] == pytest.approx(position_error, abs=1e-12)
    assert answer["orientation_error"] == pytest.approx(angle, abs=1e-9)


def assert_same_pose(a: dict, b: dict, tol: float = 1e-9) -> None:
    np.testing.assert_allclose(a["position"], b["position"], atol=tol)
    qa, qb = np.array(a["orientation"]), np.array(b["orientation"])
    assert min(np.abs(qa - qb).max(), np.abs(qa + qb).max()) < tol, (qa, qb)


# ------------------------------------------------------------------ dynamics (stubbed)
def stub_dynamics(tab: Tab, answer) -> list[dict]:
    """Answer the page's POST /robots/{id}/dynamics in the browser, without the server.

    ``answer(robot_id, body)`` returns ``(status, json)``: a ``DynamicsResponse`` of the
    contract (joint_names, torques, effort_limits, effort_ratios, binding_joint, …) or an
    RFC 9457 problem. The request bodies the page sent are appended to the returned list.
    The one place the browser tests stand in for the route: to test against the live
    route, make this a no-op that returns an empty list.
    """
    import json

    sent: list[dict] = []

    def handle(route) -> None:
        request = route.request
        if request.method != "POST":
            route.continue_()
            return
        robot_id = urlsplit(request.url).path.split("/")[2]
        body = json.loads(request.post_data or "{}")
        sent.append(body)
        status, doc = answer(robot_id, body)
        media = "application/json" if status < 400 else "application/problem+json"
        route.fulfill(status=status, content_type=media, body=json.dumps(doc))

    tab.page.route(re.compile(r".*/robots/[^/]+/dynamics$"), handle)
    return sent


def missing_inertia(robot_id: str, link: str) -> dict:
    """The 422 problem of a robot without inertias (app/api/errors.py's shape)."""
    return {
        "type": "https://denavit.dev/problems/missing-inertia",
        "title": "Unprocessable Content",
        "status": 422,
        "detail": f"link {link!r} has no inertia",
        "field": "robot_id",
        "instance": f"/robots/{robot_id}/dynamics",
    }

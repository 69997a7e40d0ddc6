"""The viewer's collisions, reachability and Cartesian path panels in a real Chromium.

Each test drives the page with its own controls and checks what it draws against answers
the test fetches from the API itself (POST /collisions, the reachability map's metadata and
slice PNG, POST /ik/path and POST /fk), and against the API's documented conventions (shape
axes of obstacles, slice image orientation), not against the page's own numbers.
"""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from tests.browser.tools import (
    BENT,
    Tab,
    api_fk,
    open_viewer,
    page_q,
    rendered_pose,
    set_q,
    wait_idle,
)
from tests.helpers import poll_live

ROBOT = "panda"
#: A bent, well-conditioned panda configuration (its neutral has joint 4 at a limit).
PANDA_BENT = BENT[ROBOT]
PATH_OPTIONS = {"timeout_ms": 40, "max_iterations": 500, "random_seed": 0}


def quat_matrix(x: float, y: float, z: float, w: float) -> np.ndarray:
    """Rotation matrix of a unit quaternion [x, y, z, w]."""
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


# --------------------------------------------------------------------------- collisions
def highlighted(tab: Tab) -> tuple[list[str], set[str]]:
    """Every link of the robot on the page, and those drawn highlighted (red)."""
    links = tab.page.evaluate(
        "(() => { const r = denavit.viewer.robot;"
        " return Object.keys(r.root.links).map((n) => [n, r.isHighlighted(n)]); })()"
    )
    return [n for n, _ in links], {n for n, lit in links if lit}


def expected_extent(o: dict) -> np.ndarray:
    """Half extents along the obstacle's own x, y, z (ObstacleIn: cylinders and capsules
    along local z; a capsule's length is the segment between its hemisphere centres)."""
    if o["shape"] == "box":
        return np.array(o["size"]) / 2
    r = o["radius"]
    if o["shape"] == "sphere":
        return np.array([r, r, r])
    half = o["length"] / 2 + (r if o["shape"] == "capsule" else 0.0)
    return np.array([r, r, half])


def test_collisions_highlight_the_links_the_api_reports(page: Tab) -> None:
    detail = open_viewer(page, ROBOT)
    hand = api_fk(page, ROBOT, PANDA_BENT, "panda_hand")["position"]
    s = np.sqrt(0.5)
    obstacles = [
        {"name": "block", "shape": "box", "size": [0.12, 0.16, 0.08],
         "pose": {"position": hand, "orientation": [0.0, 0.0, np.sin(0.2), np.cos(0.2)]}},
        {"name": "ball", "shape": "sphere", "radius": 0.07,
         "pose": {"position": [-0.6, 0.5, 0.3]}},
        {"name": "pipe", "shape": "cylinder", "radius": 0.04, "length": 0.3,
         "pose": {"position": [0.0, -0.6, 0.4], "orientation": [s, 0.0, 0.0, s]}},
        {"name": "pill", "shape": "capsule", "radius": 0.05, "length": 0.2,
         "pose": {"position": [-0.5, -0.5, 0.2], "orientation": [0.0, s, 0.0, s]}},
    ]  # fmt: skip
    resp = page.http.post("/scenes", json={"name": "viewer-block", "obstacles": obstacles})
    assert resp.status_code == 201, resp.text
    scene = resp.json()
    api = page.http.post(
        f"/robots/{ROBOT}/collisions", json={"q": PANDA_BENT, "scene": "viewer-block"}
    )
    assert api.status_code == 200, api.text
    hits = [p for p in api.json()["pairs"] if p["in_collision"]]
    links = {p["a"] for p in hits} | {p["b"] for p in hits if p["kind"] == "self"}
    touched = {p["b"] for p in hits if p["kind"] == "environment"}
    assert links and touched == {"block"}, hits  # the scene is what the test means

    page.page.click("#scene-refresh")  # lists the scenes again (they are listed on load)
    wait_idle(page)
    page.page.select_option("#scene-picker", "viewer-block")
    page.page.check("#collision-toggle")
    set_q(page, PANDA_BENT)

    answer = page.page.evaluate("denavit.panels.collisions.lastAnswer")
    assert answer["q"] == PANDA_BENT and answer["scene"] == "viewer-block"
    all_links, lit = highlighted(page)
    assert lit == links, (lit, links)
    assert set(all_links) - lit, "every link is red"
    readout = page.page.inner_text("#collision-readout")
    for p in hits:
        assert f"{p['a']} — {p['b']} ({p['kind']})" in readout

    drawn = {d["name"]: d for d in page.page.evaluate("denavit.panels.collisions.drawn()")}
    assert set(drawn) == {o["name"] for o in scene["obstacles"]}
    for o in scene["obstacles"]:
        d = drawn[o["name"]]
        np.testing.assert_allclose(d["position"], o["pose"]["position"], atol=1e-12)
        np.testing.assert_allclose(
            quat_matrix(*d["orientation"]), quat_matrix(*o["pose"]["orientation"]), atol=1e-12
        )
        half = expected_extent(o)
        np.testing.assert_allclose(d["max"], half, rtol=1e-6, atol=1e-7)
        np.testing.assert_allclose(d["min"], -half, rtol=1e-6, atol=1e-7)
        assert d["red"] == (o["name"] in touched), d
    page.shot("collision")

    # Free again: nothing red, the readout says so.
    set_q(page, detail["neutral"])
    assert highlighted(page)[1] == set()
    assert not any(d["red"] for d in page.page.evaluate("denavit.panels.collisions.drawn()"))
    assert page.page.inner_text("#collision-readout").startswith("no collision")
    assert page.errors() == []


@pytest.mark.parametrize("robot_id", ["panda_dh", "so100"])
def test_self_collision_highlights_both_links_of_each_pair(page: Tab, robot_id: str) -> None:
    """Both neutrals self-collide (a DH robot's generated URDF, a mesh robot's own)."""
    neutral = open_viewer(page, robot_id)["neutral"]
    api = page.http.post(f"/robots/{robot_id}/collisions", json={"q": neutral})
    assert api.status_code == 200, api.text
    hits = [p for p in api.json()["pairs"] if p["in_collision"]]
    assert hits and all(p["kind"] == "self" for p in hits), hits
    links = {p["a"] for p in hits} | {p["b"] for p in hits}

    page.page.check("#collision-toggle")
    wait_idle(page)
    _, lit = highlighted(page)
    assert lit == links, (lit, links)
    page.shot("self-collision")
    page.page.uncheck("#collision-toggle")
    wait_idle(page)
    assert highlighted(page)[1] == set()
    assert page.page.inner_text("#collision-readout") == ""
    assert page.errors() == []


# ------------------------------------------------------------------------- reachability
def build_map(tab: Tab) -> dict:
    """A small map built through the API (a background job, polled to its end)."""
    resp = tab.http.post(
        f"/robots/{ROBOT}/reachability",
        json={"voxel_size": 0.2, "samples": 3000, "orientation_divisions": 0, "seed": 1},
    )
    assert resp.status_code == 202, resp.text
    url = tab.url + resp.headers["location"]
    job = poll_live(url, lambda j: j["status"] not in ("queued", "running"), timeout=120)
    assert job["status"] == "done", job
    return tab.http.get(f"/robots/{ROBOT}/reachability/maps/{job['map_id']}").json()


def test_reachability_slice_plane_spans_the_map_and_shows_its_slice(page: Tab) -> None:
    meta = build_map(page)
    open_viewer(page, ROBOT)
    page.page.select_option("#map-picker", meta["map_id"])
    wait_idle(page)
    drawn = page.page.evaluate("denavit.panels.reachability.drawn()")
    assert drawn is not None
    (x0, y0, z0), (x1, y1, _) = meta["bounds"]["min"], meta["bounds"]["max"]
    layer = meta["shape"][2] // 2
    z = z0 + (layer + 0.5) * meta["voxel_size"]
    assert drawn["layer"] == layer
    np.testing.assert_allclose(drawn["min"], [x0, y0, z], atol=1e-12)
    np.testing.assert_allclose(drawn["max"], [x1, y1, z], atol=1e-12)

    png = page.http.get(
        f"/robots/{ROBOT}/reachability/maps/{meta['map_id']}/slice.png", params={"z": z}
    )
    assert png.status_code == 200, png.text
    rgb = np.asarray(Image.open(io.BytesIO(png.content)).convert("RGB")).astype(int)
    height, width = rgb.shape[:2]
    assert drawn["texture"] == {"width": width, "height": height}
    assert width % meta["shape"][0] == 0 and height % meta["shape"][1] == 0
    assert width // meta["shape"][0] == height // meta["shape"][1]  # square voxels
    # Texture row v = 0 lies at y = min (PlaneGeometry), so it must hold the image's bottom
    # row (slice_image: top row = largest y); row v = height-1 the image's top row.
    for u in range(0, width, max(1, width // 8)):
        bottom = page.page.evaluate("a => denavit.panels.reachability.texel(...a)", [u, 0])
        top = page.page.evaluate("a => denavit.panels.reachability.texel(...a)", [u, height - 1])
        np.testing.assert_allclose(bottom[:3], rgb[height - 1, u], atol=2)
        np.testing.assert_allclose(top[:3], rgb[0, u], atol=2)
    page.page.locator("#map-readout").scroll_into_view_if_needed()
    page.shot("reachability")

    # The slider moves the plane to another layer.
    page.page.eval_on_selector(
        "#map-layer", "e => { e.value = '0'; e.dispatchEvent(new Event('input')); }"
    )
    wait_idle(page)
    drawn = page.page.evaluate("denavit.panels.reachability.drawn()")
    assert drawn["layer"] == 0
    np.testing.assert_allclose(drawn["min"][2], z0 + 0.5 * meta["voxel_size"], atol=1e-12)
    assert page.errors() == []


# ---------------------------------------------------------------------------------- path
def plan_in_page(tab: Tab, dz: float) -> dict:
    tab.page.fill("#path-dx", "0")
    tab.page.fill("#path-dy", "0")
    tab.page.fill("#path-dz", repr(dz))
    tab.page.click("#path-plan")
    wait_idle(tab)
    return tab.page.evaluate("denavit.panels.path.lastAnswer")


def api_path(tab: Tab, q: list[float], frame: str, dz: float) -> tuple[dict, dict]:
    """The request the panel should send for a move by dz, and the API's answer to it."""
    start = api_fk(tab, ROBOT, q, frame)
    x, y, z = start["position"]
    body = {
        "start": q,
        "waypoints": [{"position": [x, y, z + dz], "orientation": start["orientation"]}],
        **PATH_OPTIONS,
    }
    resp = tab.http.post(f"/robots/{ROBOT}/ik/path", json=body)
    assert resp.status_code == 200, resp.text
    return body, resp.json()


def test_path_plays_the_api_line_to_its_end(page: Tab) -> None:
    detail = open_viewer(page, ROBOT)
    tip = detail["end_effector"]
    set_q(page, PANDA_BENT)
    answer = plan_in_page(page, -0.05)
    body, expected = api_path(page, PANDA_BENT, tip, -0.05)
    assert page.page.evaluate("denavit.panels.path.lastRequest") == body
    assert expected["fraction"] == 1.0 and expected["failure"] is None
    assert answer["fraction"] == expected["fraction"]
    assert len(answer["points"]) == len(expected["points"]) > 2
    assert f"fraction {expected['fraction']:.2f}" in page.page.inner_text("#path-readout")
    line = page.page.evaluate(
        "Array.from(denavit.panels.path.line.geometry.attributes.position.array)"
    )  # float32 vertices: the line asked for, from the tip to the waypoint
    start = api_fk(page, ROBOT, PANDA_BENT, tip)["position"]
    np.testing.assert_allclose(line[:3], start, atol=1e-6)
    np.testing.assert_allclose(line[-3:], body["waypoints"][0]["position"], atol=1e-6)

    page.page.click("#path-play")
    last = len(expected["points"]) - 1
    page.page.wait_for_function(
        f"!denavit.panels.path.playing && denavit.panels.path.index === {last}"
    )
    wait_idle(page)
    q_end = expected["points"][-1]["q"]
    np.testing.assert_allclose(page_q(page), q_end, atol=1e-12)
    drawn = rendered_pose(page, tip)
    fk = api_fk(page, ROBOT, q_end, tip)
    np.testing.assert_allclose(drawn["position"], fk["position"], atol=1e-9)
    np.testing.assert_allclose(
        quat_matrix(*drawn["orientation"]), quat_matrix(*fk["orientation"]), atol=1e-9
    )
    np.testing.assert_allclose(fk["position"][2], body["waypoints"][0]["position"][2], atol=1e-5)
    page.page.locator("#path-readout").scroll_into_view_if_needed()
    page.shot("path")

    # Scrubbing back to the start poses the start configuration.
    page.page.eval_on_selector(
        "#path-scrub", "e => { e.value = '0'; e.dispatchEvent(new Event('input')); }"
    )
    wait_idle(page)
    assert page_q(page) == PANDA_BENT
    assert page.errors() == []


@pytest.mark.parametrize("dz", [5.0])
def test_path_the_arm_cannot_follow_shows_where_and_why_it_stopped(page: Tab, dz: float) -> None:
    detail = open_viewer(page, ROBOT)
    set_q(page, PANDA_BENT)
    answer = plan_in_page(page, dz)
    _, expected = api_path(page, PANDA_BENT, detail["end_effector"], dz)
    failure = expected["failure"]
    assert expected["fraction"] < 1 and failure is not None
    assert answer["fraction"] == expected["fraction"]
    assert answer["failure"]["reason"] == failure["reason"]
    readout = page.page.inner_text("#path-readout")
    assert readout.startswith(f"fraction {expected['fraction']:.2f}: stopped at s=")
    assert f"({failure['reason']})" in readout
    page.page.locator("#path-readout").scroll_into_view_if_needed()
    page.shot("path-stopped")
    assert page.errors() == []


def test_path_the_api_refuses_clears_the_last_one_and_says_why(page: Tab) -> None:
    """A line too long for the server's budget (points × timeout_ms > ik_max_request_s) is
    a 422 naming max_step: the page shows the problem and has nothing left to play."""
    detail = open_viewer(page, ROBOT)
    set_q(page, PANDA_BENT)
    assert plan_in_page(page, -0.05)["fraction"] == 1.0
    far = 40.0
    body, _ = api_path(page, PANDA_BENT, detail["end_effector"], -0.05)
    body["waypoints"][0]["position"][2] += far
    refused = page.http.post(f"/robots/{ROBOT}/ik/path", json=body)
    assert refused.status_code == 422 and refused.json()["field"] == "max_step", refused.text

    assert plan_in_page(page, far - 0.05) is None
    readout = page.page.inner_text("#path-readout")
    assert readout.startswith("not planned: 422 (max_step)"), readout
    assert page.page.evaluate("denavit.panels.path.line.visible") is False
    assert page.page.is_disabled("#path-play") and page.page.is_disabled("#path-scrub")
    assert "(max_step)" in page.page.inner_text("#status")
    # The browser's own log line of the 422 response is the only console message.
    assert page.page_errors == [] and page.external == []
    assert all("status of 422" in e for e in page.console_errors), page.console_errors

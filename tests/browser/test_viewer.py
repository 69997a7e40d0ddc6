"""The viewer in a real Chromium: loads, poses, drags, draws, checked against the API.

References are independent of the page: the URDF's own visual elements (counted here
with ElementTree), and the API's FK, IK and manipulability answers fetched by the test
itself. Every state is saved as a screenshot artifact and must be non-blank.
"""

from __future__ import annotations

import colorsys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from tests.browser.tools import (
    BENT,
    Tab,
    api_fk,
    assert_reaches,
    assert_same_pose,
    open_viewer,
    page_q,
    pixels_changed,
    rendered_pose,
    set_q,
    wait_idle,
)


def visual_counts(urdf: str) -> tuple[int, int]:
    """(mesh visuals, primitive visuals) of a URDF document."""
    meshes = primitives = 0
    for visual in ET.fromstring(urdf).iter("visual"):
        geometry = visual.find("geometry")
        kinds = {child.tag for child in geometry} if geometry is not None else set()
        meshes += "mesh" in kinds
        primitives += bool(kinds & {"box", "cylinder", "sphere"})
    return meshes, primitives


# ------------------------------------------------------------------------------ loading
@pytest.mark.parametrize("robot_id", ["panda", "ur5", "puma560"])
def test_page_loads_robot_with_its_meshes_and_no_errors(page: Tab, robot_id: str) -> None:
    open_viewer(page, robot_id)
    meshes, primitives = visual_counts(page.http.get(f"/robots/{robot_id}/urdf").text)
    stats = page.page.evaluate("denavit.viewer.robot.stats")
    assert (stats["meshes"], stats["loaded"], stats["failed"]) == (meshes, meshes, 0), stats
    assert stats["primitives"] == primitives
    # A mesh file may hold several meshes; every visual draws at least one.
    assert page.page.evaluate("denavit.viewer.robot.meshCount()") >= meshes + primitives > 0
    assert page.page.evaluate("document.querySelector('#robot-picker').value") == robot_id
    page.shot("loaded")
    assert page.errors() == []


def test_bare_viewer_opens_the_first_robot(page: Tab) -> None:
    page.goto("/viewer")
    wait_idle(page)
    first = page.http.get("/robots").json()["robots"][0]["id"]
    assert page.page.evaluate("denavit.viewer.detail.id") == first
    assert page.page.url.endswith(f"/viewer/{first}")
    assert page.errors() == []


def test_picker_switches_robot(page: Tab) -> None:
    open_viewer(page, "panda")
    page.page.select_option("#robot-picker", "ur5")
    page.page.wait_for_function("denavit.viewer.detail.id === 'ur5' && denavit.idle()")
    ur5 = page.http.get("/robots/ur5").json()
    assert page_q(page) == ur5["neutral"]
    assert len(page.page.query_selector_all("#sliders input[type=range]")) == len(ur5["joints"])
    assert page.errors() == []


def test_only_the_latest_choice_renders_when_loads_finish_out_of_order(page: Tab) -> None:
    """Panda is chosen, then puma560; Panda's URDF is held back (route interception) until
    puma560 is shown, then let through. The page must keep showing puma560 (before: the
    late Panda load rendered over it while the picker said puma560)."""
    open_viewer(page, "ur5")
    held = []

    def hold(route) -> None:  # answered when the test says
        held.append(route)

    page.page.route("**/robots/panda/urdf", hold)
    with page.page.expect_request("**/robots/panda/urdf"):
        page.page.select_option("#robot-picker", "panda")
    page.page.select_option("#robot-picker", "puma560")
    page.page.wait_for_function("denavit.viewer.detail.id === 'puma560' && denavit.viewer.ready")
    assert len(held) == 1
    held[0].continue_()
    # Panda's load has settled: dropped (loading back to 0), or rendered (the defect).
    page.page.wait_for_function(
        "denavit.viewer.loading === 0 || denavit.viewer.detail.id === 'panda'"
    )
    wait_idle(page)
    viewer = "denavit.viewer"
    assert page.page.evaluate(f"{viewer}.detail.id") == "puma560"
    assert page.page.evaluate(f"{viewer}.robot.detail.id") == "puma560"
    assert page.page.evaluate(f"{viewer}.stage.world.children.includes({viewer}.robot.root)")
    robots_on_stage = page.page.evaluate(
        f"{viewer}.stage.world.children.filter((o) => o.isURDFRobot).length"
    )
    assert robots_on_stage == 1
    assert page.page.evaluate("document.querySelector('#robot-picker').value") == "puma560"
    assert page.page.url.endswith("/viewer/puma560")
    puma = page.http.get("/robots/puma560").json()
    assert page_q(page) == puma["neutral"]
    assert page.errors() == []


# ------------------------------------------------------------------------ sliders → FK
def test_slider_moves_rendered_pose_and_fk_readout_to_the_api_value(page: Tab) -> None:
    robot = open_viewer(page, "panda")
    frame = robot["end_effector"]
    before = rendered_pose(page, frame)
    canvas_before = page.shot("slider-before", "#stage canvas")
    slider = page.page.locator("#sliders input[data-joint=panda_joint2]")
    slider.focus()
    for _ in range(40):  # a user's arrow keys: 40 steps of (upper - lower) / 1000
        page.page.keyboard.press("ArrowRight")
    wait_idle(page)
    q = page_q(page)
    lower, upper = robot["joints"][1]["limits"]["lower"], robot["joints"][1]["limits"]["upper"]
    assert q[1] == pytest.approx(40 * (upper - lower) / 1000, abs=1e-9)
    assert q[0] == q[2] == 0.0
    reference = api_fk(page, "panda", q, frame)
    after = rendered_pose(page, frame)
    assert np.linalg.norm(np.subtract(after["position"], before["position"])) > 0.05
    assert_same_pose(after, reference)
    shown = page.page.evaluate("denavit.panels.joints.lastFk")
    assert shown["q"] == q and shown["pose"] == reference
    text = page.page.locator("#fk-readout").inner_text()
    assert " ".join(f"{x:.6f}" for x in reference["position"]) in text.replace(",", "")
    assert " ".join(f"{x:.6f}" for x in reference["orientation"]) in text.replace(",", "")
    canvas_after = page.shot("slider", "#stage canvas")
    assert pixels_changed(canvas_before, canvas_after) > 0.01  # the picture moved too
    assert page.errors() == []


def test_frame_picker_shows_the_chosen_frame(page: Tab) -> None:
    open_viewer(page, "ur5")
    page.page.select_option("#frame-picker", "forearm_link")
    wait_idle(page)
    shown = page.page.evaluate("denavit.panels.joints.lastFk")
    assert shown["frame"] == "forearm_link"
    reference = api_fk(page, "ur5", page_q(page), "forearm_link")
    assert shown["pose"] == reference
    assert_same_pose(rendered_pose(page, "forearm_link"), reference)


# ---------------------------------------------------------------------------- gizmo → IK
@pytest.mark.parametrize(("robot_id", "pixels"), [("panda", (0, 60)), ("ur5", (60, 0))])
def test_dragging_the_gizmo_solves_ik_to_the_new_target(
    page: Tab, robot_id: str, pixels: tuple[int, int]
) -> None:
    robot = open_viewer(page, robot_id)
    tip = robot["end_effector"]
    # From a bent arm, away from the neutral's stretched (near-singular) elbow.
    set_q(page, BENT[robot_id])
    q0 = page_q(page)
    start = rendered_pose(page, tip)
    axis = "X" if pixels[0] else "Z"
    x, y = page.page.evaluate(f"denavit.panels.ik.handleScreenPoint('{axis}')")
    mouse = page.page.mouse
    mouse.move(x, y)
    assert page.page.evaluate("denavit.panels.ik.controls.axis") == axis  # hovering it
    mouse.down()
    mouse.move(x + pixels[0], y + pixels[1], steps=8)
    mouse.up()
    wait_idle(page)
    last = page.page.evaluate("denavit.panels.ik.last")
    target = page.page.evaluate("denavit.panels.ik.targetPose()")
    assert last["target"] == target  # the last solve was for where the gizmo ended
    moved = np.subtract(target["position"], start["position"])
    assert np.linalg.norm(moved) > 0.01, moved  # the drag moved the target
    assert abs(moved["XYZ".index(axis)]) == pytest.approx(np.linalg.norm(moved), rel=1e-9), moved
    why = "status reason detail iterations restarts position_error solve_time_ms".split()
    assert last["answer"]["success"], (moved, {k: last["answer"].get(k) for k in why})
    q = page_q(page)
    assert q == last["answer"]["q"]
    reached = api_fk(page, robot_id, q, tip)  # the API's FK of the page's configuration
    assert_reaches(last["answer"], reached, target)  # within the default 1e-5 m / 1e-5 rad
    assert_same_pose(rendered_pose(page, tip), reached)
    # Seeded by the current configuration: the arm moved a little, on its branch.
    assert np.max(np.abs(np.subtract(q, q0))) < 0.5
    page.shot("dragged")
    assert page.errors() == []


def test_other_branches_are_listed_and_taken_on_click(page: Tab) -> None:
    open_viewer(page, "ur5")
    set_q(page, BENT["ur5"])
    tip = rendered_pose(page, "tool0")
    page.page.click("#branches-button")
    page.page.wait_for_function("document.querySelectorAll('#branches button').length > 1")
    answer = page.page.evaluate("denavit.panels.ik.lastBranches")
    labels = [s["branch"] for s in answer["solutions"]]
    assert len(labels) == 8 and len(set(labels)) == 8  # the UR5's eight branches
    page.page.locator("#branches button").nth(5).click()
    wait_idle(page)
    q = page_q(page)
    assert q == answer["solutions"][5]["q"]
    assert_reaches(answer["solutions"][5], api_fk(page, "ur5", q, "tool0"), tip)
    page.shot("branch")
    assert page.errors() == []


# ------------------------------------------------------------------------- the ellipsoid
def assert_colour(hex_colour: str, answer: dict) -> None:
    """Hue from red (1/κ = 0) to green (1/κ = 1), saturation 0.85, lightness 0.5."""
    expected = colorsys.hls_to_rgb(answer["inverse_condition"] / 3, 0.5, 0.85)
    drawn = [int(hex_colour[i : i + 2], 16) / 255 for i in (0, 2, 4)]
    np.testing.assert_allclose(drawn, expected, atol=1.5 / 255)


@pytest.mark.parametrize("part", ["translation", "rotation"])
def test_ellipsoid_axes_equal_the_api_singular_values(page: Tab, part: str) -> None:
    robot = open_viewer(page, "panda")
    set_q(page, [0.2, -0.4, 0.1, -2.0, 0.3, 1.9, 0.5, 0.0])
    if part == "rotation":
        page.page.check("#ellipsoid-rotational")
    page.page.check("#ellipsoid-toggle")
    wait_idle(page)
    drawn = page.page.evaluate("denavit.panels.ellipsoid.drawn()")
    assert drawn is not None
    q = page_q(page)
    answer = page.http.post("/robots/panda/manipulability", json={"q": q, "part": part}).json()
    sigma = answer["singular_values"]
    np.testing.assert_allclose(drawn["half_lengths"], sigma, rtol=1e-9)
    for u, axis in zip(answer["velocity_ellipsoid"]["axes"], drawn["axes"], strict=True):
        assert abs(np.dot(u, axis)) == pytest.approx(1.0, abs=1e-9)
    tip = api_fk(page, "panda", q, robot["end_effector"])
    np.testing.assert_allclose(drawn["centre"], tip["position"], atol=1e-9)
    readout = page.page.locator("#ellipsoid-readout").inner_text()
    assert ("SINGULAR" in readout) == answer["singular"]
    assert f"{answer['inverse_condition']:.3f}" in readout
    assert_colour(drawn["colour"], answer)
    page.shot(f"ellipsoid-{part}")
    page.page.uncheck("#ellipsoid-toggle")
    wait_idle(page)
    assert page.page.evaluate("denavit.panels.ellipsoid.drawn()") is None
    assert page.errors() == []


def test_singular_configuration_is_called_singular(page: Tab) -> None:
    open_viewer(page, "ur5")  # the neutral: q5 = 0, wrist axes 4 and 6 aligned
    page.page.check("#ellipsoid-rotational")
    page.page.check("#ellipsoid-toggle")
    wait_idle(page)
    answer = page.http.post(
        "/robots/ur5/manipulability", json={"q": page_q(page), "part": "rotation"}
    ).json()
    assert answer["singular"]
    assert "SINGULAR" in page.page.locator("#ellipsoid-readout").inner_text()
    assert_colour(page.page.evaluate("denavit.panels.ellipsoid.drawn().colour"), answer)
    assert page.errors() == []

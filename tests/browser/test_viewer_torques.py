"""The joints panel's torque bars: |τ| / effort limit per joint from POST
/robots/{id}/dynamics, in a real Chromium, the route stubbed (tools.stub_dynamics) with
answers of the contract's shape built here, so each bar is checked against the answer the
page was given: width = min(ratio, 1)·100 %, red past 100 %, the binding joint marked, the
tooltip's τ and limit; a robot without inertias shows no bars and one line."""

from __future__ import annotations

import math

import pytest

from tests.browser.tools import Tab, missing_inertia, open_viewer, set_q, stub_dynamics

ROBOT = "ur5_dh"
#: Torques at q = 0 (N·m) and the limits of the answer (joint 4 has none here).
BASE = [37.5, -210.0, 90.0, 3.0, 14.0, -7.0]
LIMITS = [150.0, 150.0, 150.0, None, 28.0, 28.0]


def torque_answer(robot_id: str, body: dict) -> tuple[int, dict]:
    """τ_i = BASE_i · (1 + q_1): the bars must follow the configuration."""
    if robot_id != ROBOT:
        return 422, missing_inertia(robot_id, "link_1")
    scale = 1.0 + body["q"][0]
    torques = [t * scale for t in BASE]
    ratios = [None if lim is None else abs(t) / lim for t, lim in zip(torques, LIMITS, strict=True)]
    limited = [(r, i) for i, r in enumerate(ratios) if r is not None]
    names = ["shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3"]
    return 200, {
        "joint_names": names,
        "torques": torques,
        "gravity_torques": torques,
        "effort_limits": LIMITS,
        "effort_ratios": ratios,
        "binding_joint": names[max(limited)[1]],
        "payload": None,
    }


def bars(tab: Tab) -> list[dict]:
    """What the page draws: each bar's joint, visibility, fill width (%), classes, tooltip."""
    return tab.page.evaluate(
        """() => [...document.querySelectorAll('#sliders .torque-bar')].map((b) => ({
            joint: b.dataset.joint,
            visible: !b.hidden && b.getBoundingClientRect().height > 0,
            width: b.querySelector('.torque-fill').getBoundingClientRect().width
                   / b.getBoundingClientRect().width * 100,
            over: b.classList.contains('over'),
            binding: b.classList.contains('binding'),
            red: getComputedStyle(b.querySelector('.torque-fill')).backgroundColor,
            title: b.title }))"""
    )


@pytest.mark.parametrize("q1", [0.0, 0.5])
def test_bars_show_each_joints_torque_ratio(page: Tab, q1: float) -> None:
    sent = stub_dynamics(page, torque_answer)
    open_viewer(page, ROBOT)
    q = [q1, -1.0, 1.2, 0.3, 0.0, 0.0]
    set_q(page, q)
    assert sent[-1] == {"q": q}
    status, answer = torque_answer(ROBOT, {"q": q})
    drawn = bars(page)
    assert [b["joint"] for b in drawn] == answer["joint_names"]
    binding = answer["binding_joint"]
    for b, tau, limit, ratio in zip(
        drawn, answer["torques"], answer["effort_limits"], answer["effort_ratios"], strict=True
    ):
        assert b["visible"], b
        expected = 0.0 if ratio is None else min(ratio, 1.0) * 100
        assert math.isclose(b["width"], expected, abs_tol=0.5), (b, expected)
        assert b["over"] == (ratio is not None and ratio > 1), b
        assert b["binding"] == (b["joint"] == binding), b
        assert f"τ = {tau:.3f} N·m" in b["title"], b
        assert ("no effort limit" in b["title"]) == (limit is None), b
        if limit is not None:
            assert f"limit {limit:g} N·m" in b["title"], b
    over = [b for b in drawn if b["over"]]
    assert [b["joint"] for b in over] == ["shoulder_lift"]
    assert over[0]["red"] == "rgb(211, 47, 47)"
    assert all(b["red"] != over[0]["red"] for b in drawn if not b["over"])
    assert page.page.locator("#torque-note").is_hidden()
    page.shot("torques", "#panel-joints")


@pytest.mark.parametrize("robot_id", ["puma560", "planar3r"])
def test_robot_without_inertias_shows_one_line_and_no_bars(page: Tab, robot_id: str) -> None:
    """puma560 has inertias: the stub's 422 is the answer (a link without one); planar3r's
    URDF has none at all: the page says so without asking."""
    sent = stub_dynamics(page, lambda rid, body: (422, missing_inertia(rid, "link_3")))
    detail = open_viewer(page, robot_id)
    q = [0.1 * (i + 1) for i in range(len(detail["joints"]))]
    set_q(page, q)
    if robot_id == "puma560":
        assert sent and sent[-1] == {"q": q}
    else:
        assert sent == []
    assert not any(b["visible"] for b in bars(page))
    note = page.page.locator("#torque-note")
    assert note.is_visible()
    assert note.inner_text() == "no inertias in this robot's description"
    status = page.page.locator("#status")
    assert status.inner_text() == ""
    assert "error" not in (status.get_attribute("class") or "")
    assert page.page_errors == []


def test_switching_robots_redraws_the_bars_of_the_new_one(page: Tab) -> None:
    stub_dynamics(page, torque_answer)
    open_viewer(page, ROBOT)
    assert all(b["visible"] for b in bars(page))
    page.page.select_option("#robot-picker", "planar3r")
    page.page.wait_for_function("denavit.viewer.detail.id === 'planar3r' && denavit.idle()")
    drawn = bars(page)
    assert len(drawn) == 3 and not any(b["visible"] for b in drawn)
    assert (
        page.page.locator("#torque-note").inner_text() == "no inertias in this robot's description"
    )
    page.page.select_option("#robot-picker", ROBOT)
    page.page.wait_for_function(f"denavit.viewer.detail.id === '{ROBOT}' && denavit.idle()")
    assert [b["visible"] for b in bars(page)] == [True] * 6
    assert page.page.locator("#torque-note").is_hidden()


PARTIAL = {
    "name": "partial_dyn",
    "convention": "standard",
    "joints": [
        {"a": 0.5, "alpha": 0, "d": 0, "theta": 0, "mass": 1.0},
        {"a": 0.4, "alpha": 0, "d": 0, "theta": 0},
    ],
}


def test_the_pages_inertia_check_agrees_with_the_core(page: Tab) -> None:
    """The page asks for torques only where the core would answer (check_inertias)."""
    from app.kinematics.dynamics import check_inertias
    from app.kinematics.errors import MissingInertiaError
    from app.kinematics.models import RobotModel

    assert page.http.post("/robots/dh", json=PARTIAL).status_code == 201
    for robot_id in ["panda", "puma560", "stanford_arm", "planar3r", "partial_dyn"]:
        open_viewer(page, robot_id)
        urdf = page.http.get(f"/robots/{robot_id}/urdf").text
        try:
            check_inertias(RobotModel(robot_id, urdf, ee_frame=None))
            core = True
        except MissingInertiaError:
            core = False
        drawn = page.page.evaluate(
            "import('/static/viewer/torques.js')"
            ".then((m) => m.hasInertias(denavit.viewer.robot.root))"
        )
        assert drawn == core, robot_id
    assert core is False  # partial_dyn: row 2's link has none

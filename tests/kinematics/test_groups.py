"""SRDF semantics in the core: group resolution, tips, the default tip, group configurations,
named states and group-restricted IK, on a small hand-written robot."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from app.kinematics import ik
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import (
    configuration,
    default_frame,
    group,
    named_states,
    robot_groups,
    state_configuration,
)
from app.kinematics.ik.problem import IKOptions
from app.kinematics.models import RobotModel
from app.robots.catalog import load_catalog


def _joint(name: str, parent: str, child: str, jtype: str, extra: str = "", xyz: str = "0 0 0.3"):
    lim = '<limit lower="-2" upper="2" effort="1" velocity="1"/>'
    if jtype == "prismatic":
        lim = '<limit lower="0" upper="0.04" effort="1" velocity="1"/>'
    return (f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{xyz}"/><axis xyz="0 1 0"/>{lim if jtype != "fixed" else ""}{extra}'
            "</joint>")  # fmt: skip


#: base -j1-> l1 -j2-> l2 -j3-> l3 -fixed-> tool; l3 -f1 (prismatic)-> fa, l3 -f2 (mimic)-> fb
URDF = (
    '<robot name="g">'
    + "".join(f'<link name="{n}"/>' for n in "base l1 l2 l3 tool fa fb".split())
    + _joint("j1", "base", "l1", "revolute")
    + _joint("j2", "l1", "l2", "revolute")
    + _joint("j3", "l2", "l3", "revolute")
    + _joint("tool_joint", "l3", "tool", "fixed", xyz="0 0 0.1")
    + _joint("f1", "l3", "fa", "prismatic", xyz="0 0.05 0.1")
    + _joint("f2", "l3", "fb", "prismatic", '<mimic joint="f1" multiplier="-1"/>', "0 -0.05 0.1")
    + "</robot>"
)


def srdf(body: str) -> str:
    return f'<robot name="g">{body}</robot>'


SRDF = srdf(
    '<group name="arm"><chain base_link="base" tip_link="tool"/></group>'
    '<group name="wrist"><joint name="j2"/><joint name="j3"/></group>'
    '<group name="fingers"><link name="fa"/><link name="fb"/></group>'
    '<group name="all"><group name="arm"/><group name="fingers"/></group>'
    '<group name="upper"><joint name="j1"/><joint name="j2"/></group>'
    '<end_effector name="gripper" parent_link="tool" group="fingers" parent_group="arm"/>'
    '<end_effector name="upper_tool" parent_link="l2" group="upper"/>'
    '<group_state name="ready" group="arm">'
    '<joint name="j1" value="0.1"/><joint name="j2" value="-0.2"/><joint name="j3" value="0.3"/>'
    "</group_state>"
    '<group_state name="ready" group="wrist"><joint name="j3" value="1.0"/></group_state>'
)


@pytest.fixture(scope="module")
def robot() -> RobotModel:
    return RobotModel("g", URDF, srdf_text=SRDF)


def test_groups_resolve_to_actuated_joints_and_tips(robot: RobotModel) -> None:
    groups = robot_groups(robot)
    assert {n: g.joints for n, g in groups.items()} == {
        "arm": ("j1", "j2", "j3"),  # the chain's fixed tool_joint is no configuration entry
        "wrist": ("j2", "j3"),
        "fingers": ("f1",),  # f2 mimics f1: not a configuration entry
        "all": ("j1", "j2", "j3", "f1"),
        "upper": ("j1", "j2"),
    }
    assert groups["arm"].indices.tolist() == [0, 1, 2]
    assert groups["fingers"].indices.tolist() == [3]
    tips = {n: g.tip for n, g in groups.items()}
    assert tips["arm"] == "tool"  # chain tip_link
    assert tips["upper"] == "l2"  # an end effector whose group it is, parent_link it moves
    assert tips["wrist"] == "l3"  # deepest of its links
    assert tips["fingers"] == "fa"  # deepest, first in URDF order on ties


def test_end_effector_parent_group_gives_the_tip() -> None:
    r = RobotModel(
        "g",
        URDF,
        srdf_text=srdf(
            '<group name="w"><joint name="j1"/><joint name="j2"/></group>'
            '<group name="f"><link name="fa"/></group>'
            '<end_effector name="e" parent_link="l3" group="f" parent_group="w"/>'
        ),
    )
    assert robot_groups(r)["w"].tip == "l3"


def test_default_tip_rule_1(robot: RobotModel) -> None:
    assert robot.ee_frame == "tool"  # the first end effector's parent_link
    assert RobotModel("g", URDF, srdf_text=SRDF, ee_frame="l2").ee_frame == "l2"
    plain = RobotModel("g", URDF)
    assert plain.ee_frame == "tool" and robot_groups(plain) == {}  # rules 2-3 pick it too
    # An end effector on l2, which rules 2-3 would never pick: rule 1 decides.
    on_l2 = srdf('<end_effector name="e" parent_link="l2" group="upper"/>' + SRDF[16:-8])
    assert RobotModel("g", URDF, srdf_text=on_l2).ee_frame == "l2"


def test_group_configuration(robot: RobotModel) -> None:
    wrist = group(robot, "wrist")
    np.testing.assert_array_equal(configuration(robot, wrist, [0.5, -0.5]), [0, 0.5, -0.5, 0])
    base = np.array([1.0, 1.0, 1.0, 0.01])
    np.testing.assert_array_equal(
        configuration(robot, wrist, [0.5, -0.5], base=base), [1.0, 0.5, -0.5, 0.01]
    )
    np.testing.assert_array_equal(configuration(robot, wrist, [1, 2, 3, 0.02]), [1, 2, 3, 0.02])
    with pytest.raises(InvalidInputError) as exc:
        configuration(robot, wrist, [1, 2, 3])
    assert exc.value.field == "q" and "2 values" in exc.value.message
    with pytest.raises(InvalidInputError) as exc:
        configuration(robot, None, [0.5, -0.5])
    assert exc.value.field == "q"
    with pytest.raises(InvalidInputError) as exc:
        group(robot, "nope")
    assert exc.value.field == "group" and "'arm'" in exc.value.message
    assert default_frame(robot, wrist, None) == "l3"
    assert default_frame(robot, wrist, "l1") == "l1"
    assert default_frame(robot, None, None) == "tool"


def test_named_states(robot: RobotModel) -> None:
    base = np.zeros(4)
    np.testing.assert_array_equal(
        state_configuration(robot, "ready", None, base), [0.1, -0.2, 0.3, 0]
    )
    # two states named "ready": the group's own is taken
    np.testing.assert_array_equal(
        state_configuration(robot, "ready", group(robot, "wrist"), base), [0, 0, 1.0, 0]
    )
    with pytest.raises(InvalidInputError) as exc:
        state_configuration(robot, "home", None, base)
    assert exc.value.field == "seed" and "'ready'" in exc.value.message


def test_group_ik_moves_only_the_groups_joints(robot: RobotModel) -> None:
    """Group wrist (j2, j3) reaching a pose made with j1 = 0.4: j1 keeps its seed value."""
    q_goal = np.array([0.4, 0.3, -0.5, 0.0])
    data = robot.model.createData()
    pin.framesForwardKinematics(robot.model, data, robot.to_pin(q_goal))
    target = data.oMf[robot.frame_id("l3")].copy()
    seed = np.array([0.4, 0.0, 0.0, 0.02])
    res = ik.solve(
        robot,
        target,
        IKOptions(group="wrist", mode="position", timeout_ms=1000, max_iterations=2000),
        seed=seed,
    )
    assert res.success
    assert res.q[0] == 0.4 and res.q[3] == 0.02
    with pytest.raises(InvalidInputError) as exc:
        ik.solve(robot, target, IKOptions(group="fingers", frame="l2"), seed=seed)
    assert exc.value.field == "group"


def test_catalog_srdfs_resolve_leniently() -> None:
    """Catalog SRDFs are not upload-checked: z1's chain names a missing link (skipped, the
    group keeps its joints) and kinova's `arm_up` state lies beyond a limit (left out)."""
    catalog = load_catalog()
    z1 = catalog["z1"].build()
    assert robot_groups(z1)["end_effector"].joints == tuple(f"joint{i}" for i in range(1, 7))
    kinova = catalog["kinova"].build()
    assert [s.name for s in kinova.semantics.states] == ["arm_up"]
    assert named_states(kinova) == ()
    for entry in catalog.values():
        r = entry.build()
        for g in robot_groups(r).values():
            r.frame_id(g.tip)

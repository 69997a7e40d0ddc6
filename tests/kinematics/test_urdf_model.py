"""The URDF builder against Pinocchio's own ``mimic=True`` build, where that one accepts
the document: the very same model (joint order, ids, frames, mimic joints, limits)."""

from __future__ import annotations

import pinocchio as pin
import pytest

from app.kinematics.urdf_model import build_model
from app.robots.catalog import load_catalog
from tests.mimic_robots import gripper


@pytest.mark.parametrize("robot_id", ["panda", "ur5"])
def test_catalog_robots_build_as_pinocchio_builds_them(robot_id: str) -> None:
    urdf = load_catalog()[robot_id].urdf_path.read_text()
    assert build_model(urdf) == pin.buildModelFromXML(urdf, mimic=True)


def test_follower_after_its_leader_builds_as_pinocchio_builds_it() -> None:
    urdf = gripper("a_leader", "b_follower", "wrist", "pad")
    model = build_model(urdf)
    assert model == pin.buildModelFromXML(urdf, mimic=True)
    assert [int(j) for j in model.mimicking_joints] == [model.getJointId("b_follower")]


def test_follower_before_its_leader_is_the_renamed_twin() -> None:
    """The follower named first builds the model of its twin whose names sort the other way,
    joint for joint (names aside)."""
    model = build_model(gripper("b_leader", "a_follower", "wrist", "pad"))
    twin = build_model(gripper("a_leader", "b_follower", "wrist", "pad"))
    assert list(model.names) == ["universe", "wrist", "b_leader", "a_follower", "pad"]
    assert model.nq == twin.nq == 3 and model.nv == twin.nv == 3
    for jid in range(1, model.njoints):
        assert model.joints[jid] == twin.joints[jid]
        assert model.jointPlacements[jid] == twin.jointPlacements[jid]
        assert model.parents[jid] == twin.parents[jid]
    assert [f.name for f in model.frames if f.type == pin.FrameType.BODY] == [
        f.name for f in twin.frames if f.type == pin.FrameType.BODY
    ]

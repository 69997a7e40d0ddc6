"""Robot models: catalog metadata, joint descriptions, configuration conversion."""

from __future__ import annotations

import numpy as np
import pytest

from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.models import RobotModel
from tests.kinematics.chains import continuous_arm, planar_2link


def test_catalog_joint_counts_match_models(registry) -> None:
    """The joint counts GET /robots lists without parsing equal the loaded models'."""
    for entry in registry.catalog.values():
        robot = registry.get(entry.id)
        assert robot.n == entry.joints, entry.id
        assert robot.ee_frame == entry.ee_frame
        assert robot.frame_id(robot.ee_frame) >= 0


def test_catalog_files_resolve_meshes(registry) -> None:
    """package:// URIs of every catalog robot resolve under the package dirs."""
    import re
    from pathlib import Path

    for entry in registry.catalog.values():
        robot = registry.get(entry.id)
        uris = set(re.findall(r'filename="package://([^"]+)"', robot.urdf_text))
        assert uris or entry.id == "so100" or not robot.has_collision_geometry
        for uri in uris:
            assert any(
                (Path(d) / "example-robot-data" / "robots" / uri).exists()
                or (Path(d) / uri).exists()
                for d in robot.package_dirs
            ), uri


def test_joint_description() -> None:
    robot = RobotModel("c", continuous_arm())
    c1, r2 = robot.joints
    assert (c1.type, c1.parent, c1.child, c1.axis, c1.continuous) == (
        "continuous",
        "base",
        "l1",
        (0.0, 0.0, 1.0),
        True,
    )
    assert (r2.type, r2.lower, r2.upper, r2.velocity, r2.effort) == ("revolute", -1, 1, 1, 1)


def test_configuration_validation() -> None:
    robot = RobotModel("p", planar_2link(), ee_frame="tip")
    np.testing.assert_array_equal(robot.configuration(joint_positions={"j2": 0.5}), [0, 0.5])
    with pytest.raises(InvalidInputError) as e:
        robot.configuration([1.0])
    assert e.value.field == "q"
    with pytest.raises(InvalidInputError) as e:
        robot.configuration([1.0, float("nan")])
    assert e.value.field == "q.1"
    with pytest.raises(UnknownNameError) as e:
        robot.configuration(joint_positions={"j3": 0.1})
    assert e.value.field == "joint_positions.j3" and "j1" in e.value.suggestions
    with pytest.raises(InvalidInputError):
        robot.configuration([0, 0], {"j1": 0})
    with pytest.raises(UnknownNameError) as e:
        robot.frame_id("tipp")
    assert e.value.suggestions[0] == "tip"


def test_limits_flagged_not_clipped() -> None:
    robot = RobotModel("p", planar_2link(), ee_frame="tip")
    assert robot.limit_violations(np.array([0.0, 4.0])) == ["j2"]
    assert robot.limit_violations(np.array([0.0, 1.0])) == []


def test_default_end_effector_is_deepest_link() -> None:
    assert RobotModel("p", planar_2link()).ee_frame == "tip"

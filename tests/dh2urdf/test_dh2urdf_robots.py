"""Every built-in table in robots/dh loads, converts and loads in Pinocchio; spot checks."""

from __future__ import annotations

import importlib.metadata
import math
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from dh2urdf.math import chain
from dh2urdf.table import DHTable
from dh2urdf.urdf import to_urdf

from .helpers import frame_names, pin_frames, random_q

DH_DIR = Path(__file__).resolve().parents[2] / "robots" / "dh"
FILES = sorted(DH_DIR.glob("*.yaml"))
EXPECTED = {
    "planar2",
    "planar3r",
    "rrp",
    "armar1_arm",
    "puma560",
    "stanford_arm",
    "ur5_dh",
    "panda_dh",
}


def test_expected_tables_exist() -> None:
    assert EXPECTED <= {p.stem for p in FILES}


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_table_loads_converts_and_builds(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert text.startswith("# "), "comment header citing the source"
    assert "Source:" in text.split("\nname:")[0]
    table = DHTable.from_file(path)
    assert table.name == path.stem
    assert table.description
    urdf = to_urdf(table)
    model = pin.buildModelFromXML(urdf)
    assert list(model.names)[1:] == table.joint_names
    assert model.nv == table.dof
    geom = pin.buildGeomFromUrdfString(model, urdf, pin.GeometryType.COLLISION)
    assert geom.ngeoms > 0
    for joint in table.joints:
        assert joint.lower is not None and joint.upper is not None and joint.lower <= joint.upper
    q = random_q(table, np.random.default_rng(0))
    frames = pin_frames(urdf, q, frame_names(table.dof))
    for name, expected in zip(frame_names(table.dof), chain(table, q), strict=True):
        np.testing.assert_allclose(frames[name], expected, rtol=0, atol=1e-12)


def test_armar1_values_as_in_the_course() -> None:
    t = DHTable.from_file(DH_DIR / "armar1_arm.yaml")
    deg = math.pi / 180
    rows = [(j.theta, j.a, j.alpha, j.d) for j in t.joints]
    expected = [
        (0, 0.03, -90, 0),
        (-90, 0, -90, 0),
        (90, 0, 90, 0.2235),
        (0, 0, -90, 0),
        (0, 0, 90, 0.27),
        (90, 0, -90, 0),
        (0, 0.14, 90, 0),
    ]
    for got, (theta, a, alpha, d) in zip(rows, expected, strict=True):
        assert got == pytest.approx((theta * deg, a, alpha * deg, d), abs=1e-15)


def test_ur5_published_values() -> None:
    t = DHTable.from_file(DH_DIR / "ur5_dh.yaml")
    assert [j.d for j in t.joints] == [0.089159, 0, 0, 0.10915, 0.09465, 0.0823]
    assert [j.a for j in t.joints] == [0, -0.425, -0.39225, 0, 0, 0]
    half = math.pi / 2
    assert [j.alpha for j in t.joints] == pytest.approx([half, 0, 0, half, -half, 0], abs=1e-15)


def test_stanford_arm_has_prismatic_joint_3() -> None:
    t = DHTable.from_file(DH_DIR / "stanford_arm.yaml")
    assert [j.type for j in t.joints].count("prismatic") == 1
    j3 = t.joints[2]
    assert j3.type == "prismatic" and (j3.lower, j3.upper) == (0.3048, 1.27)
    assert j3.theta == pytest.approx(-math.pi / 2, abs=1e-15)


def test_panda_limits_are_frankas() -> None:
    t = DHTable.from_file(DH_DIR / "panda_dh.yaml")
    assert t.convention == "modified" and t.tool.xyz == (0.0, 0.0, 0.107)
    q_max = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973]
    q_min = [-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973]
    np.testing.assert_allclose([j.upper for j in t.joints], q_max, rtol=0, atol=1e-15)
    np.testing.assert_allclose([j.lower for j in t.joints], q_min, rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        [j.velocity for j in t.joints], [2.175] * 4 + [2.61] * 3, rtol=0, atol=1e-15
    )
    assert [j.effort for j in t.joints] == [87] * 4 + [12] * 3


def _erd_panda_urdf() -> Path | None:
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        return None
    for f in dist.files or ():
        if str(f).replace("\\", "/").endswith("panda_description/urdf/panda.urdf"):
            return Path(dist.locate_file(f))
    return None


def test_panda_dh_matches_example_robot_data_panda() -> None:
    """Franka's modified DH table reproduces the panda URDF (links 0..7, link8 = flange)."""
    path = _erd_panda_urdf()
    assert path is not None, "example-robot-data (a pinned dependency) has no panda URDF"
    erd = pin.buildModelFromUrdf(str(path))
    data = erd.createData()
    table = DHTable.from_file(DH_DIR / "panda_dh.yaml")
    urdf = to_urdf(table)
    for seed in range(5):
        q = random_q(table, np.random.default_rng(seed))
        q_erd = pin.neutral(erd)
        q_erd[:7] = q
        pin.framesForwardKinematics(erd, data, q_erd)
        ours = pin_frames(urdf, q, frame_names(7))
        for i in range(8):
            theirs = data.oMf[erd.getFrameId(f"panda_link{i}")].homogeneous
            np.testing.assert_allclose(ours[f"dh_{i}"], theirs, rtol=0, atol=1e-12)
        flange = data.oMf[erd.getFrameId("panda_link8")].homogeneous
        np.testing.assert_allclose(ours["tool"], flange, rtol=0, atol=1e-12)

"""The Robotiq 2F-85 of PickNikRobotics/ros2_robotiq_gripper, uploaded as its package: its
mimic followers (``robotiq_85_left_inner_knuckle_joint`` and four others) follow
``robotiq_85_left_knuckle_joint``, and the first sorts before it (a 422 "The parent joint
of the mimic joint is not in the kinematic tree" before the URDF builder).

Reference: the real ``xacro`` CLI expands the same files (its ``$(find)`` answered by an
ament index written by the test, as a ROS install would), and yourdfpy (which applies
``<mimic>`` itself) gives the FK of every link. Files: tests/data/ros2_robotiq_gripper
(README.md: origin, commit, license, trim).
"""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import yourdfpy
from fastapi.testclient import TestClient

from tests.helpers import ROOT
from tests.packages import zip_bytes

DATA = Path(__file__).resolve().parents[1] / "data" / "ros2_robotiq_gripper"
DESCRIPTION = "robotiq_description/urdf/robotiq_2f_85_gripper.urdf.xacro"
LEADER = "robotiq_85_left_knuckle_joint"
ARGS = '{"use_fake_hardware": false}'


def _package() -> dict[str, bytes]:
    return {
        p.relative_to(DATA).as_posix(): p.read_bytes()
        for p in sorted((DATA / "robotiq_description").rglob("*"))
        if p.is_file()
    }


def _xacro_cli(tmp: Path) -> str:
    index = tmp / "ament" / "ament_index_python"
    index.mkdir(parents=True)
    (index / "__init__.py").write_text("")
    share = str(DATA / "robotiq_description")
    (index / "packages.py").write_text(
        f"def get_package_share_directory(name):\n    return {{'robotiq_description': {share!r}}}[name]\n"  # noqa: E501
    )
    out = subprocess.run(
        [
            str(Path(sys.executable).parent / "xacro"),
            str(DATA / DESCRIPTION),
            "use_fake_hardware:=false",
        ],  # fmt: skip  # noqa: E501
        capture_output=True,
        text=True,
        check=True,
        env={**os.environ, "PYTHONPATH": str(tmp / "ament")},
        cwd=ROOT,
    )
    return out.stdout


def test_robotiq_2f85_package_loads_with_the_xacro_cli_and_yourdfpy_fk(
    client: TestClient, tmp_path: Path
) -> None:
    r = client.post(
        "/robots/package",
        data={"name": "robotiq", "description": DESCRIPTION, "xacro_args": ARGS},
        files={"archive": ("robotiq.zip", zip_bytes(_package()), "application/zip")},
    )
    assert r.status_code == 201, r.text
    reference = yourdfpy.URDF.load(io.BytesIO(_xacro_cli(tmp_path).encode()), load_meshes=False)
    detail = client.get("/robots/robotiq").json()
    assert [j["name"] for j in detail["joints"]] == reference.actuated_joint_names == [LEADER]
    followers = {j.name: j.mimic for j in reference.robot.joints if j.mimic is not None}
    assert {m["name"]: (m["leader"], m["multiplier"], m["offset"]) for m in detail["mimic_joints"]} == {  # noqa: E501
        name: (m.joint, m.multiplier, m.offset) for name, m in followers.items()
    }  # fmt: skip
    assert "robotiq_85_left_inner_knuckle_joint" in followers
    links = [link.name for link in reference.robot.links]
    lower, upper = detail["joints"][0]["limits"]["lower"], detail["joints"][0]["limits"]["upper"]
    for value in np.random.default_rng(5).uniform(lower, upper, 20):
        fk = client.post("/robots/robotiq/fk", json={"q": [float(value)], "frames": links})
        assert fk.status_code == 200, fk.text
        reference.update_cfg([value])
        for link in links:
            expected = reference.get_transform(link, reference.base_link)
            got = np.array(fk.json()["poses"][link]["matrix"])
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12, err_msg=link)

"""An SRDF given as xacro (``ur_moveit_config`` ships only ``srdf/ur.srdf.xacro``) is
expanded by the service's sandboxed xacro, with the package's ``$(find)`` and
``xacro_args`` (or ``srdf_xacro_args``), then checked like any SRDF; an SRDF that still holds
xacro given as plain ``.srdf`` is a 422 naming it, never a robot with 0 groups.

Reference: the real ``xacro`` CLI (``.venv/bin/xacro``) expanding the same files, its
``$(find)`` answered by an ament index of the test's own (xacro asks
``ament_index_python``, which a ROS install provides): the number of groups, group states
and disabled collision pairs after upload equal those of its output.

The two xacro files are from UniversalRobots/Universal_Robots_ROS2_Driver
(BSD-3-Clause, Copyright 2021 Universal Robots A/S), ``ur_moveit_config/srdf/``:
``ur.srdf.xacro`` as published at commit f015749a50ea991f9cb6da0e35486d6634e6810e, and
``ur_macro.srdf.xacro`` at commit cb7cf0d1503b8e38a4be60d9cabffacb4e7b5355 trimmed of its
comments and of the two ``base_link_inertia`` pairs (the catalog's UR5 URDF, used as the
description here, has no such link).
"""

from __future__ import annotations

import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.main import create_app
from tests.helpers import ROOT, problem
from tests.packages import zip_bytes

UR_SRDF_XACRO = """<?xml version="1.0" encoding="UTF-8"?>
<robot xmlns:xacro="http://wiki.ros.org/xacro" name="$(arg name)">

  <!-- robot name parameter -->
  <xacro:arg name="name" default="ur"/>
  <!-- parameters -->
  <xacro:arg name="prefix" default="" />

  <xacro:include filename="$(find ur_moveit_config)/srdf/ur_macro.srdf.xacro"/>

  <xacro:ur_srdf name="$(arg name)" prefix="$(arg prefix)"/>

</robot>
"""
_STATE = """    <group_state name="${{prefix}}{name}" group="${{prefix}}${{name}}_manipulator">
      <joint name="${{prefix}}elbow_joint" value="{elbow}" />
      <joint name="${{prefix}}shoulder_lift_joint" value="{lift}" />
      <joint name="${{prefix}}shoulder_pan_joint" value="{pan}" />
      <joint name="${{prefix}}wrist_1_joint" value="{w1}" />
      <joint name="${{prefix}}wrist_2_joint" value="{w2}" />
      <joint name="${{prefix}}wrist_3_joint" value="{w3}" />
    </group_state>
"""
_PAIRS = [
    ("tool0", "wrist_1_link", "Never"),
    ("tool0", "wrist_2_link", "Never"),
    ("tool0", "wrist_3_link", "Adjacent"),
    ("forearm_link", "upper_arm_link", "Adjacent"),
    ("forearm_link", "wrist_1_link", "Adjacent"),
    ("shoulder_link", "upper_arm_link", "Adjacent"),
    ("wrist_1_link", "wrist_2_link", "Adjacent"),
    ("wrist_1_link", "wrist_3_link", "Never"),
    ("wrist_2_link", "wrist_3_link", "Adjacent"),
]
UR_MACRO_SRDF_XACRO = (
    '<?xml version="1.0" encoding="UTF-8"?>\n<robot xmlns:xacro="http://wiki.ros.org/xacro">\n'
    '  <xacro:macro name="ur_srdf" params="name prefix">\n'
    '    <group name="${prefix}${name}_manipulator">\n'
    '      <chain base_link="${prefix}base_link" tip_link="${prefix}tool0" />\n'
    "    </group>\n"
    + _STATE.format(name="home", elbow=0, lift=-1.5707, pan=0, w1=0, w2=0, w3=0)
    + _STATE.format(name="up", elbow=0, lift=-1.5707, pan=0, w1=-1.5707, w2=0, w3=0)
    + _STATE.format(
        name="test_configuration", elbow=1.4, lift=-1.62, pan=1.54, w1=-1.2, w2=-1.6, w3=-0.11
    )
    + "".join(
        f'    <disable_collisions link1="${{prefix}}{a}" link2="${{prefix}}{b}" reason="{r}" />\n'
        for a, b, r in _PAIRS
    )
    + "  </xacro:macro>\n</robot>\n"
)

CATALOG_UR5 = "package://example-robot-data/robots/ur_description/urdf/ur5_robot.urdf"


def _manifest(name: str) -> bytes:
    return f'<package format="3"><name>{name}</name><version>1.0.0</version></package>'.encode()


def ur_files(registry, macro: str = UR_MACRO_SRDF_XACRO) -> dict[str, bytes]:
    """A lab's workspace: the UR5 description (meshes from the catalog) and the MoveIt
    config with its xacro SRDF."""
    return {
        "ws/ur_description/package.xml": _manifest("ur_description"),
        "ws/ur_description/urdf/ur5.urdf": registry.get("ur5").urdf_text.encode(),
        "ws/ur_moveit_config/package.xml": _manifest("ur_moveit_config"),
        "ws/ur_moveit_config/srdf/ur.srdf.xacro": UR_SRDF_XACRO.encode(),
        "ws/ur_moveit_config/srdf/ur_macro.srdf.xacro": macro.encode(),
    }


def _post(client: TestClient, files: dict[str, bytes], **fields: str):
    return client.post(
        "/robots/package",
        data={"name": "ur", "description": "ws/ur_description/urdf/ur5.urdf", **fields},
        files={"archive": ("ws.zip", zip_bytes(files), "application/zip")},
    )


def xacro_cli(files: dict[str, bytes], tmp: Path, *args: str) -> ET.Element:
    """The real xacro CLI's expansion of ``ur.srdf.xacro``; ``$(find)`` of the workspace's
    packages through an ament index written here."""
    for name, data in files.items():
        (tmp / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp / name).write_bytes(data)
    index = tmp / "ament"
    (index / "ament_index_python").mkdir(parents=True)
    shares = {"ur_moveit_config": str(tmp / "ws" / "ur_moveit_config")}
    (index / "ament_index_python" / "__init__.py").write_text("")
    (index / "ament_index_python" / "packages.py").write_text(
        f"def get_package_share_directory(name):\n    return {shares!r}[name]\n"
    )
    out = subprocess.run(
        [
            str(Path(sys.executable).parent / "xacro"),
            str(tmp / "ws/ur_moveit_config/srdf/ur.srdf.xacro"),
            *args,
        ],  # fmt: skip
        capture_output=True,
        text=True,
        check=True,
        env={**os.environ, "PYTHONPATH": str(index)},
        cwd=ROOT,
    )
    return ET.fromstring(out.stdout)


@pytest.mark.parametrize(
    ("fields", "cli_args", "group"),
    [
        ({"xacro_args": '{"name": "ur5"}'}, ("name:=ur5",), "ur5_manipulator"),
        (
            {"xacro_args": '{"name": "ur5"}', "srdf_xacro_args": '{"name": "lab"}'},
            ("name:=lab",),
            "lab_manipulator",
        ),
    ],
    ids=["xacro_args", "srdf_xacro_args"],
)
def test_srdf_xacro_expands_like_the_xacro_cli(
    client: TestClient, registry, tmp_path: Path, fields, cli_args, group: str
) -> None:
    files = ur_files(registry)
    reference = xacro_cli(files, tmp_path, *cli_args)
    r = _post(client, files, srdf="ws/ur_moveit_config/srdf/ur.srdf.xacro", **fields)
    assert r.status_code == 201, r.text
    detail = client.get("/robots/ur").json()
    assert [g["name"] for g in detail["groups"]] == [g.get("name") for g in reference.iter("group")]
    assert [g["name"] for g in detail["groups"]] == [group]
    states = [s.get("name") for s in reference.iter("group_state")]
    assert [s["name"] for s in detail["named_states"]] == states
    assert states == ["home", "up", "test_configuration"]
    disabled = {
        frozenset((p.get("link1"), p.get("link2"))) for p in reference.iter("disable_collisions")
    }
    assert len(disabled) == len(_PAIRS)
    pairs = {frozenset(p) for p in detail["collision_pairs"]}
    assert pairs and not pairs & disabled
    fk = client.post("/robots/ur/fk", json={"group": group, "q": [0.1] * 6})
    assert fk.status_code == 200, fk.text


def test_srdf_xacro_without_its_required_arg_is_refused_like_the_cli(
    client: TestClient, registry, tmp_path: Path
) -> None:
    files = ur_files(registry)
    with pytest.raises(subprocess.CalledProcessError) as cli:
        xacro_cli(files, tmp_path)
    assert "name" in cli.value.stderr
    srdf = "ws/ur_moveit_config/srdf/ur.srdf.xacro"
    body = problem(_post(client, files, srdf=srdf), 422, "xacro_args")
    assert "$(arg name)" in body["detail"] and "ur.srdf.xacro" in body["detail"]


def test_srdf_xacro_refusals_name_srdf_fields(client: TestClient, registry) -> None:
    files = ur_files(registry)
    srdf = "ws/ur_moveit_config/srdf/ur.srdf.xacro"
    args = '{"name": "ur"}'
    body = problem(_post(client, files, srdf=srdf, srdf_xacro_args="[1]"), 422, "srdf_xacro_args")
    assert "object" in body["detail"]
    bad_value = '{"name": {"a": 1}}'
    problem(_post(client, files, srdf=srdf, srdf_xacro_args=bad_value), 422, "srdf_xacro_args.name")
    body = problem(
        _post(client, files, srdf=srdf, xacro_args=args, srdf_xacro_args="{}"),
        422,
        "srdf_xacro_args",
    )
    assert "$(arg name)" in body["detail"]
    missing = {**files}
    del missing["ws/ur_moveit_config/srdf/ur_macro.srdf.xacro"]
    body = problem(_post(client, missing, srdf=srdf, xacro_args=args), 422, "srdf")
    assert "ur_macro.srdf.xacro" in body["detail"]
    wrong_link = UR_MACRO_SRDF_XACRO.replace(
        'tip_link="${prefix}tool0"', 'tip_link="${prefix}nope"'
    )
    wrong = ur_files(registry, wrong_link)
    body = problem(_post(client, wrong, srdf=srdf, xacro_args=args), 422, "srdf")
    assert "nope" in body["detail"]
    assert client.get("/robots/ur").status_code == 404


@pytest.mark.parametrize(
    ("text", "words"),
    [
        (UR_SRDF_XACRO, "$(arg name)"),
        ('<robot name="r"><group name="${name}_arm"/></robot>', "${name}_arm"),
        ('<robot name="$(arg name)"/>', "$(arg name)"),
        (
            '<robot name="r" xmlns:x="http://www.ros.org/wiki/xacro">'
            '<x:property name="a"/></robot>',
            "<x:property>",
        ),
    ],
    ids=["xacro-element", "expression", "substitution", "other-prefix"],
)
def test_plain_srdf_holding_xacro_is_a_422_naming_it(
    client: TestClient, registry, text: str, words: str
) -> None:
    files = {**ur_files(registry), "ws/ur_moveit_config/srdf/ur.srdf": text.encode()}
    body = problem(_post(client, files, srdf="ws/ur_moveit_config/srdf/ur.srdf"), 422, "srdf")
    assert words in body["detail"] and ".xacro" in body["detail"], body["detail"]
    urdf = registry.get("ur5").urdf_text
    body = problem(
        client.post("/robots/urdf", json={"name": "ur", "urdf": urdf, "srdf": text}), 422, "srdf"
    )
    assert words in body["detail"]


#: The macro with a tool group and an end effector at the wrist (MoveIt configs of a UR
#: with a tool add these): the longest-chain rule alone would pick ``tool0``.
WITH_END_EFFECTOR = UR_MACRO_SRDF_XACRO.replace(
    "  </xacro:macro>",
    '    <group name="${prefix}tool"><link name="${prefix}tool0"/></group>\n'
    '    <end_effector name="${prefix}tool" parent_link="${prefix}wrist_3_link" '
    'group="${prefix}tool" parent_group="${prefix}${name}_manipulator"/>\n'
    "  </xacro:macro>",
)


def test_default_tip_of_a_package_is_its_srdf_end_effector(
    client: TestClient, registry, settings, tmp_path: Path
) -> None:
    srdf = "ws/ur_moveit_config/srdf/ur.srdf.xacro"
    args = '{"name": "ur5"}'
    bare = client.post(
        "/robots/package",
        data={"name": "bare", "description": "ws/ur_description/urdf/ur5.urdf"},
        files={"archive": ("ws.zip", zip_bytes(ur_files(registry)), "application/zip")},
    )
    assert bare.status_code == 201, bare.text
    assert bare.json()["end_effector"] == "tool0"  # the longest-chain rule's pick
    files = ur_files(registry, WITH_END_EFFECTOR)
    reference = xacro_cli(files, tmp_path, "name:=ur5")
    (ee,) = reference.iter("end_effector")
    r = _post(client, files, srdf=srdf, xacro_args=args)
    assert r.status_code == 201, r.text
    detail = client.get("/robots/ur").json()
    assert detail["end_effector"] == ee.get("parent_link") == "wrist_3_link"
    assert [e["name"] for e in detail["end_effectors"]] == ["tool"]
    assert [g["name"] for g in detail["groups"]] == [g.get("name") for g in reference.iter("group")]
    with TestClient(create_app(settings)) as again:  # the stored robot, read back
        assert again.get("/robots/ur").json()["end_effector"] == "wrist_3_link"

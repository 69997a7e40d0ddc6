"""POST /robots/package with a xacro or MJCF description, end to end over HTTP.

- A lab's xacro wrapper (an arg, a macro, an include of the Panda's URDF through
  ``$(find <package>)``, meshes by relative path): FK equals yourdfpy's FK of the same robot
  expanded by hand, to 1e-12; a sphere on a mesh collides; the default tip is the SRDF-less
  rule's, never a finger.
- An MJCF arm (hinge and slide joints, a mesh asset): FK equals yourdfpy's FK of its URDF
  twin written by hand from MuJoCo's rules, to 1e-12.
"""

from __future__ import annotations

import io
import json
import math

import yourdfpy
from fastapi.testclient import TestClient

from app.main import create_app
from app.operations.settings import Settings
from tests.helpers import problem
from tests.packages import PANDA_DIR, assert_fk_matches, panda_files, panda_urdf, zip_bytes

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'

#: The wrapper a lab writes around its arm: a flange-mounted tool whose length is an arg.
WRAPPER = f"""<?xml version="1.0"?>
<robot name="lab_panda" {XACRO_NS}>
  <xacro:arg name="tool_length" default="0.1"/>
  <xacro:include filename="$(find lab_panda)/urdf/panda.urdf"/>
  <xacro:macro name="tool" params="parent length">
    <link name="tool_tip"/>
    <joint name="tool_joint" type="fixed">
      <parent link="${{parent}}"/>
      <child link="tool_tip"/>
      <origin xyz="0.01 -0.02 ${{length}}" rpy="0 0 ${{pi / 4}}"/>
    </joint>
  </xacro:macro>
  <xacro:tool parent="panda_hand" length="$(arg tool_length)"/>
</robot>
"""


def _expanded_by_hand(tool_length: float) -> str:
    """The wrapper's result, written out: the Panda URDF plus the tool."""
    tool = (
        '<link name="tool_tip"/><joint name="tool_joint" type="fixed">'
        '<parent link="panda_hand"/><child link="tool_tip"/>'
        f'<origin xyz="0.01 -0.02 {tool_length!r}" rpy="0 0 {math.pi / 4!r}"/></joint></robot>'
    )
    return panda_urdf().replace("</robot>", tool)


def _upload(client: TestClient, files: dict[str, bytes], description: str, **fields: str):
    return client.post(
        "/robots/package",
        data={"name": "lab", "description": description, **fields},
        files={"archive": ("lab.zip", zip_bytes(files))},
    )


def test_xacro_package_fk_collisions_and_default_tip(client: TestClient) -> None:
    files = {**panda_files(), "urdf/lab_panda.urdf.xacro": WRAPPER.encode()}
    del files["srdf/panda.srdf"]  # no SRDF: the default tip comes from the tree alone
    resp = _upload(
        client,
        files,
        "urdf/lab_panda.urdf.xacro",
        xacro_args=json.dumps({"tool_length": 0.25}),
    )
    assert resp.status_code == 201, resp.text
    body = resp.json()
    # The longest chain's tip that is no finger: the tool (the hand's TCP is as deep).
    assert body["end_effector"] in {"tool_tip", "panda_hand_tcp"}, body["end_effector"]
    assert "finger" not in body["end_effector"]

    reference = yourdfpy.URDF.load(
        io.BytesIO(_expanded_by_hand(0.25).encode()),
        load_meshes=False,
        load_collision_meshes=False,
    )
    assert_fk_matches(client, "lab", reference, ["panda_link4", "panda_hand", "tool_tip"], seed=16)

    # The included URDF's relative meshes resolved inside the package and were loaded.
    q = body["neutral"]
    pose = client.post("/robots/lab/fk", json={"q": q, "frames": ["panda_link4"]}).json()
    ball = {
        "name": "ball",
        "shape": "sphere",
        "radius": 0.02,
        "pose": {"position": pose["poses"]["panda_link4"]["position"]},
    }
    hit = client.post("/robots/lab/collisions", json={"q": q, "obstacles": [ball]}).json()
    assert "panda_link4" in {p["a"] for p in hit["pairs"] if p["b"] == "ball"}
    mesh = client.get("/robots/lab/files/meshes/collision/link4.stl")
    assert mesh.content == (PANDA_DIR / "meshes" / "collision" / "link4.stl").read_bytes()


def test_panda_package_without_srdf_tips_at_the_tcp_not_a_finger(client: TestClient) -> None:
    """The Panda as a lab ships it, no SRDF and no ee_frame: the tip is the hand's TCP (the
    deepest link, the old rule, was panda_rightfinger); IK on it moves the arm."""
    files = panda_files()
    del files["srdf/panda.srdf"]
    resp = _upload(client, files, "urdf/panda.urdf")
    assert resp.status_code == 201, resp.text
    assert resp.json()["end_effector"] == "panda_hand_tcp"
    q = [0.1, -0.6, 0.2, -2.2, 0.1, 1.7, 0.6, 0.02]
    pose = client.post("/robots/lab/fk", json={"q": q}).json()["poses"]["panda_hand_tcp"]
    target = {"position": pose["position"], "orientation": pose["orientation"]}
    ik = client.post(
        "/robots/lab/ik", json={"target": target, "timeout_ms": 1000, "max_iterations": 5000}
    ).json()
    assert ik["success"] and ik["frame"] == "panda_hand_tcp", ik


def test_xacro_package_errors_name_the_field(client: TestClient, settings: Settings) -> None:
    files = {**panda_files(), "urdf/lab_panda.urdf.xacro": WRAPPER.encode()}
    bad_args = _upload(client, files, "urdf/lab_panda.urdf.xacro", xacro_args="[1, 2]")
    problem(bad_args, 422, "xacro_args")
    escaping = WRAPPER.replace("$(find lab_panda)/urdf/panda.urdf", "/etc/passwd")
    files["urdf/lab_panda.urdf.xacro"] = escaping.encode()
    refused = problem(_upload(client, files, "urdf/lab_panda.urdf.xacro"), 422, "description")
    assert "lab_panda.urdf.xacro" in refused["detail"]
    assert client.get("/robots/lab").status_code == 404
    robots = settings.data_dir / "robots"
    assert not [p for p in robots.iterdir() if p.name not in (".lock", ".generation")]


def test_xacro_settings_bound_the_expansion(settings: Settings) -> None:
    """DENAVIT_XACRO_MAX_OUTPUT_CHARS reaches the expansion (the Panda expands to ~30 kB)."""
    small = settings.model_copy(update={"xacro_max_output_chars": 4096})
    files = {**panda_files(), "urdf/lab_panda.urdf.xacro": WRAPPER.encode()}
    with TestClient(create_app(small), raise_server_exceptions=False) as client:
        refused = _upload(client, files, "urdf/lab_panda.urdf.xacro")
        assert "DENAVIT_XACRO_MAX_OUTPUT_CHARS" in problem(refused, 422, "description")["detail"]


C8, S8 = math.cos(math.pi / 8), math.sin(math.pi / 8)  # quaternion (w x y z) of 45° about y

#: An arm as MuJoCo Menagerie writes them: a mesh asset, body poses, hinge and slide joints.
MJCF = f"""<mujoco model="lab_arm">
  <compiler angle="radian" meshdir="assets"/>
  <asset><mesh name="base_mesh" file="link0.stl"/></asset>
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <geom type="mesh" mesh="base_mesh"/>
      <body name="l1" pos="0 0 0.2" euler="0 0 0.3">
        <joint name="j1" type="hinge" axis="0 0 1" range="-2 2"/>
        <geom type="box" size="0.02 0.02 0.1"/>
        <body name="l2" pos="0.1 0 0.3" quat="{C8!r} 0 {S8!r} 0">
          <joint name="j2" type="hinge" axis="0 1 0" range="-2.5 2.5"/>
          <geom type="sphere" size="0.03"/>
          <body name="l3" pos="0 0 0.25">
            <joint name="s3" type="slide" axis="1 0 0" range="0 0.1"/>
            <body name="tip" pos="0 0 0.05"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

#: Its twin, written by hand: body pos then rotation become the joint origin.
TWIN = f"""<robot name="twin">
  <link name="world"/><link name="base"/><link name="l1"/><link name="l2"/>
  <link name="l3"/><link name="tip"/>
  <joint name="base_fixed" type="fixed"><parent link="world"/><child link="base"/>
    <origin xyz="0 0 0.1"/></joint>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.2" rpy="0 0 0.3"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.1 0 0.3" rpy="0 {math.pi / 4!r} 0"/><axis xyz="0 1 0"/>
    <limit lower="-2.5" upper="2.5" effort="1" velocity="1"/></joint>
  <joint name="s3" type="prismatic"><parent link="l2"/><child link="l3"/>
    <origin xyz="0 0 0.25"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>
  <joint name="tip_fixed" type="fixed"><parent link="l3"/><child link="tip"/>
    <origin xyz="0 0 0.05"/></joint>
</robot>
"""


def test_mjcf_package_matches_its_urdf_twin(client: TestClient) -> None:
    files = {
        "mjcf/arm.xml": MJCF.encode(),
        "mjcf/assets/link0.stl": (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes(),
    }
    resp = _upload(client, files, "mjcf/arm.xml")
    assert resp.status_code == 201, resp.text
    assert resp.json()["has_collision_geometry"]
    reference = yourdfpy.URDF.load(io.BytesIO(TWIN.encode()), load_meshes=False)
    assert_fk_matches(client, "lab", reference, ["base", "l1", "l2", "l3", "tip"], seed=7)
    assert client.get("/robots/lab/files/mjcf/assets/link0.stl").status_code == 200


def test_mjcf_ball_joint_is_422_naming_it(client: TestClient) -> None:
    ball = MJCF.replace('type="hinge" axis="0 1 0" range="-2.5 2.5"', 'type="ball"')
    files = {
        "mjcf/arm.xml": ball.encode(),
        "mjcf/assets/link0.stl": (PANDA_DIR / "meshes" / "collision" / "link0.stl").read_bytes(),
    }
    detail = problem(_upload(client, files, "mjcf/arm.xml"), 422, "description")["detail"]
    assert "j2" in detail and "ball" in detail

"""POST /robots/package with MJCF read as MuJoCo compiles it.

The reference is MuJoCo itself: ``mj_kinematics`` on the same ``qpos`` gives every body's and
site's pose (``xpos``/``xmat``, ``site_xpos``/``site_xmat``) and every geom's
(``geom_xpos``/``geom_xmat``); the service's FK over HTTP must equal them to 1e-9 at random
configurations (fixed seed). A mimic follower, which ``mj_kinematics`` leaves where
``qpos`` says, is given the value its ``<equality>`` asks.

- Default classes set a mesh's ``scale`` and a joint's ``pos`` (and ``ref``) through a
  ``childclass``: the stored URDF keeps the scale, the mesh file's vertices are where
  MuJoCo puts the compiled mesh, FK matches.
- A Menagerie-style ``scene.xml`` including the robot file (with a ``<keyframe>``),
  a floor plane, lights and textures loads; the floor is not part of the robot.
- The default tip of a gripper arm is its TCP site, not a finger; the site is a frame;
  materials and ``rgba`` reach GET /robots/{id}/urdf.
- What the service cannot model is a 422 naming the element (a ball or free joint, a
  nonlinear or tendon coupling, a loop, a site named like a body), and nothing is stored.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco
import numpy as np
import pytest
import trimesh
from fastapi.testclient import TestClient

from tests.helpers import problem
from tests.packages import PANDA_DIR, zip_bytes

FINGER_STL = (PANDA_DIR / "meshes" / "collision" / "finger.stl").read_bytes()

#: A gripper arm as Menagerie writes them: classes, childclass, a mesh scale and a joint
#: anchor from defaults, materials, a TCP site, a fixed tendon for the actuator, a joint
#: equality coupling the fingers, a keyframe.
MINI = """<mujoco model="mini">
  <compiler angle="radian" meshdir="assets" autolimits="true"/>
  <asset>
    <material name="grey" rgba="0.4 0.4 0.4 1"/>
    <material name="orange" rgba="1 0.5 0 1"/>
    <mesh class="arm" file="finger.stl"/>
  </asset>
  <default>
    <default class="arm">
      <mesh scale="0.5 0.5 0.5"/>
      <joint axis="0 1 0" range="-2 2"/>
      <default class="offset">
        <joint pos="0 -0.018 0.0065" axis="1 0 0" range="-0.8 0.8" ref="0.1"/>
      </default>
      <default class="visual">
        <geom type="mesh" contype="0" conaffinity="0" group="2"/>
      </default>
      <default class="collision">
        <geom type="mesh" group="3"/>
      </default>
    </default>
  </default>
  <worldbody>
    <light name="top" pos="0 0 2"/>
    <body name="base" pos="0 0 0.1" childclass="arm">
      <geom name="base_visual" class="visual" mesh="finger" material="grey"/>
      <geom name="base_collision" class="collision" mesh="finger"/>
      <body name="upper" pos="0 0 0.2" euler="0 0 0.3">
        <joint name="shoulder"/>
        <geom name="upper_capsule" type="capsule" fromto="0 0 0 0 0 0.3" size="0.03"
            material="orange"/>
        <body name="fore" pos="0 0 0.3">
          <joint name="elbow" class="offset"/>
          <geom name="fore_visual" class="visual" mesh="finger" material="grey" rgba="0 0 1 1"
              pos="0.01 0 0.05" euler="0.2 0 0"/>
          <site name="tcp" pos="0 0 0.2" euler="0 0.5 0"/>
          <body name="left_finger" pos="0 0.02 0.15">
            <joint name="left" type="slide" axis="0 1 0" range="0 0.04"/>
            <geom type="box" size="0.005 0.005 0.02"/>
          </body>
          <body name="right_finger" pos="0 -0.02 0.15" quat="0 0 0 1">
            <joint name="right" type="slide" axis="0 1 0" range="0 0.04"/>
            <geom type="box" size="0.005 0.005 0.02"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  <equality>
    <joint joint1="right" joint2="left" polycoef="0.001 1 0 0 0"/>
  </equality>
  <tendon>
    <fixed name="split">
      <joint joint="left" coef="0.5"/>
      <joint joint="right" coef="0.5"/>
    </fixed>
  </tendon>
  <actuator>
    <general name="grip" tendon="split" ctrlrange="0 255"/>
  </actuator>
  <keyframe>
    <key name="home" qpos="0.2 0.5 0.01 0.011"/>
  </keyframe>
</mujoco>
"""

#: Menagerie's scene.xml: the robot included, a floor with a textured material, lights.
SCENE = """<mujoco model="mini scene">
  <include file="mini.xml"/>
  <statistic center="0 0 0.4" extent="1"/>
  <asset>
    <texture type="skybox" builtin="gradient" rgb1="0.3 0.5 0.7" rgb2="0 0 0" width="512"
        height="3072"/>
    <texture type="2d" name="groundplane" builtin="checker" mark="edge" rgb1="0.2 0.3 0.4"
        rgb2="0.1 0.2 0.3" markrgb="0.8 0.8 0.8" width="300" height="300"/>
    <material name="groundplane" texture="groundplane" texuniform="true" texrepeat="5 5"
        reflectance="0.2"/>
  </asset>
  <worldbody>
    <light pos="0 0 1.5" dir="0 0 -1" directional="true"/>
    <geom name="floor" size="0 0 0.05" type="plane" material="groundplane"/>
    <geom name="table" type="box" size="0.5 0.5 0.02" pos="1 0 0.3"/>
  </worldbody>
</mujoco>
"""


def _files(text: str = MINI, **extra: str) -> dict[str, bytes]:
    files = {"mini/mini.xml": text.encode(), "mini/assets/finger.stl": FINGER_STL}
    files.update({f"mini/{name}": body.encode() for name, body in extra.items()})
    return files


def _upload(client: TestClient, files: dict[str, bytes], description: str):
    return client.post(
        "/robots/package",
        data={"name": "mini", "description": description},
        files={"archive": ("mini.zip", zip_bytes(files))},
    )


def _pose(pos: np.ndarray, mat: np.ndarray) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = np.asarray(mat).reshape(3, 3)
    T[:3, 3] = pos
    return T


def _quat_pose(pos: np.ndarray, quat: np.ndarray) -> np.ndarray:
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, quat)
    return _pose(pos, mat)


def _mujoco(model: mujoco.MjModel, q: dict[str, float]) -> mujoco.MjData:
    """MuJoCo's kinematics at ``q`` (by joint name), the finger follower set by its
    equality (right = 0.001 + left)."""
    data = mujoco.MjData(model)
    data.qpos[:] = model.qpos0
    for name, value in q.items():
        data.qpos[model.jnt_qposadr[model.joint(name).id]] = value
    data.qpos[model.jnt_qposadr[model.joint("right").id]] = 0.001 + q["left"]
    mujoco.mj_kinematics(model, data)
    return data


def _check_fk(client: TestClient, reference: mujoco.MjModel, seed: int) -> None:
    """FK over HTTP of every body and site equals MuJoCo's, to 1e-9."""
    detail = client.get("/robots/mini").json()
    names = [j["name"] for j in detail["joints"]]
    assert names == ["shoulder", "elbow", "left"]  # the follower is no configuration entry
    lower = np.array([j["limits"]["lower"] for j in detail["joints"]])
    upper = np.array([j["limits"]["upper"] for j in detail["joints"]])
    bodies = [reference.body(b).name for b in range(1, reference.nbody)]
    rng = np.random.default_rng(seed)
    for _ in range(20):
        q = rng.uniform(lower, upper)
        data = _mujoco(reference, dict(zip(names, q, strict=True)))
        fk = client.post("/robots/mini/fk", json={"q": q.tolist(), "frames": [*bodies, "tcp"]})
        assert fk.status_code == 200, fk.text
        poses = fk.json()["poses"]
        for b, name in enumerate(bodies, start=1):
            expected = _pose(data.xpos[b], data.xmat[b])
            got = np.array(poses[name]["matrix"])
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9, err_msg=name)
        tcp = reference.site("tcp").id
        expected = _pose(data.site_xpos[tcp], data.site_xmat[tcp])
        np.testing.assert_allclose(np.array(poses["tcp"]["matrix"]), expected, atol=1e-9)


def _origin(element: ET.Element) -> np.ndarray:
    origin = element.find("origin")
    xyz = [float(v) for v in origin.get("xyz", "0 0 0").split()]
    r, p, y = (float(v) for v in origin.get("rpy", "0 0 0").split())
    cr, sr, cp, sp, cy, sy = np.cos(r), np.sin(r), np.cos(p), np.sin(p), np.cos(y), np.sin(y)
    rot = np.array(
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    )
    return _pose(np.array(xyz), rot)


def test_default_classes_set_mesh_scale_and_joint_anchor(client: TestClient) -> None:
    """Mesh scale and joint pos from default classes, as MuJoCo compiles them."""
    resp = _upload(client, _files(), "mini/mini.xml")
    assert resp.status_code == 201, resp.text
    reference = mujoco.MjModel.from_xml_string(MINI, {"assets/finger.stl": FINGER_STL})
    _check_fk(client, reference, seed=4)
    urdf = ET.fromstring(client.get("/robots/mini/urdf").text)
    visuals = {v.get("name"): (link.get("name"), v) for link in urdf.iter("link") for v in link}
    link, fore = visuals["fore_visual"]
    assert fore.find("geometry/mesh").get("scale") == "0.5 0.5 0.5"
    # the mesh file's vertices, placed by the service's FK, where MuJoCo puts its mesh
    q = [0.4, -0.3, 0.02]
    data = _mujoco(reference, dict(zip(["shoulder", "elbow", "left"], q, strict=True)))
    fk = client.post("/robots/mini/fk", json={"q": q, "frames": [link]}).json()
    placed = np.array(fk["poses"][link]["matrix"]) @ _origin(fore)
    g, mesh = reference.geom("fore_visual").id, reference.geom("fore_visual").dataid[0]
    offset = _quat_pose(reference.mesh_pos[mesh], reference.mesh_quat[mesh])
    expected = _pose(data.geom_xpos[g], data.geom_xmat[g]) @ np.linalg.inv(offset)
    np.testing.assert_allclose(placed, expected, rtol=0, atol=1e-9)
    vertices = trimesh.load(trimesh.util.wrap_as_stream(FINGER_STL), file_type="stl").vertices
    ours = (placed[:3, :3] @ (0.5 * vertices).T).T + placed[:3, 3]
    start, count = reference.mesh_vertadr[mesh], reference.mesh_vertnum[mesh]
    compiled = reference.mesh_vert[start : start + count].astype(float)  # float32 in MuJoCo
    theirs = (data.geom_xmat[g].reshape(3, 3) @ compiled.T).T + data.geom_xpos[g]
    distance = np.linalg.norm(ours[:, None, :] - theirs[None, :, :], axis=2)
    assert distance.min(axis=1).max() < 1e-6 and distance.min(axis=0).max() < 1e-6


def test_menagerie_scene_with_keyframe_loads_without_its_floor(client: TestClient) -> None:
    """scene.xml (the robot included, its keyframe, a floor) loads."""
    resp = _upload(client, _files(**{"scene.xml": SCENE}), "mini/scene.xml")
    assert resp.status_code == 201, resp.text
    assets = {"assets/finger.stl": FINGER_STL, "mini.xml": MINI.encode()}
    reference = mujoco.MjModel.from_xml_string(SCENE, assets)
    assert reference.nkey == 1
    _check_fk(client, reference, seed=5)
    urdf = client.get("/robots/mini/urdf").text
    # the world body's geoms (the floor, a table) are the scene's, not the robot's
    assert "floor" not in urdf and "table" not in urdf and "groundplane" not in urdf


def test_gripper_arm_tips_at_its_tcp_site_with_colours(client: TestClient) -> None:
    """The tip is the TCP site (a frame), not a finger; colours survive."""
    assert _upload(client, _files(), "mini/mini.xml").status_code == 201
    detail = client.get("/robots/mini").json()
    assert detail["end_effector"] == "tcp"
    urdf = ET.fromstring(client.get("/robots/mini/urdf").text)
    colours = {v.get("name"): v.find("material/color").get("rgba") for v in urdf.iter("visual")}
    assert colours["base_visual"] == "0.4000000059604645 0.4000000059604645 0.4000000059604645 1.0"
    assert colours["fore_visual"] == "0.0 0.0 1.0 1.0"
    assert colours["upper_capsule"] == "1.0 0.5 0.0 1.0"
    # Menagerie's convention: group-3 collision geoms are not drawn, visual ones do not collide
    collisions = {c.get("name") for c in urdf.iter("collision")}
    assert "base_collision" in collisions and "base_visual" not in collisions
    assert "base_collision" not in colours


@pytest.mark.parametrize(
    ("old", "new", "named"),
    [
        (
            '<joint name="shoulder"/>',
            '<joint name="shoulder" type="ball" range="0 1"/>',
            "joint 'shoulder' of type 'ball'",
        ),
        (
            '<body name="base" pos="0 0 0.1" childclass="arm">',
            '<body name="base"><freejoint name="float"/>',
            "joint 'float' of type 'free'",
        ),
        ('polycoef="0.001 1 0 0 0"', 'polycoef="0 1 0.5 0 0"', "polycoef"),
        (
            '<joint joint1="right" joint2="left" polycoef="0.001 1 0 0 0"/>',
            '<tendon tendon1="split"/>',
            "<tendon> (tendon 'split') is not supported: a tendon coupling joints",
        ),
        (
            '<joint joint1="right" joint2="left" polycoef="0.001 1 0 0 0"/>',
            '<connect name="loop" body1="left_finger" body2="right_finger" anchor="0 0 0"/>',
            "<connect name='loop'> (bodies 'left_finger' and 'right_finger') is not supported: "
            "it closes a kinematic loop",
        ),
        ('<site name="tcp"', '<site name="upper"', "<site name='upper'>: its name is already"),
        (
            '<joint joint1="right" joint2="left" polycoef="0.001 1 0 0 0"/>',
            '<weld body1="left_finger" body2="right_finger"/>',
            "<weld> (bodies 'left_finger' and 'right_finger') is not supported: it welds",
        ),
    ],
)
def test_what_the_service_cannot_model_is_a_422_naming_it(
    client: TestClient, old: str, new: str, named: str
) -> None:
    assert old in MINI
    text = MINI.replace(old, new)
    if "<freejoint" in new:
        text = text.replace('<body name="upper"', '<body name="upper" childclass="arm"')
    detail = problem(_upload(client, _files(text), "mini/mini.xml"), 422, "description")["detail"]
    assert named in detail, detail
    assert client.get("/robots/mini").status_code == 404

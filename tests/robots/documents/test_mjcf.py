"""app.robots.documents.mjcf: an MJCF arm written out as URDF.

The arm below is also written by hand as URDF (its "twin", from MuJoCo's rules: body pose
= pos then rotation; ``euler`` intrinsic x-y-z in degrees, as a chain of fixed joints; a
joint's ``pos`` as a joint frame offset inside its body). FK of the generated URDF through
Pinocchio must equal yourdfpy's FK of the twin and MuJoCo's own kinematics of the MJCF
(``mj_kinematics``: ``xpos``/``xmat``).
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import mujoco
import numpy as np
import pinocchio as pin
import pytest
import yourdfpy

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.mjcf import mjcf_to_urdf
from app.robots.documents.urdf import check_urdf_document

C8, S8 = math.cos(math.pi / 8), math.sin(math.pi / 8)  # quaternion of 45° about z
C12, S12 = math.cos(math.pi / 12), math.sin(math.pi / 12)  # quaternion of 30° about x

ARM = f"""<mujoco model="twin">
  <default><joint damping="0.1"/></default>
  <worldbody>
    <geom type="plane" size="1 1 0.1"/>
    <body name="base" pos="0.1 0.2 0.3" euler="0 0 90">
      <geom type="cylinder" size="0.05 0.05" mass="2"/>
      <body name="link1" pos="0 0 0.1" quat="{C8!r} 0 0 {S8!r}">
        <joint name="j1" type="hinge" axis="0 0 1" range="-170 170"/>
        <geom type="capsule" fromto="0 0 0 0 0 0.3" size="0.04"/>
        <body name="link2" pos="0 0.05 0.3" euler="10 20 30">
          <joint name="j2" axis="0 1 1" range="-90 90" pos="0.01 0 0.02"/>
          <geom type="box" size="0.02 0.03 0.15" pos="0 0 0.15" euler="0 0 20"/>
          <body name="link3" pos="0.02 0 0.3" quat="{C12!r} {S12!r} 0 0">
            <joint name="j3" axis="1 0 0"/>
            <geom type="sphere" size="0.03" mass="0.7"/>
            <body name="link4" pos="0 0 0.2" euler="-30 0 15">
              <joint name="j4" axis="0 0 -1" range="-120 120"/>
              <geom type="cylinder" size="0.02 0.05" mass="0.3"/>
              <body name="slider" pos="0.05 0 0.1">
                <joint name="s1" type="slide" axis="0 0 1" range="-0.05 0.1"/>
                <geom type="sphere" size="0.02"/>
                <body name="tool" pos="0 0 0.05" euler="0 90 0"/>
              </body>
            </body>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

R = math.radians
H = math.sqrt(0.5)


def _fixed(name: str, parent: str, child: str, xyz: str = "0 0 0", rpy: str = "0 0 0") -> str:
    return (
        f'<link name="{child}"/><joint name="{name}" type="fixed"><parent link="{parent}"/>'
        f'<child link="{child}"/><origin xyz="{xyz}" rpy="{rpy}"/></joint>\n'
    )


def _euler(body: str, parent: str, pos: str, a: float, b: float, c: float) -> str:
    """MuJoCo's intrinsic x-y-z Euler angles (degrees) as three fixed joints."""
    return (
        _fixed(f"{body}_p", parent, f"{body}_p", pos)
        + _fixed(f"{body}_x", f"{body}_p", f"{body}_x", rpy=f"{R(a)!r} 0 0")
        + _fixed(f"{body}_y", f"{body}_x", f"{body}_y", rpy=f"0 {R(b)!r} 0")
        + _fixed(f"{body}_z", f"{body}_y", f"{body}_pre", rpy=f"0 0 {R(c)!r}")
    )


def _moving(name: str, kind: str, parent: str, child: str, axis: str, limit: str) -> str:
    return (
        f'<link name="{child}"/><joint name="{name}" type="{kind}"><parent link="{parent}"/>'
        f'<child link="{child}"/><origin xyz="0 0 0" rpy="0 0 0"/><axis xyz="{axis}"/>'
        f"{limit}</joint>\n"
    )


def _limit(lo: float, hi: float) -> str:
    return f'<limit lower="{lo!r}" upper="{hi!r}" effort="1" velocity="1"/>'


TWIN = (
    '<robot name="twin"><link name="world"/>\n'
    + _euler("base", "world", "0.1 0.2 0.3", 0, 0, 90)
    + _fixed("base_f", "base_pre", "base")
    + _fixed("link1_p", "base", "link1_pre", "0 0 0.1", f"0 0 {math.pi / 4!r}")
    + _moving("j1", "revolute", "link1_pre", "link1", "0 0 1", _limit(R(-170), R(170)))
    + _euler("link2", "link1", "0 0.05 0.3", 10, 20, 30)
    + _fixed("link2_j", "link2_pre", "link2_jpre", "0.01 0 0.02")
    + _moving("j2", "revolute", "link2_jpre", "link2_j", f"0 {H!r} {H!r}", _limit(R(-90), R(90)))
    + _fixed("link2_f", "link2_j", "link2", "-0.01 0 -0.02")
    + _fixed("link3_p", "link2", "link3_pre", "0.02 0 0.3", f"{math.pi / 6!r} 0 0")
    + _moving("j3", "continuous", "link3_pre", "link3", "1 0 0", "")
    + _euler("link4", "link3", "0 0 0.2", -30, 0, 15)
    + _moving("j4", "revolute", "link4_pre", "link4", "0 0 -1", _limit(R(-120), R(120)))
    + _fixed("slider_p", "link4", "slider_pre", "0.05 0 0.1")
    + _moving("s1", "prismatic", "slider_pre", "slider", "0 0 1", _limit(-0.05, 0.1))
    + _euler("tool", "slider", "0 0 0.05", 0, 90, 0)
    + _fixed("tool_f", "tool_pre", "tool")
    + "</robot>"
)
BODIES = ("base", "link1", "link2", "link3", "link4", "slider", "tool")
JOINTS = ("j1", "j2", "j3", "j4", "s1")


def _write(tmp_path: Path, text: str, name: str = "arm.xml") -> str:
    (tmp_path / "robot").mkdir(exist_ok=True)
    (tmp_path / "robot" / name).write_text(text)
    return f"robot/{name}"


def _poses(model: pin.Model, q: dict[str, float]) -> dict[str, np.ndarray]:
    qv = []
    for j in range(1, model.njoints):
        v = q[model.names[j]]
        qv += [math.cos(v), math.sin(v)] if model.joints[j].nq == 2 else [v]
    data = model.createData()
    pin.framesForwardKinematics(model, data, np.array(qv))
    return {b: data.oMf[model.getFrameId(b, pin.FrameType.BODY)].homogeneous for b in BODIES}


def mujoco_poses(model: mujoco.MjModel, q: dict[str, float]) -> dict[str, np.ndarray]:
    """MuJoCo's own kinematics (the reference): every named body's and site's pose in the
    world at the joint positions ``q`` (by joint name; the others at ``qpos0``)."""
    data = mujoco.MjData(model)
    data.qpos[:] = model.qpos0
    for name, value in q.items():
        data.qpos[model.jnt_qposadr[model.joint(name).id]] = value
    mujoco.mj_kinematics(model, data)
    poses = {}
    for kind, count, pos, mat in (
        (mujoco.mjtObj.mjOBJ_BODY, model.nbody, data.xpos, data.xmat),
        (mujoco.mjtObj.mjOBJ_SITE, model.nsite, data.site_xpos, data.site_xmat),
    ):
        for i in range(count):
            T = np.eye(4)
            T[:3, :3] = mat[i].reshape(3, 3)
            T[:3, 3] = pos[i]
            poses[mujoco.mj_id2name(model, kind, i)] = T
    return poses


def test_arm_matches_its_hand_written_twin_and_mujoco(tmp_path: Path) -> None:
    description = _write(tmp_path, ARM)
    urdf = mjcf_to_urdf(tmp_path, description, XmlLimits())
    check_urdf_document(parse_literal_xml(urdf, "urdf"))
    generated = pin.buildModelFromXML(urdf)
    mjcf = mujoco.MjModel.from_xml_path(str(tmp_path / description))
    twin = yourdfpy.URDF.load(io.BytesIO(TWIN.encode()), load_meshes=False)
    rng = np.random.default_rng(16)
    for _ in range(50):
        q = {}
        for name in JOINTS:
            limit = twin.joint_map[name].limit
            lo, hi = (limit.lower, limit.upper) if limit is not None else (-math.pi, math.pi)
            q[name] = rng.uniform(lo, hi)
        twin.update_cfg(q)
        ours = _poses(generated, q)
        theirs = mujoco_poses(mjcf, q)
        for body in BODIES:
            expected = twin.get_transform(body, "world")
            assert np.abs(ours[body] - expected).max() < 1e-12, body
            assert np.abs(theirs[body] - expected).max() < 1e-12, body


def test_joint_kinds_limits_and_inertias(tmp_path: Path) -> None:
    urdf = mjcf_to_urdf(tmp_path, _write(tmp_path, ARM), XmlLimits())
    generated = pin.buildModelFromXML(urdf)
    mjcf = mujoco.MjModel.from_xml_path(str(tmp_path / "robot/arm.xml"))
    kinds = {generated.names[j]: generated.joints[j].shortname() for j in range(1, 6)}
    assert kinds["j3"] == "JointModelRUBX"  # unlimited hinge: continuous
    assert kinds["s1"] == "JointModelPZ"
    j1 = generated.joints[generated.getJointId("j1")].idx_q
    assert generated.lowerPositionLimit[j1] == pytest.approx(math.radians(-170), abs=1e-15)
    # each body's inertia (MuJoCo's: mass, centre, principal axes) on its link, in its frame
    links = yourdfpy.URDF.load(io.BytesIO(urdf.encode()), load_meshes=False).link_map
    for body in BODIES:
        b = mjcf.body(body).id
        inertial = links[body].inertial
        if mjcf.body_mass[b] > 1e-6:
            assert inertial.mass == pytest.approx(mjcf.body_mass[b], abs=1e-12), body
            rot = np.zeros(9)
            mujoco.mju_quat2Mat(rot, mjcf.body_iquat[b])
            rot = rot.reshape(3, 3)
            assert np.abs(inertial.origin[:3, 3] - mjcf.body_ipos[b]).max() < 1e-12, body
            expected = rot @ np.diag(mjcf.body_inertia[b]) @ rot.T
            origin = inertial.origin[:3, :3]
            inertia = origin @ inertial.inertia @ origin.T
            assert np.abs(inertia - expected).max() < 1e-12, body


def test_geometry_is_where_pinocchio_puts_it(tmp_path: Path) -> None:
    description = _write(tmp_path, ARM)
    urdf = mjcf_to_urdf(tmp_path, description, XmlLimits())
    model = pin.buildModelFromXML(urdf)
    geom = pin.buildGeomFromUrdfString(model, urdf, pin.GeometryType.COLLISION)
    data, gdata = model.createData(), geom.createData()
    q = pin.randomConfiguration(model)
    pin.framesForwardKinematics(model, data, q)
    pin.updateGeometryPlacements(model, data, geom, gdata, q)
    kinds = sorted(type(o.geometry).__name__ for o in geom.geometryObjects)
    # cylinder (base), capsule as cylinder + 2 spheres, box, sphere, cylinder, sphere
    assert kinds == [
        "Box",
        "Cylinder",
        "Cylinder",
        "Cylinder",
        "Sphere",
        "Sphere",
        "Sphere",
        "Sphere",
    ]
    box = next(i for i, o in enumerate(geom.geometryObjects) if type(o.geometry).__name__ == "Box")
    assert np.allclose(2 * geom.geometryObjects[box].geometry.halfSide, [0.04, 0.06, 0.3])
    link2 = data.oMf[model.getFrameId("link2", pin.FrameType.BODY)]
    expected = np.eye(4)
    expected[:3, :3] = pin.rpy.rpyToMatrix(0, 0, math.radians(20))
    expected[:3, 3] = (0, 0, 0.15)
    assert np.abs(gdata.oMg[box].homogeneous - link2.homogeneous @ expected).max() < 1e-12


@pytest.mark.parametrize(
    ("joint", "kind"),
    [
        ('<joint name="shoulder" type="ball"/>', "ball"),
        ('<joint name="floating" type="free"/>', "free"),
        ('<freejoint name="floating"/>', "free"),
    ],
)
def test_other_joint_types_are_refused_naming_joint_and_type(
    tmp_path: Path, joint: str, kind: str
) -> None:
    text = ARM.replace('<joint name="j3" axis="1 0 0"/>', joint)
    with pytest.raises(InvalidInputError) as info:
        mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits())
    name = joint.split('"')[1]
    assert info.value.field == "description"
    assert repr(name) in info.value.message and repr(kind) in info.value.message


def test_include_is_followed_inside_the_package(tmp_path: Path) -> None:
    start = ARM.index('<body name="link3"')
    end = ARM.index("</body>\n      </body>\n    </body>\n  </worldbody>")
    _write(tmp_path, f"<mujoco>{ARM[start:end]}</mujoco>", "part.xml")
    text = ARM[:start] + '<include file="part.xml"/>' + ARM[end:]
    urdf = mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits())
    frames = {f.name for f in pin.buildModelFromXML(urdf).frames}
    assert {"link3", "link4", "slider", "tool"} <= frames


@pytest.mark.parametrize(
    "snippet",
    [
        '<include file="../../outside.xml"/>',
        '<include file="/etc/passwd"/>',
        '<compiler meshdir="../.."/>',
        '<asset><mesh name="m" file="../../outside.stl"/></asset>',
    ],
)
def test_files_outside_the_package_are_refused(tmp_path: Path, snippet: str) -> None:
    (tmp_path / "outside.xml").write_text("<mujoco/>")
    root = tmp_path / "pkg"
    root.mkdir()
    text = ARM.replace("<worldbody>", snippet + "<worldbody>")
    with pytest.raises(InvalidInputError) as info:
        mjcf_to_urdf(root, _write(root, text), XmlLimits())
    assert "outside the package" in info.value.message or "relative path" in info.value.message


def test_include_through_symlink_out_of_the_package_is_refused(tmp_path: Path) -> None:
    (tmp_path / "outside.xml").write_text("<mujoco/>")
    root = tmp_path / "pkg"
    root.mkdir()
    description = _write(root, ARM.replace("<worldbody>", '<include file="in.xml"/><worldbody>'))
    (root / "robot" / "in.xml").symlink_to(tmp_path / "outside.xml")
    with pytest.raises(InvalidInputError) as info:
        mjcf_to_urdf(root, description, XmlLimits())
    assert "outside the package" in info.value.message


def test_meshes_keep_paths_relative_to_the_description(tmp_path: Path) -> None:
    (tmp_path / "robot" / "assets").mkdir(parents=True)
    (tmp_path / "robot" / "assets" / "tri.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"
    )
    text = ARM.replace(
        "<worldbody>",
        '<compiler meshdir="assets"/><asset><mesh name="tri" file="tri.obj" scale="1 2 3"/>'
        "</asset><worldbody>",
    ).replace('<geom type="sphere" size="0.02"/>', '<geom type="mesh" mesh="tri"/>')
    urdf = mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits())
    assert '<mesh filename="assets/tri.obj" scale="1.0 2.0 3.0"/>' in urdf


def test_an_unlimited_slide_is_refused_and_two_root_bodies_load(tmp_path: Path) -> None:
    text = ARM.replace('type="slide" axis="0 0 1" range="-0.05 0.1"', 'type="slide"')
    with pytest.raises(InvalidInputError, match="s1"):
        mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits())
    text = ARM.replace(
        "</worldbody>", '<body name="other" pos="1 2 3"><geom size="0.1"/></body></worldbody>'
    )
    model = pin.buildModelFromXML(mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits()))
    data = model.createData()
    pin.framesForwardKinematics(model, data, pin.neutral(model))
    other = data.oMf[model.getFrameId("other", pin.FrameType.BODY)].homogeneous
    expected = mujoco_poses(mujoco.MjModel.from_xml_string(text), {})["other"]
    assert np.abs(other - expected).max() < 1e-12


def test_xml_limits_apply_to_the_document(tmp_path: Path) -> None:
    with pytest.raises(InvalidInputError, match="DENAVIT_MAX_XML_ELEMENTS"):
        mjcf_to_urdf(tmp_path, _write(tmp_path, ARM), XmlLimits(max_elements=10))


@pytest.mark.parametrize(
    ("old", "new", "shown"),
    [
        ('<body name="link4" pos="0 0 0.2"', '<body name="link4" pos="x 0 0.2"', "pos='x 0 0.2'"),
        ('euler="-30 0 15"', 'euler="-30 0"', "euler='-30 0'"),
        ('<joint name="j4" axis="0 0 -1"', '<joint name="j4" axis="0 0 0"', "zero vector"),
        ('range="-120 120"', 'range="120 -120"', "lower bound"),
        ('size="0.03" mass="0.7"', 'size="-0.03" mass="0.7"', "negative"),
        ('size="0.03" mass="0.7"', 'size="0.03" mass="nan"', "mass='nan'"),
    ],
)
def test_malformed_numbers_are_refused(tmp_path: Path, old: str, new: str, shown: str) -> None:
    # Pinocchio's parser would read them as 0 or uninitialised memory without a word
    assert old in ARM
    with pytest.raises(InvalidInputError) as info:
        mjcf_to_urdf(tmp_path, _write(tmp_path, ARM.replace(old, new)), XmlLimits())
    assert shown in info.value.message and "robot/arm.xml" in info.value.message


def test_parser_errors_do_not_show_server_paths(tmp_path: Path) -> None:
    text = ARM.replace(
        "<worldbody>", '<asset><mesh name="m" file="missing.stl"/></asset><worldbody>'
    ).replace('<geom type="sphere" size="0.02"/>', '<geom type="mesh" mesh="m"/>')
    with pytest.raises(InvalidInputError) as info:
        mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits())
    assert "missing.stl" in info.value.message and str(tmp_path) not in info.value.message


def test_frame_elements_are_read_as_mujoco_reads_them(tmp_path: Path) -> None:
    text = ARM.replace(
        '<body name="link4"', '<frame pos="0.1 0 0" euler="0 0 30"><body name="link4"'
    ).replace(
        '<body name="tool" pos="0 0 0.05" euler="0 90 0"/>\n              </body>\n'
        "            </body>",
        '<body name="tool" pos="0 0 0.05" euler="0 90 0"/>\n              </body>\n'
        "            </body></frame>",
    )
    assert "</frame>" in text
    model = pin.buildModelFromXML(mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits()))
    reference = mujoco.MjModel.from_xml_string(text)
    rng = np.random.default_rng(3)
    for _ in range(10):
        q = {name: rng.uniform(-0.05, 0.1) for name in JOINTS}
        ours, theirs = _poses(model, q), mujoco_poses(reference, q)
        for body in BODIES:
            assert np.abs(ours[body] - theirs[body]).max() < 1e-12, body


def test_several_joints_in_one_body_chain_in_mujocos_order(tmp_path: Path) -> None:
    """A body with a hinge off its origin, a slide and a hinge with a ``ref``: MuJoCo
    composes them in order (each about its anchor in the body frame)."""
    text = ARM.replace(
        '<joint name="j3" axis="1 0 0"/>',
        '<joint name="j3" axis="1 0 0"/><joint name="j3b" type="slide" axis="0 1 1" '
        'range="-0.1 0.1" ref="0.02"/><joint name="j3c" axis="0 1 0" pos="0.01 0.02 0.03" '
        'range="-60 60" ref="10"/>',
    )
    model = pin.buildModelFromXML(mjcf_to_urdf(tmp_path, _write(tmp_path, text), XmlLimits()))
    reference = mujoco.MjModel.from_xml_string(text)
    rng = np.random.default_rng(9)
    for _ in range(20):
        q = {name: rng.uniform(-0.05, 0.1) for name in JOINTS}
        q.update(j3b=rng.uniform(-0.1, 0.1), j3c=rng.uniform(-1.0, 1.0))
        ours, theirs = _poses(model, q), mujoco_poses(reference, q)
        for body in BODIES:
            assert np.abs(ours[body] - theirs[body]).max() < 1e-12, body

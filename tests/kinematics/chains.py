"""Small hand-written URDF chains with known closed forms (independent of dh2urdf), and
the reachability map spec of the planar ones."""

from __future__ import annotations

import math
from typing import Any

from app.kinematics.models import RobotModel
from app.kinematics.reachability.spec import MapSpec, make_spec


def planar_2link(
    l1: float = 1.0,
    l2: float = 0.7,
    *,
    base_xyz: tuple[float, float, float] | None = None,
    base_rpy: tuple[float, float, float] = (0.0, 0.0, 0.0),
    limit: float = 3.14159,
    name: str = "planar2",
) -> str:
    """Two revolute z joints, links along x, a fixed ``tip`` frame at the end of link 2:
    x = l1c1 + l2c12, y = l1s1 + l2s12 in the ``base`` frame. With ``base_xyz``, the root is
    a ``world`` link and ``base`` hangs from it at (base_xyz, base_rpy)."""
    root = ""
    if base_xyz is not None:
        bx, by, bz = base_xyz
        br, bp, byaw = base_rpy
        root = f"""
  <link name="world"/>
  <joint name="base_joint" type="fixed">
    <parent link="world"/><child link="base"/>
    <origin xyz="{bx!r} {by!r} {bz!r}" rpy="{br!r} {bp!r} {byaw!r}"/>
  </joint>"""
    return f"""<?xml version="1.0"?>
<robot name="{name}">{root}
  <link name="base"/>
  <link name="link1"/>
  <link name="link2"/>
  <link name="tip"/>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="link1"/>
    <origin xyz="0 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="{-limit!r}" upper="{limit!r}" velocity="1" effort="1"/>
  </joint>
  <joint name="j2" type="revolute">
    <parent link="link1"/><child link="link2"/>
    <origin xyz="{l1!r} 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="{-limit!r}" upper="{limit!r}" velocity="1" effort="1"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="link2"/><child link="tip"/>
    <origin xyz="{l2!r} 0 0" rpy="0 0 0"/>
  </joint>
</robot>"""


def rrp_like(d_base: float = 0.4, a1: float = 0.3) -> str:
    """Revolute z, revolute y (offset along x), prismatic along the second link's x.

    A revolute-and-prismatic chain for the course's geometric Jacobian construction.
    """
    return f"""<?xml version="1.0"?>
<robot name="rrp">
  <link name="base"/>
  <link name="l1"/>
  <link name="l2"/>
  <link name="l3"/>
  <link name="tip"/>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="l1"/>
    <origin xyz="0 0 {d_base!r}" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" velocity="1" effort="1"/>
  </joint>
  <joint name="j2" type="revolute">
    <parent link="l1"/><child link="l2"/>
    <origin xyz="{a1!r} 0 0.05" rpy="0.3 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" velocity="1" effort="1"/>
  </joint>
  <joint name="j3" type="prismatic">
    <parent link="l2"/><child link="l3"/>
    <origin xyz="0.1 0 0" rpy="0 0 0"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="1" velocity="1" effort="1"/>
  </joint>
  <joint name="tip_joint" type="fixed">
    <parent link="l3"/><child link="tip"/>
    <origin xyz="0.05 0.02 0" rpy="0 0.2 0"/>
  </joint>
</robot>"""


def continuous_arm() -> str:
    """A continuous joint then a revolute one (nq = 3, nv = 2 in Pinocchio)."""
    return """<?xml version="1.0"?>
<robot name="cont">
  <link name="base"/><link name="l1"/><link name="l2"/>
  <joint name="c1" type="continuous">
    <parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="r2" type="revolute">
    <parent link="l1"/><child link="l2"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" velocity="1" effort="1"/>
  </joint>
</robot>"""


L1, L2 = 0.9, 0.6


def planar2_urdf(
    l1: float = L1,
    l2: float = L2,
    base_xyz: tuple[float, float, float] = (0.0, 0.0, 0.0),
    base_rpy: tuple[float, float, float] = (0.0, 0.0, 0.0),
    limit: float = math.pi,
) -> str:
    """Planar 2-link arm on a fixed base joint (world → base): x = l1c1 + l2c12,
    y = l1s1 + l2s12 in the base frame (tests/kinematics/chains.py)."""
    return planar_2link(
        l1, l2, base_xyz=base_xyz, base_rpy=base_rpy, limit=limit, name="planar2_test"
    )


def planar_map_spec(robot: RobotModel, **kw: Any) -> MapSpec:
    """A reachability map of a planar arm's ``tip`` over its plane: 5 cm voxels one layer
    thick around z = 0, position only (rows vx, vy), 60 000 samples; ``kw`` overrides."""
    args: dict[str, Any] = dict(
        voxel_size=0.05,
        lower=[-1.6, -1.6, -0.025],
        upper=[1.6, 1.6, 0.025],
        orientation_divisions=0,
        rows=["vx", "vy"],
        samples=60_000,
    )
    args.update(kw)
    return make_spec(robot, "tip", **args)


#: A planar 2R arm with box collision geometry: folded back, link 2 enters the base box.
COLLIDING_URDF = """<?xml version="1.0"?>
<robot name="planar_boxes">
  <link name="base"><collision><geometry><box size="0.8 0.8 0.1"/></geometry></collision>
  </link>
  <link name="link1"><collision><origin xyz="0.45 0 0.2"/>
    <geometry><box size="0.5 0.05 0.05"/></geometry></collision></link>
  <link name="link2"><collision><origin xyz="0.3 0 0"/>
    <geometry><box size="0.6 0.05 0.1"/></geometry></collision></link>
  <link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-3.14159" upper="3.14159" velocity="1" effort="1"/>
  </joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
    <origin xyz="0.9 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3.14159" upper="3.14159" velocity="1" effort="1"/>
  </joint>
  <joint name="tip_joint" type="fixed"><parent link="link2"/><child link="tip"/>
    <origin xyz="0.6 0 0"/></joint>
</robot>"""


# The vertical 2-link arm of the dynamics tests (Spong §7.4), lengths L1, L2: masses, centres
# of mass along each link, inertias about them (about the joint axis), effort limits.
M1, M2 = 3.0, 2.0  # link masses (kg)
C1, C2 = 0.4, 0.25  # centres of mass along each link (m)
I1, I2 = 0.21, 0.07  # inertias about each centre of mass, about the joint axis (kg·m²)
E1, E2 = 150.0, 60.0  # effort limits (N·m)


def vertical_2link() -> str:
    """Two revolute joints about −y (so positive angles lift the arm), links along x: the
    arm moves in the vertical x–z plane, angles measured from the horizontal."""

    def link(name: str, m: float, c: float, i: float) -> str:
        return f"""<link name="{name}"><inertial><origin xyz="{c} 0 0"/><mass value="{m}"/>
  <inertia ixx="0.01" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="0.02"/></inertial></link>"""

    return f"""<?xml version="1.0"?>
<robot name="vertical2">
  <link name="base"/>
  {link("link1", M1, C1, I1)}
  {link("link2", M2, C2, I2)}
  <link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="link1"/>
    <axis xyz="0 -1 0"/><limit lower="-3" upper="3" velocity="2" effort="{E1}"/></joint>
  <joint name="j2" type="revolute"><parent link="link1"/><child link="link2"/>
    <origin xyz="{L1} 0 0"/><axis xyz="0 -1 0"/>
    <limit lower="-3" upper="3" velocity="2" effort="{E2}"/></joint>
  <joint name="tip_joint" type="fixed"><parent link="link2"/><child link="tip"/>
    <origin xyz="{L2} 0 0"/></joint>
</robot>"""

"""DH table → URDF, built with yourdfpy's data model.

Structure (names from :mod:`dh2urdf.names`), for rows i = 1..n::

    world --fixed_dh_0 (B)--> dh_0
    dh_{i-1} --<joint i> (origin O_i, axis z)--> link_i --fixed_dh_i (F_i)--> dh_i
    dh_n --fixed_tool (T_tool)--> tool

In URDF a joint's motion comes *after* its origin, so each row is split such that
``O_i · M(q) · F_i = A_i(q)`` with ``M(q)`` = Rz(q) (revolute, continuous) or Tz(q)
(prismatic):

``standard``  A_i = Rz(θ)·Tz(d)·Tx(a)·Rx(α) starts with the motion about/along z_{i-1}:
    ``O_i = I`` and ``F_i = Rz(θ_off)·Tz(d_off)·Tx(a)·Rx(α)``
    (origin xyz = (a·cos θ_off, a·sin θ_off, d_off), rpy = (α, 0, θ_off), exact).
``modified``  A_i = Rx(α)·Tx(a)·Rz(θ)·Tz(d) ends with the motion about/along z_i, since
    Rz(q + θ_off) = Rz(θ_off)·Rz(q) commutes with Tz(d) and Tz(q + d_off) = Tz(d_off)·Tz(q):
    ``O_i = Rx(α)·Tx(a)·Rz(θ_off)·Tz(d_off)`` and ``F_i = I``.

Dynamics: a row's :class:`~dh2urdf.joint.LinkDynamics` (mass, com and inertia in frame i,
the DH frame at the END of the row, i.e. the link ``dh_i``) becomes the ``<inertial>`` of
``link_i``, the moving body, whose frame is ``dh_i·F_i⁻¹``. Its origin is therefore
``F_i·Tr(com)`` with the rotation of ``F_i`` (the inertia tensor keeps frame i's axes):
``standard`` xyz = (a·cos θ_off, a·sin θ_off, d_off) + Rz(θ_off)·Rx(α)·com, rpy =
(α, 0, θ_off); ``modified`` (F_i = I) xyz = com, rpy = 0. Pinocchio merges the fixed link
``dh_i`` into joint i's body either way; the origin is what matters.

Hence the world pose of link ``dh_i`` is ``B·A_1⋯A_i`` and that of ``tool`` is
``B·A_1⋯A_n·T_tool`` for every configuration, where q is the joint variable *without* the
table's offset. All values are SI (m, rad, m/s, rad/s, N, N·m). Every number is written
with ``repr`` precision (shortest string that round-trips the float64): origins are written
by this module from exact (xyz, rpy) pairs, not by yourdfpy's matrix → Euler conversion.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import yourdfpy
from lxml import etree

from dh2urdf.geometry import MIN_SEGMENT_LENGTH, capsule_axis_origin, segments
from dh2urdf.math import rot_x, rot_z, rotation_to_rpy
from dh2urdf.names import (
    ROOT_LINK,
    TOOL_JOINT,
    TOOL_LINK,
    body_link,
    dh_joint,
    dh_link,
)
from dh2urdf.table import DHJoint, DHTable, Transform

__all__ = [
    "to_urdf",
    "to_yourdfpy",
    "write_urdf",
    "row_origins",
    "inertial_origin",
    "CAPSULE_MATERIAL",
]

#: Name of the material of the generated visuals.
CAPSULE_MATERIAL = "dh2urdf_capsule"
_CAPSULE_RGBA = (0.7, 0.7, 0.75, 1.0)
_IDENTITY = Transform()


def _num(value: float) -> str:
    """Full-precision decimal of a float (``repr``: round-trips exactly; no ``-0.0``)."""
    return repr(float(value) + 0.0)


def _nums(values: tuple[float, ...] | list[float]) -> str:
    return " ".join(_num(v) for v in values)


def row_origins(joint: DHJoint, convention: str) -> tuple[Transform, Transform]:
    """``(O_i, F_i)``: origin of the actuated joint and of the fixed joint link_i → dh_i.

    See the module docstring; both are exact (xyz, rpy) pairs in SI units.
    """
    if convention == "standard":
        ct, st = math.cos(joint.theta), math.sin(joint.theta)
        fixed = Transform(
            xyz=(joint.a * ct + 0.0, joint.a * st + 0.0, joint.d + 0.0),
            rpy=(joint.alpha + 0.0, 0.0, joint.theta + 0.0),
        )
        return _IDENTITY, fixed
    if convention == "modified":
        ca, sa = math.cos(joint.alpha), math.sin(joint.alpha)
        rotation = rot_x(joint.alpha) @ rot_z(joint.theta)
        origin = Transform(
            xyz=(joint.a + 0.0, -sa * joint.d + 0.0, ca * joint.d + 0.0),
            rpy=rotation_to_rpy(rotation),
        )
        return origin, _IDENTITY
    raise ValueError(f"unknown DH convention {convention!r}")


def inertial_origin(joint: DHJoint, convention: str) -> Transform:
    """Origin of ``link_i``'s ``<inertial>`` frame: the row's com (given in frame i) seen
    from ``link_i``, with frame i's axes (see the module docstring). Exact (xyz, rpy)."""
    dynamics = joint.dynamics
    com = np.zeros(3) if dynamics is None else np.array(dynamics.com, dtype=float)
    _, fixed = row_origins(joint, convention)
    if fixed.is_identity:
        return Transform(xyz=_point(com), rpy=(0.0, 0.0, 0.0))
    rotation = (rot_z(joint.theta) @ rot_x(joint.alpha))[:3, :3]
    xyz = np.array(fixed.xyz) + rotation @ com
    return Transform(xyz=_point(xyz), rpy=fixed.rpy)


def _point(v: np.ndarray) -> tuple[float, float, float]:
    return (float(v[0]) + 0.0, float(v[1]) + 0.0, float(v[2]) + 0.0)


def _limit(joint: DHJoint) -> yourdfpy.Limit:
    return yourdfpy.Limit(
        effort=joint.effort, velocity=joint.velocity, lower=joint.lower, upper=joint.upper
    )


def _fixed(name: str, parent: str, child: str, origin: Transform) -> yourdfpy.Joint:
    return yourdfpy.Joint(
        name=name, type="fixed", parent=parent, child=child, origin=origin.matrix()
    )


def _build(table: DHTable) -> tuple[yourdfpy.Robot, dict[tuple[str, str], Transform]]:
    """The yourdfpy robot and the exact origin of every named element carrying one."""
    origins: dict[tuple[str, str], Transform] = {}
    links: dict[str, yourdfpy.Link] = {ROOT_LINK: yourdfpy.Link(name=ROOT_LINK)}
    joints: list[yourdfpy.Joint] = []

    def fixed(name: str, parent: str, child: str, origin: Transform) -> None:
        links[child] = yourdfpy.Link(name=child)
        joints.append(_fixed(name, parent, child, origin))
        origins[("joint", name)] = origin

    fixed(dh_joint(0), ROOT_LINK, dh_link(0), table.base)
    for i, joint in enumerate(table.joints, start=1):
        origin, fixed_part = row_origins(joint, table.convention)
        links[body_link(i)] = yourdfpy.Link(name=body_link(i))
        if joint.dynamics is not None:
            inertial = inertial_origin(joint, table.convention)
            links[body_link(i)].inertial = yourdfpy.Inertial(
                origin=inertial.matrix(),
                mass=joint.dynamics.mass,
                inertia=joint.dynamics.inertia_matrix(),
            )
            origins[("inertial", body_link(i))] = inertial
        joints.append(
            yourdfpy.Joint(
                name=joint.name,
                type=joint.type,
                parent=dh_link(i - 1),
                child=body_link(i),
                origin=origin.matrix(),
                axis=np.array([0.0, 0.0, 1.0]),
                limit=_limit(joint),
            )
        )
        origins[("joint", joint.name)] = origin
        fixed(dh_joint(i), body_link(i), dh_link(i), fixed_part)
    fixed(TOOL_JOINT, dh_link(table.dof), TOOL_LINK, table.tool)

    materials: list[yourdfpy.Material] = []
    radius = table.geometry_radius
    if radius > 0.0:
        materials.append(
            yourdfpy.Material(
                name=CAPSULE_MATERIAL, color=yourdfpy.Color(rgba=np.array(_CAPSULE_RGBA))
            )
        )
        spheres: dict[str, list[tuple[float, float, float]]] = {}

        def shape(link: str, name: str, geometry: yourdfpy.Geometry, origin: Transform) -> None:
            links[link].visuals.append(
                yourdfpy.Visual(
                    name=name,
                    origin=origin.matrix(),
                    geometry=geometry,
                    material=yourdfpy.Material(name=CAPSULE_MATERIAL),
                )
            )
            links[link].collisions.append(
                yourdfpy.Collision(name=name, origin=origin.matrix(), geometry=geometry)
            )
            origins[("visual", name)] = origin
            origins[("collision", name)] = origin

        for seg in segments(table):
            cylinder = yourdfpy.Cylinder(radius=radius, length=seg.length)
            shape(
                seg.link,
                f"{seg.link}_{seg.kind}{seg.row}",
                yourdfpy.Geometry(cylinder=cylinder),
                capsule_axis_origin(seg),
            )
            known = spheres.setdefault(seg.link, [])
            for point in (seg.start, seg.end):
                if any(math.dist(point, p) <= MIN_SEGMENT_LENGTH for p in known):
                    continue
                known.append(point)
                shape(
                    seg.link,
                    f"{seg.link}_sphere{len(known) - 1}",
                    yourdfpy.Geometry(sphere=yourdfpy.Sphere(radius=radius)),
                    Transform(xyz=point),
                )

    robot = yourdfpy.Robot(
        name=table.name, links=list(links.values()), joints=joints, materials=materials
    )
    return robot, origins


def to_yourdfpy(table: DHTable, *, load_geometry: bool = False) -> yourdfpy.URDF:
    """The table as a :class:`yourdfpy.URDF` (scene graph built, ready for FK).

    Parameters
    ----------
    table : DHTable
        The validated table.
    load_geometry : bool
        Also create trimesh primitives for the generated capsules (for display).

    Notes
    -----
    ``urdf.update_cfg(q)`` takes the joint variables in row order (rad or m, without the
    table's offsets); ``urdf.get_transform("dh_i", "world")`` is then ``B·A_1⋯A_i``.
    """
    robot, _ = _build(table)
    return yourdfpy.URDF(robot=robot, build_scene_graph=True, load_meshes=load_geometry)


def _set_origin(element: etree._Element, origin: Transform) -> None:
    node = element.find("origin")
    if node is None:
        node = etree.SubElement(element, "origin")
    node.set("xyz", _nums(origin.xyz))
    node.set("rpy", _nums(origin.rpy))


def to_urdf(table: DHTable) -> str:
    """The table as URDF text (UTF-8 XML with declaration), every number at full precision.

    Frames: links ``dh_0`` … ``dh_n`` on the DH frames, ``tool`` on the TCP, root
    ``world``; actuated joints named as in the table, in row order. See the module docstring.
    """
    robot, origins = _build(table)
    urdf = yourdfpy.URDF(robot=robot, build_scene_graph=False, load_meshes=False)
    tree = urdf.write_xml()
    root = tree.getroot()
    for tag in ("joint", "visual", "collision"):
        for element in root.iter(tag):
            origin = origins.get((tag, element.get("name", "")))
            if origin is not None:
                _set_origin(element, origin)
    for link in root.iter("link"):
        origin = origins.get(("inertial", link.get("name", "")))
        inertial = link.find("inertial")
        if origin is None or inertial is None:
            continue
        _set_origin(inertial, origin)
        mass = inertial.find("mass")
        mass.set("value", _num(float(mass.get("value"))))
        inertia = inertial.find("inertia")
        for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            inertia.set(key, _num(float(inertia.get(key))))
    # Re-write the remaining numeric attributes with repr precision as well.
    for element in root.iter("cylinder"):
        for key in ("radius", "length"):
            element.set(key, _num(float(element.get(key))))
    for element in root.iter("sphere"):
        element.set("radius", _num(float(element.get("radius"))))
    for element in root.iter("limit"):
        for key in ("lower", "upper", "velocity", "effort"):
            if element.get(key) is not None:
                element.set(key, _num(float(element.get(key))))
    for element in root.iter("axis"):
        element.set("xyz", "0.0 0.0 1.0")
    root.insert(
        0,
        etree.Comment(
            _comment_safe(
                f" Generated by dh2urdf from the {table.convention} DH table {table.name!r}."
                " Links dh_0..dh_n are the DH frames, 'tool' the TCP, 'world' the root;"
                " SI units (m, rad). "
            )
        ),
    )
    text = etree.tostring(tree, pretty_print=True, xml_declaration=True, encoding="UTF-8")
    return text.decode("utf-8")


def _comment_safe(text: str) -> str:
    """``text`` as XML comment content: no ``--`` (a robot name such as ``a--b`` is
    written ``a- -b``; ``<robot name>`` holds it exactly) and no trailing ``-``."""
    while "--" in text:
        text = text.replace("--", "- -")
    return text + " " if text.endswith("-") else text


def write_urdf(table: DHTable, path: str | Path) -> None:
    """Write :func:`to_urdf` text to ``path`` (UTF-8)."""
    Path(path).write_text(to_urdf(table), encoding="utf-8")

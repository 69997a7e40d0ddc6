"""The child side of MJCF conversion: Pinocchio's model of a checked MJCF file, as URDF.

:func:`convert_in_child` runs in the bounded child process of :mod:`app.documents.sandbox`
(task ``mjcf``, started by :func:`app.documents.mjcf.mjcf_to_urdf` once the document and its
files are checked). Pinocchio's MJCF parser builds the model (``pin.buildModelFromMJCF``)
and its collision and visual geometry (``pin.buildGeomFromMJCF``), and the URDF is written
from that model:

- one link per MJCF body (its name), plus a root link ``world`` (the worldbody) and, for
  a joint that is not at its body's origin (``<joint pos>``), a link ``<joint>_link`` at
  the joint frame, fixed to the body's link;
- hinge → ``revolute`` with ``<limit>`` (its range) or, unlimited, ``continuous``;
  slide → ``prismatic`` (an unlimited slide is refused: URDF needs its limits);
  axes as Pinocchio normalised them; origins as ``xyz`` and ``rpy`` of Pinocchio's
  placements, written with ``repr`` (full precision);
- each joint's inertia (Pinocchio's: the bodies it moves, fixed ones included) on the
  joint's link, expressed in its frame;
- geometry as ``<collision>`` (geoms that collide) and ``<visual>`` (all): box, sphere,
  cylinder, capsule (as a cylinder and two spheres: urdfdom reads no capsule), and meshes
  by file name relative to the description's directory with their scale; planes,
  ellipsoids and height fields are left out;
- the pose of the root body, which Pinocchio drops when that body has no joint, given by
  the parent (:func:`app.documents.mjcf.root_body_pose`).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError

FIELD = "description"
_SHORTNAME_TYPES = {
    "JointModelFreeFlyer": "free",
    "JointModelSpherical": "ball",
    "JointModelSphericalZYX": "ball",
    "JointModelComposite": "several joints in one body",
    "JointModelPlanar": "planar",
}
_REVOLUTE = {"JointModelRX": (1, 0, 0), "JointModelRY": (0, 1, 0), "JointModelRZ": (0, 0, 1)}
_PRISMATIC = {"JointModelPX": (1, 0, 0), "JointModelPY": (0, 1, 0), "JointModelPZ": (0, 0, 1)}


def convert_in_child(args: dict[str, Any]) -> str:
    """The sandbox task: Pinocchio reads the merged model ``args["model"]`` and its
    geometry, and the URDF is written from them (runs in the child only)."""
    try:
        model = pin.buildModelFromMJCF(args["model"])
        geoms = {
            kind: pin.buildGeomFromMJCF(model, args["model"], kind)
            for kind in (pin.GeometryType.COLLISION, pin.GeometryType.VISUAL)
        }
    except Exception as exc:  # noqa: BLE001 - whatever the parser throws: the document
        message = " ".join(str(exc).split("message:")[-1].split())
        for hidden in args["hide"]:
            message = message.replace(f"{hidden}/", "").replace(hidden, ".")
        raise InvalidInputError(f"not a valid MJCF model: {message}"[:500], FIELD) from None
    root_pose = pin.SE3(np.array(args["root_pose"]))
    return _urdf(model, geoms, Path(args["base"]), root_pose)


def _num(x: float) -> str:
    if not math.isfinite(x):
        raise InvalidInputError(f"the model has a non-finite value ({x!r})", FIELD)
    return repr(float(x)) if x != 0 else "0.0"


def _origin(m: pin.SE3) -> str:
    xyz = " ".join(_num(v) for v in m.translation)
    rpy = " ".join(_num(v) for v in pin.rpy.matrixToRpy(m.rotation))
    return f'<origin xyz="{xyz}" rpy="{rpy}"/>'


def _unique(name: str, taken: set[str]) -> str:
    while name in taken:
        name += "_"
    taken.add(name)
    return name


def _geometry(obj: pin.GeometryObject, base: Path) -> str | None:
    """URDF ``<geometry>`` of a Pinocchio geometry object, or ``None`` if URDF has none."""
    g = obj.geometry
    kind = type(g).__name__
    if kind == "Box":
        return f'<box size="{" ".join(_num(2 * v) for v in g.halfSide)}"/>'
    if kind == "Sphere":
        return f'<sphere radius="{_num(g.radius)}"/>'
    if kind == "Cylinder":
        return f'<cylinder radius="{_num(g.radius)}" length="{_num(2 * g.halfLength)}"/>'
    if obj.meshPath and kind.startswith(("BVHModel", "Convex")):
        name = Path(os.path.relpath(os.path.realpath(obj.meshPath), base)).as_posix()
        scale = " ".join(_num(v) for v in obj.meshScale)
        return f'<mesh filename="{_xml(name)}" scale="{scale}"/>'
    return None


def _shapes(obj: pin.GeometryObject, placement: pin.SE3, base: Path) -> list[tuple[str, pin.SE3]]:
    """URDF geometries (with their origins in the link) of one geometry object: a capsule
    (which urdfdom does not read) is a cylinder and two spheres, exactly its volume."""
    g = obj.geometry
    if type(g).__name__ == "Capsule":
        r, h = _num(g.radius), g.halfLength
        ends = [placement * pin.SE3(np.eye(3), np.array([0.0, 0.0, z])) for z in (h, -h)]
        return [(f'<cylinder radius="{r}" length="{_num(2 * h)}"/>', placement)] + [
            (f'<sphere radius="{r}"/>', end) for end in ends
        ]
    geometry = _geometry(obj, base)
    return [] if geometry is None else [(geometry, placement)]


def _xml(text: str) -> str:
    return (
        text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
    )


def _joint_xml(model: pin.Model, j: int, parent: str, child: str, origin: pin.SE3) -> str:
    joint = model.joints[j]
    short = joint.shortname()
    name = model.names[j]
    if short in _REVOLUTE or short == "JointModelRevoluteUnaligned":
        axis = _REVOLUTE.get(short) or tuple(joint.extract().axis)
        revolute = True
    elif short in _PRISMATIC or short == "JointModelPrismaticUnaligned":
        axis = _PRISMATIC.get(short) or tuple(joint.extract().axis)
        revolute = False
    else:
        mjcf_type = _SHORTNAME_TYPES.get(short, short)
        raise InvalidInputError(
            f"joint {name!r} of type {mjcf_type!r} is not supported (hinge and slide only)", FIELD
        )
    i = joint.idx_q
    lower, upper = model.lowerPositionLimit[i], model.upperPositionLimit[i]
    limited = math.isfinite(lower) and math.isfinite(upper)
    if not limited and not revolute:
        raise InvalidInputError(f"slide joint {name!r} needs a range (URDF needs limits)", FIELD)
    jtype = ("revolute" if limited else "continuous") if revolute else "prismatic"
    effort = model.effortLimit[joint.idx_v]
    velocity = model.velocityLimit[joint.idx_v]
    effort = effort if math.isfinite(effort) else 1e6
    velocity = velocity if math.isfinite(velocity) else 1e6
    limit = f'<limit effort="{_num(effort)}" velocity="{_num(velocity)}"'
    limit += f' lower="{_num(lower)}" upper="{_num(upper)}"/>' if limited else "/>"
    return (
        f'  <joint name="{_xml(name)}" type="{jtype}">\n'
        f'    <parent link="{_xml(parent)}"/>\n    <child link="{_xml(child)}"/>\n'
        f"    {_origin(origin)}\n"
        f'    <axis xyz="{" ".join(_num(v) for v in axis)}"/>\n    {limit}\n  </joint>\n'
    )


def _fixed_xml(name: str, parent: str, child: str, origin: pin.SE3) -> str:
    return (
        f'  <joint name="{_xml(name)}" type="fixed">\n'
        f'    <parent link="{_xml(parent)}"/>\n    <child link="{_xml(child)}"/>\n'
        f"    {_origin(origin)}\n  </joint>\n"
    )


def _inertial_xml(inertia: pin.Inertia) -> str:
    if inertia.mass == 0.0 and not np.any(inertia.inertia):
        return ""
    i = inertia.inertia
    values = " ".join(
        f'{k}="{_num(v)}"'
        for k, v in (
            ("ixx", i[0, 0]),
            ("ixy", i[0, 1]),
            ("ixz", i[0, 2]),
            ("iyy", i[1, 1]),
            ("iyz", i[1, 2]),
            ("izz", i[2, 2]),
        )
    )
    lever = " ".join(_num(v) for v in inertia.lever)
    return (
        f'    <inertial>\n      <origin xyz="{lever}" rpy="0.0 0.0 0.0"/>\n'
        f'      <mass value="{_num(inertia.mass)}"/>\n      <inertia {values}/>\n    </inertial>\n'
    )


def _urdf(
    model: pin.Model, geoms: dict[object, pin.GeometryModel], base: Path, root_pose: pin.SE3
) -> str:
    """The URDF text of a Pinocchio model built from MJCF (see the module's docstring)."""
    frames = list(model.frames)
    taken = {f.name for f in frames if f.type == pin.FrameType.BODY}
    link_of: dict[int, str] = {0: _unique("world", taken)}  # frame index -> URDF link
    joint_link: dict[int, str] = {}  # joint index -> the link at the joint's frame
    # placement of each link's frame in its parent joint's frame
    link_in_joint: dict[str, pin.SE3] = {link_of[0]: pin.SE3.Identity()}
    links: list[str] = [link_of[0]]
    joints: list[str] = []
    for index, frame in enumerate(frames):
        if frame.type != pin.FrameType.BODY:
            continue
        parent = frames[frame.parentFrame]
        if parent.type == pin.FrameType.JOINT:
            j = frame.parentJoint
            parent_link = link_of[_body_of(frames, parent.parentFrame)]
            origin = link_in_joint[parent_link].inverse() * model.jointPlacements[j]
            if frame.placement.isIdentity():
                child = frame.name
            else:
                child = _unique(f"{model.names[j]}_link", taken)
                links.append(child)
            joints.append(_joint_xml(model, j, parent_link, child, origin))
            joint_link[j] = child
            link_in_joint[child] = pin.SE3.Identity()
            if child != frame.name:
                joints.append(_fixed_xml(f"{frame.name}_fixed", child, frame.name, frame.placement))
        else:
            parent_link = link_of[_body_of(frames, frame.parentFrame)]
            origin = link_in_joint[parent_link].inverse() * frame.placement
            name = parent.name if parent.type == pin.FrameType.FIXED_JOINT else ""
            if not name or name == "universe":
                name = f"{frame.name}_fixed"
            if frame.parentFrame == 0:
                origin = root_pose * origin  # Pinocchio dropped the root body's pose
            joints.append(_fixed_xml(name, parent_link, frame.name, origin))
        link_of[index] = frame.name
        link_in_joint[frame.name] = frame.placement
        links.append(frame.name)
    body: dict[str, list[str]] = {name: [] for name in links}
    for j, link in joint_link.items():
        body[link].append(_inertial_xml(model.inertias[j]))
    for kind, tag in (
        (pin.GeometryType.VISUAL, "visual"),
        (pin.GeometryType.COLLISION, "collision"),
    ):
        for obj in geoms[kind].geometryObjects:
            link = link_of[_body_of(frames, obj.parentFrame)]
            placement = link_in_joint[link].inverse() * obj.placement
            for geometry, origin in _shapes(obj, placement, base):
                body[link].append(
                    f'    <{tag} name="{_xml(obj.name)}">\n      {_origin(origin)}\n'
                    f"      <geometry>{geometry}</geometry>\n    </{tag}>\n"
                )
    out = [f'<?xml version="1.0"?>\n<robot name="{_xml(model.name or "mjcf")}">\n']
    for name in links:
        out.append(f'  <link name="{_xml(name)}">\n{"".join(body[name])}  </link>\n')
    out.extend(joints)
    out.append("</robot>\n")
    return "".join(out)


def _body_of(frames: list[pin.Frame], index: int) -> int:
    """The BODY frame (or the universe, 0) a frame hangs from, walking up parents."""
    while index != 0 and frames[index].type != pin.FrameType.BODY:
        index = frames[index].parentFrame
    return index

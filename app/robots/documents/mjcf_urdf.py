"""The child side of MJCF conversion: MuJoCo's compiled model of a checked MJCF file, as URDF.

:func:`convert_in_child` runs in the bounded child process of :mod:`app.robots.documents.sandbox`
(task ``mjcf``, started by :func:`app.robots.documents.mjcf.mjcf_to_urdf` once the document and its
files are checked). MuJoCo's own compiler (``mujoco.MjModel.from_xml_path``) reads the model,
so default classes, ``childclass``, the ``<compiler>`` settings (angle, eulerseq, autolimits),
includes and keyframes mean what they mean to MuJoCo; the URDF is written from the compiled
model (frames: MuJoCo's, every pose relative to the parent body; lengths in metres, angles
in radians; a joint's position on the wire is MuJoCo's ``qpos``):

- a link per body (its name; the world body is the root link ``world``); a body without
  joints hangs from its parent by a fixed joint at ``body_pos``/``body_quat``;
- hinge → ``revolute`` (limited) or ``continuous``; slide → ``prismatic`` (an unlimited
  slide is refused: URDF needs its limits). MuJoCo turns a joint about its anchor
  ``jnt_pos`` (body frame) by ``qpos - qpos0`` (``ref``): the URDF joint sits at the anchor,
  turned by ``-ref`` about its axis, and a joint off the body's origin gets a link
  ``<joint>_link`` at the anchor and a fixed joint from it to the body's link, so that the
  body's link is where MuJoCo puts the body. Several joints in one body chain that way in
  MuJoCo's order;
- a ``<site>`` is a bare link of its name on a fixed joint (a name clash is refused);
- ``<equality><joint>`` with ``polycoef="c0 c1 0 0 0"`` → ``<mimic>`` of joint1 following
  joint2 (multiplier ``c1``, offset ``joint1_ref + c0 - c1 * joint2_ref``); ball and free
  joints, nonlinear polycoefs, tendon, ``connect``, ``weld`` and flex equalities that are
  active are refused naming the element (the service models kinematic trees of hinges
  and slides: each would be a different robot); actuators, sensors, contact excludes,
  tendons no equality uses and keyframes are not kinematics: ignored;
- geoms of a body (the world body's, such as a scene's floor, are not the robot's and are
  left out): a ``<collision>`` when the geom collides (``contype`` or ``conaffinity``
  non-zero), a ``<visual>`` when it is in a group MuJoCo's viewer shows by default
  (0, 1, 2: Menagerie's visual geoms are group 2 without contacts, its collision geoms group
  3), coloured as MuJoCo colours it (the geom's ``rgba`` if set, else its material's);
  box, sphere, cylinder, capsule (a cylinder and two spheres: urdfdom reads no capsule),
  mesh (its file, relative to the description's directory, with its ``scale``, at the
  pose of the file's own frame: MuJoCo re-centres a mesh at compile and moves the geom by
  the mesh's offset ``mesh_pos``/``mesh_quat``, which the origin undoes); planes,
  ellipsoids, height fields and SDFs are left out;
- each body's inertia on its link, at its inertial frame.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any
from xml.sax.saxutils import escape

import mujoco
import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.rotations import matrix_to_rpy

FIELD = "description"
_VISIBLE_GROUPS = (0, 1, 2)
#: MuJoCo's default geom colour: a geom with another ``rgba`` overrides its material.
_DEFAULT_RGBA = (0.5, 0.5, 0.5, 1.0)
_JOINT_TYPES = {0: "free", 1: "ball", 2: "slide", 3: "hinge"}
_EQUALITY_TYPES = {0: "connect", 1: "weld", 2: "joint", 3: "tendon", 4: "flex"}


def convert_in_child(args: dict[str, Any]) -> str:
    """The sandbox task: MuJoCo compiles the merged model ``args["model"]`` and the URDF is
    written from it (runs in the child only)."""
    try:
        model = mujoco.MjModel.from_xml_path(args["model"])
    except Exception as exc:  # noqa: BLE001 - whatever the compiler throws: the document
        message = " ".join(str(exc).split())
        for hidden in args["hide"]:
            message = message.replace(f"{hidden}/", "").replace(hidden, ".")
        raise InvalidInputError(f"not a valid MJCF model: {message}"[:500], FIELD) from None
    return _Writer(model, Path(args["base"])).urdf()


def _num(x: float) -> str:
    if not math.isfinite(x):
        raise InvalidInputError(f"the model has a non-finite value ({x!r})", FIELD)
    return repr(float(x)) if x != 0 else "0.0"


def _xml(text: str) -> str:
    """``text`` for an XML attribute value in double quotes."""
    return escape(text, {'"': "&quot;"})


def _pose(pos: Any, quat: Any) -> np.ndarray:
    """A 4×4 transform from a position and a MuJoCo quaternion [w, x, y, z]."""
    mat = np.zeros(9)
    mujoco.mju_quat2Mat(mat, np.asarray(quat, dtype=float))
    T = np.eye(4)
    T[:3, :3] = mat.reshape(3, 3)
    T[:3, 3] = pos
    return T


def _translation(v: Any) -> np.ndarray:
    T = np.eye(4)
    T[:3, 3] = v
    return T


def _rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    quat = np.zeros(4)
    mujoco.mju_axisAngle2Quat(quat, np.asarray(axis, dtype=float), float(angle))
    return _pose(np.zeros(3), quat)


def _origin(T: np.ndarray) -> str:
    xyz = " ".join(_num(v) for v in T[:3, 3])
    rpy = " ".join(_num(v) for v in matrix_to_rpy(T[:3, :3]))
    return f'<origin xyz="{xyz}" rpy="{rpy}"/>'


class _Writer:
    """The URDF of one compiled MjModel (see the module's docstring)."""

    def __init__(self, model: mujoco.MjModel, base: Path) -> None:
        self.m = model
        self.base = base
        self.links: list[str] = []
        self.body: dict[str, list[str]] = {}
        self.joints: list[str] = []
        self.joint_names = {
            self.name(mujoco.mjtObj.mjOBJ_JOINT, j) or f"joint{j}" for j in range(model.njnt)
        }
        self.mimic = self._mimics()

    def fixed(self, name: str, parent: str, child: str, origin: np.ndarray) -> None:
        """A fixed joint named ``name`` (``_`` appended while a joint has that name)."""
        while name in self.joint_names:
            name += "_"
        self.joint_names.add(name)
        self.joints.append(_fixed(name, parent, child, origin))

    def name(self, kind: mujoco.mjtObj, i: int) -> str:
        return mujoco.mj_id2name(self.m, kind, i) or ""

    def _between(self, e: int) -> str:
        """What equality ``e`` ties (its bodies, sites or tendons by name), for a refusal."""
        m = self.m
        tendon = int(m.eq_type[e]) == 3  # a tendon equality has no object type
        kind = mujoco.mjtObj.mjOBJ_TENDON if tendon else mujoco.mjtObj(int(m.eq_objtype[e]))
        noun = kind.name.removeprefix("mjOBJ_").lower()
        ids = [int(i) for i in (m.eq_obj1id[e], m.eq_obj2id[e]) if int(i) >= 0]
        names = " and ".join(repr(self.name(kind, i) or f"#{i}") for i in ids)
        if len(ids) > 1:
            noun = "bodies" if noun == "body" else noun + "s"
        return f" ({noun} {names})" if names else ""

    def _mimics(self) -> dict[int, tuple[int, float, float]]:
        """Follower joint id → (leader joint id, multiplier, offset), from active joint
        equalities; every other active equality refused (module doc)."""
        m, out = self.m, {}
        for e in range(m.neq):
            if not m.eq_active0[e]:
                continue
            kind = _EQUALITY_TYPES.get(int(m.eq_type[e]), str(m.eq_type[e]))
            label = self.name(mujoco.mjtObj.mjOBJ_EQUALITY, e)
            shown = f"<equality><{kind}{f' name={label!r}' if label else ''}>"
            if kind != "joint":
                why = {
                    "connect": "it closes a kinematic loop",
                    "weld": "it welds two bodies (a kinematic loop)",
                    "tendon": "a tendon coupling joints is not a mimic joint",
                }.get(kind, "it is not a joint coupling")
                raise InvalidInputError(
                    f"{shown}{self._between(e)} is not supported: {why}; the service models "
                    "kinematic trees "
                    "of hinge and slide joints (mimic joints from <equality><joint>)",
                    FIELD,
                )
            j1, j2 = int(m.eq_obj1id[e]), int(m.eq_obj2id[e])
            name1 = self.name(mujoco.mjtObj.mjOBJ_JOINT, j1)
            coef = [float(c) for c in m.eq_data[e][:5]]
            if j2 < 0:
                raise InvalidInputError(
                    f"{shown} on joint {name1!r} alone (it locks the joint) is not supported",
                    FIELD,
                )
            name2 = self.name(mujoco.mjtObj.mjOBJ_JOINT, j2)
            if any(coef[2:]) or coef[1] == 0.0:
                raise InvalidInputError(
                    f"{shown} coupling {name1!r} to {name2!r} with polycoef "
                    f"{' '.join(f'{c:g}' for c in coef)} is not supported: only a linear "
                    "coupling 'c0 c1 0 0 0' with c1 != 0 is a mimic joint",
                    FIELD,
                )
            if j1 in out:
                raise InvalidInputError(f"joint {name1!r} is coupled by two equalities", FIELD)
            ref1, ref2 = m.qpos0[m.jnt_qposadr[j1]], m.qpos0[m.jnt_qposadr[j2]]
            out[j1] = (j2, coef[1], ref1 + coef[0] - coef[1] * ref2)
        return out

    def urdf(self) -> str:
        m = self.m
        taken: set[str] = set()
        names: list[str] = []
        for b in range(m.nbody):
            name = "world" if b == 0 else self.name(mujoco.mjtObj.mjOBJ_BODY, b)
            if not name:
                name = f"body{b}"
            if name in taken:
                raise InvalidInputError(f"two bodies are named {name!r}", FIELD)
            taken.add(name)
            names.append(name)
            self._link(name)
        for b in range(1, m.nbody):
            self._body(b, names[int(m.body_parentid[b])], names[b], taken)
        for s in range(m.nsite):
            name = self.name(mujoco.mjtObj.mjOBJ_SITE, s)
            if not name:
                continue
            if name in taken:
                raise InvalidInputError(
                    f"<site name={name!r}>: its name is already a body's or a joint's link "
                    "(each site becomes a link of its name)",
                    FIELD,
                )
            taken.add(name)
            self._link(name)
            origin = _pose(m.site_pos[s], m.site_quat[s])
            self.fixed(f"{name}_site", names[int(m.site_bodyid[s])], name, origin)
        for b in range(1, m.nbody):
            self._inertial(b, names[b])
        for g in range(m.ngeom):
            if m.geom_bodyid[g] != 0:
                self._geom(g, names[int(m.geom_bodyid[g])])
        model_name = self.name(mujoco.mjtObj.mjOBJ_MODEL, 0) or "mjcf"
        out = [f'<?xml version="1.0"?>\n<robot name="{_xml(model_name)}">\n']
        for name in self.links:
            out.append(f'  <link name="{_xml(name)}">\n{"".join(self.body[name])}  </link>\n')
        out.extend(self.joints)
        out.append("</robot>\n")
        return "".join(out)

    def _link(self, name: str) -> None:
        self.links.append(name)
        self.body[name] = []

    def _body(self, b: int, parent: str, name: str, taken: set[str]) -> None:
        """The joints from ``parent``'s link to body ``b``'s link ``name`` (module doc)."""
        m = self.m
        pending = _pose(m.body_pos[b], m.body_quat[b])  # where we are, in ``parent``'s link
        first, count = int(m.body_jntadr[b]), int(m.body_jntnum[b])
        for j in range(first, first + count):
            jname = self.name(mujoco.mjtObj.mjOBJ_JOINT, j) or f"joint{j}"
            kind = _JOINT_TYPES.get(int(m.jnt_type[j]), str(m.jnt_type[j]))
            if kind not in ("hinge", "slide"):
                where = "the root body" if m.body_parentid[b] == 0 else f"body {name!r}"
                why = (
                    "it makes the robot float (remove it to fix the robot at its pose)"
                    if kind == "free" and m.body_parentid[b] == 0
                    else "hinge and slide only"
                )
                raise InvalidInputError(
                    f"joint {jname!r} of type {kind!r} on {where} is not supported ({why})",
                    FIELD,
                )
            axis = np.asarray(m.jnt_axis[j], dtype=float)
            ref = float(m.qpos0[m.jnt_qposadr[j]])
            if kind == "hinge":
                origin = pending @ _translation(m.jnt_pos[j]) @ _rotation(axis, -ref)
                after = _translation(-np.asarray(m.jnt_pos[j], dtype=float))
            else:
                origin = pending @ _translation(-ref * axis)
                after = np.eye(4)
            last = j == first + count - 1
            if last and np.array_equal(after, np.eye(4)):
                child = name
            else:
                child = f"{jname}_link"
                if child in taken:
                    raise InvalidInputError(
                        f"joint {jname!r} needs a link {child!r} at its anchor, a name taken",
                        FIELD,
                    )
                taken.add(child)
                self._link(child)
            self.joints.append(self._joint(j, jname, kind, parent, child, origin, axis))
            parent, pending = child, after
        if parent != name:
            self.fixed(f"{name}_fixed", parent, name, pending)

    def _joint(
        self,
        j: int,
        name: str,
        kind: str,
        parent: str,
        child: str,
        origin: np.ndarray,
        axis: np.ndarray,
    ) -> str:
        m = self.m
        limited = bool(m.jnt_limited[j])
        lower, upper = (float(v) for v in m.jnt_range[j])
        if kind == "slide" and not limited:
            raise InvalidInputError(
                f"slide joint {name!r} needs a range (URDF needs a prismatic joint's limits)",
                FIELD,
            )
        jtype = ("revolute" if limited else "continuous") if kind == "hinge" else "prismatic"
        limit = '<limit effort="1000000.0" velocity="1000000.0"'
        limit += f' lower="{_num(lower)}" upper="{_num(upper)}"/>' if limited else "/>"
        mimic = ""
        if j in self.mimic:
            leader, multiplier, offset = self.mimic[j]
            lname = self.name(mujoco.mjtObj.mjOBJ_JOINT, leader) or f"joint{leader}"
            mimic = (
                f'    <mimic joint="{_xml(lname)}" multiplier="{_num(multiplier)}" '
                f'offset="{_num(offset)}"/>\n'
            )
        unit = axis / np.linalg.norm(axis)
        return (
            f'  <joint name="{_xml(name)}" type="{jtype}">\n'
            f'    <parent link="{_xml(parent)}"/>\n    <child link="{_xml(child)}"/>\n'
            f"    {_origin(origin)}\n"
            f'    <axis xyz="{" ".join(_num(v) for v in unit)}"/>\n    {limit}\n{mimic}'
            "  </joint>\n"
        )

    def _inertial(self, b: int, link: str) -> None:
        m = self.m
        mass = float(m.body_mass[b])
        if mass <= 0.0:
            return
        T = _pose(m.body_ipos[b], m.body_iquat[b])
        d = m.body_inertia[b]
        self.body[link].append(
            f'    <inertial>\n      {_origin(T)}\n      <mass value="{_num(mass)}"/>\n'
            f'      <inertia ixx="{_num(d[0])}" ixy="0.0" ixz="0.0" iyy="{_num(d[1])}" '
            f'iyz="0.0" izz="{_num(d[2])}"/>\n    </inertial>\n'
        )

    def _rgba(self, g: int) -> tuple[str, tuple[float, ...]]:
        """The material name and colour MuJoCo draws geom ``g`` with."""
        m = self.m
        rgba = tuple(float(v) for v in m.geom_rgba[g])
        mat = int(m.geom_matid[g])
        if mat >= 0 and np.allclose(rgba, _DEFAULT_RGBA, rtol=0, atol=1e-7):
            name = self.name(mujoco.mjtObj.mjOBJ_MATERIAL, mat)
            if name:
                return name, tuple(float(v) for v in m.mat_rgba[mat])
            rgba = tuple(float(v) for v in m.mat_rgba[mat])
        return "rgba_" + "_".join(f"{v:.6g}" for v in rgba), rgba

    def _geom(self, g: int, link: str) -> None:
        m = self.m
        placement = _pose(m.geom_pos[g], m.geom_quat[g])
        kind = int(m.geom_type[g])
        size = [float(v) for v in m.geom_size[g]]
        shapes: list[tuple[str, np.ndarray]] = []
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            shapes = [(f'<box size="{" ".join(_num(2 * v) for v in size)}"/>', placement)]
        elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
            shapes = [(f'<sphere radius="{_num(size[0])}"/>', placement)]
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            cyl = f'<cylinder radius="{_num(size[0])}" length="{_num(2 * size[1])}"/>'
            shapes = [(cyl, placement)]
        elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
            r, h = _num(size[0]), size[1]
            shapes = [(f'<cylinder radius="{r}" length="{_num(2 * h)}"/>', placement)]
            shapes += [
                (f'<sphere radius="{r}"/>', placement @ _translation([0.0, 0.0, z]))
                for z in (h, -h)
            ]
        elif kind == mujoco.mjtGeom.mjGEOM_MESH:
            mesh = int(m.geom_dataid[g])
            adr = int(m.mesh_pathadr[mesh])
            if adr >= 0:
                path = m.paths[adr:].split(b"\0", 1)[0].decode("utf-8", "surrogateescape")
                rel = Path(os.path.relpath(os.path.realpath(path), self.base)).as_posix()
                scale = " ".join(_num(v) for v in m.mesh_scale[mesh])
                offset = _pose(m.mesh_pos[mesh], m.mesh_quat[mesh])
                shapes = [
                    (
                        f'<mesh filename="{_xml(rel)}" scale="{scale}"/>',
                        placement @ np.linalg.inv(offset),
                    )
                ]
        gname = self.name(mujoco.mjtObj.mjOBJ_GEOM, g) or f"geom{g}"
        collides = bool(m.geom_contype[g] or m.geom_conaffinity[g])
        visible = int(m.geom_group[g]) in _VISIBLE_GROUPS
        for geometry, origin in shapes:
            if visible:
                mname, rgba = self._rgba(g)
                colour = " ".join(_num(v) for v in rgba)
                self.body[link].append(
                    f'    <visual name="{_xml(gname)}">\n      {_origin(origin)}\n'
                    f"      <geometry>{geometry}</geometry>\n"
                    f'      <material name="{_xml(mname)}"><color rgba="{colour}"/></material>\n'
                    "    </visual>\n"
                )
            if collides:
                self.body[link].append(
                    f'    <collision name="{_xml(gname)}">\n      {_origin(origin)}\n'
                    f"      <geometry>{geometry}</geometry>\n    </collision>\n"
                )


def _fixed(name: str, parent: str, child: str, origin: np.ndarray) -> str:
    return (
        f'  <joint name="{_xml(name)}" type="fixed">\n'
        f'    <parent link="{_xml(parent)}"/>\n    <child link="{_xml(child)}"/>\n'
        f"    {_origin(origin)}\n  </joint>\n"
    )

"""Reading a client's MJCF (MuJoCo) arm into URDF text, confined to its package.

The document and its ``<include>``s are first read with
:func:`app.kinematics.xmldoc.parse_literal_xml` (the upload's XML limits): every ``file``
(include, mesh, skin, hfield, texture) and every ``<compiler meshdir/assetdir/texturedir>``
must resolve (symlinks followed) inside the package, and joints whose type is not
``hinge`` or ``slide`` (``ball``, ``free``, ``<freejoint>``) are refused naming the joint.
Pinocchio's MJCF parser then builds the model (``pin.buildModelFromMJCF``) and its
collision and visual geometry (``pin.buildGeomFromMJCF``), and the URDF is written from
that model:

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
  ellipsoids and height fields are left out.
"""

from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path
from xml.etree.ElementTree import Element, tostring

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml

FIELD = "description"
#: Most files an MJCF document may pull in with ``<include>``.
MAX_INCLUDES = 64
_SUPPORTED = {"hinge", "slide"}
_SHORTNAME_TYPES = {
    "JointModelFreeFlyer": "free",
    "JointModelSpherical": "ball",
    "JointModelSphericalZYX": "ball",
    "JointModelComposite": "several joints in one body",
    "JointModelPlanar": "planar",
}
_REVOLUTE = {"JointModelRX": (1, 0, 0), "JointModelRY": (0, 1, 0), "JointModelRZ": (0, 0, 1)}
_PRISMATIC = {"JointModelPX": (1, 0, 0), "JointModelPY": (0, 1, 0), "JointModelPZ": (0, 0, 1)}


def _inside(root: Path, path: Path) -> bool:
    return path == root or root in path.parents


def _resolve(root: Path, base: Path, value: str, what: str) -> Path:
    """``value`` (a relative path) against ``base``, real path inside ``root``, else 422."""
    if not value or os.path.isabs(value) or "\x00" in value:
        raise InvalidInputError(f"{what} {value[:200]!r} must be a relative path", FIELD)
    real = Path(os.path.realpath(base / value))
    if not _inside(root, real):
        raise InvalidInputError(f"{what} {value[:200]!r} is outside the package", FIELD)
    return real


def _read(root: Path, path: Path, limits: XmlLimits) -> Element:
    rel = path.relative_to(root).as_posix()
    if not path.is_file():
        raise InvalidInputError(f"{rel}: no such file in the package", FIELD)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InvalidInputError(f"{rel}: cannot be read as UTF-8 text ({exc})", FIELD) from None
    try:
        return parse_literal_xml(text, FIELD, limits)
    except InvalidInputError as exc:
        raise InvalidInputError(f"{rel}: {exc.message}", FIELD) from None


_POSE = {"pos": (3,), "quat": (4,), "euler": (3,), "axisangle": (4,), "xyaxes": (6,), "zaxis": (3,)}
#: Numeric attributes checked per element (Pinocchio's parser reads a malformed number as
#: 0 or garbage without a word): attribute -> allowed counts.
_NUMERIC: dict[str, dict[str, tuple[int, ...]]] = {
    "body": _POSE,
    "joint": {"pos": (3,), "axis": (3,), "range": (2,), "ref": (1,)},
    "geom": {**_POSE, "size": (1, 2, 3), "fromto": (6,), "mass": (1,)},
    "inertial": {**_POSE, "mass": (1,), "diaginertia": (3,), "fullinertia": (6,)},
    "mesh": {"scale": (3,)},
}


def _check_numbers(tree: Element, rel: str) -> None:
    """Every numeric attribute Pinocchio reads is a list of finite numbers of the right
    length; joint axes are not zero and ranges not reversed."""
    for element in tree.iter():
        for attr, counts in _NUMERIC.get(element.tag, {}).items():
            raw = element.get(attr)
            if raw is None:
                continue
            try:
                values = [float(v) for v in raw.split()]
            except ValueError:
                values = []
            name = element.get("name")
            shown = f"{rel}: <{element.tag}{f' name={name!r}' if name else ''} {attr}={raw[:60]!r}>"
            if len(values) not in counts or not all(math.isfinite(v) for v in values):
                wanted = " or ".join(map(str, counts))
                raise InvalidInputError(f"{shown}: expected {wanted} finite numbers", FIELD)
            if attr in ("size", "mass", "diaginertia") and min(values) < 0:
                raise InvalidInputError(f"{shown}: must not be negative", FIELD)
            if element.tag == "joint" and attr == "axis" and not any(values):
                raise InvalidInputError(f"{shown}: the axis is the zero vector", FIELD)
            if attr == "range" and values[0] > values[1]:
                raise InvalidInputError(f"{shown}: lower bound above the upper one", FIELD)


def _check_joint_types(tree: Element, rel: str) -> None:
    _check_numbers(tree, rel)
    for element in tree.iter():
        if element.tag in ("frame", "replicate", "attach"):
            raise InvalidInputError(
                f"{rel}: <{element.tag}> is not supported (Pinocchio's MJCF parser skips what "
                "it holds); write its bodies out",
                FIELD,
            )
        if element.tag == "freejoint":
            name = element.get("name") or "(unnamed)"
            raise InvalidInputError(
                f"{rel}: joint {name!r} of type 'free' is not supported (hinge and slide only)",
                FIELD,
            )
        if element.tag == "joint" and element.get("type", "hinge") not in _SUPPORTED:
            name = element.get("name") or "(unnamed)"
            raise InvalidInputError(
                f"{rel}: joint {name!r} of type {element.get('type')!r} is not supported "
                "(hinge and slide only)",
                FIELD,
            )


def _expand(root: Path, base: Path, path: Path, limits: XmlLimits, count: list[int]) -> Element:
    """The literal tree of ``path`` with every ``<include>`` replaced by the children of the
    included file's root (MuJoCo's rule; Pinocchio's parser does not follow includes)."""
    tree = _read(root, path, limits)
    _check_joint_types(tree, path.relative_to(root).as_posix())
    for parent in list(tree.iter()):
        children = list(parent)
        if not any(child.tag == "include" for child in children):
            continue
        merged: list[Element] = []
        for child in children:
            if child.tag != "include":
                merged.append(child)
                continue
            count[0] += 1
            if count[0] > MAX_INCLUDES:
                raise InvalidInputError(
                    f"more than {MAX_INCLUDES} <include>s (or an include cycle)", FIELD
                )
            target = _resolve(root, base, child.get("file", ""), "<include file>")
            merged.extend(list(_expand(root, base, target, limits, count)))
        parent[:] = merged
    return tree


def check_mjcf_files(root: Path, description: str, limits: XmlLimits) -> tuple[Path, Element]:
    """Check the document, its includes and every file and directory it names.

    Returns the description's real path and the document with its includes merged and
    the ``<compiler>``'s ``meshdir``/``texturedir`` made absolute (so that it can be
    parsed from any directory). Raises :class:`InvalidInputError` (field ``description``).
    """
    root = Path(os.path.realpath(root))
    main = _resolve(root, root, description, "description")
    base = main.parent
    tree = _expand(root, base, main, limits, [0])
    if sum(1 for _ in tree.iter()) > limits.max_elements:
        raise InvalidInputError(
            f"more than {limits.max_elements} XML elements with the includes "
            "(DENAVIT_MAX_XML_ELEMENTS)",
            FIELD,
        )
    dirs: dict[str, Path] = {}
    compilers = list(tree.iter("compiler"))
    for compiler in compilers:
        for attr in ("meshdir", "assetdir", "texturedir"):
            if compiler.get(attr) is not None:
                dirs[attr] = _resolve(root, base, compiler.get(attr, ""), f"<compiler {attr}>")
    for element in tree.iter():
        value = element.get("file")
        if value is None:
            continue
        key = "texturedir" if element.tag == "texture" else "meshdir"
        _resolve(root, dirs.get(key, dirs.get("assetdir", base)), value, f"<{element.tag} file>")
    if not compilers:
        compilers = [Element("compiler")]
        tree.insert(0, compilers[0])
    for compiler in compilers:
        compiler.attrib.pop("assetdir", None)
        for key in ("meshdir", "texturedir"):
            compiler.set(key, str(dirs.get(key, dirs.get("assetdir", base))))
    return main, tree


def _numbers(element: Element, attr: str) -> list[float] | None:
    """The numbers of ``attr`` (already checked by :func:`_check_numbers`), or ``None``."""
    raw = element.get(attr)
    return None if raw is None else [float(v) for v in raw.split()]


def _axis_rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    return pin.AngleAxis(angle, axis / np.linalg.norm(axis)).matrix()


def root_body_pose(tree: Element) -> pin.SE3:
    """The pose of the one body under ``<worldbody>`` as MuJoCo places it (``pos`` and
    ``quat``, ``euler`` or ``axisangle``, in the ``<compiler>``'s angle unit and Euler
    sequence). Pinocchio's MJCF parser reads only the first body under ``<worldbody>`` and,
    when that body has no joint, drops its pose: the URDF puts it back. More than one
    top-level body, or ``xyaxes``/``zaxis`` on it, is refused. ``tree`` is one that
    :func:`check_mjcf_files` gave (its numbers are checked)."""
    degree, seq = True, "xyz"
    for compiler in tree.iter("compiler"):
        degree = compiler.get("angle", "degree" if degree else "radian") == "degree"
        seq = compiler.get("eulerseq", seq)
    bodies = [b for w in tree.iter("worldbody") for b in w.findall("body")]
    if len(bodies) != 1:
        raise InvalidInputError(
            f"an arm needs exactly one <body> directly under <worldbody>, found {len(bodies)} "
            "(Pinocchio's MJCF parser reads only the first)",
            FIELD,
        )
    body = bodies[0]
    unit = math.pi / 180 if degree else 1.0
    rotation = np.eye(3)
    for attr in ("xyaxes", "zaxis"):
        if body.get(attr) is not None:
            raise InvalidInputError(f"the root body's {attr!r} is not supported", FIELD)
    if (quat := _numbers(body, "quat")) is not None:
        rotation = pin.Quaternion(*quat).normalized().matrix()  # w x y z
    elif (axisangle := _numbers(body, "axisangle")) is not None:
        rotation = _axis_rotation(np.array(axisangle[:3]), axisangle[3] * unit)
    elif (euler := _numbers(body, "euler")) is not None:
        if len(seq) != 3 or any(c not in "xyzXYZ" for c in seq):
            raise InvalidInputError(f"<compiler eulerseq={seq[:10]!r}> is not valid", FIELD)
        for axis_name, angle in zip(seq, euler, strict=True):
            step = _axis_rotation(np.eye(3)["xyz".index(axis_name.lower())], angle * unit)
            rotation = rotation @ step if axis_name.islower() else step @ rotation
    pos = _numbers(body, "pos") or [0.0, 0.0, 0.0]
    return pin.SE3(rotation, np.array(pos))


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


def mjcf_to_urdf(root: Path, description: str, limits: XmlLimits) -> str:
    """URDF text equivalent to the MJCF file ``root / description``.

    Mesh ``filename``s in the result are paths relative to the description's directory.
    Raises :class:`~app.kinematics.errors.InvalidInputError` (field ``description``; a
    joint that is not a hinge or slide names the joint and its type).
    """
    main, tree = check_mjcf_files(root, description, limits)
    root_pose = root_body_pose(tree)
    with tempfile.TemporaryDirectory(prefix="denavit-mjcf-") as tmp:
        merged = Path(tmp) / "model.xml"
        merged.write_bytes(tostring(tree, encoding="utf-8"))
        try:
            model = pin.buildModelFromMJCF(str(merged))
            geoms = {
                kind: pin.buildGeomFromMJCF(model, str(merged), kind)
                for kind in (pin.GeometryType.COLLISION, pin.GeometryType.VISUAL)
            }
        except Exception as exc:  # noqa: BLE001 - whatever the parser throws: the document
            message = " ".join(str(exc).split("message:")[-1].split())
            message = message.replace(f"{os.path.realpath(root)}/", "").replace(f"{tmp}/", "")
            raise InvalidInputError(f"not a valid MJCF model: {message}"[:500], FIELD) from None
    return _urdf(model, geoms, main.parent, root_pose)


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

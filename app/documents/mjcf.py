"""Reading a client's MJCF (MuJoCo) arm into URDF text, confined to its package.

In the worker, the document and its ``<include>``s are first read with
:func:`app.kinematics.xmldoc.parse_literal_xml` (the upload's XML limits): every file
attribute (``file`` of include, mesh, skin, hfield, texture, model; a cube texture's
``fileright``, ``fileleft``, ``fileup``, ``filedown``, ``filefront``, ``fileback``) and
every ``<compiler meshdir/assetdir/texturedir>`` must resolve (symlinks followed) inside the
package, joints whose type is not ``hinge`` or ``slide`` (``ball``, ``free``,
``<freejoint>``) are refused naming the joint, the merged model (includes in place) may
nest no deeper than ``DENAVIT_MAX_XML_DEPTH`` and hold no more bodies than
``DENAVIT_MAX_URDF_JOINTS``, and each mesh is checked by the caller (its header and the
files it names) before any loader sees it. Then, in a bounded child process
(:mod:`app.documents.sandbox`, task ``mjcf``: :func:`convert_in_child`), Pinocchio's MJCF
parser builds the model (``pin.buildModelFromMJCF``) and its collision and visual geometry
(``pin.buildGeomFromMJCF``), and the URDF is written from that model
(:mod:`app.documents.mjcf_urdf`).
"""

from __future__ import annotations

import math
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from xml.etree.ElementTree import Element, tostring

import numpy as np
import pinocchio as pin

from app.documents.sandbox import PARSE_LIMITS, ChildLimits, run_child
from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml

FIELD = "description"
#: Most files an MJCF document may pull in with ``<include>``.
MAX_INCLUDES = 64
_SUPPORTED = {"hinge", "slide"}


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
        key = "texturedir" if element.tag == "texture" else "meshdir"
        for attr, value in element.attrib.items():
            if attr.startswith("file"):
                folder = dirs.get(key, dirs.get("assetdir", base))
                _resolve(root, folder, value, f"<{element.tag} {attr}>")
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


def _depth(tree: Element) -> int:
    """How deep ``tree`` nests (the root is 1), without recursion."""
    deepest, todo = 0, [(tree, 1)]
    while todo:
        element, depth = todo.pop()
        deepest = max(deepest, depth)
        todo.extend((child, depth + 1) for child in element)
    return deepest


def mesh_assets(tree: Element) -> list[tuple[str, Path]]:
    """``(file attribute, real path)`` of every ``<mesh>`` asset of a checked tree (its
    ``meshdir`` made absolute by :func:`check_mjcf_files`)."""
    meshdir = next((c.get("meshdir") for c in tree.iter("compiler") if c.get("meshdir")), "")
    return [
        (m.get("file", ""), Path(os.path.realpath(Path(meshdir) / m.get("file", ""))))
        for m in tree.iter("mesh")
        if m.get("file")
    ]


def mjcf_to_urdf(
    root: Path,
    description: str,
    limits: XmlLimits,
    *,
    max_bodies: int = 256,
    child: ChildLimits = PARSE_LIMITS,
    check_mesh: Callable[[str, Path], None] | None = None,
) -> str:
    """URDF text equivalent to the MJCF file ``root / description``.

    Parameters
    ----------
    root, description
        The package, and the path of the MJCF file in it.
    limits, max_bodies
        XML bounds (the merged model's depth included); most bodies
        (``DENAVIT_MAX_URDF_JOINTS``).
    child
        Bounds on the child process that runs Pinocchio's parser.
    check_mesh
        Called as ``check_mesh(name, path)`` for every mesh asset before any loader sees
        one (the package's header and reference checks).

    Mesh ``filename``s in the result are paths relative to the description's directory.
    Raises :class:`~app.kinematics.errors.InvalidInputError` (field ``description``; a
    joint that is not a hinge or slide names the joint and its type).
    """
    main, tree = check_mjcf_files(root, description, limits)
    depth = _depth(tree)
    if depth > limits.max_depth:
        raise InvalidInputError(
            f"the model with its includes nests {depth} levels deep, deeper than "
            f"{limits.max_depth} (DENAVIT_MAX_XML_DEPTH)",
            FIELD,
        )
    bodies = sum(1 for _ in tree.iter("body"))
    if bodies > max_bodies:
        raise InvalidInputError(
            f"{bodies} bodies, more than {max_bodies} (each is a URDF joint: "
            "DENAVIT_MAX_URDF_JOINTS)",
            FIELD,
        )
    root_pose = root_body_pose(tree)
    for name, path in mesh_assets(tree):
        if check_mesh is not None:
            check_mesh(name, path)
    real_root = os.path.realpath(root)
    with tempfile.TemporaryDirectory(prefix="denavit-mjcf-") as tmp:
        merged = Path(tmp) / "model.xml"
        merged.write_bytes(tostring(tree, encoding="utf-8"))
        args = {
            "model": str(merged),
            "base": str(main.parent),
            "root_pose": root_pose.homogeneous.tolist(),
            "hide": [real_root, tmp],
        }
        urdf = run_child("mjcf", args, child, field=FIELD, what="reading the MJCF model")
    if not isinstance(urdf, str):  # pragma: no cover - the child answers a document
        raise InvalidInputError("the MJCF model gave no document", FIELD)
    return urdf

"""Reading a client's MJCF (MuJoCo) model into URDF text, confined to its package.

In the worker, the document and its ``<include>``s are first read with
:func:`app.kinematics.xmldoc.parse_literal_xml` (the upload's XML limits): every file
attribute (``file`` of include, mesh, skin, hfield, texture; a cube texture's
``fileright``, ``fileleft``, ``fileup``, ``filedown``, ``filefront``, ``fileback``) and
every ``<compiler meshdir/assetdir/texturedir>`` must resolve (symlinks followed) inside the
package; ``<replicate>``, ``<attach>`` and ``<model>`` assets (bodies that cannot be counted
before MuJoCo compiles them, or another model's files) are refused; the merged model
(includes in place) may nest no deeper than ``DENAVIT_MAX_XML_DEPTH`` and hold no more
bodies than ``DENAVIT_MAX_URDF_JOINTS``, and each mesh is checked by the caller (its header
and the files it names) before any loader sees it. Textures (images: the URDF keeps colours
only) are taken out, every mesh ``file`` is made the checked real path, MuJoCo is told
to compile in one thread, and, unless the document sets them, ``boundmass="1e-9"`` and
``boundinertia="1e-12"`` let a kinematic model without masses compile (MuJoCo refuses a
moving body without mass). Then, in a bounded child process (:mod:`app.robots.documents.sandbox`,
task ``mjcf``: :func:`app.robots.documents.mjcf_urdf.convert_in_child`), MuJoCo's own compiler
reads the model and the URDF is written from the compiled model
(:mod:`app.robots.documents.mjcf_urdf`: what is supported and what is refused).
"""

from __future__ import annotations

import math
import os
import tempfile
from collections.abc import Callable
from pathlib import Path
from xml.etree.ElementTree import Element, tostring

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.sandbox import PARSE_LIMITS, ChildLimits, run_child

FIELD = "description"
#: Most files an MJCF document may pull in with ``<include>``.
MAX_INCLUDES = 64


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


#: Elements refused before MuJoCo compiles: what they add cannot be bounded (counted) first.
_REFUSED = {
    "replicate": "it repeats bodies that cannot be counted before compiling",
    "attach": "it attaches another model's bodies",
    "model": "it reads another model's files",
}


def _check_elements(tree: Element, rel: str) -> None:
    _check_numbers(tree, rel)
    for element in tree.iter():
        if element.tag == "freejoint" or (element.tag == "joint" and element.get("type") == "free"):
            name = element.get("name") or "(unnamed)"
            raise InvalidInputError(
                f"{rel}: joint {name!r} of type 'free' is not supported: a free body floats, "
                "and the service models robots fixed to the world (on the root body, remove "
                "the free joint to fix the robot at its pose; MuJoCo allows it nowhere else)",
                FIELD,
            )
        if element.tag in _REFUSED:
            raise InvalidInputError(
                f"{rel}: <{element.tag}> is not supported ({_REFUSED[element.tag]}); write its "
                "bodies out",
                FIELD,
            )


def _expand(root: Path, base: Path, path: Path, limits: XmlLimits, count: list[int]) -> Element:
    """The literal tree of ``path`` with every ``<include>`` replaced by the children of the
    included file's root (MuJoCo's rule; Pinocchio's parser does not follow includes)."""
    tree = _read(root, path, limits)
    _check_elements(tree, path.relative_to(root).as_posix())
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
        compiler.attrib.pop("texturedir", None)
        compiler.set("meshdir", str(dirs.get("meshdir", dirs.get("assetdir", base))))
        compiler.set("usethread", "false")  # the child may start no thread
        # MuJoCo refuses a moving body without mass; a kinematic model may have none
        for attr, bound in (("boundmass", "1e-9"), ("boundinertia", "1e-12")):
            compiler.set(attr, compiler.get(attr, bound))
    _drop_textures(tree)
    return main, tree


def _drop_textures(tree: Element) -> None:
    """Take textures out (images the URDF does not use: colours only)."""
    for parent in list(tree.iter()):
        for child in list(parent):
            if child.tag in ("texture", "skin") or (parent.tag, child.tag) == ("material", "layer"):
                parent.remove(child)
    for material in tree.iter("material"):
        material.attrib.pop("texture", None)


def _depth(tree: Element) -> int:
    """How deep ``tree`` nests (the root is 1), without recursion."""
    deepest, todo = 0, [(tree, 1)]
    while todo:
        element, depth = todo.pop()
        deepest = max(deepest, depth)
        todo.extend((child, depth + 1) for child in element)
    return deepest


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
        Bounds on the child process that runs MuJoCo's compiler.
    check_mesh
        Called as ``check_mesh(name, path)`` for every mesh asset before any loader sees
        one (the package's header and reference checks).

    Mesh ``filename``s in the result are paths relative to the description's directory.
    Raises :class:`~app.kinematics.errors.InvalidInputError` (field ``description``; what
    the service does not support names the element and why, see
    :mod:`app.robots.documents.mjcf_urdf`).
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
    meshdir = next((c.get("meshdir") for c in tree.iter("compiler") if c.get("meshdir")), "")
    for mesh in tree.iter("mesh"):
        if mesh.get("file"):
            path = Path(os.path.realpath(Path(meshdir) / mesh.get("file", "")))
            if check_mesh is not None:
                check_mesh(mesh.get("file", ""), path)
            mesh.set("file", str(path))  # what was checked is what MuJoCo reads
    real_root = os.path.realpath(root)
    with tempfile.TemporaryDirectory(prefix="denavit-mjcf-") as tmp:
        merged = Path(tmp) / "model.xml"
        merged.write_bytes(tostring(tree, encoding="utf-8"))
        args = {"model": str(merged), "base": str(main.parent), "hide": [real_root, tmp]}
        urdf = run_child("mjcf", args, child, field=FIELD, what="reading the MJCF model")
    if not isinstance(urdf, str):  # pragma: no cover - the child answers a document
        raise InvalidInputError("the MJCF model gave no document", FIELD)
    return urdf

"""Checks of client-supplied URDF, made on the document as Pinocchio will read it.

The XML is parsed by :func:`app.kinematics.xmldoc.parse_literal_xml`: no DTD or entities,
bounded work, and element/attribute names kept literally (namespace-unaware, like urdfdom's
TinyXML2), so ``<mesh xmlns="urn:x" filename="/etc/passwd"/>`` is a ``mesh`` here exactly
as it is for Pinocchio, and a namespace trick cannot hide an element from a check.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from xml.etree.ElementTree import Element

from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.models import MAX_JOINT_VALUE, RobotModel
from app.kinematics.urdf_model import mimic_specs, urdf_joint_table
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml
from app.robots.documents.srdf import check_srdf_document

#: Joint types a URDF upload may use (the wire has one value per actuated joint).
URDF_JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed")
#: Largest magnitude of a length, angle or size in an uploaded URDF (m or rad).
MAX_ABS_VALUE = 1e6
#: Smallest norm of a joint axis (below it, normalising the axis is meaningless).
MIN_AXIS_NORM = 1e-6
#: The one URI form a mesh or texture ``filename`` may take.
PACKAGE_PREFIX = "package://"

_NUMERIC_ATTRIBUTES = {
    "origin": ("xyz", "rpy"),
    "axis": ("xyz",),
    "limit": ("lower", "upper", "effort", "velocity"),
    "mimic": ("multiplier", "offset"),
    "mass": ("value",),
    "inertia": ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"),
    "box": ("size",),
    "cylinder": ("radius", "length"),
    "sphere": ("radius",),
    "capsule": ("radius", "length"),
    "mesh": ("scale",),
    "dynamics": ("damping", "friction"),
    "safety_controller": ("soft_lower_limit", "soft_upper_limit", "k_position", "k_velocity"),
}
#: Attributes holding three numbers (the others hold one).
_VECTOR_ATTRIBUTES = frozenset(
    {("origin", "xyz"), ("origin", "rpy"), ("axis", "xyz"), ("box", "size"), ("mesh", "scale")}
)
#: Attributes that are lengths, angles or sizes: bounded by :data:`MAX_ABS_VALUE`.
_BOUNDED_ATTRIBUTES = frozenset(
    {
        ("origin", "xyz"),
        ("origin", "rpy"),
        ("axis", "xyz"),
        ("limit", "lower"),
        ("limit", "upper"),
        ("mimic", "multiplier"),
        ("mimic", "offset"),
        ("box", "size"),
        ("cylinder", "radius"),
        ("cylinder", "length"),
        ("sphere", "radius"),
        ("capsule", "radius"),
        ("capsule", "length"),
        ("mesh", "scale"),
        ("safety_controller", "soft_lower_limit"),
        ("safety_controller", "soft_upper_limit"),
    }
)


@dataclass(frozen=True, slots=True)
class UrdfLimits:
    """Bounds on the work one uploaded URDF may cause (see
    :class:`app.operations.settings.Settings`).

    ``max_joints`` counts joints of every type; ``max_dof`` the movable ones (revolute,
    continuous, prismatic, mimic included): Pinocchio's per-thread Data grows roughly as
    34·dof³ bytes (≈ 15 MB at 64, 80 MB at 128, 570 MB at 256, 4.5 GB at 512).
    """

    xml: XmlLimits = field(default_factory=XmlLimits)
    max_joints: int = 256
    max_dof: int = 64


def check_resource_uri(uri: str) -> str | None:
    """Why a mesh/texture ``filename`` is refused, or ``None`` when it is allowed.

    Allowed: exactly ``package://<package>/<path>`` (lower-case scheme, as Pinocchio's
    ``retrieveResourcePath`` compares it) with plain segments: no ``..``, ``.``, empty
    segments, whitespace anywhere (Pinocchio does not strip it), backslashes, percent
    escapes, queries or fragments. Pinocchio resolves such a URI as
    ``<package_dir>/<package>/<path>`` for one of the package directories the service was
    given, and nowhere else. Refused: absolute or relative paths, ``file://``,
    ``Package://`` and every other scheme.
    """
    if not uri:
        return "empty filename"
    if any(c.isspace() for c in uri):
        return "whitespace is not allowed (Pinocchio would not strip it)"
    if any(c in uri for c in "\\%\x00?#") or any(ord(c) < 32 or ord(c) == 127 for c in uri):
        return "backslashes, percent escapes, '?', '#' and control characters are not allowed"
    if not uri.startswith(PACKAGE_PREFIX):
        scheme, sep, _ = uri.partition("://")
        if sep:
            return f"scheme {scheme}:// is not allowed (use package://<package>/<path>, lower-case)"
        return "plain paths are not allowed (use package://<package>/<path>)"
    segments = uri[len(PACKAGE_PREFIX) :].split("/")
    if "@" in segments[0] or ":" in segments[0]:
        return "package URIs take no user or port"
    if len(segments) < 2 or any(s in ("", ".", "..") for s in segments):
        return "package URIs need a package name and a path without '..', '.' or empty segments"
    return None


def _check_numbers(root: Element, field: str) -> None:
    for element in root.iter():
        for attr in _NUMERIC_ATTRIBUTES.get(element.tag, ()):
            raw = element.get(attr)
            if raw is None:
                continue
            shown = f"<{element.tag} {attr}={raw[:40]!r}>"
            try:
                values = [float(v) for v in raw.split()]
            except ValueError:
                raise InvalidInputError(f"{shown}: not a list of numbers", field) from None
            if not all(math.isfinite(v) for v in values):
                raise InvalidInputError(f"{shown}: numbers must be finite", field)
            count = 3 if (element.tag, attr) in _VECTOR_ATTRIBUTES else 1
            if len(values) != count:
                raise InvalidInputError(
                    f"{shown}: expected {count} number{'s' if count > 1 else ''}, "
                    f"got {len(values)}",
                    field,
                )
            if (element.tag, attr) in _BOUNDED_ATTRIBUTES and any(
                abs(v) > MAX_ABS_VALUE for v in values
            ):
                raise InvalidInputError(
                    f"{shown}: magnitudes above {MAX_ABS_VALUE:g} (m or rad) are not accepted",
                    field,
                )


def resource_elements(root: Element) -> Iterator[tuple[Element, str]]:
    """Every ``<mesh>`` and ``<texture>`` element with a ``filename``, and that filename."""
    for element in root.iter():
        if element.tag in ("mesh", "texture"):
            uri = element.get("filename")
            if uri is not None:
                yield element, uri


def _check_resources(root: Element, field: str) -> None:
    for element, uri in resource_elements(root):
        reason = check_resource_uri(uri)
        if reason:
            raise InvalidInputError(
                f"<{element.tag} filename={uri[:80]!r}> refused: {reason}", field
            )


def _check_joint(joint: Element, name: str, jtype: str, field: str) -> None:
    """Axis and limits of one joint (numbers already checked by :func:`_check_numbers`)."""
    axis = joint.find("axis")
    if jtype != "fixed" and axis is not None and axis.get("xyz") is not None:
        norm = math.hypot(*(float(v) for v in axis.get("xyz", "").split()))
        if norm < MIN_AXIS_NORM:
            what = "the zero vector" if norm == 0.0 else f"of norm {norm:.3g}"
            raise InvalidInputError(
                f"joint {name!r}: the axis is {what} (at least {MIN_AXIS_NORM:g} needed)", field
            )
    if jtype in ("revolute", "prismatic"):
        limit = joint.find("limit")
        if limit is None:
            raise InvalidInputError(f"joint {name!r}: a {jtype} joint needs <limit>", field)
        for attr in ("effort", "velocity"):  # urdfdom refuses a limit without them
            if limit.get(attr) is None:
                raise InvalidInputError(f"joint {name!r}: <limit> needs {attr}=", field)
        lower = float(limit.get("lower", 0.0))
        upper = float(limit.get("upper", 0.0))
        if lower > upper:
            raise InvalidInputError(
                f"joint {name!r}: <limit> lower ({lower!r}) > upper ({upper!r})", field
            )
        # Every configuration the service takes lies within ±MAX_JOINT_VALUE: a joint whose
        # range reaches beyond it would have configurations (even its neutral one) that
        # FK, IK and the analyses refuse.
        if max(abs(lower), abs(upper)) > MAX_JOINT_VALUE:
            raise InvalidInputError(
                f"joint {name!r}: <limit> lower/upper must lie within ±{MAX_JOINT_VALUE:g} "
                f"(rad or m), got [{lower!r}, {upper!r}]",
                field,
            )


def _new_name(element: Element, seen: set[str], field: str) -> str:
    """The ``name`` of a ``<link>`` or ``<joint>``, added to ``seen``; missing or taken: 422."""
    name = element.get("name")
    if not name:
        raise InvalidInputError(f"a <{element.tag}> has no name", field)
    if name in seen:
        raise InvalidInputError(f"{element.tag} {name!r} is defined twice", field)
    seen.add(name)
    return name


def check_urdf_document(
    root: Element, field: str = "urdf", limits: UrdfLimits | None = None
) -> None:
    """Structural checks of an uploaded URDF, with messages that name the culprit.

    Pinocchio's own parser only says "not a valid URDF model"; these checks say why: the
    root element, link and joint names, joint types and limits, the tree structure
    (one root, one parent per link, no cycle), finite and bounded numbers, axes of norm at
    least :data:`MIN_AXIS_NORM`, at least one actuated joint, at most ``limits.max_joints``
    joints and ``limits.max_dof`` movable ones, and safe ``<mesh>``/``<texture>``
    ``filename`` URIs (see :func:`check_resource_uri`; other ``filename`` attributes, e.g.
    Gazebo plugins, are never opened). ``root`` must come from
    :func:`~app.kinematics.xmldoc.parse_literal_xml` (literal names).
    """
    limits = limits or UrdfLimits()
    if root.tag != "robot":
        raise InvalidInputError(f"the root element must be <robot>, got <{root.tag}>", field)
    _check_resources(root, field)
    _check_numbers(root, field)

    links: set[str] = set()
    for link in root.findall("link"):
        _new_name(link, links, field)
    if not links:
        raise InvalidInputError("the URDF has no <link>", field)

    joints = root.findall("joint")
    if len(joints) > limits.max_joints:
        raise InvalidInputError(
            f"at most {limits.max_joints} joints (DENAVIT_MAX_URDF_JOINTS), got {len(joints)}",
            field,
        )
    movable = sum(1 for j in joints if j.get("type") != "fixed")
    if movable > limits.max_dof:
        raise InvalidInputError(
            f"at most {limits.max_dof} movable joints (DENAVIT_MAX_ROBOT_DOF), got {movable}",
            field,
        )
    names: set[str] = set()
    parent_of: dict[str, str] = {}
    actuated = 0
    for joint in joints:
        name = _new_name(joint, names, field)
        jtype = joint.get("type")
        if jtype not in URDF_JOINT_TYPES:
            raise InvalidInputError(
                f"joint {name!r}: type {jtype!r} is not supported "
                f"(use {', '.join(URDF_JOINT_TYPES)})",
                field,
            )
        ends = {}
        for end in ("parent", "child"):
            el = joint.find(end)
            link = el.get("link") if el is not None else None
            if not link:
                raise InvalidInputError(f"joint {name!r} has no <{end} link=...>", field)
            if link not in links:
                raise InvalidInputError(
                    f"joint {name!r}: {end} link {link!r} is not defined", field
                )
            ends[end] = link
        if ends["child"] in parent_of:
            raise InvalidInputError(
                f"link {ends['child']!r} has two parent joints "
                f"({parent_of[ends['child']]!r} and {name!r})",
                field,
            )
        parent_of[ends["child"]] = name
        _check_joint(joint, name, jtype, field)
        if jtype != "fixed" and joint.find("mimic") is None:
            actuated += 1
    mimic_specs(root, field)  # leaders known, no cycle, types Pinocchio can mimic

    roots = sorted(links - set(parent_of))
    if len(roots) != 1:
        what = f"{len(roots)} root links ({', '.join(map(repr, roots[:5]))})" if roots else "none"
        raise InvalidInputError(f"the links must form one tree with one root; found {what}", field)
    child_of: dict[str, list[str]] = {}
    for joint in joints:
        child_of.setdefault(joint.find("parent").get("link"), []).append(
            joint.find("child").get("link")
        )
    seen, stack = {roots[0]}, [roots[0]]
    while stack:
        for child in child_of.get(stack.pop(), ()):
            if child not in seen:
                seen.add(child)
                stack.append(child)
    if len(seen) != len(links):
        raise InvalidInputError("the joints form a cycle", field)
    if actuated == 0:
        raise InvalidInputError(
            "the URDF has no actuated joint (revolute, continuous or prismatic)", field
        )


def check_documents(
    urdf: str, srdf: str | None, limits: UrdfLimits, urdf_field: str = "urdf"
) -> Element:
    """The upload checks of a URDF (and its SRDF) within ``limits``: parsed with
    literal names as Pinocchio reads them, no DTD or entities, bounded work
    (:func:`check_urdf_document`, :func:`~app.robots.documents.srdf.check_srdf_document`); raises
    :class:`InvalidInputError` naming ``urdf_field`` or ``srdf``. Returns the checked URDF's
    root element (for further reading without parsing it again)."""
    root = parse_literal_xml(urdf, urdf_field, limits.xml)
    check_urdf_document(root, urdf_field, limits)
    if srdf is not None:
        links = {link.get("name", "") for link in root.findall("link")}
        check_srdf_document(srdf, links, "srdf", limits.xml, urdf_joint_table(root))
    return root


def build_checked_model(
    robot_id: str,
    urdf: str,
    *,
    source: str,
    srdf: str | None = None,
    ee_frame: str | None = None,
    description: str = "",
    package_dirs: Iterable[str] = (),
    urdf_field: str = "urdf",
) -> RobotModel:
    """A :class:`RobotModel` from text a client sent; every failure is an InvalidInputError."""
    try:
        robot = RobotModel(
            robot_id,
            urdf,
            name=robot_id,
            source=source,
            package_dirs=list(package_dirs),
            srdf_text=srdf,
            ee_frame=ee_frame,
            description=description,
        )
    except UnknownNameError as exc:
        raise InvalidInputError(exc.message, "ee_frame") from None
    except InvalidInputError as exc:  # a mimic joint the builder refuses, named
        raise InvalidInputError(exc.message, urdf_field) from None
    except (ValueError, RuntimeError, IndexError, KeyError, TypeError) as exc:
        # Pinocchio's messages start with the C++ source file and function: keep the reason.
        why = " ".join(str(exc).split("message:")[-1].split()) or type(exc).__name__
        raise InvalidInputError(f"Pinocchio rejected the URDF ({why})", urdf_field) from None
    if robot.n == 0:
        raise InvalidInputError(
            "the URDF has no actuated joint (revolute, continuous or prismatic)", urdf_field
        )
    return robot

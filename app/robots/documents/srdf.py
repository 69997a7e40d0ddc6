"""Checks of a client-supplied SRDF: collision pairs, groups, end effectors, named states.

An SRDF that still holds xacro (``xacro:`` elements, ``${…}``, ``$(…)``) is refused naming
the element: it must be given as ``.xacro`` to be expanded
(:func:`app.robots.documents.package.read_package`).

Parsed like the URDF by :func:`app.kinematics.xmldoc.parse_literal_xml` (no DTD or
entities, bounded work, literal names, as Boost.PropertyTree reads it for Pinocchio).
Groups, end effectors and group states are resolved against the URDF's joints
(:func:`app.kinematics.semantics.resolve`), so a stored SRDF always resolves.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any
from xml.etree.ElementTree import Element

from app.kinematics.errors import InvalidInputError
from app.kinematics.semantics import resolve, semantics_of
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml


def _refuse_xacro(root: Element, field: str) -> None:
    """Refuse an SRDF that still holds xacro (an element of the xacro namespace, ``${…}``
    or ``$(…)``): MoveIt's parser would read it as an SRDF without those groups."""
    prefixes = {"xacro"} | {
        name.split(":", 1)[1]
        for element in root.iter()
        for name, value in element.attrib.items()
        if name.startswith("xmlns:") and "xacro" in value
    }
    hint = "it is xacro: give it as a file ending .xacro (e.g. robot.srdf.xacro) to expand it"
    for element in root.iter():
        if element.tag.split(":", 1)[0] in prefixes and ":" in element.tag:
            raise InvalidInputError(f"<{element.tag[:60]}> {hint}", field)
        texts = [(f"{name}=", value) for name, value in element.attrib.items()]
        texts.append(("holds ", element.text or ""))
        for what, value in texts:
            if "${" in value or "$(" in value:
                shown = f"<{element.tag[:60]}> {what}{value[:80]!r}"
                raise InvalidInputError(f"{shown}: {hint}", field)


def check_srdf_document(
    text: str,
    links: set[str],
    field: str = "srdf",
    limits: XmlLimits | None = None,
    joints: Mapping[str, Mapping[str, Any]] | None = None,
) -> None:
    """Checks of an uploaded SRDF: safe XML, a <robot> root, known links in collision pairs,
    and, given the URDF's ``joints`` (:func:`app.kinematics.urdf_model.urdf_joint_table`),
    groups, end effectors and group states that resolve (422 naming the SRDF element)."""
    root = parse_literal_xml(text, field, limits)
    if root.tag != "robot":
        raise InvalidInputError(f"the root element must be <robot>, got <{root.tag}>", field)
    _refuse_xacro(root, field)
    for pair in root.iter("disable_collisions"):
        for attr in ("link1", "link2"):
            link = pair.get(attr)
            if link not in links:
                raise InvalidInputError(
                    f"<disable_collisions {attr}={link!r}>: no such link in the URDF", field
                )
    if joints is not None:
        resolve(semantics_of(root, field), joints, field)

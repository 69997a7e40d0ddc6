"""Checks of a client-supplied SRDF: collision pairs, groups, end effectors, named states.

Parsed like the URDF by :func:`app.kinematics.xmldoc.parse_literal_xml` (no DTD or
entities, bounded work, literal names, as Boost.PropertyTree reads it for Pinocchio).
Groups, end effectors and group states are resolved against the URDF's joints
(:func:`app.kinematics.semantics.resolve`), so a stored SRDF always resolves.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from app.kinematics.errors import InvalidInputError
from app.kinematics.semantics import resolve, semantics_of
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml


def check_srdf_document(
    text: str,
    links: set[str],
    field: str = "srdf",
    limits: XmlLimits | None = None,
    joints: Mapping[str, Mapping[str, Any]] | None = None,
) -> None:
    """Checks of an uploaded SRDF: safe XML, a <robot> root, known links in collision pairs,
    and, given the URDF's ``joints`` (:func:`app.kinematics.models.urdf_joint_table`),
    groups, end effectors and group states that resolve (422 naming the SRDF element)."""
    root = parse_literal_xml(text, field, limits)
    if root.tag != "robot":
        raise InvalidInputError(f"the root element must be <robot>, got <{root.tag}>", field)
    for pair in root.iter("disable_collisions"):
        for attr in ("link1", "link2"):
            link = pair.get(attr)
            if link not in links:
                raise InvalidInputError(
                    f"<disable_collisions {attr}={link!r}>: no such link in the URDF", field
                )
    if joints is not None:
        resolve(semantics_of(root, field), joints, field)

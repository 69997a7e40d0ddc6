"""Checks of a client-supplied SRDF (the collision pairs a URDF upload may disable).

Parsed like the URDF by :func:`app.kinematics.xmldoc.parse_literal_xml` (no DTD or
entities, bounded work, literal names, as Boost.PropertyTree reads it for Pinocchio).
"""

from __future__ import annotations

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import XmlLimits, parse_literal_xml


def check_srdf_document(
    text: str, links: set[str], field: str = "srdf", limits: XmlLimits | None = None
) -> None:
    """Checks of an uploaded SRDF: safe XML, a <robot> root, known links in collision pairs."""
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

"""Which link pairs a self-collision check looks at.

Pairs are decided per link pair (every geometry pair of two links is checked, and the pair
is reported once, with the smallest distance). Starting from all pairs of links that have
collision geometry, the model removes

1. links attached to the same Pinocchio joint (links joined by fixed joints): they can never
   move relative to each other;
2. *adjacent* links: links whose joints are joined by one joint in the kinematic tree. A
   joint whose bodies carry no geometry is bridged, as MoveIt does (two links separated
   only by geometry-less bodies touch at a joint, e.g. the spherical wrist of a DH arm);
3. the pairs the robot's SRDF disables (``<disable_collisions link1 link2>``; a
   ``<disable_default_collisions link>`` removes every pair of that link unless an
   ``<enable_collisions>`` restores it).

The rules read only the kinematic tree, the URDF's ``<collision>`` elements and the SRDF,
so the pairs are known without loading a mesh (:func:`collision_link_pairs`, used by the
robot description endpoint) and are the same pairs
:class:`app.kinematics.collision.CollisionModel` checks.
"""

from __future__ import annotations

from collections.abc import Iterable

import pinocchio as pin

from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.kinematics.xmldoc import TRUSTED, parse_literal_xml

LinkPair = tuple[str, str]
#: The model's lazy-cache key of its checked link pairs (:func:`link_pairs`).
LINK_PAIRS_KEY: LazyKey[list] = LazyKey("collision.link_pairs", list)


def srdf_disabled_pairs(srdf_text: str | None, links: Iterable[str]) -> set[frozenset[str]]:
    """Link pairs an SRDF disables (``disable_collisions`` and ``disable_default_collisions``).

    Parameters
    ----------
    srdf_text
        The SRDF document (read with literal names, as checked on upload), or ``None``.
    links
        The links with collision geometry (used to expand ``disable_default_collisions``).
    """
    if not srdf_text:
        return set()
    root = parse_literal_xml(srdf_text, "srdf", TRUSTED)
    links = list(links)
    disabled: set[frozenset[str]] = set()
    for el in root.iter("disable_default_collisions"):
        link = el.get("link")
        if link:
            disabled.update(frozenset((link, other)) for other in links if other != link)
    for el in root.iter("enable_collisions"):
        a, b = el.get("link1"), el.get("link2")
        if a and b:
            disabled.discard(frozenset((a, b)))
    for el in root.iter("disable_collisions"):
        a, b = el.get("link1"), el.get("link2")
        if a and b and a != b:
            disabled.add(frozenset((a, b)))
    return disabled


def _adjacent_bodies(model: pin.Model, with_geometry: set[int]) -> set[frozenset[int]]:
    """Joint pairs (bodies) adjacent in the kinematic tree, bridging geometry-less bodies.

    Two bodies with geometry are adjacent when the tree path between them has no interior
    body with geometry (usually: one is the other's parent joint).
    """
    neighbours: dict[int, set[int]] = {j: set() for j in range(model.njoints)}
    for j in range(1, model.njoints):
        p = int(model.parents[j])
        neighbours[j].add(p)
        neighbours[p].add(j)
    adjacent: set[frozenset[int]] = set()
    for start in with_geometry:
        seen = {start}
        stack = list(neighbours[start])
        while stack:
            j = stack.pop()
            if j in seen:
                continue
            seen.add(j)
            if j in with_geometry:
                adjacent.add(frozenset((start, j)))
            else:
                stack.extend(neighbours[j])
    return adjacent


def checked_link_pairs(robot: RobotModel, link_joints: dict[str, int]) -> list[LinkPair]:
    """The self-collision link pairs to check (see module docs for the rules).

    Parameters
    ----------
    robot
        The robot (its kinematic tree and SRDF).
    link_joints
        Link with collision geometry → Pinocchio joint id that moves it.

    Returns
    -------
    list of (str, str)
        Pairs ``(a, b)`` ordered by the links' frame ids (a before b).
    """
    order = {name: robot.frame_id(name) for name in link_joints}
    links = sorted(link_joints, key=lambda name: (order[name], name))
    bodies = set(link_joints.values())
    adjacent = _adjacent_bodies(robot.model, bodies)
    disabled = srdf_disabled_pairs(robot.srdf_text, links)
    pairs: list[LinkPair] = []
    for i, a in enumerate(links):
        for b in links[i + 1 :]:
            ja, jb = link_joints[a], link_joints[b]
            if ja == jb or frozenset((ja, jb)) in adjacent:
                continue
            if frozenset((a, b)) in disabled:
                continue
            pairs.append((a, b))
    return pairs


def collision_links(robot: RobotModel) -> dict[str, int]:
    """Links with ``<collision>`` elements → the Pinocchio joint moving them (URDF order).

    Read from the URDF text alone (no mesh is loaded).
    """
    root = parse_literal_xml(robot.urdf_text, "urdf", TRUSTED)
    out: dict[str, int] = {}
    for link in root.iter("link"):
        name = link.get("name")
        if name and link.find("collision") is not None:
            out[name] = int(robot.model.frames[robot.frame_id(name)].parentJoint)
    return out


def collision_link_pairs(robot: RobotModel) -> list[LinkPair]:
    """The checked self-collision link pairs, computed cheaply (no mesh is loaded).

    Same rules and result as :attr:`CollisionModel.link_pairs`, derived from the URDF's
    ``<collision>`` elements; cached per robot.
    """
    return robot.lazy(LINK_PAIRS_KEY, lambda r: checked_link_pairs(r, collision_links(r)))

"""The corpus references' own reading of the adjacency rule of self-collision pairs.

Written from the rule documented in ``app/kinematics/collision_pairs.py`` (not imported
from it): two bodies with collision geometry are *adjacent* when one joint of the tree
joins them, bodies without geometry on the way being bridged (as MoveIt does).
"""

from __future__ import annotations

from collections.abc import Hashable, Iterable, Mapping
from typing import TypeVar

Node = TypeVar("Node", bound=Hashable)


def bridged_adjacent(
    parent: Mapping[Node, Node | None], with_geometry: Iterable[Node]
) -> set[frozenset[Node]]:
    """Adjacent pairs among ``with_geometry``.

    Parameters
    ----------
    parent
        Each body of the joint tree (a moving body, or the root) to its parent body
        (``None`` for the root).
    with_geometry
        The bodies that carry collision geometry.
    """
    neighbours: dict[Node, set[Node]] = {n: set() for n in parent}
    for n, p in parent.items():
        if p is not None:
            neighbours[n].add(p)
            neighbours[p].add(n)
    geometry = set(with_geometry)
    adjacent: set[frozenset[Node]] = set()
    for start in geometry:
        seen, stack = {start}, list(neighbours[start])
        while stack:
            n = stack.pop()
            if n in seen:
                continue
            seen.add(n)
            if n in geometry:
                adjacent.add(frozenset((start, n)))
            else:
                stack.extend(neighbours[n])
    return adjacent

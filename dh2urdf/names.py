"""Names of the links and joints that dh2urdf generates (one place, shared by all modules).

For a table with n rows the URDF holds:

* link ``world`` (the root) and fixed joint ``fixed_dh_0`` (world → ``dh_0``, the base
  transform B);
* per row i = 1..n: the actuated joint (named by the table, parent ``dh_{i-1}``), its moving
  link ``link_i`` and the fixed joint ``fixed_dh_i`` (``link_i`` → ``dh_i``);
* fixed joint ``fixed_tool`` (``dh_n`` → ``tool``, the tool transform).

Pinocchio puts joint and link names into one frame namespace (next to its own
``universe``), so table joint names must avoid all of these (:func:`reserved_names`).
"""

from __future__ import annotations

__all__ = [
    "ROOT_LINK",
    "TOOL_LINK",
    "TOOL_JOINT",
    "dh_link",
    "dh_joint",
    "body_link",
    "generated_names",
    "reserved_names",
]

#: Root link of every generated URDF (world frame).
ROOT_LINK = "world"
#: Link on the tool centre point (TCP).
TOOL_LINK = "tool"
#: Fixed joint dh_n → tool.
TOOL_JOINT = "fixed_tool"
#: Frame names Pinocchio creates by itself.
PINOCCHIO_NAMES = frozenset({"universe"})


def dh_link(i: int) -> str:
    """Name of the link on DH frame ``i`` (0 = base frame)."""
    return f"dh_{i}"


def dh_joint(i: int) -> str:
    """Name of the fixed joint whose child is :func:`dh_link` ``(i)``."""
    return f"fixed_dh_{i}"


def body_link(i: int) -> str:
    """Name of the moving link of row ``i`` (1-based), the child of the actuated joint."""
    return f"link_{i}"


def generated_names(n: int) -> frozenset[str]:
    """Every link and fixed-joint name generated for a table with ``n`` rows."""
    names = {ROOT_LINK, TOOL_LINK, TOOL_JOINT}
    for i in range(n + 1):
        names.update((dh_link(i), dh_joint(i)))
    for i in range(1, n + 1):
        names.add(body_link(i))
    return frozenset(names)


def reserved_names(n: int) -> frozenset[str]:
    """Names a table joint may not take: :func:`generated_names` plus Pinocchio's own."""
    return generated_names(n) | PINOCCHIO_NAMES

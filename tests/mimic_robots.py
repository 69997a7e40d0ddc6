"""Small robots with mimic joints, written for the tests of the URDF builder: a gripper
whose joint names the test chooses (so Pinocchio's name-ordered siblings come in any order).
"""

from __future__ import annotations

LIMIT = '<limit lower="-1" upper="1" effort="1" velocity="1"/>'


def joint(
    name: str,
    parent: str,
    child: str,
    xyz: str,
    axis: str,
    jtype: str = "revolute",
    mimic: tuple[str, float, float] | None = None,
) -> str:
    m = (
        f'<mimic joint="{mimic[0]}" multiplier="{mimic[1]!r}" offset="{mimic[2]!r}"/>'
        if mimic
        else ""
    )
    return (f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{xyz}" rpy="0.1 -0.2 0.3"/><axis xyz="{axis}"/>'
            f'{LIMIT if jtype != "continuous" else ""}{m}</joint>')  # fmt: skip


def gripper(
    leader: str, follower: str, wrist: str, finger: str, follower_type: str = "revolute"
) -> str:
    """A wrist, two fingers on a palm, and a prismatic pad on the follower's finger.

    ``follower`` mimics ``leader`` (×-0.8, +0.1); both hang from the palm on sibling
    branches, so Pinocchio visits them in name order.
    """
    links = "".join(f'<link name="{n}"/>' for n in ("base", "palm", "left", "right", "pad"))
    return (
        f'<robot name="gripper">{links}'
        + joint(wrist, "base", "palm", "0 0 0.1", "0 0 1")
        + joint(leader, "palm", "left", "0 0.03 0.05", "1 0 0")
        + joint(
            follower, "palm", "right", "0 -0.03 0.05", "1 0 0", follower_type, (leader, -0.8, 0.1)
        )
        + joint(finger, "right", "pad", "0 0 0.04", "0 1 0", "prismatic")
        + "</robot>"
    )

"""The default tip of a robot given without ``ee_frame`` (app/kinematics/tip.py).

The expected tips are read off the robots' drawings: the flange or TCP of the arm, never a
gripper finger. Catalog robots are loaded from their URDF without the catalog's choice.
"""

from __future__ import annotations

from app.kinematics.models import RobotModel

BOX = '<visual><geometry><box size="0.01 0.01 0.01"/></geometry></visual>'


def _robot(joints: list[tuple[str, str, str, str, str]], bare: set[str] = frozenset()) -> str:
    """A URDF from (name, type, parent, child, extra XML) rows; links get a box visual unless
    named in ``bare``."""
    links = {"base"} | {j[3] for j in joints}
    body = "".join(
        f'<link name="{name}">{"" if name in bare else BOX}</link>' for name in sorted(links)
    )
    for name, jtype, parent, child, extra in joints:
        limit = '<limit lower="-1" upper="1" velocity="1" effort="1"/>' if jtype != "fixed" else ""
        body += (
            f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>{limit}'
            f"{extra}</joint>"
        )
    return f'<?xml version="1.0"?><robot name="t">{body}</robot>'


ARM = [
    ("a1", "revolute", "base", "l1", ""),
    ("a2", "revolute", "l1", "l2", ""),
    ("a3", "revolute", "l2", "l3", ""),
    ("flange_joint", "fixed", "l3", "flange", ""),
]


def _tip(joints, bare=frozenset()) -> str:
    return RobotModel("t", _robot(joints, set(bare))).ee_frame


def test_two_prismatic_jaws_are_fingers_one_slide_is_not() -> None:
    """Two sibling prismatic jaws (no mimic) are a finger pair: the tip is the flange. A lone
    prismatic joint at the end (a linear axis) is part of the arm, and a bare gripper (jaws
    at the root, nothing else moving) falls back to the deepest link."""
    jaws = [
        ("jaw_a", "prismatic", "flange", "jaw_left", ""),
        ("jaw_b", "prismatic", "flange", "jaw_right", ""),
    ]
    assert _tip(ARM + jaws) == "flange"
    assert _tip(ARM + jaws[:1]) == "jaw_left"
    at_root = [(name, t, "base", child, x) for name, t, _, child, x in jaws]
    assert _tip(at_root) in {"jaw_left", "jaw_right"}


def test_mimic_finger_linkage_is_a_finger() -> None:
    """A Robotiq-2F-like gripper: a revolute knuckle leading mimic followers, two levels."""
    mimic = '<mimic joint="f_knuckle" multiplier="-1"/>'
    gripper = [
        ("f_knuckle", "revolute", "flange", "left_knuckle", ""),
        ("f_left_tip", "revolute", "left_knuckle", "left_tip", mimic),
        ("f_right_knuckle", "revolute", "flange", "right_knuckle", mimic),
        ("f_right_tip", "revolute", "right_knuckle", "right_tip", mimic),
    ]
    assert _tip(ARM + gripper) == "flange"


def test_tcp_marker_before_geometry_on_the_same_joint() -> None:
    """Fixed fingers (Kinova-style) and a bare TCP frame on the last joint: the TCP."""
    fixed = [
        ("a_tcp_joint", "fixed", "flange", "tcp", ""),  # parsed first: not last on ties
        ("finger_a", "fixed", "flange", "finger_a_link", ""),
        ("finger_a_tip", "fixed", "finger_a_link", "finger_a_tip_link", ""),
    ]
    assert _tip(ARM + fixed, bare={"tcp"}) == "tcp"
    # without a bare frame: the link named like a tool frame, not the fingers beyond it
    assert _tip(ARM + fixed[1:]) == "flange"
    # and without one either: the farthest link held by the last joint
    unnamed = [(j, t, "l3" if p == "flange" else p, c, x) for j, t, p, c, x in fixed[1:]]
    assert _tip(ARM[:3] + unnamed) == "finger_a_tip_link"


def test_a_link_named_like_a_tool_frame_first_among_equally_deep_ones() -> None:
    """Among links held by the last joint, one named like a tool frame (Menagerie UR5e's
    ``attachment_site``, a ``tool0``, an ``ee_link``) before a bare marker farther out; a
    deeper link still wins, a name inside a word (``knee``, ``tooling``) is no tool frame,
    and fingers are never the tip whatever their names."""
    arm = ARM[:3]  # ends at l3, which has geometry
    frames = [
        ("site_joint", "fixed", "l3", "attachment_site", ""),
        ("marker_joint", "fixed", "l3", "marker", ""),
        ("far_joint", "fixed", "marker", "far", ""),
    ]
    bare = {"attachment_site", "marker", "far", "knee", "tooling"}
    assert _tip(arm + frames, bare=bare) == "attachment_site"
    assert _tip(arm + frames[1:], bare=bare) == "far"  # no name: the farthest bare frame
    knee = [
        ("site_joint", "fixed", "l3", "knee", ""),
        ("rack_joint", "fixed", "l3", "tooling", ""),
        *frames[1:],
    ]
    assert _tip(arm + knee, bare=bare) == "far"
    for name in ("tool0", "ee_link", "link_eef", "j2s6s200_end_effector", "hand_tcp"):
        renamed = [("site_joint", "fixed", "l3", name, ""), *frames[1:]]
        assert _tip(arm + renamed, bare=bare | {name}) == name
    jaws = [
        ("jaw_a", "prismatic", "l3", "tool_jaw_a", ""),
        ("jaw_b", "prismatic", "l3", "tool_jaw_b", ""),
    ]
    assert _tip(arm + jaws) == "l3"
    deeper = [("a4", "revolute", "l3", "wrist", "")]
    assert _tip(arm + frames + deeper, bare=bare) == "wrist"


#: The tips of the catalog robots' own URDFs (the catalog names them; an upload does not).
CATALOG_TIPS = {
    "panda": "panda_hand_tcp",
    "ur5": "tool0",
    "ur10": "tool0",
    "kinova": "j2s6s200_end_effector",
    "xarm": "link_eef",
}


def test_catalog_urdfs_without_ee_frame(registry) -> None:
    tips = {rid: RobotModel("x", registry.get(rid).urdf_text).ee_frame for rid in CATALOG_TIPS}
    assert tips == CATALOG_TIPS


def test_panda_without_its_tcp_is_the_hand_or_flange(registry) -> None:
    """The catalog Panda with the TCP link removed: still the hand or flange."""
    text = registry.get("panda").urdf_text
    for opening, closing in (
        ('<joint name="panda_hand_tcp_joint"', "</joint>"),
        ('<link name="panda_hand_tcp"', "</link>"),
    ):
        start = text.index(opening)
        text = text[:start] + text[text.index(closing, start) + len(closing) :]
    assert "panda_hand_tcp" not in text
    assert RobotModel("x", text).ee_frame in {"panda_hand", "panda_link8"}

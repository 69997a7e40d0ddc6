"""The default tip of a robot: the frame FK, Jacobians and IK use when no frame is named.

A robot's own choice comes first (the catalog's ``ee_frame``, an SRDF end effector's parent
link, both given to :class:`app.kinematics.models.RobotModel` as ``ee_frame``). Without one,
:func:`default_tip` picks **the tip of the longest serial chain that is not a gripper
finger**, defined on Pinocchio's joint tree (fixed joints merged into the links they hold):

- a *gripper joint* is a prismatic joint, a mimic follower or a mimic leader;
- a *finger branch* is a joint whose whole subtree (itself and every joint below it) holds
  gripper joints only, and whose parent joint (or the root) has at least one other child
  with that property: fingers come in similar pairs (the Panda's ``panda_finger_joint1``,
  prismatic and the leader of ``panda_finger_joint2``, and its mimic follower; a Robotiq
  2F's knuckle leader and its mimic followers; two independent prismatic jaws);
- a *finger link* is a link moved by a finger branch (one in its support);
- among the other links, the tip is the one with the most moving joints to the root; on a
  tie (links held by the same joint through fixed joints, e.g. a flange, a hand, a TCP, or
  fingers fixed to the hand), a link *named like a tool frame* first (:data:`TOOL_NAME`:
  ``tcp``, ``flange``, ``attachment``, ``tool``, ``ee``, ``eef``, ``end_effector``,
  ``grasp`` as a word of its name, e.g. ``tool0``, ``panda_hand_tcp``, ``link_eef``, an
  MJCF ``attachment_site`` of MuJoCo Menagerie's UR5e), then a *bare* link (no
  ``<visual>`` and no ``<collision>``: a frame marker such as ``tool0`` or a TCP) before
  one with geometry, then the one with the most fixed joints below that joint (the TCP
  beyond the hand beyond the flange), then the one defined last.

If every moving link is a finger link (a bare gripper), the deepest link is the tip, by the
same ordering over all links. A lone prismatic or revolute joint at the end of an arm (a
linear axis, a one-jaw gripper) is not a finger by this rule: its link is the tip.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from xml.etree.ElementTree import Element

import pinocchio as pin

from app.kinematics.joint_types import PRISMATIC_MODELS

#: A link named like a tool frame (a word of its name, letters not run on: ``tool0``,
#: ``ee_link``, ``attachment_site``; not ``knee``).
TOOL_NAME = re.compile(
    r"(?<![a-z])(tcp|flange|attachment|tool|ee|eef|end_?effector|grasp)(?![a-z])", re.I
)


def _gripper_joints(model: pin.Model) -> set[int]:
    """Joint ids of the gripper joints (module doc): prismatic, mimic followers, leaders."""
    ids = {int(j) for j in model.mimicking_joints} | {int(j) for j in model.mimicked_joints}
    for jid in range(1, model.njoints):
        if model.joints[jid].shortname() in PRISMATIC_MODELS:
            ids.add(jid)
    return ids


def finger_branches(model: pin.Model) -> set[int]:
    """Joint ids heading a finger branch (module doc)."""
    children: dict[int, list[int]] = {j: [] for j in range(model.njoints)}
    for jid in range(1, model.njoints):
        children[model.parents[jid]].append(jid)
    gripper = _gripper_joints(model)
    only_gripper: dict[int, bool] = {}
    for jid in range(model.njoints - 1, 0, -1):  # children have larger ids than parents
        only_gripper[jid] = jid in gripper and all(only_gripper[c] for c in children[jid])
    heads: set[int] = set()
    for kids in children.values():
        pure = [c for c in kids if only_gripper[c]]
        if len(pure) >= 2:
            heads.update(pure)
    return heads


def bare_links(root: Element) -> set[str]:
    """Names of the links of a parsed URDF (``root``, read with literal names by
    :func:`~app.kinematics.xmldoc.parse_literal_xml`) with neither ``<visual>`` nor
    ``<collision>``."""
    return {
        link.get("name", "")
        for link in root.iter("link")
        if link.find("visual") is None and link.find("collision") is None
    }


def default_tip(model: pin.Model, link_frames: Iterable[int], bare: Iterable[int] = ()) -> int:
    """The default tip (module doc) among ``link_frames`` (Pinocchio frame ids of the links,
    non-empty; ``bare`` those of the links without geometry): its frame id."""
    bare = set(bare)
    links = list(link_frames)
    moving = {0: 0}
    for jid in range(1, model.njoints):
        moving[jid] = moving[model.parents[jid]] + 1
    fixed = [0] * len(model.frames)  # frames between a frame and its parent joint's frame
    for fid in range(1, len(model.frames)):
        f = model.frames[fid]
        parent = model.frames[f.parentFrame]
        fixed[fid] = 0 if parent.parentJoint != f.parentJoint else fixed[f.parentFrame] + 1

    def key(fid: int) -> tuple[int, bool, bool, int, int]:
        frame = model.frames[fid]
        named = TOOL_NAME.search(frame.name) is not None
        return moving[frame.parentJoint], named, fid in bare, fixed[fid], fid

    heads = finger_branches(model)
    arm = [
        fid
        for fid in links
        if not heads.intersection(model.supports[model.frames[fid].parentJoint])
        and model.frames[fid].parentJoint > 0
    ]
    return max(arm or links, key=key)

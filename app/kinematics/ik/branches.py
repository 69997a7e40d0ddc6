"""IK branches: which closed-form solution family a configuration belongs to.

A 6R arm with a closed form (UR type) or a recognisable structure (spherical wrist: the last
three axes through one point, e.g. the PUMA 560 and the Stanford arm) reaches a generic pose
in up to 8 configurations, told apart by three binary flags; a planar 2-link arm reaches a
point in two (its elbow). :func:`branch_label` names the flags of a configuration, e.g.
``"shoulder_left/elbow_up/wrist_noflip"`` (planar: ``"elbow_up"``), and ``None`` for other
chains (their solutions are told apart by clusters in joint space, :mod:`.rank`).

Definitions
-----------
All vectors are in the root (world) frame at the configuration q. For the i-th moving joint
of the chain (1-based), z_i is the unit joint axis in the direction of positive motion (as
declared by the robot description), o_i the origin of the joint's frame (a point on axis i),
and [a, b, c] = (a × b)·c the triple product. The wrist point w is the common point of axes
4, 5, 6 (spherical wrist) or of axes 5 and 6 (UR type); ``w`` is fixed in link 5 and found
once at q = 0.

- shoulder: ``right`` when [z_1, z_2, w − o_2] > 0, i.e. a positive motion of joint 2 moves
  the wrist point along +z_1 (Fu, Gonzalez & Lee's ARM indicator, *Robotics: Control, Sensing,
  Vision and Intelligence*, §3.3); ``left`` otherwise. The two solutions of joint 1 put the
  wrist point on opposite sides of the plane spanned by z_1 and z_2 through o_2, so they get
  different shoulder flags.
- elbow (joints 2 and 3 revolute with parallel axes): with e = o_3 the elbow and t the end
  of the 2-link arm of axes 2 and 3 (spherical wrist: t = w; UR type: t = o_4, a point of
  axis 4, parallel to axis 2), ``up`` when [z_2, e − o_2, t − e] · [z_1, z_2, w − o_2] < 0:
  the turn from upper arm to forearm about z_2, times the shoulder's factor (the side of
  the plane of z_1 and z_2 on which the wrist point lies). For a spherical wrist (t = w) this
  is the elbow on the +z_1 side of the line from the shoulder o_2 to t in the arm's plane
  (the textbook's ELBOW relative to ARM). Each factor uses z_2 once, so the flag does not
  depend on the direction of z_2. The two elbow solutions of a 2-link arm are mirror images
  across the line from o_2 to t, so they get different flags. No elbow flag when joint 2
  or 3 is prismatic (the Stanford arm).

  The first factor vanishes only at the elbow singularity (axes 2, 3 and 4 coplanar, or
  o_2, o_3, w collinear), the second only at the shoulder singularity (the wrist point in
  the plane of axes 1 and 2), so the flag, like the other two, changes only where the arm is
  singular: a continuous motion away from singularities keeps its whole label (the path
  follower relies on it). (Taking the side of t = o_4 instead of w would flip the UR's
  elbow flag where o_4 crosses that plane, at configurations that are not singular.)
- wrist: ``noflip`` when [z_4, z_6, z_5] > 0, ``flip`` otherwise. For orthogonal
  consecutive axes this is ±sin(q_5 + β) (β the zero offset): the two wrist solutions of the
  same shoulder and elbow (q_5 and its mirror, the PUMA's (q_4 + π, −q_5, q_6 + π)) have
  opposite signs. It vanishes at the wrist singularity (axes 4 and 6 aligned).
- planar 2-link arm: ``elbow_up`` when [z_1, o_2 − o_1, p − o_2] > 0 (p the frame origin):
  the forearm turns counter-clockwise about z_1 from the upper arm. For the course's arm
  (DH table, θ2 the second joint angle) this is sin θ2 > 0: ``elbow_up`` for θ2 ∈ (0, π).

Every flag is a sign of a triple product of joint axes and points at q, so it does not depend
on the joints' zero offsets. A product that is exactly 0 (a singular configuration, where two
branches meet) counts as positive. The structure of a chain is detected once
(:func:`branch_form`) and cached on the chain.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.models import RobotModel

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain

#: Axes closer than this (|a × b| of unit vectors, distance of lines in m) are parallel /
#: meeting when the structure of a chain is detected.
STRUCTURE_TOL = 1e-9


@dataclass(frozen=True, slots=True)
class BranchForm:
    """The structure of a chain that :func:`branch_label` recognises.

    ``kind`` is ``"6r"`` (UR type or spherical wrist) or ``"planar2"``; ``pin_ids`` are the
    Pinocchio joint ids of the moving joints, ``axes`` their local axes; ``wrist`` is the
    wrist point in the frame of joint 5 (6R only); ``elbow`` whether the elbow flag exists;
    ``tip_axis4`` whether the 2-link arm ends on axis 4 (UR type) rather than at ``wrist``.
    """

    kind: str
    pin_ids: tuple[int, ...]
    axes: np.ndarray  # (k, 3) unit axes in each joint's frame
    idx_v: tuple[int, ...] = ()  # the moving joints' columns of the Jacobian
    wrist: np.ndarray | None = None
    elbow: bool = False
    tip_axis4: bool = False


def _lines_meet(p1: np.ndarray, w1: np.ndarray, p2: np.ndarray, w2: np.ndarray) -> np.ndarray:
    """The common point of two non-parallel lines, or an empty array if they are skew or
    parallel."""
    n = np.cross(w1, w2)
    nn = float(n @ n)
    if nn < STRUCTURE_TOL:
        return np.empty(0)
    d = p2 - p1
    if abs(float(d @ n)) / np.sqrt(nn) > STRUCTURE_TOL * max(1.0, float(np.linalg.norm(d))):
        return np.empty(0)
    return p1 + (float(np.cross(d, w2) @ n) / nn) * w1


def _parallel(a: np.ndarray, b: np.ndarray) -> bool:
    return float(np.linalg.norm(np.cross(a, b))) <= STRUCTURE_TOL


def detect_branch_form(robot: RobotModel, ch: IKChain) -> BranchForm | None:
    """The :class:`BranchForm` of a chain, or None (computed: :attr:`IKChain.branch_form`
    caches it)."""
    joints = [robot.joints[i] for i in ch.active]
    model = robot.model
    if any(model.joints[j.pin_id].nv != 1 for j in joints):
        return None
    forms = ch.closed_form
    pin_ids = tuple(j.pin_id for j in joints)
    idx_v = tuple(int(model.joints[p].idx_v) for p in pin_ids)
    axes = np.array([np.asarray(j.axis, float) / np.linalg.norm(j.axis) for j in joints])
    if forms[1] is not None:  # the planar 2-link closed form applies
        return BranchForm("planar2", pin_ids, axes, idx_v)
    if len(joints) != 6:
        return None
    revolute = [j.type != "prismatic" for j in joints]
    if not (revolute[0] and revolute[1] and all(revolute[3:])):
        return None
    data = model.createData()
    pin.forwardKinematics(model, data, robot.to_pin(np.zeros(robot.n)))
    z = np.array([data.oMi[p].rotation @ a for p, a in zip(pin_ids, axes, strict=True)])
    o = np.array([data.oMi[p].translation for p in pin_ids])
    if _parallel(z[0], z[1]):
        return None
    c = _lines_meet(o[4], z[4], o[5], z[5])
    if c.size == 0:
        return None
    ur = forms[0] is not None
    if not ur:  # spherical wrist: axis 4 also through c
        d = c - o[3]
        if float(np.linalg.norm(np.cross(d, z[3]))) > STRUCTURE_TOL * max(1.0, np.linalg.norm(d)):
            return None
    elbow = revolute[2] and _parallel(z[1], z[2])
    wrist_local = data.oMi[pin_ids[4]].actInv(c)
    return BranchForm("6r", pin_ids, axes, idx_v, wrist_local, elbow, ur)


def branch_form(robot: RobotModel, ch: IKChain) -> BranchForm | None:
    """The chain's :class:`BranchForm` (None: no branch flags), detected once and cached on
    the chain (:attr:`IKChain.branch_form`)."""
    return ch.branch_form


def branch_label(robot: RobotModel, chain: IKChain, q: np.ndarray) -> str | None:
    """The branch flags of the wire configuration ``q`` (see the module's definitions).

    Parameters
    ----------
    robot
        The robot.
    chain
        The IK chain (robot, frame, group) whose moving joints are labelled.
    q
        Wire configuration (rad for revolute joints, m for prismatic ones).

    Returns
    -------
    str or None
        ``"shoulder_<left|right>/elbow_<up|down>/wrist_<flip|noflip>"`` for 6R arms (no
        elbow part when joint 2 or 3 is prismatic), ``"elbow_<up|down>"`` for planar 2-link
        arms, None for other chains.
    """
    form = branch_form(robot, chain)
    if form is None:
        return None
    model, data = robot.model, robot.data
    # One call gives every axis: column i of the world Jacobian is the joint's twist at the
    # world origin, (v_i, z_i) with v_i = o_i × z_i, so z_i × v_i (unit z_i) is a point of
    # axis i. Every flag below is unchanged by sliding o_i along its axis (each o_i enters a
    # triple product with its own axis, or with a parallel one).
    pin.computeJointJacobians(model, data, robot.to_pin(np.asarray(q, dtype=float)))
    cols = data.J[:, form.idx_v].T.tolist()
    z = [c[3:] for c in cols]
    o = [_cross(c[3:], c[:3]) for c in cols]
    if form.kind == "planar2":
        p = pin.updateFramePlacement(model, data, chain.frame_id).translation.tolist()
        up = _triple(z[0], _sub(o[1], o[0]), _sub(p, o[1])) >= 0.0
        return "elbow_up" if up else "elbow_down"
    w = data.oMi[form.pin_ids[4]].act(form.wrist).tolist()
    shoulder = _triple(z[0], z[1], _sub(w, o[1]))
    parts = ["shoulder_right" if shoulder >= 0.0 else "shoulder_left"]
    if form.elbow:
        t = o[3] if form.tip_axis4 else w
        turn = _triple(z[1], _sub(o[2], o[1]), _sub(t, o[2]))
        parts.append("elbow_up" if turn * shoulder < 0.0 else "elbow_down")
    noflip = _triple(z[3], z[5], z[4]) >= 0.0
    parts.append("wrist_noflip" if noflip else "wrist_flip")
    return "/".join(parts)


def _sub(a: list[float], b: list[float]) -> list[float]:
    """a − b of two 3-vectors (plain floats)."""
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def _cross(a: list[float], b: list[float]) -> list[float]:
    """a × b of two 3-vectors (plain floats)."""
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _triple(a: list[float], b: list[float], c: list[float]) -> float:
    """(a × b)·c of three 3-vectors (plain floats: no array overhead on the hot path)."""
    return (
        (a[1] * b[2] - a[2] * b[1]) * c[0]
        + (a[2] * b[0] - a[0] * b[2]) * c[1]
        + (a[0] * b[1] - a[1] * b[0]) * c[2]
    )

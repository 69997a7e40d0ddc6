"""Mimic joints: URDF joints that follow another joint (``<mimic joint= multiplier= offset=>``).

In the model :func:`app.kinematics.urdf_model.build_model` builds, a follower is a
``JointModelMimic`` of its root leader (a chain composed) with no configuration or velocity
of its own (nq = nv = 0): its value is

    q_follower = multiplier · q_leader + offset

read from its leader's slot of q, and its motion is added to the leader's column of every
Jacobian (so the frame Jacobian of a link under a follower already holds, in the leader's
column, the follower's motion times the multiplier). What Pinocchio does *not* do is put the
leader into the *support* of such a link (``model.supports`` lists the follower, whose leader
usually sits on another branch, e.g. the other finger of a gripper): :func:`with_leaders`
adds it, so that IK, velocity and analysis move the leader.

On the wire a follower is never a configuration entry (configurations hold the actuated
joints only), but a ``joint_positions`` map may name it, as a ROS ``JointState`` of the whole
robot does: its value is then checked (:func:`check_followers`), never used to set anything.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError

#: Largest |given − (multiplier · leader + offset)| (rad or m) accepted for a follower's value
#: in a ``joint_positions`` map.
MIMIC_TOLERANCE = 1e-9


@dataclass(frozen=True, slots=True)
class MimicJoint:
    """One mimic follower: ``value = multiplier · value(leader) + offset`` (rad or m)."""

    name: str
    type: str  # the URDF type of the follower: revolute | prismatic
    leader: str
    multiplier: float
    offset: float
    pin_id: int  # Pinocchio joint id of the follower
    leader_pin_id: int
    leader_index: int  # wire index of the leader

    def value(self, leader_value: float) -> float:
        """The follower's value for a leader value (rad or m)."""
        return self.multiplier * leader_value + self.offset

    def describe(self) -> dict[str, Any]:
        """The wire description (GET /robots/{id}, ``mimic_joints``)."""
        return {
            "name": self.name,
            "type": self.type,
            "leader": self.leader,
            "multiplier": self.multiplier,
            "offset": self.offset,
        }


def mimic_joints(
    model: pin.Model, wire_index: Mapping[int, int], urdf_types: Mapping[str, str]
) -> list[MimicJoint]:
    """The mimic followers of ``model`` in Pinocchio's joint order.

    Parameters
    ----------
    model
        A model built by :func:`app.kinematics.urdf_model.build_model`.
    wire_index
        Pinocchio joint id → wire index, for the actuated joints (the leaders among them).
    urdf_types
        Joint name → URDF joint type (for the description).
    """
    out = []
    for follower, leader in zip(model.mimicking_joints, model.mimicked_joints, strict=True):
        follower, leader = int(follower), int(leader)
        jm = model.joints[follower].extract()
        name = model.names[follower]
        out.append(
            MimicJoint(
                name=name,
                type=urdf_types.get(name) or "revolute",
                leader=model.names[leader],
                multiplier=float(jm.scaling),
                offset=float(jm.offset),
                pin_id=follower,
                leader_pin_id=leader,
                leader_index=wire_index[leader],
            )
        )
    return out


def with_leaders(support: Iterable[int], mimics: Iterable[MimicJoint]) -> set[int]:
    """Pinocchio joint ids ``support`` (the joints on a frame's path to the root) plus the
    leader of every follower among them: the joints whose values move the frame."""
    ids = set(support)
    ids |= {m.leader_pin_id for m in mimics if m.pin_id in ids}
    return ids


def has_followers(support: Iterable[int], mimics: Iterable[MimicJoint]) -> bool:
    """Whether a mimic follower is among Pinocchio joint ids ``support``: the frame's chain
    is then not a plain serial chain of its moving joints (no closed form applies)."""
    ids = set(support)
    return any(m.pin_id in ids for m in mimics)


def check_followers(
    mimics: Mapping[str, MimicJoint], given: Mapping[str, float], q: np.ndarray, field: str
) -> None:
    """Refuse a follower value of a joint map that its leader does not produce.

    ``given`` maps follower names to the values a ``joint_positions`` map gave for them;
    ``q`` is the wire configuration the map produced (the leader's value given in the same
    map, or its default when the map does not name it). A follower whose value differs from
    ``multiplier · q[leader] + offset`` by more than :data:`MIMIC_TOLERANCE` raises
    :class:`InvalidInputError` naming ``<field>.<follower>`` and the expected value.
    """
    for name, value in given.items():
        m = mimics[name]
        lead = float(q[m.leader_index])
        expected = m.value(lead)
        if not math.isfinite(expected) or abs(value - expected) > MIMIC_TOLERANCE:
            raise InvalidInputError(
                f"{name} is a mimic joint of {m.leader} (value = {m.multiplier:g} × "
                f"{m.leader} + {m.offset:g}): expected {expected!r} for {m.leader} = "
                f"{lead!r}, got {value!r} (tolerance {MIMIC_TOLERANCE:g})",
                f"{field}.{name}",
            )


def follower_travel(m: MimicJoint, lower: float | None, upper: float | None, at: float) -> float:
    """Largest |value − value(at)| (m or rad) of a follower while its leader spans
    [lower, upper] (a missing limit taken as 0): how far it moves from where it is when its
    leader is at ``at``."""
    return abs(m.multiplier) * max(abs((lower or 0.0) - at), abs((upper or 0.0) - at))

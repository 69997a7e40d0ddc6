"""The one way a URDF becomes a Pinocchio model: mimic joints as urdfdom and ROS read them.

``pin.buildModelFromXML(urdf, mimic=True)`` visits sibling joints in name order and refuses
a mimic follower met before its leader ("The parent joint of the mimic joint is not in the
kinematic tree"), so a gripper whose follower's name sorts before its leader's (the Robotiq
2F-85's ``robotiq_85_left_inner_knuckle_joint`` mimics ``robotiq_85_left_knuckle_joint``)
would be refused, and renaming a joint would change what is accepted. :func:`build_model`
reads the URDF the way robot_state_publisher / joint_state_publisher do instead:

1. :func:`mimic_specs` reads every ``<mimic joint= multiplier= offset=>`` of a moving joint
   (a ``<mimic>`` on a fixed joint moves nothing and is ignored) and composes chains to
   their root leader, as joint_state_publisher does: a follower ``f = m₂·g + o₂`` of a
   follower ``g = m₁·r + o₁`` of ``r`` is ``f = (m₁·m₂)·r + (m₂·o₁ + o₂)``. An unknown or
   fixed leader, a cycle, and a continuous root leader (Pinocchio cannot mimic its
   (cos θ, sin θ) configuration) are refused naming the joint; a continuous follower is
   built as an unbounded revolute joint (the same motion: it has no configuration of its
   own);
2. the model is built with ``mimic=False`` (every joint its own), in Pinocchio's usual
   depth-first order with siblings by name, unless a root leader would then come after
   one of its followers: the siblings are then ordered so that every leader's branch comes
   first (ties by name, so a robot accepted before keeps its joint order). A follower
   above its own leader, or two branches that each hold a leader of the other, cannot be
   ordered depth-first and are refused naming the joints;
3. each follower is turned into a ``JointModelMimic`` of its root leader with
   ``pin.transformJointIntoMimic`` (nq = nv = 0 of its own; joint ids, names and frames
   unchanged; the same model ``mimic=True`` builds when it accepts the document).

Units: ``multiplier`` is dimensionless (rad/rad, m/m, or m/rad between a prismatic follower
and a revolute leader), ``offset`` is in the follower's unit (rad or m).
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Mapping
from copy import deepcopy
from dataclasses import dataclass
from typing import Any
from xml.etree.ElementTree import Element, SubElement, tostring

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import TRUSTED, parse_literal_xml

#: Joint types a root leader may have (one configuration value each).
LEADER_TYPES = ("revolute", "prismatic")
#: Joint types a follower may have: a continuous follower (the Robotiq 2F-85's inner
#: knuckles) is no configuration entry, so it is built as an unbounded revolute joint.
FOLLOWER_TYPES = ("revolute", "prismatic", "continuous")
#: The ``<limit>`` a continuous follower is built with (Pinocchio drops a mimic's limits).
_FOLLOWER_LIMIT = {"lower": "-10000", "upper": "10000", "effort": "0", "velocity": "0"}
#: The prefix of the temporary joint names that set Pinocchio's order (never seen outside).
_ORDER_PREFIX = "denavit.order."


@dataclass(frozen=True, slots=True)
class MimicSpec:
    """One follower composed to its root leader: ``q = multiplier · q(leader) + offset``."""

    follower: str
    leader: str  # the root leader (an actuated joint)
    multiplier: float
    offset: float


def _number(mimic: Element, attr: str, default: float, joint: str, field: str) -> float:
    raw = mimic.get(attr)
    try:
        value = default if raw is None else float(raw)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise InvalidInputError(
            f"joint {joint!r}: <mimic {attr}={(raw or '')[:40]!r}> must be a finite number", field
        )
    return value


def mimic_specs(root: Element, field: str = "urdf") -> dict[str, MimicSpec]:
    """Every mimic follower of the URDF ``root`` (literal names), composed to its root
    leader (module doc, step 1), keyed by follower name; raises
    :class:`InvalidInputError` (``field``) naming the joint for an unknown, fixed or
    continuous leader, or a cycle."""
    types: dict[str, str] = {}
    direct: dict[str, tuple[str, float, float]] = {}
    for joint in root.findall("joint"):
        name = joint.get("name") or ""
        types[name] = joint.get("type") or ""
        mimic = joint.find("mimic")
        if mimic is None or types[name] == "fixed":
            continue
        leader = mimic.get("joint")
        if not leader:
            raise InvalidInputError(f"joint {name!r}: <mimic> names no joint", field)
        direct[name] = (
            leader,
            _number(mimic, "multiplier", 1.0, name, field),
            _number(mimic, "offset", 0.0, name, field),
        )
    specs: dict[str, MimicSpec] = {}
    for follower in direct:
        chain = [follower]
        multiplier, offset = 1.0, 0.0
        current = follower
        while current in direct:
            leader, m, o = direct[current]
            if leader not in types:
                raise InvalidInputError(
                    f"joint {current!r} mimics {leader!r}, which is not a joint of the URDF",
                    field,
                )
            if leader in chain:
                cycle = " → ".join(map(repr, [*chain[chain.index(leader) :], leader]))
                raise InvalidInputError(f"joint {follower!r}: mimic cycle {cycle}", field)
            # current = m·leader + o, and follower = multiplier·current + offset
            multiplier, offset = multiplier * m, multiplier * o + offset
            chain.append(leader)
            current = leader
        if types[follower] not in FOLLOWER_TYPES:
            raise InvalidInputError(
                f"joint {follower!r}: a {types[follower]} joint cannot be a mimic follower "
                f"(only {', '.join(FOLLOWER_TYPES)} joints)",
                field,
            )
        if types[current] not in LEADER_TYPES:
            raise InvalidInputError(
                f"joint {current!r}: a {types[current]} joint cannot be the mimic leader of "
                f"{follower!r} (only {' or '.join(LEADER_TYPES)} joints"
                + (
                    ": Pinocchio cannot mimic a continuous joint's (cos θ, sin θ) configuration)"
                    if types[current] == "continuous"
                    else ")"
                ),
                field,
            )
        if not (math.isfinite(multiplier) and math.isfinite(offset)):
            raise InvalidInputError(
                f"joint {follower!r}: its mimic chain composes to a non-finite multiplier "
                "or offset",
                field,
            )
        specs[follower] = MimicSpec(follower, current, multiplier, offset)
    return specs


def _joint_order(root: Element, specs: Mapping[str, MimicSpec], field: str) -> list[str] | None:
    """The depth-first joint order with every root leader before its followers (module
    doc, step 2), or ``None`` when Pinocchio's own order (siblings by name) already is."""
    children: dict[str, list[str]] = {}  # link -> joints under it
    child_of: dict[str, str] = {}  # joint -> its child link
    parent_joint: dict[str, str] = {}  # link -> the joint above it
    for joint in root.findall("joint"):
        name = joint.get("name") or ""
        parent = joint.find("parent")
        child = joint.find("child")
        if parent is None or child is None:
            continue
        children.setdefault(parent.get("link") or "", []).append(name)
        child_of[name] = child.get("link") or ""
        parent_joint[child_of[name]] = name

    parent_link = {j: link for link, js in children.items() for j in js}

    def path(joint: str) -> list[str]:
        """The joints from the root down to ``joint``."""
        out = [joint]
        while parent_link[out[-1]] in parent_joint and len(out) <= len(child_of):
            out.append(parent_joint[parent_link[out[-1]]])  # (bounded: no loop on a cycle)
        return out[::-1]

    before: dict[str, set[str]] = {}  # sibling joint -> siblings that must come before it
    for spec in specs.values():
        lead, follow = path(spec.leader), path(spec.follower)
        common = 0
        while common < min(len(lead), len(follow)) and lead[common] == follow[common]:
            common += 1
        if common == len(follow):  # the follower is on its leader's path to the root
            raise InvalidInputError(
                f"joint {spec.follower!r} mimics {spec.leader!r}, which it carries: "
                "a follower must not hold its leader",
                field,
            )
        if common == len(lead):  # the leader carries the follower: always first
            continue
        before.setdefault(follow[common], set()).add(lead[common])
    if all(all(b < j for b in bs) for j, bs in before.items()):
        return None
    order: list[str] = []

    def visit(link: str) -> None:
        siblings = sorted(children.get(link, ()))
        waiting = {j: {b for b in before.get(j, ()) if b in siblings} for j in siblings}
        ready = [j for j in siblings if not waiting[j]]
        heapq.heapify(ready)
        done = 0
        while ready:
            joint = heapq.heappop(ready)
            done += 1
            order.append(joint)
            visit(child_of[joint])
            for other in siblings:
                if joint in waiting[other]:
                    waiting[other].discard(joint)
                    if not waiting[other]:
                        heapq.heappush(ready, other)
        if done < len(siblings):
            stuck = sorted(j for j in siblings if waiting[j])
            raise InvalidInputError(
                "the mimic joints cannot be ordered (each leader before its followers, "
                f"depth first): the branches of joints {', '.join(map(repr, stuck))} each "
                "hold a leader of the other's followers",
                field,
            )

    links = {link for link in children} | set(child_of.values())
    for link in sorted(links - set(parent_joint)):
        visit(link)
    return order


def build_model(
    urdf_text: str, root: Element | None = None, field: str = "urdf", *, mimic: bool = True
) -> pin.Model:
    """The Pinocchio model of ``urdf_text`` with its mimic joints (module doc).

    Parameters
    ----------
    urdf_text
        The URDF document (already checked when it comes from a client).
    root
        The document parsed with literal names
        (:func:`app.kinematics.xmldoc.parse_literal_xml`), when the caller has it.
    field
        The request field a refusal names.
    mimic
        False: every follower stays a joint of its own (with its own configuration and
        velocity entry, a continuous follower an unbounded revolute joint), in the same
        order as with ``mimic=True``: the model the dynamics map wire values onto
        (:mod:`app.kinematics.dynamics`), since not every Pinocchio algorithm honours a
        mimic joint.

    Raises
    ------
    InvalidInputError
        ``field``, naming the joint, for a mimic Pinocchio cannot build (see
        :func:`mimic_specs`, :func:`_joint_order`).
    ValueError, RuntimeError
        Pinocchio's own refusals of the document.
    """
    if "<mimic" not in urdf_text:
        return pin.buildModelFromXML(urdf_text, mimic=False)
    if root is None:
        root = parse_literal_xml(urdf_text, field, TRUSTED)
    specs = mimic_specs(root, field)
    order = _joint_order(root, specs, field) if specs else None
    continuous = {
        j.get("name") or ""
        for j in root.findall("joint")
        if j.get("type") == "continuous" and j.get("name") in specs
    }
    if order is None and not continuous:
        model = pin.buildModelFromXML(urdf_text, mimic=False)
    else:
        model = _build_copy(root, order, continuous)
    if not mimic:
        return model
    for spec in sorted(specs.values(), key=lambda s: model.getJointId(s.follower)):
        model = pin.transformJointIntoMimic(
            model,
            model.getJointId(spec.leader),
            model.getJointId(spec.follower),
            spec.multiplier,
            spec.offset,
        )
    return model


def _build_copy(root: Element, order: list[str] | None, continuous: set[str]) -> pin.Model:
    """The model of a copy of ``root`` whose joints Pinocchio visits in ``order`` (when
    given: it visits siblings by name, so each joint is built under a temporary name that
    sorts by its rank, then given its own) and whose ``continuous`` followers are unbounded
    revolute joints (the same motion; a follower has no configuration of its own)."""
    copy = deepcopy(root)
    order = order or []
    width = len(str(len(order)))
    temporary = {name: f"{_ORDER_PREFIX}{rank:0{width}d}" for rank, name in enumerate(order)}
    for joint in copy.findall("joint"):
        name = joint.get("name") or ""
        if name in continuous:
            joint.set("type", "revolute")
            for limit in joint.findall("limit"):
                joint.remove(limit)
            SubElement(joint, "limit", _FOLLOWER_LIMIT)
        if name in temporary:
            joint.set("name", temporary[name])
        for mimic in joint.findall("mimic"):
            joint.remove(mimic)
    model = pin.buildModelFromXML(tostring(copy, encoding="unicode"), mimic=False)
    original = {tmp: name for name, tmp in temporary.items()}
    for jid in range(model.njoints):
        model.names[jid] = original.get(model.names[jid], model.names[jid])
    for fid in range(len(model.frames)):
        frame = model.frames[fid]
        if frame.name in original:
            model.frames[fid].name = original[frame.name]
    return model


def _floats(text: str | None, default: tuple[float, ...]) -> tuple[float, ...]:
    if not text:
        return default
    return tuple(float(v) for v in text.split())


def model_axis(jm: Any) -> tuple[float, float, float] | None:
    """The axis Pinocchio's joint model moves along (what FK uses), ``None`` if not 1-DoF.

    Read from the joint's motion subspace S (6×1, linear then angular): the angular part
    for a revolute joint, the linear part for a prismatic one. Pinocchio's URDF parser
    normalises the URDF ``<axis>`` (``0 0 2`` moves along ``0 0 1``).
    """
    if jm.nv != 1:
        return None
    S = np.asarray(jm.createData().S, dtype=float).reshape(-1)
    if S.shape != (6,):
        return None
    part = S[3:] if np.any(S[3:]) else S[:3]
    return (float(part[0]), float(part[1]), float(part[2]))


def urdf_joint_table(root: Element) -> dict[str, dict[str, Any]]:
    """Joint descriptions of a parsed URDF, keyed by joint name.

    ``root`` is the document read with literal (namespace-unaware) names, as Pinocchio's
    URDF parser reads it (:func:`app.kinematics.xmldoc.parse_literal_xml`).
    """
    joints: dict[str, dict[str, Any]] = {}
    for j in root.iter("joint"):
        name = j.get("name")
        if not name or j.find("parent") is None:  # transmission joints have no parent
            continue
        limit = j.find("limit")
        axis = j.find("axis")

        def lim(attr: str, limit: Any = limit) -> float | None:
            if limit is None or limit.get(attr) is None:
                return None
            return float(limit.get(attr))

        joints[name] = {
            "type": j.get("type"),
            "parent": j.find("parent").get("link"),
            "child": j.find("child").get("link"),
            "axis": _floats(axis.get("xyz") if axis is not None else None, (1.0, 0.0, 0.0)),
            "lower": lim("lower"),
            "upper": lim("upper"),
            "velocity": lim("velocity"),
            "effort": lim("effort"),
            "mimic": j.find("mimic") is not None,
        }
    return joints

"""SRDF semantics: planning groups, end effectors and named states, read and resolved.

MoveIt's SRDF names parts of a robot the URDF does not:

- ``<group name>``: a planning group, made of ``<chain base_link tip_link>`` (the joints on
  the tree path from ``base_link`` down to ``tip_link``), ``<joint name>`` (that joint),
  ``<link name>`` (the joint whose child is that link) and ``<group name>`` (a subgroup:
  everything it holds). A group's *configuration joints* are the actuated joints among
  these; fixed joints and mimic followers (which follow their leader) are not
  configuration entries and are left out.
- ``<end_effector name parent_link group [parent_group]>``: a tool (``group``) attached at
  ``parent_link`` to the arm group ``parent_group``.
- ``<group_state name group>`` with ``<joint name value>`` entries: a named configuration
  (e.g. ``ready``) of a group.

``disable_collisions`` is read by :mod:`app.kinematics.collision_pairs`.

A group's **tip** (its default frame) is, in order:

1. the ``tip_link`` of its own ``<chain>`` (the last one if it has several);
2. else the ``parent_link`` of the first end effector whose ``parent_group`` is the group,
   or, failing that, of the first end effector whose ``group`` is the group and whose
   ``parent_link`` is moved by one of the group's joints (SRDFs that name the arm as the
   end effector's group, as the example-robot-data Panda's does);
3. else the deepest of the group's links (most joints between it and the root; the first
   in URDF order on ties): the child links of its joints and its listed links, its
   subgroups' included;
4. ``None`` for a group with no link at all (the robot's default tip is used).

The robot's default tip from the SRDF (rule 1 of the default tip) is the ``parent_link`` of
the first ``<end_effector>`` in document order (:meth:`Semantics.default_tip`).

Everything here is pure: the URDF enters as the joint table of
:func:`app.kinematics.urdf_model.urdf_joint_table` (name → type, parent, child, limits,
mimic). :func:`resolve` raises :class:`InvalidInputError` naming the SRDF element for every
inconsistency, so uploads are checked with it (:mod:`app.robots.documents.srdf`) and models built
from checked documents resolve without error.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any
from xml.etree.ElementTree import Element

from app.kinematics.errors import InvalidInputError
from app.kinematics.xmldoc import TRUSTED, XmlLimits, parse_literal_xml

#: A group-state value may exceed a joint limit by this much (rad or m): SRDF files round.
STATE_LIMIT_TOLERANCE = 1e-6


@dataclass(frozen=True, slots=True)
class GroupSpec:
    """A ``<group>`` as written: its chains, joints, links and subgroups."""

    name: str
    chains: tuple[tuple[str, str], ...]
    joints: tuple[str, ...]
    links: tuple[str, ...]
    subgroups: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class EndEffector:
    """An ``<end_effector>``: the tool group ``group`` attached at ``parent_link``."""

    name: str
    parent_link: str
    group: str
    parent_group: str | None


@dataclass(frozen=True, slots=True)
class NamedState:
    """A ``<group_state>``: joint name → value (rad or m), for ``group`` (None if not given)."""

    name: str
    group: str | None
    joint_positions: dict[str, float]


@dataclass(frozen=True, slots=True)
class Semantics:
    """What an SRDF says about groups, end effectors and named states (empty without one)."""

    groups: tuple[GroupSpec, ...] = ()
    end_effectors: tuple[EndEffector, ...] = ()
    states: tuple[NamedState, ...] = ()

    def default_tip(self) -> str | None:
        """The robot's default tip per the SRDF: the first end effector's ``parent_link``."""
        return self.end_effectors[0].parent_link if self.end_effectors else None


@dataclass(frozen=True, slots=True)
class ResolvedGroup:
    """A group resolved against the URDF: every joint it holds (URDF order) and its tip."""

    name: str
    joints: tuple[str, ...]  # every joint (fixed and mimic included), URDF order
    tip: str | None


EMPTY = Semantics()


def _attr(el: Any, attr: str, where: str, field: str) -> str:
    value = el.get(attr)
    if not value:
        raise InvalidInputError(f"{where}: missing {attr}", field)
    return value


def parse_semantics(
    text: str | None, field: str = "srdf", limits: XmlLimits | None = TRUSTED
) -> Semantics:
    """The groups, end effectors and named states of an SRDF (``None``: empty).

    Parsed with literal names (:func:`~app.kinematics.xmldoc.parse_literal_xml`). Missing
    names and values that are not numbers raise :class:`InvalidInputError` naming the
    element; names are checked against the URDF by :func:`resolve`.
    """
    if not text:
        return EMPTY
    return semantics_of(parse_literal_xml(text, field, limits), field)


def semantics_of(root: Element, field: str = "srdf") -> Semantics:
    """The groups, end effectors and named states of a parsed SRDF (``root``, read with
    literal names); errors as :func:`parse_semantics`."""
    groups: list[GroupSpec] = []
    for g in root.findall("group"):
        name = _attr(g, "name", "<group>", field)
        where = f"<group name={name!r}>"
        chains = tuple(
            (
                _attr(c, "base_link", f"{where}: <chain>", field),
                _attr(c, "tip_link", f"{where}: <chain>", field),
            )
            for c in g.findall("chain")
        )
        groups.append(
            GroupSpec(
                name,
                chains,
                tuple(_attr(j, "name", f"{where}: <joint>", field) for j in g.findall("joint")),
                tuple(_attr(x, "name", f"{where}: <link>", field) for x in g.findall("link")),
                tuple(_attr(s, "name", f"{where}: <group>", field) for s in g.findall("group")),
            )
        )
    effectors = []
    for e in root.findall("end_effector"):
        name = _attr(e, "name", "<end_effector>", field)
        where = f"<end_effector name={name!r}>"
        effectors.append(
            EndEffector(
                name,
                _attr(e, "parent_link", where, field),
                _attr(e, "group", where, field),
                e.get("parent_group") or None,
            )
        )
    states = []
    for s in root.findall("group_state"):
        name = _attr(s, "name", "<group_state>", field)
        where = f"<group_state name={name!r}>"
        values: dict[str, float] = {}
        for j in s.findall("joint"):
            joint = _attr(j, "name", f"{where}: <joint>", field)
            raw = _attr(j, "value", f"{where}: <joint name={joint!r}>", field)
            try:
                value = float(raw)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                raise InvalidInputError(
                    f"{where}: <joint name={joint!r}>: value {raw[:40]!r} is not one finite number",
                    field,
                )
            values[joint] = value
        states.append(NamedState(name, s.get("group") or None, values))
    return Semantics(tuple(groups), tuple(effectors), tuple(states))


def resolve(
    sem: Semantics,
    joints: Mapping[str, Mapping[str, Any]],
    field: str = "srdf",
    *,
    strict: bool = True,
) -> dict[str, ResolvedGroup]:
    """Each group's joints and tip, checked against the URDF's joint table.

    Parameters
    ----------
    sem
        The SRDF's semantics (:func:`parse_semantics`).
    joints
        The URDF's joints (:func:`app.kinematics.urdf_model.urdf_joint_table`): name →
        ``type``, ``parent``, ``child``, ``lower``, ``upper``, ``mimic``.
    strict
        Raise on the first inconsistency (uploads). Models built from the catalog's SRDFs
        (never checked on upload; some name a missing link or a state beyond the limits)
        resolve with ``strict=False``: a bad element is skipped, a group in a subgroup cycle
        left out (and group states are filtered by :func:`usable_states`).

    Raises
    ------
    InvalidInputError
        Naming the SRDF element (field ``srdf``): a duplicate group name, an unknown joint,
        link or subgroup, a chain whose base is not above its tip, subgroups that form a
        cycle, an end effector naming an unknown link or group, a group state of an unknown
        group, naming an unknown or fixed joint, or a value beyond the joint's limits.
    """
    parent_joint = {j["child"]: name for name, j in joints.items()}
    links = set(parent_joint) | {j["parent"] for j in joints.values()}
    order = {name: i for i, name in enumerate(joints)}

    def bad(message: str) -> None:
        if strict:
            raise InvalidInputError(message, field)

    specs: dict[str, GroupSpec] = {}
    for g in sem.groups:
        if g.name in specs:
            bad(f"two <group name={g.name!r}> elements")
            continue
        specs[g.name] = g

    def depth(link: str) -> int:
        d = 0
        while link in parent_joint:
            link = joints[parent_joint[link]]["parent"]
            d += 1
        return d

    def chain_joints(where: str, base: str, tip: str) -> list[str] | None:
        for attr, link in (("base_link", base), ("tip_link", tip)):
            if link not in links:
                return bad(f"{where}: {attr} {link!r}: no such link in the URDF")
        path: list[str] = []
        link = tip
        while link != base:
            if link not in parent_joint:
                return bad(f"{where}: base_link {base!r} is not above tip_link {tip!r} in the tree")
            path.append(parent_joint[link])
            link = joints[path[-1]]["parent"]
        return path[::-1]

    own: dict[str, tuple[set[str], set[str]]] = {}  # group → (joints, links), subgroups aside
    chain_tip: dict[str, str] = {}
    for g in specs.values():
        where = f"<group name={g.name!r}>"
        gj: set[str] = set()
        gl: set[str] = set()
        for base, tip in g.chains:
            path = chain_joints(f"{where}: <chain>", base, tip)
            if path is not None:
                gj.update(path)
                gl.update(joints[j]["child"] for j in path)
                chain_tip[g.name] = tip
        for j in g.joints:
            if j not in joints:
                bad(f"{where}: <joint name={j!r}>: no such joint in the URDF")
                continue
            gj.add(j)
            gl.add(joints[j]["child"])
        for link in g.links:
            if link not in links:
                bad(f"{where}: <link name={link!r}>: no such link in the URDF")
                continue
            gl.add(link)
            if link in parent_joint:
                gj.add(parent_joint[link])
        for sub in g.subgroups:
            if sub not in specs:
                bad(
                    f"{where}: subgroup <group name={sub!r}>: no such group in the SRDF "
                    f"(groups: {', '.join(specs) or 'none'})"
                )
        own[g.name] = (gj, gl)

    closed: dict[str, tuple[set[str], set[str]] | None] = {}

    def close(name: str, stack: tuple[str, ...]) -> tuple[set[str], set[str]] | None:
        if name in stack:
            cycle = " → ".join([*stack[stack.index(name) :], name])
            bad(f"<group name={name!r}>: subgroups form a cycle ({cycle})")
            return None
        if name not in closed:
            gj, gl = set(own[name][0]), set(own[name][1])
            result: tuple[set[str], set[str]] | None = (gj, gl)
            for sub in specs[name].subgroups:
                part = close(sub, (*stack, name)) if sub in specs else (set(), set())
                if part is None:
                    result = None
                    break
                gj |= part[0]
                gl |= part[1]
            closed[name] = result
        return closed[name]

    for name in specs:
        close(name, ())
    if strict:
        _check_effectors(sem, specs, links, field)
        _check_states(sem, specs, joints, field)

    def moved_by(link: str, group_joints: set[str]) -> bool:
        while link in parent_joint:
            j = parent_joint[link]
            if j in group_joints and joints[j]["type"] != "fixed":
                return True
            link = joints[j]["parent"]
        return False

    out: dict[str, ResolvedGroup] = {}
    for name in specs:
        members = closed[name]
        if members is None:
            continue
        gj, gl = members
        tip: str | None = chain_tip.get(name)
        effectors = [e for e in sem.end_effectors if e.parent_link in links]
        if tip is None:
            tip = next((e.parent_link for e in effectors if e.parent_group == name), None)
        if tip is None:
            tip = next(
                (
                    e.parent_link
                    for e in effectors
                    if e.group == name and moved_by(e.parent_link, gj)
                ),
                None,
            )
        if tip is None and gl:
            rank = {link: order.get(parent_joint.get(link, ""), -1) for link in gl}
            tip = max(gl, key=lambda link: (depth(link), -rank[link]))
        out[name] = ResolvedGroup(name, tuple(sorted(gj, key=order.__getitem__)), tip)
    return out


def _check_effectors(
    sem: Semantics, specs: Mapping[str, GroupSpec], links: set[str], field: str
) -> None:
    for e in sem.end_effectors:
        where = f"<end_effector name={e.name!r}>"
        if e.parent_link not in links:
            raise InvalidInputError(
                f"{where}: parent_link {e.parent_link!r}: no such link in the URDF", field
            )
        for attr, group in (("group", e.group), ("parent_group", e.parent_group)):
            if group is not None and group not in specs:
                raise InvalidInputError(
                    f"{where}: {attr} {group!r}: no such group in the SRDF "
                    f"(groups: {', '.join(specs) or 'none'})",
                    field,
                )


def _state_problem(
    s: NamedState,
    specs: Mapping[str, GroupSpec],
    joints: Mapping[str, Mapping[str, Any]],
) -> str | None:
    """Why a group state cannot be used (unknown group or joint, fixed joint, value beyond
    the joint's limits), or ``None``."""
    where = f"<group_state name={s.name!r}>"
    if s.group is not None and s.group not in specs:
        return (
            f"{where}: group {s.group!r}: no such group in the SRDF "
            f"(groups: {', '.join(specs) or 'none'})"
        )
    for name, value in s.joint_positions.items():
        at = f"{where}: <joint name={name!r}>"
        j = joints.get(name)
        if j is None:
            return f"{at}: no such joint in the URDF"
        if j["type"] == "fixed":
            return f"{at}: a fixed joint has no value"
        lo, hi = j.get("lower"), j.get("upper")
        if j["type"] == "continuous" or lo is None or hi is None:
            continue
        if not lo - STATE_LIMIT_TOLERANCE <= value <= hi + STATE_LIMIT_TOLERANCE:
            return f"{at}: value {value:g} is beyond the joint's limits [{lo:g}, {hi:g}]"
    return None


def usable_states(
    sem: Semantics, joints: Mapping[str, Mapping[str, Any]]
) -> tuple[NamedState, ...]:
    """The group states that pass the upload checks (catalog SRDFs, never checked on upload,
    may hold a state beyond the joint limits: it is left out)."""
    specs = {g.name: g for g in sem.groups}
    return tuple(s for s in sem.states if _state_problem(s, specs, joints) is None)


def _check_states(
    sem: Semantics,
    specs: Mapping[str, GroupSpec],
    joints: Mapping[str, Mapping[str, Any]],
    field: str,
) -> None:
    seen: set[tuple[str, str | None]] = set()
    for s in sem.states:
        if (s.name, s.group) in seen:
            raise InvalidInputError(
                f"<group_state name={s.name!r}>: given twice for group {s.group!r}", field
            )
        seen.add((s.name, s.group))
        problem = _state_problem(s, specs, joints)
        if problem is not None:
            raise InvalidInputError(problem, field)

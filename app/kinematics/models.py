"""Robot models: a Pinocchio model plus what the wire needs to talk about it.

A :class:`RobotModel` wraps one ``pinocchio.Model`` built from URDF text and adds

- the actuated joints in Pinocchio's order, with their URDF description (parent and child
  link, axis, limits), skipping mimic joints, which follow their leader;
- the conversion between *wire* configurations (one value per actuated joint, a continuous
  joint as one angle in radians) and Pinocchio configurations (a continuous joint is stored
  as (cos θ, sin θ), so ``nq != nv``);
- frame lookup by name (links first, then fixed frames, then joint frames);
- a per-thread ``pinocchio.Data``: Data is scratch space and is never shared between
  threads, so concurrent requests cannot corrupt each other.

Everything here is plain Python: no FastAPI.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pinocchio as pin

from app.kinematics.angles import wrap_angle
from app.kinematics.errors import InvalidInputError, UnknownNameError
from app.kinematics.lazy import MISSING, LazyKey, T
from app.kinematics.meshes import MeshLimits
from app.kinematics.mimic import MimicJoint, check_followers, mimic_joints, with_leaders
from app.kinematics.semantics import parse_semantics
from app.kinematics.tip import bare_links, default_tip
from app.kinematics.urdf_model import build_model, model_axis, urdf_joint_table
from app.kinematics.xmldoc import TRUSTED, parse_literal_xml

#: Frame types in the order a name is resolved when several frames share it.
_FRAME_PRIORITY = {
    pin.FrameType.BODY: 0,
    pin.FrameType.FIXED_JOINT: 1,
    pin.FrameType.JOINT: 2,
    pin.FrameType.OP_FRAME: 3,
    pin.FrameType.SENSOR: 4,
}
_FRAME_KIND = {
    pin.FrameType.BODY: "link",
    pin.FrameType.FIXED_JOINT: "fixed",
    pin.FrameType.JOINT: "joint",
    pin.FrameType.OP_FRAME: "operational",
    pin.FrameType.SENSOR: "sensor",
}


#: Largest |joint value| (rad or m) accepted wherever a configuration enters: FK, batches,
#: Jacobian, velocity, analysis, statics, collisions, IK seeds. float64 represents |q| ≤ 1e4
#: to within 1.8e-12 (its spacing there), the precision the service answers to; beyond, the
#: spacing grows with |q| (at 1e300 it is ~1e284, so sin and cos of the value, and any pose
#: computed from it, carry no information) and no real joint travels 10 km or 1600 turns.
MAX_JOINT_VALUE = 1e4
#: Largest |coordinate| (m) of a target position (IK targets, reachability queries): 1000 km,
#: where float64's spacing is still 1.2e-10 m; beyond, positions only lose precision.
MAX_POSITION = 1e6


def check_bounded(values: Any, field: str, bound: float, unit: str) -> None:
    """Raise :class:`InvalidInputError` naming the first non-finite value of ``values``, or
    the first beyond ±``bound``, as ``field.i`` (1-D) or ``field.i.j`` (2-D)."""
    arr = np.asarray(values, dtype=float)
    if arr.ndim == 1 and arr.shape[0] <= 64:
        # One configuration (the hot path of every request): Python floats beat NumPy's
        # per-call overhead; a comparison with NaN is False, so NaN goes on to the report.
        if all(-bound <= v <= bound for v in arr.tolist()):
            return
    ok = np.abs(arr) <= bound  # False for NaN too
    if ok.all():
        return
    where = tuple(int(i) for i in np.argwhere(~ok)[0])
    value = float(arr[where])
    path = ".".join([field, *map(str, where)])
    if not math.isfinite(value):
        raise InvalidInputError("must be a finite number", path)
    raise InvalidInputError(f"must lie within ±{bound:g} {unit} (got {value:g})", path)


def check_joint_values(values: Any, field: str) -> None:
    """Refuse (:class:`InvalidInputError`, naming ``field.i`` or ``field.i.j``) joint values
    that are not finite or beyond ±:data:`MAX_JOINT_VALUE` (rad or m)."""
    check_bounded(values, field, MAX_JOINT_VALUE, "(rad or m)")


def check_joint_value(value: float, field: str) -> float:
    """One joint value (e.g. ``joint_positions.<name>``), checked as :func:`check_joint_values`."""
    if not math.isfinite(value):
        raise InvalidInputError("must be a finite number", field)
    if abs(value) > MAX_JOINT_VALUE:
        raise InvalidInputError(
            f"must lie within ±{MAX_JOINT_VALUE:g} (rad or m) (got {value:g})", field
        )
    return float(value)


@dataclass(frozen=True, slots=True)
class Joint:
    """One actuated joint, as the URDF describes it.

    Limits are SI (rad or m); ``lower``/``upper`` are ``None`` for a continuous joint.
    ``axis`` is the unit axis Pinocchio moves the joint along (the URDF ``<axis>``
    normalised), expressed in the joint frame.
    """

    name: str
    type: str  # revolute | prismatic | continuous
    parent: str
    child: str
    axis: tuple[float, float, float]
    lower: float | None
    upper: float | None
    velocity: float | None
    effort: float | None
    continuous: bool
    index: int  # position in wire configurations
    pin_id: int  # Pinocchio joint id
    idx_q: int  # first index in Pinocchio's q
    idx_v: int  # index in Pinocchio's v (and Jacobian column)


@dataclass(frozen=True, slots=True)
class Frame:
    """A named frame: a link, a fixed frame (URDF fixed joint) or a joint frame."""

    name: str
    kind: str
    pin_id: int
    parent_joint: str | None


class RobotModel:
    """A robot the service can answer for.

    Parameters
    ----------
    robot_id
        Identifier used in URLs.
    urdf_text
        The URDF document.
    name, source
        Human-readable name and origin (``example-robot-data``, ``dh``, ``upload``).
    package_dirs
        Directories ``package://`` mesh URIs resolve against.
    srdf_text
        Optional SRDF: disabled collision pairs (collision module), groups, end effectors
        and named states (:attr:`semantics`, :mod:`app.kinematics.groups`).
    ee_frame
        Default end-effector frame; when ``None``, the ``parent_link`` of the SRDF's first
        ``<end_effector>``, else the tip of the longest serial chain that is not a gripper
        finger (:func:`app.kinematics.tip.default_tip`).
    """

    def __init__(
        self,
        robot_id: str,
        urdf_text: str,
        *,
        name: str | None = None,
        source: str = "upload",
        package_dirs: Sequence[str] = (),
        srdf_text: str | None = None,
        ee_frame: str | None = None,
        description: str = "",
    ) -> None:
        self.id = robot_id
        self.name = name or robot_id
        self.source = source
        self.description = description
        self.urdf_text = urdf_text
        self.srdf_text = srdf_text
        self.package_dirs = list(package_dirs)
        root = parse_literal_xml(urdf_text, "urdf", TRUSTED)  # the one parse of the URDF here
        self.model: pin.Model = build_model(urdf_text, root)  # mimic joints as ROS reads them
        self._local = threading.local()
        # reentrant: a companion's build may ask for another (an IK chain, its length scale)
        self._lock = threading.RLock()
        self._extras: dict[str, object] = {}  # lazily built companions (:meth:`lazy`)
        self.mesh_limits = MeshLimits()  # bounds on its collision meshes (the registry's)

        urdf_joints = urdf_joint_table(root)
        #: The URDF's joints (fixed and mimic included), name → description.
        self.urdf_joints = urdf_joints
        #: The SRDF's groups, end effectors and named states (empty without an SRDF).
        self.semantics = parse_semantics(srdf_text)
        self.has_collision_geometry = "<collision" in urdf_text
        self.joints: list[Joint] = []
        for jid in range(1, self.model.njoints):
            jm = self.model.joints[jid]
            if jm.shortname() == "JointModelMimic":
                continue
            jname = self.model.names[jid]
            desc = urdf_joints.get(jname, {})
            continuous = jm.nq == 2 and jm.nv == 1
            jtype = desc.get("type") or ("continuous" if continuous else "revolute")
            if continuous:
                jtype = "continuous"
            lower = upper = None
            if not continuous:
                lower = float(self.model.lowerPositionLimit[jm.idx_q])
                upper = float(self.model.upperPositionLimit[jm.idx_q])
            vel = float(self.model.velocityLimit[jm.idx_v])
            eff = float(self.model.effortLimit[jm.idx_v])
            self.joints.append(
                Joint(
                    name=jname,
                    type=jtype,
                    parent=desc.get("parent", ""),
                    child=desc.get("child", ""),
                    axis=model_axis(jm) or tuple(desc.get("axis", (1.0, 0.0, 0.0))),
                    lower=lower,
                    upper=upper,
                    velocity=vel if math.isfinite(vel) else None,
                    effort=eff if math.isfinite(eff) else None,
                    continuous=continuous,
                    index=len(self.joints),
                    pin_id=jid,
                    idx_q=jm.idx_q,
                    idx_v=jm.idx_v,
                )
            )
        self.joint_names = [j.name for j in self.joints]
        self._joint_index, self.n = {j.name: j.index for j in self.joints}, len(self.joints)
        #: Mimic followers (not configuration entries; :mod:`app.kinematics.mimic`).
        self.mimic_joints: list[MimicJoint] = mimic_joints(
            self.model,
            {j.pin_id: j.index for j in self.joints},
            {name: d.get("type") or "" for name, d in urdf_joints.items()},
        )
        self._mimic_by_name = {m.name: m for m in self.mimic_joints}

        cont = np.array([j.continuous for j in self.joints], dtype=bool)
        self._cont_mask = cont
        self._plain_wire = np.flatnonzero(~cont)
        self._plain_q = np.array([j.idx_q for j in self.joints if not j.continuous], dtype=int)
        self._cont_wire = np.flatnonzero(cont)
        self._cont_wire.flags.writeable = False
        self._cont_q = np.array([j.idx_q for j in self.joints if j.continuous], dtype=int)
        #: Columns of Pinocchio's nv-wide Jacobian that belong to the wire joints.
        self.v_index = np.array([j.idx_v for j in self.joints], dtype=int)
        self.has_continuous = bool(cont.any())
        self.lower = np.array([-np.inf if j.lower is None else j.lower for j in self.joints])
        self.upper = np.array([np.inf if j.upper is None else j.upper for j in self.joints])

        self.frames: list[Frame] = []
        best: dict[str, int] = {}
        for fid, f in enumerate(self.model.frames):
            if f.name == "universe":
                continue
            prev = best.get(f.name)
            if (
                prev is None
                or _FRAME_PRIORITY[f.type] < _FRAME_PRIORITY[self.model.frames[prev].type]
            ):
                best[f.name] = fid
        for fname, fid in best.items():
            f = self.model.frames[fid]
            pj = self.model.names[f.parentJoint] if f.parentJoint > 0 else None
            self.frames.append(Frame(fname, _FRAME_KIND[f.type], fid, pj))
        self._frame_ids = best
        self.frame_names = [f.name for f in self.frames]
        srdf_tip = self.semantics.default_tip()
        if ee_frame is None and srdf_tip in self._frame_ids:
            ee_frame = srdf_tip  # rule 1 of the default tip: the SRDF's end effector
        self.ee_frame = ee_frame if ee_frame is not None else self._default_tip(bare_links(root))
        self.frame_id(self.ee_frame, field="ee_frame")

    def _default_tip(self, bare: set[str]) -> str:
        """The tip of the longest serial chain that is not a gripper finger (see
        :mod:`app.kinematics.tip`; ``bare``: the names of the links without geometry)."""
        links = [f for f in self.frames if f.kind == "link"] or self.frames
        fid = default_tip(
            self.model, [f.pin_id for f in links], [f.pin_id for f in links if f.name in bare]
        )
        return self.model.frames[fid].name

    def frame_id(self, name: str, field: str = "frame") -> int:
        """Pinocchio frame id of ``name``; raises :class:`UnknownNameError`."""
        try:
            return self._frame_ids[name]
        except KeyError:
            raise UnknownNameError("frame", name, field, self.frame_names) from None

    def joint_index(self, name: str, field: str = "joint_positions") -> int:
        """Wire index of joint ``name``; raises :class:`UnknownNameError`."""
        try:
            return self._joint_index[name]
        except KeyError:
            raise UnknownNameError(
                "joint", name, field, self.joint_names + list(self._mimic_by_name), list_known=True
            ) from None

    def supporting_joints(self, frame: str, among: np.ndarray | None = None) -> np.ndarray:
        """Wire indices of the joints that move ``frame``, in wire order: its kinematic chain,
        plus the leader of every mimic follower on it (the leader of the Panda's
        ``panda_finger_joint2`` moves ``panda_rightfinger``; :func:`.mimic.with_leaders`);
        only those among the wire indices ``among`` (e.g. a planning group's) when given."""
        parent = self.model.frames[self.frame_id(frame)].parentJoint
        support = with_leaders(self.model.supports[parent], self.mimic_joints)
        cols = np.array([j.index for j in self.joints if j.pin_id in support], dtype=int)
        return cols if among is None else cols[np.isin(cols, among)]

    @property
    def data(self) -> pin.Data:
        """This thread's Pinocchio Data for the model (created on first use)."""
        d = getattr(self._local, "data", None)
        if d is None:
            d = self._local.data = self.model.createData()
        return d

    def neutral(self) -> np.ndarray:
        """Neutral configuration on the wire: 0 where allowed, else the nearest limit."""
        return np.clip(np.zeros(self.n), self.lower, self.upper)

    def mid_range(self) -> np.ndarray:
        """Middle of the joint limits (0 for continuous joints), within ±MAX_JOINT_VALUE."""
        lo = np.where(np.isfinite(self.lower), self.lower, 0.0)
        hi = np.where(np.isfinite(self.upper), self.upper, 0.0)
        return np.clip(0.5 * lo + 0.5 * hi, -MAX_JOINT_VALUE, MAX_JOINT_VALUE)

    @property
    def continuous(self) -> np.ndarray:
        """Wire indices of the continuous joints (read-only)."""
        return self._cont_wire

    def wrap(self, q: np.ndarray) -> np.ndarray:
        """A copy of wire configuration(s) ``q`` (…, n) with the continuous joints' angles
        wrapped to (−π, π] (:func:`app.kinematics.angles.wrap_angle`)."""
        out = np.array(q, dtype=float)
        if self.has_continuous:
            out[..., self._cont_wire] = wrap_angle(out[..., self._cont_wire])
        return out

    def difference(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``b − a`` on the wire, continuous joints the short way round the circle (in
        (−π, π]): ``a + difference(a, b)`` is ``b`` up to whole turns."""
        d = np.asarray(b, dtype=float) - np.asarray(a, dtype=float)
        if self.has_continuous:
            d[..., self._cont_wire] = wrap_angle(d[..., self._cont_wire])
        return d

    def unwrap_path(self, qs: np.ndarray) -> np.ndarray:
        """A copy of the path ``qs`` (N, n) whose continuous joints never jump by more than
        π between points (``np.unwrap``): a crossing of ±π is a small move, not a turn."""
        out = np.array(qs, dtype=float)
        if self.has_continuous:
            out[:, self._cont_wire] = np.unwrap(out[:, self._cont_wire], axis=0)
        return out

    def to_pin(self, q: np.ndarray) -> np.ndarray:
        """Wire configuration (n,) → Pinocchio configuration (nq,)."""
        out = np.empty(self.model.nq)
        out[self._plain_q] = q[self._plain_wire]
        if self.has_continuous:
            th = q[self._cont_wire]
            out[self._cont_q] = np.cos(th)
            out[self._cont_q + 1] = np.sin(th)
        return out

    def to_pin_batch(self, qs: np.ndarray) -> np.ndarray:
        """Wire configurations (N, n) → Pinocchio configurations (N, nq)."""
        out = np.empty((qs.shape[0], self.model.nq))
        out[:, self._plain_q] = qs[:, self._plain_wire]
        if self.has_continuous:
            th = qs[:, self._cont_wire]
            out[:, self._cont_q] = np.cos(th)
            out[:, self._cont_q + 1] = np.sin(th)
        return out

    def from_pin(self, q_pin: np.ndarray) -> np.ndarray:
        """Pinocchio configuration (nq,) → wire configuration (n,); continuous joints' angles
        in (−π, π] (:func:`app.kinematics.angles.wrap_angle`)."""
        out = np.empty(self.n)
        out[self._plain_wire] = q_pin[self._plain_q]
        if self.has_continuous:
            # arctan2 gives −π for sin = −0.0 or −1e-16: wrapped to (−π, π] like every angle
            th = np.arctan2(q_pin[self._cont_q + 1], q_pin[self._cont_q])
            out[self._cont_wire] = wrap_angle(th)
        return out

    def configuration(
        self,
        q: Sequence[float] | np.ndarray | None = None,
        joint_positions: Mapping[str, float] | None = None,
        *,
        field: str = "q",
        map_field: str = "joint_positions",
    ) -> np.ndarray:
        """A validated wire configuration from a list or a name → value map.

        Joints missing from ``joint_positions`` take their neutral value; the map may name
        mimic followers too (:meth:`apply_joint_map`). Giving both forms, a list of the wrong
        length, or a value that is not finite or beyond ±:data:`MAX_JOINT_VALUE` raises
        :class:`InvalidInputError` naming the value (``q.3``, ``joint_positions.<name>``).
        """
        if q is not None and joint_positions is not None:
            raise InvalidInputError(f"give either {field} or {map_field}, not both", field)
        if q is None:
            return self.apply_joint_map(self.neutral(), joint_positions or {}, map_field)
        arr = np.asarray(q, dtype=float)
        if arr.ndim != 1 or arr.shape[0] != self.n:
            raise InvalidInputError(
                f"expected {self.n} values (one per joint: {', '.join(self.joint_names)}), "
                f"got {arr.shape[0] if arr.ndim == 1 else arr.shape}",
                field,
            )
        check_joint_values(arr, field)
        return arr

    def apply_joint_map(
        self, out: np.ndarray, values: Mapping[str, float], field: str
    ) -> np.ndarray:
        """Set ``out`` (a wire configuration, changed in place and returned) from a joint
        name → value map (rad or m), as a ROS ``JointState`` gives it.

        The map may name mimic followers: a follower's value is not set but checked against
        ``multiplier × leader + offset``, the leader's value being the one this map gives,
        or ``out``'s when the map does not name the leader (:func:`.mimic.check_followers`,
        422 naming ``<field>.<follower>`` with the expected value). An unknown name raises
        :class:`UnknownNameError` (``<field>.<name>``) with the closest joint names.
        """
        followers: dict[str, float] = {}
        for name, value in values.items():
            path = f"{field}.{name}"
            if name in self._mimic_by_name:
                followers[name] = check_joint_value(value, path)
            else:
                out[self.joint_index(name, field=path)] = check_joint_value(value, path)
        check_followers(self._mimic_by_name, followers, out, field)
        return out

    def limit_violations(self, q: np.ndarray, tol: float = 1e-12) -> list[str]:
        """Names of the joints whose value lies outside [lower, upper] (beyond ``tol``)."""
        bad = (q < self.lower - tol) | (q > self.upper + tol)
        return [self.joint_names[i] for i in np.flatnonzero(bad)]

    def describe_joint(self, joint: Joint) -> dict[str, Any]:
        """The wire description of a joint."""
        return {
            "name": joint.name,
            "type": joint.type,
            "parent": joint.parent,
            "child": joint.child,
            "axis": list(joint.axis),
            "limits": {
                "lower": joint.lower,
                "upper": joint.upper,
                "velocity": joint.velocity,
                "effort": joint.effort,
            },
            "continuous": joint.continuous,
        }

    def lazy(self, key: LazyKey[T], build: Callable[[RobotModel], T]) -> T:
        """The companion object of ``key`` (e.g. the collision model, an IK chain), built by
        ``build(self)`` once per model under a lock, then cached; its type is checked against
        ``key.type`` when built (TypeError: a bug, two builders for one key)."""
        value = self._extras.get(key.name, MISSING)
        if value is MISSING:
            with self._lock:
                value = self._extras.get(key.name, MISSING)
                if value is MISSING:
                    value = build(self)
                    if not (value is None or isinstance(value, key.type)):
                        raise TypeError(
                            f"lazy {key.name!r}: built a {type(value).__name__}, "
                            f"expected {key.type.__name__}"
                        )
                    self._extras[key.name] = value
        return value  # type: ignore[return-value]

    def cached(self, key: LazyKey[T]) -> T | None:
        """The companion object of ``key`` if built already, else None (nothing is built)."""
        value = self._extras.get(key.name)
        return value  # type: ignore[return-value]


@dataclass
class RobotSummary:
    """What GET /robots lists without loading the model."""

    id: str
    name: str
    source: str
    joints: int
    description: str = ""
    extra: dict[str, Any] = field(default_factory=dict)

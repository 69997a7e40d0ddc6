"""Rigid-body dynamics of a robot from its URDF inertias: inverse dynamics and its parts.

Equations of motion (joint space, wire order, SI units)
------------------------------------------------------
    τ = M(q) q̈ + C(q, q̇) q̇ + g(q) + J_f(q)ᵀ F

- ``τ`` (N·m or N): the joint torques (forces, prismatic joints) the motors apply;
- ``M(q)`` (kg·m², kg): the joint-space mass (inertia) matrix, symmetric positive definite,
  computed by the composite rigid-body algorithm (CRBA);
- ``C(q, q̇) q̇``: Coriolis and centrifugal torques; ``C`` is Pinocchio's Christoffel-symbol
  Coriolis matrix, the one for which ``Ṁ − 2C`` is skew-symmetric;
- ``g(q) = ∂V/∂q``: the torques that hold the arm still against gravity (``V`` its
  potential energy, gravity ``[0, 0, −GRAVITY]`` m/s² in the root (world) frame);
- ``J_fᵀ F``: the torques by which a frame exerts the wrench ``F = [f; m]`` on its
  environment (statics: :func:`app.kinematics.analysis.torques_from_wrench`).

``τ`` itself comes from the recursive Newton–Euler algorithm (RNEA), ``g`` from RNEA at
``q̇ = q̈ = 0`` and ``C q̇`` from RNEA at ``q̈ = 0`` minus ``g``.

Mimic followers are no wire joints: the dynamics run on the model whose followers are
joints of their own (:func:`app.kinematics.urdf_model.build_model` with ``mimic=False``)
with ``q_full = G q + c`` (``G``: 1 for a wire joint, the multiplier from a follower to its
leader; ``c``: the offsets), so by virtual work ``τ = Gᵀ τ_full(q_full, G q̇, G q̈)``,
``M = Gᵀ M_full G`` and ``C = Gᵀ C_full G`` (``G`` is constant). A leader's torque is the
torque of its motor driving itself and its followers.

Payload: a rigid body of mass ``m`` (kg) whose centre of mass ``c`` (m) and rotational
inertia ``I_c`` (kg·m², about ``c``) are given in the axes of a frame ``f``. Its spatial
inertia is added to the body of ``f``'s joint: ``Y_joint += ᶦX_f* · Y(m, c, I_c)``
(Pinocchio ``frame.placement.act(Inertia(m, c, I_c))``), so every term above includes it.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.analysis import torques_from_wrench
from app.kinematics.errors import InvalidInputError, MissingInertiaError
from app.kinematics.jacobian import Reference
from app.kinematics.lazy import LazyKey
from app.kinematics.models import RobotModel
from app.kinematics.urdf_model import build_model

#: Standard gravity (m/s²), Pinocchio's default: gravity is [0, 0, −GRAVITY] in the world.
GRAVITY = 9.81
#: Largest payload mass (kg) accepted: 1000 t, beyond any arm.
MAX_PAYLOAD_MASS = 1e6
#: Largest |coordinate| (m) of a payload's centre of mass in its frame.
MAX_PAYLOAD_OFFSET = 1e3
#: Largest |entry| (kg·m²) of a payload's rotational inertia.
MAX_PAYLOAD_INERTIA = 1e9
#: Largest |joint velocity| (rad/s or m/s) and |joint acceleration| (rad/s², m/s²) accepted.
MAX_JOINT_RATE = 1e6
#: A body lighter than this (kg) whose rotational inertia is below it too (kg·m²) carries no
#: inertia: its URDF ``<inertial>`` is missing or zero.
MIN_BODY_MASS = 1e-12
#: Tolerance (kg·m², relative to the largest entry) of the inertia checks: symmetry,
#: positive semi-definiteness, the triangle inequality of the principal moments.
INERTIA_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Payload:
    """A rigid load fixed to a frame (module doc): mass (kg), centre of mass (m, in the
    frame's axes) and rotational inertia about it (3×3, kg·m², frame axes)."""

    mass: float
    frame: str
    com: np.ndarray
    inertia: np.ndarray

    def to_json(self) -> dict[str, object]:
        """The wire echo: mass, frame, com and the inertia's six URDF entries."""
        i = self.inertia
        return {
            "mass": self.mass,
            "frame": self.frame,
            "com": self.com.tolist(),
            "inertia": [i[0, 0], i[0, 1], i[0, 2], i[1, 1], i[1, 2], i[2, 2]],
        }


def payload(
    robot: RobotModel,
    mass: float,
    frame: str | None = None,
    com: object = (0.0, 0.0, 0.0),
    inertia: object = None,
    field: str = "payload",
) -> Payload:
    """A checked :class:`Payload` at ``frame`` (the robot's tip by default).

    ``inertia``: the six URDF entries ``[ixx, ixy, ixz, iyy, iyz, izz]`` or a 3×3 matrix,
    about the centre of mass in the frame's axes; None for a point mass. Raises
    :class:`InvalidInputError` naming ``field.mass``, ``field.com.i``, ``field.inertia``
    (not finite, negative mass, out of bounds, not symmetric, not positive semi-definite,
    principal moments breaking the triangle inequality).
    """
    frame = robot.ee_frame if frame is None else frame
    robot.frame_id(frame, field=f"{field}.frame")
    m = float(mass)
    if not math.isfinite(m) or not 0.0 <= m <= MAX_PAYLOAD_MASS:
        raise InvalidInputError(
            f"must be a finite mass within [0, {MAX_PAYLOAD_MASS:g}] kg (got {mass!r})",
            f"{field}.mass",
        )
    c = np.asarray(com, dtype=float)
    if c.shape != (3,):
        raise InvalidInputError("expected 3 coordinates (m)", f"{field}.com")
    _check_bounded(c, f"{field}.com", MAX_PAYLOAD_OFFSET, "m")
    if inertia is None:
        inertia_matrix = np.zeros((3, 3))
    else:
        arr = np.asarray(inertia, dtype=float)
        if arr.shape == (6,):
            xx, xy, xz, yy, yz, zz = arr
            inertia_matrix = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        elif arr.shape == (3, 3):
            inertia_matrix = arr
        else:
            raise InvalidInputError(
                "expected the six entries [ixx, ixy, ixz, iyy, iyz, izz] (kg·m²)",
                f"{field}.inertia",
            )
        _check_bounded(arr, f"{field}.inertia", MAX_PAYLOAD_INERTIA, "kg·m²")
        check_rotational_inertia(inertia_matrix, f"{field}.inertia")
    return Payload(m, frame, c, inertia_matrix)


def _check_bounded(values: np.ndarray, field: str, bound: float, unit: str) -> None:
    for where, v in np.ndenumerate(values):
        path = ".".join([field, *map(str, where)])
        if not math.isfinite(v):
            raise InvalidInputError("must be a finite number", path)
        if abs(v) > bound:
            raise InvalidInputError(f"must lie within ±{bound:g} {unit} (got {v:g})", path)


def check_rotational_inertia(inertia: np.ndarray, field: str) -> None:
    """Refuse a 3×3 rotational inertia (kg·m²) no rigid body has: not symmetric, a negative
    principal moment, or principal moments ``a, b, c`` with ``a > b + c``."""
    scale = max(float(np.abs(inertia).max()), 1.0)
    tol = INERTIA_TOLERANCE * scale
    if np.abs(inertia - inertia.T).max() > tol:
        raise InvalidInputError("the inertia matrix must be symmetric", field)
    moments = np.linalg.eigvalsh(0.5 * (inertia + inertia.T))
    if moments[0] < -tol:
        raise InvalidInputError(
            f"the inertia must be positive semi-definite (principal moment {moments[0]:g})",
            field,
        )
    if moments[2] > moments[0] + moments[1] + tol:
        raise InvalidInputError(
            "the principal moments must satisfy the triangle inequality "
            f"({moments[2]:g} > {moments[0]:g} + {moments[1]:g}): no rigid body has them",
            field,
        )


def check_rates(values: np.ndarray, field: str) -> None:
    """Refuse joint velocities or accelerations that are not finite or beyond
    ±:data:`MAX_JOINT_RATE`, naming ``field.i`` (or ``field.i.j`` for a path)."""
    arr = np.asarray(values, dtype=float)
    ok = np.abs(arr) <= MAX_JOINT_RATE
    if ok.all():
        return
    where = tuple(int(i) for i in np.argwhere(~ok)[0])
    path = ".".join([field, *map(str, where)])
    if not math.isfinite(float(arr[where])):
        raise InvalidInputError("must be a finite number", path)
    raise InvalidInputError(f"must lie within ±{MAX_JOINT_RATE:g} (got {arr[where]:g})", path)


# --- the models the dynamics run on ---------------------------------------------------------


class _Recipe:
    """How wire values map onto the dynamics model (module doc): the model (the robot's own,
    or for mimic robots the one whose followers are joints), ``G`` (nv × n) and, for mimic
    robots, where each wire and follower value goes in its configuration."""

    def __init__(self, robot: RobotModel) -> None:
        self.mimic = bool(robot.mimic_joints)
        #: The joints' effort limits (read-only; :func:`effort_limits`).
        self.limits = np.array(
            [j.effort if j.effort else math.nan for j in robot.joints], dtype=float
        )
        self.limits.flags.writeable = False
        if not self.mimic:
            self.model = robot.model
            nv = robot.model.nv
            self.G = np.zeros((nv, robot.n))
            self.G[robot.v_index, np.arange(robot.n)] = 1.0
            self.v_index = robot.v_index
            self.identity = bool(np.array_equal(robot.v_index, np.arange(nv)))
            self.lower = np.tril_indices(nv, -1)
            return
        self.identity = False
        full = build_model(robot.urdf_text, mimic=False)
        self.model = full
        self.lower = np.tril_indices(full.nv, -1)
        self.G = np.zeros((full.nv, robot.n))
        plain_q, plain_w, cont_q, cont_w = [], [], [], []
        for j in robot.joints:
            jm = full.joints[full.getJointId(j.name)]
            self.G[jm.idx_v, j.index] = 1.0
            if jm.nq == 2:
                cont_q.append(jm.idx_q)
                cont_w.append(j.index)
            else:
                plain_q.append(jm.idx_q)
                plain_w.append(j.index)
        follow_q, leaders, mult, off = [], [], [], []
        for m in robot.mimic_joints:
            jm = full.joints[full.getJointId(m.name)]
            self.G[jm.idx_v, m.leader_index] = m.multiplier
            follow_q.append(jm.idx_q)
            leaders.append(m.leader_index)
            mult.append(m.multiplier)
            off.append(m.offset)
        # where each wire value, continuous angle and follower goes in the configuration
        self.plain = (np.array(plain_q, dtype=int), np.array(plain_w, dtype=int))
        self.cont = (np.array(cont_q, dtype=int), np.array(cont_w, dtype=int))
        self.follow = (np.array(follow_q, dtype=int), np.array(leaders, dtype=int))
        self.mult, self.offset = np.array(mult), np.array(off)

    def q(self, robot: RobotModel, q: np.ndarray) -> np.ndarray:
        """The model's configuration for the wire configuration ``q``."""
        if not self.mimic:
            return robot.to_pin(q)
        out = np.empty(self.model.nq)
        out[self.plain[0]] = q[self.plain[1]]
        if self.cont[0].size:
            th = q[self.cont[1]]
            out[self.cont[0]] = np.cos(th)
            out[self.cont[0] + 1] = np.sin(th)
        out[self.follow[0]] = self.mult * q[self.follow[1]] + self.offset
        return out

    def v(self, v: np.ndarray) -> np.ndarray:
        """The model's velocity (or acceleration) for wire values ``v``."""
        if self.identity:
            return v
        if not self.mimic:
            out = np.zeros(self.model.nv)
            out[self.v_index] = v
            return out
        return self.G @ v

    def torques(self, tau: np.ndarray) -> np.ndarray:
        """Wire torques for the model's generalised forces ``tau`` (``Gᵀ τ``)."""
        if self.identity:
            return tau
        return tau[self.v_index] if not self.mimic else self.G.T @ tau

    def matrix(self, m: np.ndarray) -> np.ndarray:
        """Wire matrix ``Gᵀ A G`` of a model matrix ``A`` (nv × nv)."""
        if self.identity:
            return m
        if not self.mimic:
            return m[np.ix_(self.v_index, self.v_index)]
        return self.G.T @ m @ self.G


_RECIPE = LazyKey("dynamics.recipe", _Recipe)
_MASSLESS = LazyKey("dynamics.massless_link", str)


class _Scratch(threading.local):
    """Per thread and robot: a copy of the dynamics model (its inertias changed while a
    payload is attached) and its Data (scratch space, never shared between threads)."""

    def __init__(self) -> None:
        self.models: dict[int, tuple[object, pin.Model, pin.Data]] = {}


_SCRATCH = _Scratch()


def _scratch(robot: RobotModel, recipe: _Recipe) -> tuple[pin.Model, pin.Data]:
    got = _SCRATCH.models.get(id(recipe))
    if got is None or got[0] is not recipe:
        model = pin.Model(recipe.model)
        got = (recipe, model, model.createData())
        if len(_SCRATCH.models) > 64:  # robots come and go: keep the newest few
            _SCRATCH.models.clear()
        _SCRATCH.models[id(recipe)] = got
    return got[1], got[2]


def recipe_of(robot: RobotModel) -> _Recipe:
    """The robot's dynamics recipe (built once per model)."""
    return robot.lazy(_RECIPE, _Recipe)


def _massless_link(robot: RobotModel) -> str:
    """The URDF child link of the first joint whose moving body has no mass and no rotational
    inertia (module doc), or ``""``."""
    model = robot.model
    for jid in range(1, model.njoints):
        body = model.inertias[jid]
        if body.mass < MIN_BODY_MASS and np.abs(body.inertia).max() < MIN_BODY_MASS:
            name = model.names[jid]
            return str(robot.urdf_joints.get(name, {}).get("child") or name)
    return ""


def check_inertias(robot: RobotModel) -> None:
    """Raise :class:`MissingInertiaError` naming the first link that moves with a joint and
    carries no inertia: torques from zero or default inertias would be wrong silently."""
    link = robot.lazy(_MASSLESS, _massless_link)
    if link:
        raise MissingInertiaError(link)


@contextmanager
def loaded(
    robot: RobotModel, load: Payload | None
) -> Iterator[tuple[_Recipe, pin.Model, pin.Data]]:
    """This thread's dynamics model with ``load`` attached (restored on exit)."""
    check_inertias(robot)
    recipe = recipe_of(robot)
    model, data = _scratch(robot, recipe)
    if load is None or load.mass == 0.0 and not load.inertia.any():
        yield recipe, model, data
        return
    fid = model.getFrameId(load.frame, robot.model.frames[robot.frame_id(load.frame)].type)
    frame = model.frames[fid]
    jid = frame.parentJoint
    before = pin.Inertia(model.inertias[jid])
    added = frame.placement.act(pin.Inertia(load.mass, load.com, load.inertia))
    model.inertias[jid] = before + added
    try:
        yield recipe, model, data
    finally:
        model.inertias[jid] = before


# --- the answers ---------------------------------------------------------------------------


def effort_limits(robot: RobotModel) -> np.ndarray:
    """The joints' URDF ``effort`` limits (N·m or N), NaN where none is given (absent, not
    finite or 0)."""
    return recipe_of(robot).limits.copy()


def effort_ratios(torques: np.ndarray, limits: np.ndarray) -> np.ndarray:
    """``|τ| / limit`` per joint (…, n), NaN where there is no limit."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(torques) / limits


def binding_joint(robot: RobotModel, ratios: np.ndarray) -> str | None:
    """The joint with the largest effort ratio (None when no joint has a limit)."""
    best, name = -1.0, None
    for value, joint in zip(ratios.tolist(), robot.joint_names, strict=True):
        if value > best:  # False for NaN
            best, name = value, joint
    return name


@dataclass
class Dynamics:
    """The terms of the equations of motion at one state (module doc), wire order."""

    torques: np.ndarray  # τ = M q̈ + C q̇ + g + Jᵀ F
    gravity: np.ndarray  # g(q)
    coriolis: np.ndarray  # C(q, q̇) q̇
    inertial: np.ndarray  # M(q) q̈
    wrench_torques: np.ndarray  # Jᵀ F (zeros without a wrench)
    mass_matrix: np.ndarray  # M(q), n × n, symmetric
    coriolis_matrix: np.ndarray  # C(q, q̇), n × n
    com: np.ndarray  # the centre of mass of robot and payload (m, world)
    mass: float  # kg, robot and payload
    effort_limits: np.ndarray  # NaN: none
    ratios: np.ndarray  # |τ| / limit, NaN without a limit
    binding: str | None  # the joint with the largest ratio


def compute_dynamics(
    robot: RobotModel,
    q: np.ndarray,
    qd: np.ndarray | None = None,
    qdd: np.ndarray | None = None,
    *,
    load: Payload | None = None,
    wrench: np.ndarray | None = None,
    wrench_frame: str | None = None,
    wrench_reference: Reference = "world",
) -> Dynamics:
    """Every term of the equations of motion at ``(q, q̇, q̈)`` (zeros when not given) with an
    optional payload and an external wrench ``F`` at ``wrench_frame`` (the tip by default;
    ``F`` as in statics: the wrench the frame exerts, in ``wrench_reference``).

    Raises :class:`MissingInertiaError` for a robot with a massless moving body."""
    n = robot.n
    qd = np.zeros(n) if qd is None else np.asarray(qd, dtype=float)
    qdd = np.zeros(n) if qdd is None else np.asarray(qdd, dtype=float)
    with loaded(robot, load) as (recipe, model, data):
        qp, vp, ap = recipe.q(robot, q), recipe.v(qd), recipe.v(qdd)
        zero = np.zeros(model.nv)
        gravity = recipe.torques(pin.rnea(model, data, qp, zero, zero).copy())
        nle = recipe.torques(pin.rnea(model, data, qp, vp, zero).copy())
        tau = recipe.torques(pin.rnea(model, data, qp, vp, ap).copy())
        M_full = pin.crba(model, data, qp).copy()  # the upper triangle
        M_full[recipe.lower] = M_full.T[recipe.lower]
        mass_matrix = recipe.matrix(M_full)
        C = recipe.matrix(pin.computeCoriolisMatrix(model, data, qp, vp).copy())
        com = pin.centerOfMass(model, data, qp).copy()
        mass = float(data.mass[0])
    wrench_tau = np.zeros(n)
    if wrench is not None:
        frame = robot.ee_frame if wrench_frame is None else wrench_frame
        wrench_tau = torques_from_wrench(robot, q, frame, wrench, wrench_reference).torques
    torques = tau + wrench_tau
    limits = recipe.limits
    ratios = effort_ratios(torques, limits)
    return Dynamics(
        torques=torques,
        gravity=gravity,
        coriolis=nle - gravity,
        inertial=tau - nle,
        wrench_torques=wrench_tau,
        mass_matrix=mass_matrix,
        coriolis_matrix=C,
        com=com,
        mass=mass,
        effort_limits=limits,
        ratios=ratios,
        binding=binding_joint(robot, ratios),
    )


def inverse_dynamics(
    robot: RobotModel,
    qs: np.ndarray,
    qds: np.ndarray | None = None,
    qdds: np.ndarray | None = None,
    *,
    load: Payload | None = None,
) -> np.ndarray:
    """τ (N, n) by RNEA for N states (wire order; zeros for velocities or accelerations not
    given), with an optional payload."""
    qs = np.asarray(qs, dtype=float)
    zeros = np.zeros_like(qs)
    qds = zeros if qds is None else np.asarray(qds, dtype=float)
    qdds = zeros if qdds is None else np.asarray(qdds, dtype=float)
    out = np.empty_like(qs)
    with loaded(robot, load) as (recipe, model, data):
        for k in range(qs.shape[0]):
            tau = pin.rnea(model, data, recipe.q(robot, qs[k]), recipe.v(qds[k]), recipe.v(qdds[k]))
            out[k] = recipe.torques(tau)
    return out


def gravity_torques(
    robot: RobotModel, qs: np.ndarray, *, load: Payload | None = None
) -> np.ndarray:
    """g(q) (N, n) for N configurations (wire order), with an optional payload."""
    return inverse_dynamics(robot, qs, load=load)

"""Jacobian analysis: manipulability, singularities and statics.

The task Jacobian
-----------------
Every measure here is computed from the *task Jacobian* ``J_t = J[rows][:, support]``:

- ``J`` is the 6×n geometric Jacobian of the frame (:mod:`.jacobian`; rows
  [vx, vy, vz, ωx, ωy, ωz], reference ``world`` / ``local`` / ``world_spatial``);
- ``rows`` are the task's rows: ``full`` (all six), ``translation`` (vx, vy, vz),
  ``rotation`` (ωx, ωy, ωz) or an explicit list such as ``["vx", "vy"]`` for a planar arm
  (robots with fewer than six joints use the task's rows only);
- ``support`` are the joints that move the frame (:meth:`RobotModel.supporting_joints`, the
  frame's kinematic chain). Other joints give identically zero columns and are left out:
  a gripper finger does not make an arm redundant, nor does it make it singular.

With m task rows, k supporting joints and the singular values σ_1 ≥ … ≥ σ_p of ``J_t``
(p = min(m, k)):

- rank r = #{σ_i > tol} with ``tol = relative_tolerance · σ_1`` (default 1e-10·σ_1; 0 for a
  zero Jacobian); the configuration is **singular** iff r < p;
- Yoshikawa w = ∏σ_i (= √det(J_t J_tᵀ) when m ≤ k, = √det(J_tᵀ J_t) when m > k);
- ``det_jjt`` = det(J_t J_tᵀ) = ∏σ_i² when m ≤ k and exactly 0 when m > k;
- smallest singular value σ_p, inverse condition σ_p/σ_1, condition number σ_1/σ_p;
- velocity ellipsoid: axes = the m left singular vectors u_i (task space), half-lengths σ_i
  (0 beyond p); force ellipsoid: the same axes, half-lengths 1/σ_i. A direction beyond the
  numerical rank (σ_i ≤ tol, or i > p) has an infinite force half-length and an infinite
  condition number: both are reported as ``None`` (JSON null);
- ``lost_directions``: an orthonormal basis of the left null space of ``J_t`` (the u_i with
  i > r): task directions in which the frame cannot move at all at this configuration. It is
  empty exactly when ``J_t`` has full row rank; for a task with more rows than joints it is
  never empty, which is why a planar arm should be analysed on its x, y rows;
- ``dependent_joints``: the supporting joints whose columns take part in a linear
  dependency, i.e. joint j with a non-zero entry in some null vector of ``J_t``
  (equivalently: removing column j does not lower the rank). For a non-redundant chain
  (k ≤ m) this set is non-empty exactly at a singularity (planar 2-link arm stretched:
  both joints, J_1 = (l1+l2)/l2 · J_2). For a redundant chain (k > m) the columns are always
  dependent (self-motion) and the set covers the joints of the self-motion as well.

Units: translation rows are m/s per rad/s (or m/s per m/s for prismatic joints), rotation
rows rad/s per rad/s; a measure over mixed rows mixes these units.

Statics
-------
τ = J_fᵀ·F (course notation) with F = [f; m] (N, N·m) the wrench the frame exerts on its
environment, expressed in the same reference as J (``world``: force and moment about the
frame origin in world axes; ``local``: in the frame's axes; ``world_spatial``: moment about
the world origin). τ are the joint torques (N·m) / forces (N) that produce F, equivalently
that hold the arm still against an external wrench −F. Inverse: given τ, the wrench is the
minimum-norm least-squares solution F = (J_fᵀ)⁺ τ with the residual τ − J_fᵀ F.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.jacobian import (
    REFERENCE_FRAMES,
    Reference,
    frame_jacobian,
    frame_jacobian_by_id,
)
from app.kinematics.models import RobotModel

Part = Literal["full", "translation", "rotation"]

ROW_NAMES: tuple[str, ...] = ("vx", "vy", "vz", "wx", "wy", "wz")
_ROW_ALIASES = {name: i for i, name in enumerate(ROW_NAMES)}
_ROW_ALIASES.update({"ωx": 3, "ωy": 4, "ωz": 5})
PART_ROWS: dict[str, tuple[int, ...]] = {
    "full": (0, 1, 2, 3, 4, 5),
    "translation": (0, 1, 2),
    "rotation": (3, 4, 5),
}
DEFAULT_RELATIVE_TOLERANCE = 1e-10
#: A joint is "dependent" when its row of the null-space projector exceeds this (unitless).
DEPENDENCE_THRESHOLD = 1e-8


def task_rows(
    part: str | None = None, rows: Sequence[str | int] | None = None, field: str = "rows"
) -> np.ndarray:
    """Indices of the task's Jacobian rows from ``part`` or an explicit ``rows`` list.

    ``rows`` entries are names (``vx vy vz wx wy wz``, ``ωx`` … accepted) or indices 0–5;
    giving both ``part`` and ``rows``, an empty list, an unknown name or a repeated row raises
    :class:`InvalidInputError` naming ``field``.
    """
    if rows is None:
        return np.array(PART_ROWS[part or "full"], dtype=int)
    if part is not None:
        raise InvalidInputError("give either part or rows, not both", field)
    if len(rows) == 0:
        raise InvalidInputError("give at least one row", field)
    out: list[int] = []
    for i, r in enumerate(rows):
        if isinstance(r, bool):
            raise InvalidInputError("a row is a name (vx … wz) or an index 0–5", f"{field}.{i}")
        if isinstance(r, int):
            if not 0 <= r < 6:
                raise InvalidInputError(f"row index {r} is not in 0–5", f"{field}.{i}")
            idx = r
        else:
            idx = _ROW_ALIASES.get(str(r).strip().lower(), _ROW_ALIASES.get(str(r).strip()))
            if idx is None:
                raise InvalidInputError(
                    f"unknown row {r!r}; rows are {', '.join(ROW_NAMES)} (or indices 0–5)",
                    f"{field}.{i}",
                )
        if idx in out:
            raise InvalidInputError(f"row {ROW_NAMES[idx]} is given twice", f"{field}.{i}")
        out.append(idx)
    return np.array(out, dtype=int)


def _require_finite(values: np.ndarray, field: str) -> None:
    """Raise when a result overflowed (e.g. a prismatic joint at 1e308 m)."""
    if not np.all(np.isfinite(values)):
        raise InvalidInputError(
            "the joint values are too large: the Jacobian or a measure is not finite", field
        )


def _canonical_sign(vectors: np.ndarray) -> np.ndarray:
    """Flip each column so that its largest-magnitude entry is positive (deterministic axes)."""
    if vectors.size == 0:
        return vectors
    idx = np.argmax(np.abs(vectors), axis=0)
    signs = np.sign(vectors[idx, np.arange(vectors.shape[1])])
    signs[signs == 0] = 1.0
    return vectors * signs


@dataclass
class Manipulability:
    """Everything :func:`manipulability` derives from one task Jacobian (see module doc)."""

    rows: list[str]
    joints: list[str]
    jacobian: np.ndarray  # m×k task Jacobian
    singular_values: np.ndarray  # p = min(m, k), descending
    yoshikawa: float
    det_jjt: float
    min_singular_value: float
    inverse_condition: float
    condition_number: float | None
    rank: int
    tolerance: float
    relative_tolerance: float
    singular: bool
    axes: np.ndarray  # m×m, column i = u_i
    velocity_half_lengths: np.ndarray  # m
    force_half_lengths: list[float | None]  # m
    lost_directions: np.ndarray  # m×(m−r), columns
    dependent_joints: list[str]
    joint_null_space: np.ndarray  # k×(k−r), columns

    def to_json(self) -> dict[str, Any]:
        """Wire form (vectors as lists of rows: one vector per entry)."""
        return {
            "rows": self.rows,
            "joints": self.joints,
            "yoshikawa": self.yoshikawa,
            "singular_values": self.singular_values,
            "min_singular_value": self.min_singular_value,
            "inverse_condition": self.inverse_condition,
            "condition_number": self.condition_number,
            "det_jjt": self.det_jjt,
            "rank": self.rank,
            "tolerance": self.tolerance,
            "relative_tolerance": self.relative_tolerance,
            "singular": self.singular,
            "velocity_ellipsoid": {
                "axes": self.axes.T,
                "half_lengths": self.velocity_half_lengths,
            },
            "force_ellipsoid": {"axes": self.axes.T, "half_lengths": self.force_half_lengths},
            "lost_directions": self.lost_directions.T,
            "dependent_joints": self.dependent_joints,
            "joint_null_space": self.joint_null_space.T,
        }


def manipulability_of(
    J_task: np.ndarray,
    *,
    row_names: Sequence[str] | None = None,
    joint_names: Sequence[str] | None = None,
    relative_tolerance: float = DEFAULT_RELATIVE_TOLERANCE,
    field: str = "q",
) -> Manipulability:
    """Manipulability measures of an m×k task Jacobian (module doc states the math).

    A Jacobian or a measure that is not finite (joint values so large that positions
    overflow) raises :class:`InvalidInputError` naming ``field``.
    """
    J = np.asarray(J_task, dtype=float)
    m, k = J.shape
    _require_finite(J, field)
    row_names = list(row_names) if row_names is not None else [str(i) for i in range(m)]
    joint_names = list(joint_names) if joint_names is not None else [str(i) for i in range(k)]
    U, s, Vt = np.linalg.svd(J, full_matrices=True)
    p = min(m, k)
    smax = float(s[0]) if p else 0.0
    tol = relative_tolerance * smax
    rank = int(np.count_nonzero(s > tol))
    smin = float(s[p - 1]) if p else 0.0
    full = np.zeros(m)
    full[:p] = s[:p]
    force: list[float | None] = [
        (1.0 / float(v)) if (i < rank and v > 0.0) else None for i, v in enumerate(full)
    ]
    U = _canonical_sign(U)
    V = Vt.T
    null = _canonical_sign(V[:, rank:].copy())
    weight = np.sqrt(np.einsum("ij,ij->i", null, null)) if null.size else np.zeros(k)
    dependent = [joint_names[j] for j in np.flatnonzero(weight > DEPENDENCE_THRESHOLD)]
    with np.errstate(over="ignore", invalid="ignore"):
        det_jjt = float(np.prod(full**2)) if m <= k else 0.0
        yoshikawa = float(np.prod(s[:p]))
    _require_finite(np.array([det_jjt, yoshikawa]), field)
    return Manipulability(
        rows=row_names,
        joints=joint_names,
        jacobian=J,
        singular_values=s[:p].copy(),
        yoshikawa=yoshikawa,
        det_jjt=det_jjt,
        min_singular_value=smin,
        inverse_condition=smin / smax if smax > 0.0 else 0.0,
        condition_number=(smax / smin) if (rank == p and smin > 0.0) else None,
        rank=rank,
        tolerance=tol,
        relative_tolerance=relative_tolerance,
        singular=rank < p,
        axes=U,
        velocity_half_lengths=full,
        force_half_lengths=force,
        lost_directions=U[:, rank:].copy(),
        dependent_joints=dependent,
        joint_null_space=null,
    )


def support_columns(
    robot: RobotModel, frame: str, field: str = "frame", joints: np.ndarray | None = None
) -> np.ndarray:
    """Wire indices of the joints that move ``frame`` (among ``joints``, e.g. a planning
    group's, when given); a frame none of them moves is an error."""
    robot.frame_id(frame, field=field)
    cols = robot.supporting_joints(frame, joints)
    if cols.size == 0 and joints is not None:
        raise InvalidInputError(f"no joint of the group moves frame {frame!r}", "group")
    if cols.size == 0:
        raise InvalidInputError(f"frame {frame!r} is not moved by any joint", field)
    return cols


def compute_manipulability(
    robot: RobotModel,
    q: np.ndarray,
    frame: str,
    *,
    part: str | None = None,
    rows: Sequence[str | int] | None = None,
    reference: Reference = "world",
    relative_tolerance: float = DEFAULT_RELATIVE_TOLERANCE,
    joints: np.ndarray | None = None,
) -> Manipulability:
    """Manipulability of ``frame`` at wire configuration ``q`` (see module doc); ``joints``
    (wire indices, e.g. a planning group's) restricts the columns further."""
    ridx = task_rows(part, rows)
    cols = support_columns(robot, frame, joints=joints)
    J = frame_jacobian(robot, q, frame, reference)
    return manipulability_of(
        J[np.ix_(ridx, cols)],
        row_names=[ROW_NAMES[i] for i in ridx],
        joint_names=[robot.joint_names[c] for c in cols],
        relative_tolerance=relative_tolerance,
        field="q",
    )


def manipulability_batch(
    robot: RobotModel,
    qs: np.ndarray,
    frame: str,
    *,
    part: str | None = None,
    rows: Sequence[str | int] | None = None,
    reference: Reference = "world",
    relative_tolerance: float = DEFAULT_RELATIVE_TOLERANCE,
    joints: np.ndarray | None = None,
) -> dict[str, Any]:
    """Scalar measures for N configurations (N, n): compact arrays, one entry per row of ``qs``
    (``joints``: as for :func:`compute_manipulability`).

    Returns ``yoshikawa``, ``min_singular_value``, ``max_singular_value``,
    ``inverse_condition``, ``condition_number`` (``None`` where singular), ``det_jjt``,
    ``rank`` and ``singular``, with the same definitions as :func:`manipulability_of`.
    """
    ridx = task_rows(part, rows)
    cols = support_columns(robot, frame, joints=joints)
    fid = robot.frame_id(frame)
    rf = REFERENCE_FRAMES[reference]
    qp = robot.to_pin_batch(np.asarray(qs, dtype=float))
    N = qp.shape[0]
    m, k = ridx.size, cols.size
    Js = np.empty((N, m, k))
    sel = np.ix_(ridx, cols)
    for i in range(N):
        Js[i] = frame_jacobian_by_id(robot, qp[i], fid, rf)[sel]
    bad = np.flatnonzero(~np.isfinite(Js).all(axis=(1, 2)))
    if bad.size:
        _require_finite(np.array([np.nan]), f"configurations.{int(bad[0])}")
    s = np.linalg.svd(Js, compute_uv=False) if N else np.zeros((0, min(m, k)))
    smax = s[:, 0]
    smin = s[:, -1]
    tol = relative_tolerance * smax
    rank = np.count_nonzero(s > tol[:, None], axis=1)
    p = min(m, k)
    singular = rank < p
    with np.errstate(divide="ignore", invalid="ignore"):
        inv_cond = np.where(smax > 0.0, smin / smax, 0.0)
        cond = np.where(singular | (smin <= 0.0), np.nan, smax / smin)
    with np.errstate(over="ignore", invalid="ignore"):
        det = np.prod(s**2, axis=1) if m <= k else np.zeros(N)
        yoshikawa = np.prod(s, axis=1)
    bad = np.flatnonzero(~(np.isfinite(det) & np.isfinite(yoshikawa)))
    if bad.size:
        _require_finite(np.array([np.nan]), f"configurations.{int(bad[0])}")
    return {
        "rows": [ROW_NAMES[i] for i in ridx],
        "joints": [robot.joint_names[c] for c in cols],
        "yoshikawa": yoshikawa,
        "min_singular_value": smin,
        "max_singular_value": smax,
        "inverse_condition": inv_cond,
        "condition_number": [None if np.isnan(c) else float(c) for c in cond],
        "det_jjt": det,
        "rank": rank,
        "singular": singular,
    }


def yoshikawa_batch(J: np.ndarray) -> np.ndarray:
    """∏σ_i of each (m, k) matrix of J (N, m, k): √det of the smaller Gram matrix."""
    m, k = J.shape[1], J.shape[2]
    G = J @ np.swapaxes(J, 1, 2) if m <= k else np.swapaxes(J, 1, 2) @ J
    return np.sqrt(np.maximum(np.linalg.det(G), 0.0))


def yoshikawa_components(J: np.ndarray) -> np.ndarray:
    """∏σ_i for component-major Jacobians J (m, k, N), elementwise over N.

    The smaller Gram matrix G (J·Jᵀ if m ≤ k, else Jᵀ·J) is factored G = L·D·Lᵀ
    (Cholesky without square roots); w = √∏D_i. A pivot at or below 1e-13 of the largest
    diagonal entry marks a singular G (w = 0): the map's values are float32 anyway.
    """
    m, k = J.shape[0], J.shape[1]
    A = J if m <= k else J.transpose(1, 0, 2)
    r = A.shape[0]
    G = [[None] * r for _ in range(r)]
    for i in range(r):
        for j in range(i + 1):
            G[i][j] = np.einsum("kn,kn->n", A[i], A[j])
    scale = np.max(np.stack([G[i][i] for i in range(r)]), axis=0)
    floor = 1e-13 * scale
    L = [[None] * r for _ in range(r)]
    D: list[np.ndarray] = []  # pivots, 0 where singular
    inv: list[np.ndarray] = []  # 1/pivot, 0 where singular (that column of L is then 0)
    det = np.ones(A.shape[2])
    for i in range(r):
        for j in range(i):
            v = G[i][j].copy()
            for l in range(j):
                v -= L[i][l] * L[j][l] * D[l]
            L[i][j] = v * inv[j]
        d = G[i][i].copy()
        for l in range(i):
            d -= L[i][l] * L[i][l] * D[l]
        good = d > floor
        d = np.where(good, d, 0.0)
        det *= d
        D.append(d)
        inv.append(np.divide(1.0, d, out=np.zeros_like(d), where=good))
    return np.sqrt(det)


@dataclass
class Statics:
    """Joint torques and the wrench at the frame, related by τ = Jᵀ·F."""

    wrench: np.ndarray  # 6
    torques: np.ndarray  # n (wire order), or one per column of ``joints``
    residual: np.ndarray  # the same length: τ − Jᵀ F (zeros for the forward map)
    residual_norm: float
    rank: int
    jacobian: np.ndarray  # 6×n (or 6×len(joints))


def _statics_jacobian(
    robot: RobotModel, q: np.ndarray, frame: str, reference: Reference, joints: np.ndarray | None
) -> np.ndarray:
    """The frame's Jacobian, restricted to the columns of ``joints`` when given."""
    robot.frame_id(frame)
    J = frame_jacobian(robot, q, frame, reference)
    return J if joints is None else J[:, joints]


def torques_from_wrench(
    robot: RobotModel,
    q: np.ndarray,
    frame: str,
    wrench: np.ndarray,
    reference: Reference,
    joints: np.ndarray | None = None,
) -> Statics:
    """τ = Jᵀ·F for a wrench F = [fx, fy, fz, mx, my, mz] at ``frame`` (module doc); with
    ``joints`` (wire indices, e.g. a planning group's), τ of those joints only."""
    J = _statics_jacobian(robot, q, frame, reference, joints)
    _require_finite(J, "q")
    F = np.asarray(wrench, dtype=float)
    with np.errstate(over="ignore", invalid="ignore"):
        tau = J.T @ F
    _require_finite(tau, "wrench")
    s = np.linalg.svd(J, compute_uv=False)
    rank = int(np.count_nonzero(s > DEFAULT_RELATIVE_TOLERANCE * (s[0] if s.size else 0.0)))
    return Statics(F, tau, np.zeros(J.shape[1]), 0.0, rank, J)


def wrench_from_torques(
    robot: RobotModel,
    q: np.ndarray,
    frame: str,
    torques: np.ndarray,
    reference: Reference,
    relative_tolerance: float = DEFAULT_RELATIVE_TOLERANCE,
    joints: np.ndarray | None = None,
) -> Statics:
    """Least-squares F with Jᵀ·F ≈ τ (minimum norm among minimisers) and its residual; with
    ``joints``, τ holds those joints' torques only."""
    J = _statics_jacobian(robot, q, frame, reference, joints)
    _require_finite(J, "q")
    tau = np.asarray(torques, dtype=float)
    U, s, Vt = np.linalg.svd(J.T, full_matrices=False)  # Jᵀ = U S Vt, n×6
    tol = relative_tolerance * (s[0] if s.size else 0.0)
    keep = s > tol
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        F = Vt[keep].T @ ((U[:, keep].T @ tau) / s[keep])
        back = J.T @ F
        res = tau - back
        norm = float(np.linalg.norm(res))
    _require_finite(np.concatenate([F, back, res, [norm]]), "torques")
    return Statics(F, back, res, norm, int(keep.sum()), J)

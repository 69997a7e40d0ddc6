"""Reachability maps (course, after Vahrenkamp et al.): a 6-D grid of frame poses.

Grid
----
A map covers an axis-aligned box of the root (world) frame, ``lower`` … ``lower + shape·s``
with cubic position voxels of edge ``s`` (m). Voxel index i = ⌊(p − lower)/s⌋ per axis; a
position outside the box belongs to no cell (not reachable). The box defaults to a
conservative reach box (:func:`default_bounds`): centred on the first joint of the frame's
chain, half-size the sum of the distances between consecutive joint origins along the
chain plus the prismatic travels plus the frame's offset.

Orientation bins (cubed 3-sphere, equal-angle)
----------------------------------------------
A rotation is its unit quaternion q = [x, y, z, w] with q and −q identified. The component
with the largest magnitude, k ∈ {x, y, z, w}, picks one of 4 *faces* (the 4-D hypercube's
8 faces, antipodal pairs identified); q is flipped so that q_k > 0. The other three
components (in x, y, z, w order without k) give the equal-angle coordinates
a_i = arctan(q_i / q_k) ∈ [−π/4, π/4], each cut into ``d`` equal intervals. So there are
4·d³ bins; a face spans rotations of ±90° about each axis (for face w and a rotation by θ
about x, a = θ/2), so a bin spans about 180°/d per axis (d = 4: 45°). Cell volumes (Haar
measure) differ by at most a factor of 2, unlike RPY bins, which crowd near pitch ±90°.
``d = 0`` keeps one bin: a position-only map.
Bin index = k·d³ + i₀·d² + i₁·d + i₂; ties between equal largest components go to the
first, for building and querying alike.

Cells
-----
Each cell (voxel × bin) keeps the best (largest) Yoshikawa manipulability w = ∏σ_i of the
task Jacobian (:mod:`.analysis`; Jacobian reference ``world``, rows ``part``/``rows``,
columns the joints that move the frame) over the samples that landed in it, stored as
float32; −1 marks a cell no sample reached. Reachable = w ≥ 0.

Building
--------
Joint space is sampled within the limits of the joints that move the frame (the others do
not change the frame's pose and stay at their neutral values); continuous joints over
[−π, π). ``random``: uniform samples, the block of :data:`BLOCK` samples starting at sample
s drawn from ``default_rng([seed, s])``, so a map depends on the seed only, not on the
number of processes. ``grid``: g = round(samples^(1/k)) values per joint, g^k samples in
all, end points included (a range that is a full turn [−π, π] leaves out the duplicate +π).
FK and the Jacobian are vectorised over a block in NumPy (:class:`ChainJacobian`; chains
with other joint kinds fall back to Pinocchio in a loop). Chunks of :data:`CHUNK` samples
are the unit of work: with ``processes`` > 1 (and enough samples, see :func:`build_map`)
worker processes (forkserver; each builds its own model from the URDF) take chunks from a
queue, fold them into a partial map of their own (``np.maximum.at``) and, when the queue is
empty, send it to the parent, which merges the partial maps by maximum; otherwise the chunks
run in the calling thread. Progress advances per chunk; a cancelled build stops within a
chunk (in the calling thread) or at once (worker processes are terminated).

Self-collision hook
-------------------
``self_collision`` = ``mesh`` or ``convex`` drops samples in self-collision before they are
binned, using ``app.kinematics.collision.collision_model(robot, mode).collides(q)`` when that
module provides it (checked at request time; otherwise the request is refused with 422
naming ``self_collision``). Joints that do not move the frame are at their neutral values
for the check. It costs one collision query per sample (far slower than FK).

Files
-----
A finished map is ``<data_dir>/maps/<robot_id>/<map_id>.npz`` (``best``: the float32 grid;
``meta``: JSON), written atomically; maps therefore survive restarts. ``meta`` holds the
robot's URDF fingerprint so a map of a robot since replaced is refused.

Build jobs run in the process that accepted them; each publishes its status as
``<data_dir>/maps/.jobs/<job_id>.json`` so that every process sharing the data directory
(uvicorn workers) answers for every job, and cancels through ``<job_id>.cancel`` markers
(:class:`BuildJobs`).
"""

from __future__ import annotations

import hashlib
import importlib
import io
import json
import logging
import math
import multiprocessing
import os
import queue
import socket
import threading
import time
import uuid
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

from app.kinematics.analysis import ROW_NAMES, support_columns, task_rows
from app.kinematics.errors import ConflictError, InvalidInputError, UnknownNameError
from app.kinematics.models import RobotModel
from app.kinematics.procwatch import kill_self, set_parent_death_signal, watch_parent
from app.store import atomic_write_bytes

#: Largest number of cells (voxels × orientation bins) of one map (float32: 4 bytes each).
MAX_CELLS = 1 << 24
MAX_SAMPLES = 1_000_000_000
MAX_ORIENTATION_DIVISIONS = 12
#: Samples per chunk (one unit of work for a process; progress advances per chunk).
CHUNK = 32_768
#: Samples evaluated at once inside a chunk (small enough for the CPU caches); random
#: samples are drawn per block, so a map does not depend on CHUNK or the process count.
BLOCK = 2_048
UNREACHED = np.float32(-1.0)
#: Fewer samples than this per process and a build runs in the calling thread instead.
MIN_SAMPLES_PER_PROCESS = 1_000_000


# --------------------------------------------------------------------------- orientation
def orientation_bins(divisions: int) -> int:
    """Number of orientation bins for ``divisions`` (4·d³, or 1 when d = 0)."""
    return 1 if divisions == 0 else 4 * divisions**3


def orientation_bin(quat: np.ndarray, divisions: int) -> np.ndarray:
    """Bin index (N,) of quaternions [x, y, z, w] (N, 4) (cubed 3-sphere, module doc)."""
    q = np.asarray(quat, dtype=float).reshape(-1, 4)
    n = q.shape[0]
    if divisions == 0:
        return np.zeros(n, dtype=np.int64)
    k = np.argmax(np.abs(q), axis=1)
    lead = q[np.arange(n), k]
    others = np.empty((n, 3))
    for face in range(4):
        sel = k == face
        if sel.any():
            others[sel] = q[sel][:, [c for c in range(4) if c != face]]
    # the sign of the lead component cancels the q ~ −q ambiguity
    return _bin_from_ratios(k, (others / lead[:, None]).T, divisions)


def orientation_bin_from_rotation(Rt: np.ndarray, divisions: int) -> np.ndarray:
    """Bin index (N,) of component-major rotations Rt (3, 3, N), same bins as
    :func:`orientation_bin` without building quaternions: 4q_c² are the Shepperd candidates
    (1 + tr, 1 + 2R_00 − tr, …), and q_i/q_k = (pair sum or difference)/(4q_k²)."""
    n = Rt.shape[2]
    if divisions == 0:
        return np.zeros(n, dtype=np.int64)
    r00, r11, r22 = Rt[0, 0], Rt[1, 1], Rt[2, 2]
    tr = r00 + r11 + r22
    cand = np.stack([1.0 + 2.0 * r00 - tr, 1.0 + 2.0 * r11 - tr, 1.0 + 2.0 * r22 - tr, 1.0 + tr])
    k = np.argmax(cand, axis=0)
    d21 = Rt[2, 1] - Rt[1, 2]
    d02 = Rt[0, 2] - Rt[2, 0]
    d10 = Rt[1, 0] - Rt[0, 1]
    s01 = Rt[0, 1] + Rt[1, 0]
    s02 = Rt[0, 2] + Rt[2, 0]
    s12 = Rt[1, 2] + Rt[2, 1]
    # the other three components, in x, y, z, w order without the largest, per face
    num = np.stack(
        [
            np.choose(k, [s01, s01, s02, d21]),
            np.choose(k, [s02, s12, s12, d02]),
            np.choose(k, [d21, d02, d10, d10]),
        ]
    )
    ratio = num / np.take_along_axis(cand, k[None], axis=0)
    return _bin_from_ratios(k, ratio, divisions)


def _bin_from_ratios(k: np.ndarray, ratio: np.ndarray, d: int) -> np.ndarray:
    a = np.arctan(ratio)
    idx = np.clip(np.floor((a / (math.pi / 2) + 0.5) * d).astype(np.int64), 0, d - 1)
    return k.astype(np.int64) * d**3 + idx[0] * d * d + idx[1] * d + idx[2]


# ------------------------------------------------------------------------- vectorised FK
def _z_to(axis: np.ndarray) -> np.ndarray:
    """A rotation A with A·e_z = axis (unit)."""
    z = np.array([0.0, 0.0, 1.0])
    c = float(axis @ z)
    if c > 1.0 - 1e-15:
        return np.eye(3)
    if c < -1.0 + 1e-15:
        return np.diag([1.0, -1.0, -1.0])
    v = np.cross(z, axis)
    return pin.exp3(v / np.linalg.norm(v) * math.acos(max(-1.0, min(1.0, c))))


#: Constant coefficients smaller than this are treated as 0 (URDF origins are mostly
#: axis-aligned, so most of a fixed rotation's entries are 0 or ±1 up to rounding).
_ZERO = 1e-15


def _accumulate(P: np.ndarray, t: np.ndarray, M: np.ndarray) -> None:
    """P += Σ_j t_j·M[j] in place (P (3, N), M (3 columns, 3, N)); no BLAS: small products
    would otherwise start OpenBLAS threads that fight the worker processes."""
    for j in range(3):
        c = float(t[j])
        if abs(c) > _ZERO:
            P += c * M[j]


def _rotate_columns(M: np.ndarray, C: np.ndarray) -> np.ndarray:
    """Columns of R·C from the columns of R: new column k = Σ_j C[j, k]·M[j]."""
    out = np.empty_like(M)
    for k in range(3):
        first = True
        for j in range(3):
            c = float(C[j, k])
            if abs(c) <= _ZERO:
                continue
            if first:
                np.multiply(M[j], c, out=out[k])
                first = False
            else:
                out[k] += c * M[j]
        if first:
            out[k] = 0.0
    return out


@dataclass(frozen=True)
class _Step:
    C: np.ndarray  # rotation: previous z-aligned frame → this joint's z-aligned frame
    t: np.ndarray  # translation in the previous z-aligned frame
    col: int  # column of the sample matrix (position in the chain)
    prismatic: bool


class ChainJacobian:
    """Vectorised pose and world Jacobian of one frame over many samples of its chain.

    Each joint of the frame's chain is rewritten in a frame whose z axis is the joint axis
    (rot(axis, θ) = A·Rz(θ)·Aᵀ, constants folded into the fixed placements); then, per
    sample, a joint's axis is the third column of the running rotation and its origin the
    running position, and the geometric Jacobian (reference ``world`` = Pinocchio
    LOCAL_WORLD_ALIGNED) is J_j = [z_j × (p − o_j); z_j] for revolute joints, [z_j; 0] for
    prismatic ones. Samples hold one column per chain joint (``self.wire`` gives their wire
    indices). ``build`` returns ``None`` for chains with mimic or multi-DoF joints.
    """

    def __init__(self, steps: list[_Step], last_C: np.ndarray, last_t: np.ndarray, wire):
        self.steps = steps
        self.last_C = last_C
        self.last_t = last_t
        self.wire = np.asarray(wire, dtype=int)

    @classmethod
    def build(cls, robot: RobotModel, frame: str) -> ChainJacobian | None:
        model = robot.model
        f = model.frames[robot.frame_id(frame)]
        by_pin = {j.pin_id: j for j in robot.joints}
        steps: list[_Step] = []
        wire: list[int] = []
        prev_At = np.eye(3)
        for jid in list(model.supports[f.parentJoint])[1:]:
            joint = by_pin.get(jid)
            if joint is None or model.joints[jid].nv != 1:
                return None
            axis = np.asarray(joint.axis, dtype=float)
            A = _z_to(axis / np.linalg.norm(axis))
            M = model.jointPlacements[jid]
            steps.append(
                _Step(prev_At @ M.rotation @ A, prev_At @ M.translation, len(wire),
                      joint.type == "prismatic")
            )  # fmt: skip
            wire.append(joint.index)
            prev_At = A.T
        return cls(steps, prev_At @ f.placement.rotation, prev_At @ f.placement.translation, wire)

    def evaluate(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Component-major results for samples Q (N, k), one column per chain joint:
        rotations Rt (3, 3, N) with Rt[i, j] = R_ij, positions (3, N), world Jacobians
        (6, k, N). Every operation is a BLAS product or an elementwise op over N."""
        n = Q.shape[0]
        k = len(self.steps)
        M = np.zeros((3, 3, n))  # M[j] = column j of R (3, N)
        M[0, 0] = M[1, 1] = M[2, 2] = 1.0
        P = np.zeros((3, n))
        J = np.zeros((6, k, n))
        origins = np.empty((k, 3, n))
        QT = np.ascontiguousarray(Q.T)
        cs = np.cos(QT)
        sn = np.sin(QT)
        for j, s in enumerate(self.steps):
            _accumulate(P, s.t, M)
            M = _rotate_columns(M, s.C)
            J[3:, j] = M[2]
            origins[j] = P
            if s.prismatic:
                P += QT[s.col] * M[2]
            else:
                c, si = cs[s.col], sn[s.col]
                x = M[0].copy()
                M[0] *= c
                M[0] += si * M[1]
                M[1] *= c
                M[1] -= si * x
        _accumulate(P, self.last_t, M)
        M = _rotate_columns(M, self.last_C)
        for j, s in enumerate(self.steps):
            z = J[3:, j]
            if s.prismatic:
                J[:3, j] = z
                J[3:, j] = 0.0
            else:
                d = P - origins[j]
                J[0, j] = z[1] * d[2] - z[2] * d[1]
                J[1, j] = z[2] * d[0] - z[0] * d[2]
                J[2, j] = z[0] * d[1] - z[1] * d[0]
        return M.transpose(1, 0, 2), P, J

    def __call__(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Rotations (N, 3, 3), positions (N, 3) and world Jacobians (N, 6, k)."""
        Rt, P, J = self.evaluate(Q)
        return Rt.transpose(2, 0, 1), P.T, J.transpose(2, 0, 1)


class PinocchioChain:
    """The same interface as :class:`ChainJacobian`, computed by Pinocchio per sample."""

    def __init__(self, robot: RobotModel, frame: str, wire: np.ndarray) -> None:
        self.robot = robot
        self.fid = robot.frame_id(frame)
        self.wire = np.asarray(wire, dtype=int)

    def __call__(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        robot = self.robot
        model, data = robot.model, robot.data
        n = Q.shape[0]
        full = np.tile(robot.neutral(), (n, 1))
        full[:, self.wire] = Q
        qp = robot.to_pin_batch(full)
        R = np.empty((n, 3, 3))
        p = np.empty((n, 3))
        J = np.empty((n, 6, self.wire.size))
        for i in range(n):
            Ji = pin.computeFrameJacobian(model, data, qp[i], self.fid, pin.LOCAL_WORLD_ALIGNED)
            M = data.oMf[self.fid]
            R[i], p[i] = M.rotation, M.translation
            # (6,) from Pinocchio when nv == 1 (one joint and its mimic followers)
            J[i] = Ji.reshape(6, -1)[:, robot.v_index[self.wire]]
        return R, p, J

    def evaluate(self, Q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Component-major form of :meth:`__call__` (as :meth:`ChainJacobian.evaluate`)."""
        R, p, J = self(Q)
        return R.transpose(1, 2, 0), p.T, J.transpose(1, 2, 0)


def chain_for(robot: RobotModel, frame: str) -> ChainJacobian | PinocchioChain:
    """The vectorised chain of ``frame`` when its joints allow, else the Pinocchio loop."""
    chain = ChainJacobian.build(robot, frame)
    if chain is not None:
        return chain
    return PinocchioChain(robot, frame, support_columns(robot, frame))


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


# ------------------------------------------------------------------------------- spec
@dataclass
class MapSpec:
    """What to build: the grid, the sampling and the measure (module doc)."""

    robot_id: str
    frame: str
    lower: list[float]
    voxel_size: float
    shape: list[int]  # voxels per axis
    orientation_divisions: int
    rows: list[int]
    samples: int  # samples actually drawn
    sampling: str  # random | grid
    seed: int
    self_collision: str  # ignore | mesh | convex
    chain_wire: list[int]  # wire indices of the sampled joints
    chain_lower: list[float]
    chain_upper: list[float]
    grid_per_joint: int = 0

    @property
    def bins(self) -> int:
        return orientation_bins(self.orientation_divisions)

    @property
    def cells(self) -> int:
        return int(np.prod(self.shape)) * self.bins

    @property
    def upper(self) -> list[float]:
        return [lo + n * self.voxel_size for lo, n in zip(self.lower, self.shape, strict=True)]


def default_bounds(robot: RobotModel, frame: str) -> tuple[np.ndarray, np.ndarray]:
    """A box that contains every position of ``frame`` (module doc), in the root frame."""
    model = robot.model
    f = model.frames[robot.frame_id(frame)]
    chain = list(model.supports[f.parentJoint])[1:]
    by_pin = {j.pin_id: j for j in robot.joints}
    data = model.createData()
    pin.forwardKinematics(model, data, robot.to_pin(robot.neutral()))
    if not chain:
        c = pin.updateFramePlacement(model, data, robot.frame_id(frame)).translation
        return c - 1e-3, c + 1e-3
    center = data.oMi[chain[0]].translation.copy()
    reach = 0.0
    for jid in chain[1:]:
        reach += float(np.linalg.norm(model.jointPlacements[jid].translation))
    for jid in chain:
        j = by_pin.get(jid)
        if j is not None and j.type == "prismatic":
            reach += max(abs(j.lower or 0.0), abs(j.upper or 0.0))
    reach += float(np.linalg.norm(f.placement.translation))
    reach = reach * (1 + 1e-6) + 1e-6
    return center - reach, center + reach


def make_spec(
    robot: RobotModel,
    frame: str,
    *,
    voxel_size: float,
    lower: Sequence[float] | None = None,
    upper: Sequence[float] | None = None,
    orientation_divisions: int = 4,
    part: str | None = None,
    rows: Sequence[str | int] | None = None,
    samples: int = 100_000,
    sampling: str = "random",
    seed: int = 0,
    self_collision: str = "ignore",
    max_cells: int = MAX_CELLS,
) -> MapSpec:
    """Validate a build request; every error names its request field."""
    ridx = task_rows(part, rows)
    cols = support_columns(robot, frame)
    if not (math.isfinite(voxel_size) and voxel_size > 0):
        raise InvalidInputError("must be a positive number of metres", "voxel_size")
    if not 0 <= orientation_divisions <= MAX_ORIENTATION_DIVISIONS:
        raise InvalidInputError(f"must be 0 … {MAX_ORIENTATION_DIVISIONS}", "orientation_divisions")
    if not 1 <= samples <= MAX_SAMPLES:
        raise InvalidInputError(f"must be 1 … {MAX_SAMPLES}", "samples")
    if sampling not in ("random", "grid"):
        raise InvalidInputError("must be random or grid", "sampling")
    if self_collision not in ("ignore", "mesh", "convex"):
        raise InvalidInputError("must be ignore, mesh or convex", "self_collision")
    if self_collision != "ignore" and self_collision_check() is None:
        raise InvalidInputError(
            "self-collision checking is not available in this build", "self_collision"
        )
    dlo, dhi = default_bounds(robot, frame)
    lo = np.asarray(lower if lower is not None else dlo, dtype=float)
    hi = np.asarray(upper if upper is not None else dhi, dtype=float)
    for name, v in (("bounds.min", lo), ("bounds.max", hi)):
        if v.shape != (3,) or not np.all(np.isfinite(v)):
            raise InvalidInputError("must be 3 finite numbers (m)", name)
    bad = np.flatnonzero(hi <= lo)
    if bad.size:
        i = int(bad[0])
        raise InvalidInputError(
            f"max must exceed min on every axis (axis {'xyz'[i]}: {hi[i]} <= {lo[i]})",
            f"bounds.max.{i}",
        )
    with np.errstate(over="ignore"):
        extent = (hi - lo) / voxel_size
    if not np.all(extent <= 1e7):
        raise InvalidInputError("voxels too small for the bounds", "voxel_size")
    shape = [max(1, math.ceil(e - 1e-9)) for e in extent]
    cells = int(np.prod(shape)) * orientation_bins(orientation_divisions)
    if cells > max_cells:
        raise InvalidInputError(
            f"{shape[0]}×{shape[1]}×{shape[2]} voxels × {orientation_bins(orientation_divisions)}"
            f" orientation bins = {cells} cells exceed the limit of {max_cells}: use bigger "
            "voxels, smaller bounds or fewer orientation_divisions",
            "voxel_size",
        )
    clo = robot.lower[cols].copy()
    chi = robot.upper[cols].copy()
    cont = ~np.isfinite(clo) | ~np.isfinite(chi)
    clo[cont], chi[cont] = -math.pi, math.pi
    k = cols.size
    per = 0
    if sampling == "grid":
        per = max(2, round(samples ** (1.0 / k)))
        while per**k > MAX_SAMPLES:
            per -= 1
        samples = per**k
    return MapSpec(
        robot_id=robot.id,
        frame=frame,
        lower=lo.tolist(),
        voxel_size=float(voxel_size),
        shape=shape,
        orientation_divisions=orientation_divisions,
        rows=ridx.tolist(),
        samples=int(samples),
        sampling=sampling,
        seed=int(seed),
        self_collision=self_collision,
        chain_wire=cols.tolist(),
        chain_lower=clo.tolist(),
        chain_upper=chi.tolist(),
        grid_per_joint=per,
    )


def self_collision_check() -> Callable[[RobotModel, str], Callable[[np.ndarray], bool]] | None:
    """The collision module's self-collision check, if it provides one (module doc)."""
    try:
        mod = importlib.import_module("app.kinematics.collision")
    except ImportError:
        return None
    factory = getattr(mod, "collision_model", None)
    if factory is None:
        return None

    def make(robot: RobotModel, mode: str) -> Callable[[np.ndarray], bool]:
        cm = factory(robot, mode)
        return lambda q: bool(cm.collides(q))

    return make


# ------------------------------------------------------------------------------ worker
def chunk_samples(spec: MapSpec, start: int, stop: int) -> np.ndarray:
    """Samples [start, stop) of the build (one column per chain joint). Random samples come
    in blocks of :data:`BLOCK`: the block starting at sample b is drawn from a generator
    seeded with (seed, b), so any range gives the samples the build used."""
    lo = np.asarray(spec.chain_lower)
    hi = np.asarray(spec.chain_upper)
    n = stop - start
    if spec.sampling == "random":
        first = start - start % BLOCK
        blocks = [
            np.random.default_rng([spec.seed, b]).random((BLOCK, lo.size))
            for b in range(first, stop, BLOCK)
        ]
        u = np.concatenate(blocks)[start - first : start - first + n]
        return lo + (hi - lo) * u
    g = spec.grid_per_joint
    cont = np.isclose(hi - lo, 2 * math.pi) & np.isclose(lo, -math.pi)
    idx = np.unravel_index(np.arange(start, stop), (g,) * lo.size)
    out = np.empty((n, lo.size))
    for j in range(lo.size):
        step = (hi[j] - lo[j]) / (g if cont[j] else g - 1)
        out[:, j] = lo[j] + step * idx[j]
    return out


class MapBuilder:
    """Computes the reached cells of sample ranges for one spec (one per process)."""

    def __init__(self, robot: RobotModel, spec: MapSpec) -> None:
        self.robot = robot
        self.spec = spec
        self.chain = chain_for(robot, spec.frame)
        self.rows = np.asarray(spec.rows, dtype=int)
        self.lower = np.asarray(spec.lower)
        self.shape = np.asarray(spec.shape, dtype=np.int64)
        self.collides: Callable[[np.ndarray], bool] | None = None
        if spec.self_collision != "ignore":
            make = self_collision_check()
            if make is None:
                raise InvalidInputError(
                    "self-collision checking is not available", "self_collision"
                )
            self.collides = make(robot, spec.self_collision)

    def cells(self, start: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
        """Cell index and manipulability (float32) of each in-bounds sample of [start, stop).

        Cells may repeat: merging takes the maximum (``np.maximum.at``).
        """
        parts = [self._block(a, min(stop, a + BLOCK)) for a in range(start, stop, BLOCK)]
        if len(parts) == 1:
            return parts[0]
        return np.concatenate([c for c, _ in parts]), np.concatenate([w for _, w in parts])

    def _block(self, start: int, stop: int) -> tuple[np.ndarray, np.ndarray]:
        spec = self.spec
        Q = chunk_samples(spec, start, stop)
        if self.collides is not None:
            full = np.tile(self.robot.neutral(), (Q.shape[0], 1))
            full[:, spec.chain_wire] = Q
            keep = np.array([not self.collides(q) for q in full], dtype=bool)
            Q = Q[keep]
        if Q.shape[0] == 0:
            return np.empty(0, np.int64), np.empty(0, np.float32)
        Rt, P, J = self.chain.evaluate(Q)
        vox, ok = voxel_index(spec, self.lower, self.shape, P)
        w = yoshikawa_components(J[self.rows])
        cell = vox * spec.bins + orientation_bin_from_rotation(Rt, spec.orientation_divisions)
        return cell[ok], w[ok].astype(np.float32)


def voxel_index(
    spec: MapSpec, lower: np.ndarray, shape: np.ndarray, P: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Flat voxel index (N,) and in-bounds mask of component-major positions P (3, N)."""
    with np.errstate(over="ignore", invalid="ignore"):  # far-off positions: out of bounds
        v = np.floor((P - lower[:, None]) / spec.voxel_size)
    ok = np.all((v >= 0) & (v < shape[:, None]), axis=0)
    v = np.where(ok, v, 0).astype(np.int64)
    return (v[0] * shape[1] + v[1]) * shape[2] + v[2], ok


def _worker_main(
    robot_args: dict[str, Any], spec_args: dict[str, Any], tasks: Any, results: Any
) -> None:
    """A build process: take chunks from ``tasks`` until ``None``, fold them into a partial
    map of its own (max per cell), report each chunk's size, then send the partial map
    (reached cells and their values) and exit.

    It dies with the process that started the build (however that one ends, SIGKILL
    included) and with its forkserver: nothing else would end it once its queues are gone.
    """
    set_parent_death_signal()  # the forkserver (see app.kinematics.forkserver_init)
    watch_parent(kill_self)  # the process that started the build
    try:
        robot = RobotModel(**robot_args)
        spec = MapSpec(**spec_args)
        builder = MapBuilder(robot, spec)
        best = np.full(spec.cells, UNREACHED, dtype=np.float32)
        while (task := tasks.get()) is not None:
            a, b = task
            cells, vals = builder.cells(a, b)
            np.maximum.at(best, cells, vals)
            results.put(("n", b - a))
        idx = np.flatnonzero(best >= 0)
        results.put(("map", idx, best[idx]))
    except BaseException as exc:  # reported to the parent, which fails the build
        results.put(("error", f"{type(exc).__name__}: {exc}"))


# ------------------------------------------------------------------------------- build
@dataclass
class Progress:
    """Shared between a build and whoever watches it."""

    total: int
    done: int = 0
    started: float | None = None  # time.monotonic() when sampling began
    finished: float | None = None
    cancel: threading.Event = field(default_factory=threading.Event)

    def elapsed(self) -> float:
        """Seconds spent sampling so far (or in all, once finished)."""
        if self.started is None:
            return 0.0
        return (self.finished if self.finished is not None else time.monotonic()) - self.started

    def rate(self) -> float | None:
        """Samples per second so far."""
        dt = self.elapsed()
        return self.done / dt if self.done and dt > 0 else None

    def eta(self) -> float | None:
        """Seconds left at the current rate."""
        rate = self.rate()
        return (self.total - self.done) / rate if rate else None


class Cancelled(Exception):
    """The build was cancelled."""


def _chunks(total: int, size: int) -> list[tuple[int, int]]:
    return [(a, min(total, a + size)) for a in range(0, total, size)]


def build_map(
    robot: RobotModel,
    spec: MapSpec,
    progress: Progress | None = None,
    processes: int = 1,
    min_samples_per_process: int | None = None,
) -> np.ndarray:
    """The map's float32 grid (shape + (bins,)): best manipulability per cell, −1 unreached.

    Up to ``processes`` worker processes, but no more than one per
    ``min_samples_per_process`` samples (default :data:`MIN_SAMPLES_PER_PROCESS`, less with
    self-collision checks): starting a process costs up to about a second. Raises
    :class:`Cancelled` when ``progress.cancel`` is set (checked after every chunk, or
    every 0.1 s while worker processes run).
    """
    progress = progress or Progress(spec.samples)
    best = np.full(spec.cells, UNREACHED, dtype=np.float32)
    chunks = _chunks(spec.samples, CHUNK)
    progress.started = time.monotonic()

    def merge(n: int, cells: np.ndarray, vals: np.ndarray) -> None:
        np.maximum.at(best, cells, vals)
        progress.done += n

    if min_samples_per_process is None:
        min_samples_per_process = MIN_SAMPLES_PER_PROCESS
        if spec.self_collision != "ignore":
            min_samples_per_process //= 100
    processes = max(1, min(processes, len(chunks), spec.samples // max(1, min_samples_per_process)))
    if processes == 1:
        builder = MapBuilder(robot, spec)
        for a, b in chunks:
            if progress.cancel.is_set():
                raise Cancelled
            merge(b - a, *builder.cells(a, b))
    else:
        _build_in_processes(robot, spec, progress, processes, chunks, best)
    return best.reshape(*spec.shape, spec.bins)


def _build_in_processes(
    robot: RobotModel,
    spec: MapSpec,
    progress: Progress,
    processes: int,
    chunks: list[tuple[int, int]],
    best: np.ndarray,
) -> None:
    """Run the chunks over worker processes (:func:`_worker_main`) and merge their partial
    maps into ``best`` by maximum. Cancelling terminates the workers at once."""
    robot_args = {
        "robot_id": robot.id,
        "urdf_text": robot.urdf_text,
        "package_dirs": robot.package_dirs,
        "srdf_text": robot.srdf_text,
        "ee_frame": robot.ee_frame,
    }
    ctx = _context()
    tasks = ctx.Queue()
    results = ctx.Queue()
    for c in chunks:
        tasks.put(c)
    for _ in range(processes):
        tasks.put(None)
    workers = [
        ctx.Process(
            target=_worker_main,
            args=(robot_args, asdict(spec), tasks, results),
            name=f"reachability-{i}",
            daemon=True,
        )
        for i in range(processes)
    ]
    for w in workers:
        w.start()
    finished = 0
    try:
        while finished < processes:
            if progress.cancel.is_set():
                raise Cancelled
            try:
                msg = results.get(timeout=0.1)
            except queue.Empty:
                dead = [w for w in workers if not w.is_alive() and w.exitcode != 0]
                if dead:
                    raise RuntimeError(
                        f"build process {dead[0].name} died (exit code {dead[0].exitcode})"
                    ) from None
                continue
            if msg[0] == "n":
                progress.done += msg[1]
            elif msg[0] == "map":
                _, idx, vals = msg
                best[idx] = np.maximum(best[idx], vals)
                finished += 1
            else:
                raise RuntimeError(f"build process failed: {msg[1]}")
        for w in workers:
            w.join()
    finally:
        for w in workers:
            if w.is_alive():
                w.terminate()
        for w in workers:
            w.join(timeout=5)
        for q in (tasks, results):
            q.cancel_join_thread()
            q.close()


def _context() -> multiprocessing.context.BaseContext:
    """Forkserver: workers fork from a clean server process, never from this threaded one.
    The forkserver dies with the process that started it (``forkserver_init``)."""
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(["app.kinematics.forkserver_init", "app.kinematics.reachability"])
    return ctx


def default_processes() -> int:
    """Worker processes for a build: every core this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover
        return os.cpu_count() or 1


# ------------------------------------------------------------------------------- maps
def robot_fingerprint(robot: RobotModel) -> str:
    """A short hash of the robot's URDF: a map is only valid for the model it was built on."""
    return hashlib.sha256(robot.urdf_text.encode()).hexdigest()[:16]


@dataclass
class ReachabilityMap:
    """A finished map: its grid and metadata (``meta`` is the JSON stored with it)."""

    meta: dict[str, Any]
    best: np.ndarray  # (nx, ny, nz, bins) float32
    _voxel_best: np.ndarray | None = field(default=None, repr=False)

    @property
    def spec(self) -> MapSpec:
        return MapSpec(**self.meta["spec"])

    def to_bytes(self) -> bytes:
        buf = io.BytesIO()
        np.savez_compressed(buf, best=self.best, meta=np.array(json.dumps(self.meta)))
        return buf.getvalue()

    @classmethod
    def load(cls, path: Path) -> ReachabilityMap:
        with np.load(path, allow_pickle=False) as z:
            return cls(json.loads(str(z["meta"])), z["best"])

    def query(
        self, positions: np.ndarray, quaternions: np.ndarray | None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Reachable (N,), best manipulability (N, NaN where unreachable), in-bounds (N,).

        ``quaternions`` row of NaN (or ``None`` for all): any orientation, the best over the
        voxel's bins. O(1) per pose.
        """
        spec = self.spec
        lower = np.asarray(spec.lower)
        shape = np.asarray(spec.shape, dtype=np.int64)
        n = positions.shape[0]
        flat_best = self.best.reshape(-1)
        vox_best = self.voxel_best().reshape(-1)
        if quaternions is None:
            quaternions = np.full((n, 4), np.nan)
        anyq = np.isnan(quaternions).any(axis=1)
        qq = np.where(anyq[:, None], np.array([0.0, 0.0, 0.0, 1.0]), quaternions)
        vox, ok = voxel_index(spec, lower, shape, positions.T)
        cell = vox * spec.bins + orientation_bin(qq, spec.orientation_divisions)
        val = np.where(anyq, vox_best[vox], flat_best[cell]).astype(float)
        val = np.where(ok, val, -1.0)
        reach = val >= 0.0
        return reach, np.where(reach, val, np.nan), ok

    def voxel_best(self) -> np.ndarray:
        """Best manipulability over orientation bins per voxel (nx, ny, nz); −1 unreached."""
        if self._voxel_best is None:
            self._voxel_best = self.best.max(axis=3)
        return self._voxel_best


def summarize(best: np.ndarray) -> dict[str, Any]:
    """Counts and extremes of a grid, for the metadata."""
    reached = best >= 0
    return {
        "reachable_cells": int(reached.sum()),
        "reachable_voxels": int(reached.any(axis=3).sum()),
        "max_manipulability": float(best.max()) if reached.any() else None,
    }


def meta_public(meta: dict[str, Any]) -> dict[str, Any]:
    """Metadata as the API shows it."""
    spec = MapSpec(**meta["spec"])
    return {
        "map_id": meta["map_id"],
        "robot_id": spec.robot_id,
        "frame": spec.frame,
        "created_at": meta["created_at"],
        "bounds": {"min": spec.lower, "max": spec.upper},
        "voxel_size": spec.voxel_size,
        "shape": spec.shape,
        "orientation_divisions": spec.orientation_divisions,
        "orientation_bins": spec.bins,
        "cells": spec.cells,
        "rows": [ROW_NAMES[i] for i in spec.rows],
        "joints": meta["joints"],
        "samples": spec.samples,
        "sampling": spec.sampling,
        "seed": spec.seed,
        "self_collision": spec.self_collision,
        "samples_per_second": meta.get("samples_per_second"),
        "build_seconds": meta.get("build_seconds"),
        "robot_fingerprint": meta["robot_fingerprint"],
        **{k: meta[k] for k in ("reachable_cells", "reachable_voxels", "max_manipulability")},
    }


# ------------------------------------------------------------------------------ storage
MAP_ID_LENGTH = 32


def _valid_id(value: str) -> bool:
    return len(value) == MAP_ID_LENGTH and all(c in "0123456789abcdef" for c in value)


class MapStore:
    """Finished maps under ``<root>/<robot_id>/<map_id>.npz`` (root = data_dir/maps).

    Loaded maps are cached (a few, least recently used dropped) so queries stay O(1).
    """

    CACHED = 4

    def __init__(self, root: Path) -> None:
        self.root = Path(root)
        self._cache: dict[tuple[str, str], ReachabilityMap] = {}
        self._lock = threading.Lock()

    def _dir(self, robot_id: str) -> Path:
        safe = hashlib.sha256(robot_id.encode()).hexdigest()[:8]
        name = robot_id if robot_id.replace("_", "").replace("-", "").isalnum() else safe
        return self.root / name

    def path(self, robot_id: str, map_id: str) -> Path:
        return self._dir(robot_id) / f"{map_id}.npz"

    def save(self, m: ReachabilityMap) -> None:
        atomic_write_bytes(self.path(m.meta["spec"]["robot_id"], m.meta["map_id"]), m.to_bytes())

    def list(self, robot_id: str) -> list[dict[str, Any]]:
        """Metadata of the robot's maps, oldest first."""
        out = []
        d = self._dir(robot_id)
        for path in sorted(d.glob("*.npz")) if d.is_dir() else ():
            if not _valid_id(path.stem):
                continue
            try:
                with np.load(path, allow_pickle=False) as z:
                    out.append(json.loads(str(z["meta"])))
            except (OSError, ValueError, KeyError):
                continue  # unreadable file: not listed
        out.sort(key=lambda m: m["created_at"])
        return out

    def get(self, robot_id: str, map_id: str, field: str = "map_id") -> ReachabilityMap:
        """The map; raises :class:`UnknownNameError` naming ``field``."""
        key = (robot_id, map_id)
        with self._lock:
            m = self._cache.pop(key, None)
            if m is not None:
                self._cache[key] = m
                return m
        path = self.path(robot_id, map_id)
        if not _valid_id(map_id) or not path.is_file():
            known = [m["map_id"] for m in self.list(robot_id)]
            raise UnknownNameError("map", map_id, field, known)
        m = ReachabilityMap.load(path)
        with self._lock:
            self._cache[key] = m
            while len(self._cache) > self.CACHED:
                self._cache.pop(next(iter(self._cache)))
        return m

    def delete(self, robot_id: str, map_id: str) -> None:
        self.get(robot_id, map_id)
        with self._lock:
            self._cache.pop((robot_id, map_id), None)
        self.path(robot_id, map_id).unlink(missing_ok=True)


# --------------------------------------------------------------------------------- jobs
#: Statuses of a job that is not finished yet.
ACTIVE = ("queued", "running")
STATUSES = (*ACTIVE, "done", "failed", "cancelled")
#: Job snapshots and cancel markers live here, under the map store's root (a name no robot
#: directory can take: robot directories never start with a dot).
JOBS_DIR = ".jobs"
#: Seconds between two snapshots of an active job (and two looks for cancel markers).
PUBLISH_INTERVAL = 0.25
#: A snapshot written in another process namespace (another container on the same volume),
#: whose owner cannot be checked by pid, counts as orphaned once this old.
STALE_SECONDS = 30.0
OWNER_GONE = "the worker process building it stopped"
_JOB_KEYS = ("job_id", "robot_id", "frame", "status", "map_id", "error", "progress")

log = logging.getLogger("denavit.reachability")


def _process_stat(pid: int) -> tuple[str, int] | None:
    """State letter and start time (clock ticks after boot) of process ``pid`` from
    ``/proc/<pid>/stat``; ``None`` where that cannot be read."""
    try:
        raw = Path(f"/proc/{pid}/stat").read_bytes()
        fields = raw[raw.rindex(b")") + 2 :].split()
        return fields[0].decode(), int(fields[19])
    except (OSError, ValueError, IndexError):
        return None


def _pid_namespace() -> str:
    """Who can check our pids: the host name and this process's pid namespace."""
    try:
        ns = os.readlink("/proc/self/ns/pid")
    except OSError:
        ns = ""
    return f"{socket.gethostname()} {ns}"


_PID_SPACE = _pid_namespace()


def _process_alive(pid: int, started: int | None) -> bool:
    """Whether process ``pid`` still runs (and is the one that started at ``started``, when
    known: a pid reused after a restart is another process)."""
    try:
        os.kill(pid, 0)  # signal 0: only checks that the process exists
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # it exists, as another user
    stat = _process_stat(pid)
    if stat is None:
        return True  # no /proc: the signal check is all there is
    state, start = stat
    return state not in ("Z", "X") and (started is None or start == started)


@dataclass
class BuildJob:
    """A map build running (or queued) in the background, owned by this process."""

    job_id: str
    robot_id: str
    spec: MapSpec
    progress: Progress
    status: str = "queued"  # queued | running | done | failed | cancelled
    created_at: float = field(default_factory=time.time)
    finished_at: float | None = None
    map_id: str | None = None
    error: str | None = None

    def to_json(self) -> dict[str, Any]:
        p = self.progress
        return {
            "job_id": self.job_id,
            "robot_id": self.robot_id,
            "frame": self.spec.frame,
            "status": self.status,
            "map_id": self.map_id,
            "error": self.error,
            "progress": {
                "percent": 100.0 * p.done / p.total if p.total else 100.0,
                "samples_done": p.done,
                "samples_total": p.total,
                "samples_per_second": p.rate(),
                "elapsed_seconds": p.elapsed(),
                "eta_seconds": 0.0
                if self.status == "done"
                else (p.eta() if self.status == "running" else None),
            },
        }


@dataclass(frozen=True)
class JobSnapshot:
    """A job of another process, as its owner last published it: ``record`` is the owner's
    :meth:`BuildJob.to_json` (``to_json`` and ``status`` read as on a :class:`BuildJob`)."""

    record: dict[str, Any]
    created_at: float
    finished_at: float | None
    updated_at: float
    owner_pid: int
    owner_token: str
    owner_space: str
    owner_started: int | None

    @property
    def job_id(self) -> str:
        return self.record["job_id"]

    @property
    def robot_id(self) -> str:
        return self.record["robot_id"]

    @property
    def status(self) -> str:
        return self.record["status"]

    def to_json(self) -> dict[str, Any]:
        return {**self.record, "progress": dict(self.record["progress"])}

    @classmethod
    def parse(cls, data: bytes, job_id: str) -> JobSnapshot | None:
        """The snapshot in a job file's bytes; ``None`` if they do not hold one of job_id."""
        try:
            raw = json.loads(data)
            record = {k: raw[k] for k in _JOB_KEYS}
            started = raw["owner_started"]
            snap = cls(
                record,
                float(raw["created_at"]),
                None if raw["finished_at"] is None else float(raw["finished_at"]),
                float(raw["updated_at"]),
                raw["owner_pid"],
                str(raw["owner_token"]),
                str(raw["owner_space"]),
                started if isinstance(started, int) else None,
            )
        except (ValueError, TypeError, KeyError):
            return None
        valid = (
            record["job_id"] == job_id
            and isinstance(record["robot_id"], str)
            and record["status"] in STATUSES
            and isinstance(record["progress"], dict)
            and type(snap.owner_pid) is int
            and snap.owner_pid > 0
        )
        return snap if valid else None

    def owner_gone(self) -> bool:
        """Whether the process that owns this job has stopped."""
        if self.owner_space != _PID_SPACE:  # its pids are not ours to check
            return time.time() - self.updated_at > STALE_SECONDS
        return not _process_alive(self.owner_pid, self.owner_started)

    def resolved(self) -> JobSnapshot:
        """This snapshot, or, if it says queued/running but its owner has stopped, the job
        reported failed (nobody will ever finish it)."""
        if self.status not in ACTIVE or not self.owner_gone():
            return self
        progress = {**self.record["progress"], "eta_seconds": None}
        record = {**self.record, "status": "failed", "error": OWNER_GONE, "progress": progress}
        return replace(self, record=record, finished_at=self.updated_at)


class BuildJobs:
    """Runs builds one after another in a background thread; each build uses ``processes``.

    Jobs run in the process that accepted them and are answered for by every process
    sharing the map store (uvicorn workers on one data directory):

    - The owner publishes each job as ``<root>/.jobs/<job_id>.json`` (root = the map
      store's root): :meth:`BuildJob.to_json` plus ``created_at``, ``finished_at``,
      ``updated_at`` (wall clock) and the owner's pid, process start time, pid namespace
      and instance token. It writes it on submit, on every status change and, from one
      publisher thread per instance, every :data:`PUBLISH_INTERVAL` s while the job is
      queued or running. Writes are atomic (temporary ``.tmp-*`` file, rename; no fsync:
      the status is ephemeral). A job's final snapshot is written before the job reads as
      finished in memory, so no process sees it finished while another still sees it run.
    - :meth:`get` and :meth:`list` answer with the in-memory job when this process owns it,
      else with the published :class:`JobSnapshot`; a snapshot that says queued/running
      whose owner has stopped (pid gone, or reused by another process) reads as failed.
    - :meth:`cancel` of another process's job creates ``<job_id>.cancel``; the owner's
      publisher looks for markers of its active jobs on every tick and cancels them as a
      local cancel does, and removes the marker when the job finishes.

    A restart forgets nothing a client needs: finished maps are files, and the jobs of a
    stopped process read as failed. At most ``max_active`` builds may be queued or running
    in one process (more is a conflict); ``max_jobs`` finished jobs are remembered in
    memory, and the job files keep the ``max_jobs`` newest finished jobs of all processes
    (older ones are deleted on submit; active ones never are).
    """

    def __init__(
        self,
        store: MapStore,
        processes: int | None = None,
        max_jobs: int = 64,
        max_active: int = 8,
        publish_interval: float = PUBLISH_INTERVAL,
    ):
        self.store = store
        self.processes = processes or default_processes()
        self.max_jobs = max_jobs
        self.max_active = max_active
        self.publish_interval = publish_interval
        self.jobs: dict[str, BuildJob] = {}
        self.dir = store.root / JOBS_DIR
        #: Tells this instance's snapshots apart from other instances in the same process.
        self.token = uuid.uuid4().hex
        self._pid = os.getpid()
        stat = _process_stat(self._pid)
        self._started = stat[1] if stat else None
        self._lock = threading.Lock()  # jobs, their statuses and their files
        self._queue: queue.Queue[tuple[RobotModel, BuildJob]] = queue.Queue()
        self._thread: threading.Thread | None = None
        self._publisher: threading.Thread | None = None
        self._publish_failing = False

    # ------------------------------------------------------------------ files
    def _path(self, job_id: str) -> Path:
        return self.dir / f"{job_id}.json"

    def _marker(self, job_id: str) -> Path:
        return self.dir / f"{job_id}.cancel"

    def _publish(self, job: BuildJob) -> None:
        """Write the job's snapshot (with the lock held). A failed write is logged, not
        raised: the job still runs and this process still answers for it."""
        record = {
            **job.to_json(),
            "created_at": job.created_at,
            "finished_at": job.finished_at,
            "updated_at": time.time(),
            "owner_pid": self._pid,
            "owner_token": self.token,
            "owner_space": _PID_SPACE,
            "owner_started": self._started,
        }
        try:
            atomic_write_bytes(self._path(job.job_id), json.dumps(record).encode(), durable=False)
        except OSError as exc:
            if not self._publish_failing:
                log.warning("cannot publish build job %s: %s", job.job_id, exc)
            self._publish_failing = True
        else:
            self._publish_failing = False

    def _read(self, job_id: str) -> JobSnapshot | None:
        """The published snapshot of ``job_id`` (a valid id), resolved; ``None`` if none."""
        try:
            data = self._path(job_id).read_bytes()
        except OSError:
            return None
        snap = JobSnapshot.parse(data, job_id)
        return None if snap is None else snap.resolved()

    def _snapshots(self, skip: frozenset[str] | set[str] = frozenset()) -> list[JobSnapshot]:
        """Every published snapshot but those of ``skip`` (job ids)."""
        try:
            names = os.listdir(self.dir)
        except OSError:
            return []
        out = []
        for name in names:
            stem, _, ext = name.partition(".")
            if ext == "json" and _valid_id(stem) and stem not in skip:
                snap = self._read(stem)
                if snap is not None:
                    out.append(snap)
        return out

    def _housekeep(self) -> None:
        """Delete the oldest finished job files beyond ``max_jobs``, and cancel markers of
        finished jobs (or of jobs without a file for :data:`STALE_SECONDS`)."""
        snaps = self._snapshots()
        finished = sorted((s for s in snaps if s.status not in ACTIVE), key=lambda s: s.created_at)
        for s in finished[: max(0, len(finished) - self.max_jobs)]:
            self._path(s.job_id).unlink(missing_ok=True)
        status = {s.job_id: s.status for s in snaps}
        try:
            markers = [n for n in os.listdir(self.dir) if n.endswith(".cancel")]
        except OSError:
            return
        for name in markers:
            path = self.dir / name
            job_status = status.get(name.removesuffix(".cancel"))
            try:
                orphan = job_status is None and time.time() - path.stat().st_mtime > STALE_SECONDS
                if orphan or (job_status is not None and job_status not in ACTIVE):
                    path.unlink(missing_ok=True)
            except OSError:
                continue

    # ------------------------------------------------------------------ jobs
    def submit(self, robot: RobotModel, spec: MapSpec) -> BuildJob:
        with self._lock:
            active = {j.job_id for j in self.jobs.values() if j.status in ACTIVE}
            if len(active) >= self.max_active:
                raise ConflictError(
                    f"{len(active)} builds are already queued or running; cancel one or wait",
                    "robot_id",
                )
            for old in [i for i in self.jobs if i not in active]:
                if len(self.jobs) < self.max_jobs:
                    break
                del self.jobs[old]
            job = BuildJob(uuid.uuid4().hex, robot.id, spec, Progress(spec.samples))
            self.jobs[job.job_id] = job
            self._publish(job)
            # daemon threads: a build in progress never holds up the process's exit
            if self._thread is None:
                self._thread = threading.Thread(
                    target=self._loop, name="reachability-builds", daemon=True
                )
                self._thread.start()
            if self._publisher is None:
                self._publisher = threading.Thread(
                    target=self._publish_loop, name="reachability-jobs", daemon=True
                )
                self._publisher.start()
        self._queue.put((robot, job))
        try:
            self._housekeep()
        except OSError as exc:  # pragma: no cover - a file system gone bad
            log.warning("cannot clean up build job files: %s", exc)
        return job

    def _loop(self) -> None:
        while True:
            robot, job = self._queue.get()
            self._run(robot, job)

    def _publish_loop(self) -> None:
        """Refresh the snapshots of active jobs and act on cancel markers; ends when no job
        is active (:meth:`submit` starts it again)."""
        while True:
            time.sleep(self.publish_interval)
            with self._lock:
                active = [j for j in self.jobs.values() if j.status in ACTIVE]
                if not active:
                    self._publisher = None
                    return
            try:
                wanted = {j.job_id for j in active if self._marker(j.job_id).exists()}
                with self._lock:
                    for job in active:
                        if job.job_id in wanted and job.status in ACTIVE:
                            self._cancel(job)
                        if job.status in ACTIVE:
                            self._publish(job)
            except Exception:  # never let the thread die while jobs depend on it
                log.exception("publishing build jobs failed")

    def get(self, robot_id: str, job_id: str) -> BuildJob | JobSnapshot:
        """The job: this process's own, else another process's published snapshot."""
        job = self.jobs.get(job_id)
        if job is not None and job.robot_id == robot_id:
            return job
        snap = self._read(job_id) if job is None and _valid_id(job_id) else None
        if snap is not None and snap.robot_id == robot_id:
            return snap
        known = [j.job_id for j in self.list(robot_id)]
        raise UnknownNameError("job", job_id, "job_id", known)

    def list(self, robot_id: str) -> list[BuildJob | JobSnapshot]:
        """The robot's jobs, this process's and the others', oldest first."""
        with self._lock:
            own = [j for j in self.jobs.values() if j.robot_id == robot_id]
            ids = set(self.jobs)
        others = [s for s in self._snapshots(skip=ids) if s.robot_id == robot_id]
        return sorted([*own, *others], key=lambda j: j.created_at)

    def cancel(self, robot_id: str, job_id: str) -> BuildJob | JobSnapshot:
        """Cancel a queued or running build (idempotent); a finished one is a conflict.

        Another process's job gets a cancel marker, which its owner acts on within
        :data:`PUBLISH_INTERVAL` s; the snapshot returned is the job before that.
        """
        job = self.get(robot_id, job_id)
        if isinstance(job, JobSnapshot):
            if job.status in ("done", "failed"):
                raise ConflictError(f"the job has already {job.status}", "job_id")
            if job.status in ACTIVE:
                self._marker(job_id).touch()
            return job
        with self._lock:
            if job.status in ("done", "failed"):
                raise ConflictError(f"the job has already {job.status}", "job_id")
            self._cancel(job)
        return job

    def _cancel(self, job: BuildJob) -> None:
        """Cancel an own job (with the lock held): a queued one at once, a running one when
        :func:`build_map` next looks at ``progress.cancel``."""
        job.progress.cancel.set()
        if job.status == "queued":
            self._finish(job, "cancelled")

    def _finish(
        self, job: BuildJob, status: str, map_id: str | None = None, error: str | None = None
    ) -> None:
        """Publish the job's final state, then make it final in memory (lock held)."""
        if job.progress.finished is None:
            job.progress.finished = time.monotonic()
        final = replace(job, status=status, map_id=map_id, error=error, finished_at=time.time())
        self._publish(final)
        job.map_id, job.error, job.finished_at = map_id, error, final.finished_at
        job.status = status
        try:
            self._marker(job.job_id).unlink(missing_ok=True)
        except OSError:
            pass

    def _run(self, robot: RobotModel, job: BuildJob) -> None:
        with self._lock:
            if job.status != "queued":  # cancelled while queued
                return
            self._publish(replace(job, status="running"))
            job.status = "running"
        try:
            best = build_map(robot, job.spec, job.progress, self.processes)
            job.progress.finished = time.monotonic()
            took = job.progress.elapsed()
            meta = {
                "map_id": uuid.uuid4().hex,
                "created_at": datetime.now(UTC).isoformat(),
                "spec": asdict(job.spec),
                "joints": [robot.joint_names[i] for i in job.spec.chain_wire],
                "robot_fingerprint": robot_fingerprint(robot),
                "build_seconds": took,
                "samples_per_second": job.spec.samples / took if took > 0 else None,
                **summarize(best),
            }
            self.store.save(ReachabilityMap(meta, best))
        except Cancelled:
            outcome: tuple[str, str | None, str | None] = ("cancelled", None, None)
        except Exception as exc:  # reported on the job, not raised into the void
            outcome = ("failed", None, f"{type(exc).__name__}: {exc}")
        else:
            outcome = ("done", meta["map_id"], None)
        with self._lock:
            self._finish(job, *outcome)

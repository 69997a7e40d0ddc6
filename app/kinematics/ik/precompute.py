"""What the IK solver precomputes per (robot, frame): :class:`IKChain`.

The joints that move the frame (their columns, continuous/plain split, clipped limits), a
fixed table of restart configurations uniform within the limits with their forward-
kinematics poses (the nearest-sample ranking of the restarts), and, where available, the
compiled loop's constants (:class:`app.kinematics.ik_kernel.CompiledChain`) and the closed
forms (:mod:`app.kinematics.analytic_ik`). Built once per model and frame and cached on the
model (:func:`ik_chain`); read-only afterwards.

Not to be confused with :mod:`app.kinematics.chain`, the vectorised serial-chain geometry
(FK and Jacobians of many configurations) that the compiled kernels use.
"""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin

from app.kinematics import analytic_ik, ik_kernel
from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group
from app.kinematics.ik import compiled as driver  # imported first by the package: no cycle
from app.kinematics.ik.scale import rotation_weight
from app.kinematics.models import MAX_JOINT_VALUE, RobotModel

#: Weight (m²) of the rotation distance (‖R − R_t‖²_F) against the position distance (m²)
#: in the ranking of table samples by pose distance to a target, for chains 0.4–2.5 m long;
#: scaled with the length outside (:func:`app.kinematics.ik.scale.rotation_weight`).
ROT_WEIGHT = 0.2
#: Seed and size of the per-chain table of restart configurations.
RNG_SEED = 0x1C0DE
TABLE = 4096


class IKChain:
    """What the solver precomputes for one (robot, frame): the joints that move it.

    Built once per model, frame and planning group (``RobotModel.lazy``) and read-only
    afterwards. With ``joints`` (wire indices of a planning group's joints), only those among
    the joints that move the frame are active.
    """

    def __init__(self, robot: RobotModel, frame: str, joints: np.ndarray | None = None) -> None:
        self.frame = frame
        self.frame_id = robot.frame_id(frame)
        self.active = robot.supporting_joints(frame, joints)  # wire indices
        joints = [robot.joints[i] for i in self.active]
        self.k = len(joints)
        self.cols = np.array([j.idx_v for j in joints], dtype=int)
        cont = np.array([j.continuous for j in joints], dtype=bool)
        self.has_continuous = bool(cont.any())
        self.plain = np.flatnonzero(~cont)  # positions within the active set
        self.plain_q = np.array([j.idx_q for j in joints if not j.continuous], dtype=int)
        self.cont = np.flatnonzero(cont)
        self.cont_q = np.array([j.idx_q for j in joints if j.continuous], dtype=int)
        self.cont_q1 = self.cont_q + 1
        # Searched within the limits, and within ±MAX_JOINT_VALUE (what every endpoint accepts
        # back) when a URDF gives wider limits; continuous joints (±inf) are wrapped instead.
        lo, hi = robot.lower[self.active], robot.upper[self.active]
        self.lower = np.where(np.isfinite(lo), np.maximum(lo, -MAX_JOINT_VALUE), lo)
        self.upper = np.where(np.isfinite(hi), np.minimum(hi, MAX_JOINT_VALUE), hi)
        # Restart sampling box: the limits, or one turn for continuous joints.
        self.sample_lo = np.where(np.isfinite(self.lower), self.lower, -math.pi)
        self.sample_hi = np.where(np.isfinite(self.upper), self.upper, math.pi)
        # A fixed table of restart configurations (uniform in the box): restarts cost no
        # random-number setup per query, and answers are reproducible.
        u = np.random.default_rng(RNG_SEED).random((TABLE, self.k))
        self.restart_table = self.sample_lo + (self.sample_hi - self.sample_lo) * u
        self.clip_lo = np.where(np.isfinite(self.lower), self.lower, -np.inf)
        self.clip_hi = np.where(np.isfinite(self.upper), self.upper, np.inf)
        # Index objects of the hot loop: slices (views, no copies) when contiguous.
        self.cols_sel = _as_slice(self.cols)
        self.plain_q_sel = _as_slice(self.plain_q) if not self.has_continuous else self.plain_q
        self.mid_range = robot.mid_range()
        #: Every wire joint's limits as lists (the verification's check, no NumPy calls).
        self.wire_lower, self.wire_upper = robot.lower.tolist(), robot.upper.tolist()
        #: Whether a wire configuration is Pinocchio's as is (no conversion to make).
        self.wire_is_pin = robot.model.nq == robot.n and np.array_equal(
            robot.to_pin(np.arange(robot.n, dtype=float)), np.arange(robot.n)
        )
        #: Closed-form geometry of the chain, set on first use by ``analytic_ik``.
        self.closed_form: tuple | None = None
        #: Branch structure (:func:`app.kinematics.ik.branches.branch_form`); False until
        #: detected on first use.
        self.branch_form: object = False
        #: Reach bound parts (:func:`app.kinematics.ik.failure.reach_bound`); False until
        #: computed on first use.
        self.reach_parts: object = False
        self._robot = robot
        self._poses: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
        self._poses_T: np.ndarray | None = None  # M transposed, for the compiled distances
        self.sample_poses()  # built now, so no query pays for it
        #: The compiled loop's constants (:mod:`ik_kernel`), or None: the Python loop.
        self.compiled = (
            ik_kernel.CompiledChain.build(robot, frame, self.active)
            if ik_kernel.available()
            else None
        )
        driver.warm_up()  # compiled now, outside any query's time budget
        analytic_ik.prepare(robot, self)
        self.cont_mask = cont
        #: The compiled search's constants (:func:`.compiled.pack`), with ``compiled``.
        self.search_pack = driver.pack(self) if self.compiled is not None else None

    def sample_poses(self) -> tuple[np.ndarray, np.ndarray]:
        """Poses of the restart table: M = −2·[p | c·vec(R)] (N, 12) and ‖p‖² + 3c (N,).

        With them the pose distance to a target is one matrix-vector product:
        ‖p − p_t‖² + c‖R − R_t‖²_F = (‖p‖² + 3c) − 2·[p | c·vec(R)]·[p_t; vec(R_t)] + K_t,
        K_t = ‖p_t‖² + 3c, using ‖R − R_t‖²_F = 6 − 2 vec(R)·vec(R_t). Computed when the chain
        is built (one FK per sample).
        """
        if self._poses is None:
            robot = self._robot
            model, data = robot.model, robot.model.createData()
            q = self.mid_range.copy()
            c = rotation_weight(robot, self.frame_id, ROT_WEIGHT)
            W = np.empty((TABLE, 12))
            for i, row in enumerate(self.restart_table):
                q[self.active] = row
                pin.forwardKinematics(model, data, robot.to_pin(q))
                T = pin.updateFramePlacement(model, data, self.frame_id)
                W[i, :3] = T.translation
                W[i, 3:] = c * T.rotation.ravel()
            P = W[:, :3]
            # float32: the ranking needs no more, and the product runs twice as fast.
            M = (-2.0 * W).astype(np.float32)
            self._poses = (M, (np.einsum("ij,ij->i", P, P) + 3.0 * c).astype(np.float32))
            if ik_kernel.available():
                self._poses_T = np.ascontiguousarray(M.T)
        return self._poses

    def sample_distances(self, target: pin.SE3) -> tuple[np.ndarray, float]:
        """Pose distances of the table samples to ``target``, up to the constant K_t returned
        with them (‖p − p_t‖² + c‖R − R_t‖²_F = d_i + K_t)."""
        return self.sample_distances_argmin(target)[:2]

    def sample_distances_argmin(self, target: pin.SE3) -> tuple[np.ndarray, float, int]:
        """:meth:`sample_distances` and the index of the nearest sample."""
        M, W2 = self.sample_poses()
        pt = target.translation
        x = np.concatenate((pt, target.rotation.ravel())).astype(np.float32)
        k_t = float(pt @ pt) + 3.0 * rotation_weight(self._robot, self.frame_id, ROT_WEIGHT)
        if self._poses_T is not None:
            d = np.empty(TABLE, dtype=np.float32)
            i = ik_kernel.sample_distances(self._poses_T, W2, x, d)
            return d, k_t, int(i)
        d = M @ x
        d += W2
        return d, k_t, int(d.argmin())


def ik_chain(robot: RobotModel, frame: str, group: Group | None = None) -> IKChain:
    """The cached :class:`IKChain` of ``frame`` (raises UnknownNameError for a bad frame),
    moving only ``group``'s joints when given (InvalidInputError naming ``group`` when none
    of them moves the frame)."""
    robot.frame_id(frame)
    if group is None:
        return robot.lazy(f"ik.chain:{frame}", lambda r: IKChain(r, frame))

    def build(r: RobotModel) -> IKChain:  # checked once, with the chain (not per request)
        if r.supporting_joints(frame, group.indices).size == 0:
            raise InvalidInputError(
                f"no joint of group {group.name!r} ({', '.join(group.joints) or 'none'}) moves "
                f"frame {frame!r}",
                "group",
            )
        return IKChain(r, frame, group.indices)

    return robot.lazy(f"ik.chain:{frame}|group:{group.name}", build)


def k_smallest(d: np.ndarray, k: int) -> np.ndarray:
    """Indices of the k smallest entries of ``d``, in increasing order."""
    k = min(k, d.size)
    idx = np.argpartition(d, k - 1)[:k]
    return idx[np.argsort(d[idx])]


def _as_slice(idx: np.ndarray) -> slice | np.ndarray:
    """``idx`` as a slice when it is a run of consecutive integers."""
    if idx.size and np.array_equal(idx, np.arange(idx[0], idx[0] + idx.size)):
        return slice(int(idx[0]), int(idx[0]) + idx.size)
    return idx

"""What the IK solver precomputes per (robot, frame): :class:`IKChain`.

The joints that move the frame (their columns, continuous/plain split, clipped limits), a
fixed table of restart configurations uniform within the limits with their forward-
kinematics poses (the nearest-sample ranking of the restarts), and, where available, the
compiled loop's constants (:class:`app.kinematics.ik.kernel.CompiledChain`) and the closed
forms (:mod:`app.kinematics.analytic_ik`). Built once per model, frame and parameters and
cached on the model (:func:`ik_chain`, typed :class:`~app.kinematics.models.LazyKey`);
read-only afterwards.

Not to be confused with :mod:`app.kinematics.chain`, the vectorised serial-chain geometry
(FK and Jacobians of many configurations) that the compiled kernels use.
"""

from __future__ import annotations

import math
from functools import cached_property, lru_cache
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.groups import Group
from app.kinematics.ik import kernel
from app.kinematics.ik.boundary import ChainConstants, SearchConstants, step_parameters
from app.kinematics.ik.kernel import CompiledChain
from app.kinematics.ik.parameters import DEFAULT_PARAMETERS, SolverParameters
from app.kinematics.ik.scale import joint_units, length_scale, rotation_weight
from app.kinematics.jit import available
from app.kinematics.lazy import LazyKey
from app.kinematics.models import MAX_JOINT_VALUE, RobotModel

if TYPE_CHECKING:
    from app.kinematics.analytic_ik import Planar2, URType
    from app.kinematics.ik.annotate import AnnotationConstants
    from app.kinematics.ik.boundary import SearchState
    from app.kinematics.ik.branches import BranchForm
    from app.kinematics.ik.failure import ReachParts
    from app.kinematics.ik.query_kernel import QueryConstants, QueryState


class SamplePoses(NamedTuple):
    """The restart table's poses, for the pose distance to a target as one product
    (:meth:`IKChain.sample_distances`): ``M`` = −2·[p | c·vec(R)] (N, 12) float32, ``W2`` =
    ‖p‖² + 3c (N,) float32 and ``MT``, M transposed (12, N), for the compiled distances
    (None without Numba)."""

    M: np.ndarray
    W2: np.ndarray
    MT: np.ndarray | None


class IKChain:
    """What the solver precomputes for one (robot, frame): the joints that move it.

    Built once per model, frame, planning group and parameters (``RobotModel.lazy``) and
    read-only afterwards. With ``joints`` (wire indices of a planning group's joints), only
    those among the joints that move the frame are active. The constructor computes the
    index sets and the restart table's configurations only; the costly parts are cached
    properties, computed on first use (:func:`ik_chain` computes them before handing the
    chain out: :meth:`prepare`): :attr:`poses` (one FK per table sample), :attr:`compiled`
    and :attr:`search_constants` (the compiled loop's), :attr:`closed_form`,
    :attr:`branch_form` and :attr:`reach_parts`.
    """

    def __init__(
        self,
        robot: RobotModel,
        frame: str,
        joints: np.ndarray | None = None,
        parameters: SolverParameters = DEFAULT_PARAMETERS,
    ) -> None:
        self.parameters = parameters
        self.frame = frame
        self.frame_id = robot.frame_id(frame)
        self.active = robot.supporting_joints(frame, joints)  # wire indices
        joints = [robot.joints[i] for i in self.active]
        self.k = len(joints)
        self.cols = np.array([j.idx_v for j in joints], dtype=int)
        cont = np.array([j.continuous for j in joints], dtype=bool)
        self.cont_mask = cont
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
        u = np.random.default_rng(parameters.rng_seed).random((parameters.table, self.k))
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
        #: One idle compiled-search state per thread (:func:`app.kinematics.ik.compiled.
        #: run_compiled` takes it and puts it back): the next query on that thread reuses
        #: its arrays, hot in cache, instead of allocating them.
        self.idle_states: dict[int, SearchState] = {}
        #: The same for the single-answer fast path (:mod:`app.kinematics.ik.single`).
        self.idle_query_states: dict[int, QueryState] = {}
        self._robot = robot

    def prepare(self) -> IKChain:
        """Compute every cached part now (the restart table's poses, the compiled loop's
        constants, the closed forms, compiled for this chain's argument types), so that no
        query's time budget pays for them; returns the chain."""
        from app.kinematics import analytic_ik
        from app.kinematics.ik.warmup import warm_up

        warm_up()  # the kernels (once per process)
        _ = self.poses, self.search_constants, self.annotation, self.query_constants
        analytic_ik.prepare(self._robot, self)
        return self

    @cached_property
    def rot_weight(self) -> float:
        """The restart ranking's rotation weight c (m²) for this chain's length
        (:func:`app.kinematics.ik.scale.rotation_weight` of ``parameters.rot_weight``)."""
        return rotation_weight(self._robot, self.frame_id, self.parameters.rot_weight)

    @cached_property
    def distinct(self) -> np.ndarray:
        """Per wire joint, the largest difference (rad, or m for a prismatic joint: scaled by
        the chain's length) at which two solutions are the same one."""
        return self.parameters.distinct * joint_units(
            self._robot, length_scale(self._robot, self.frame_id)
        )

    @cached_property
    def poses(self) -> SamplePoses:
        """The restart table's poses (:class:`SamplePoses`; one FK per sample)."""
        return table_poses(self._robot, self)

    @cached_property
    def compiled(self) -> CompiledChain | None:
        """The compiled loop's kinematic constants (:mod:`.kernel`), or None: the Python
        loop (not a plain serial chain of 1-DoF joints, or no Numba)."""
        if not (available() and self.parameters.compiled):
            return None
        return CompiledChain.build(self._robot, self.frame, self.active)

    @cached_property
    def chain_constants(self) -> ChainConstants | None:
        """:attr:`compiled` with this chain's limits and continuous joints, or None."""
        cc = self.compiled
        return None if cc is None else cc.constants(self.clip_lo, self.clip_hi, self.cont_mask)

    @cached_property
    def search_constants(self) -> SearchConstants | None:
        """What :func:`.search_kernel.search` reads of this chain, or None (no
        :attr:`compiled`)."""
        chain = self.chain_constants
        if chain is None:
            return None
        p = self.parameters
        redundant = self.k > 6
        M, W2, _ = self.poses
        tab32 = np.ascontiguousarray(np.vstack((M.T, W2[None])), dtype=np.float32)
        return SearchConstants(
            chain, step_parameters(p), float(p.nearest_ratio), float(self.rot_weight),
            bool(redundant and p.null_gain > 0.0), bool(p.clamp and redundant),
            bool(p.nearest_first), tab32, self.restart_table,
        )  # fmt: skip

    @cached_property
    def closed_form(self) -> tuple[URType | None, Planar2 | None]:
        """The chain's closed-form geometries (:func:`app.kinematics.analytic_ik.closed_forms`;
        (None, None): none applies)."""
        from app.kinematics.analytic_ik import closed_forms

        return closed_forms(self._robot, self)

    @cached_property
    def branch_form(self) -> BranchForm | None:
        """Branch structure (:func:`app.kinematics.ik.branches.detect_branch_form`)."""
        from app.kinematics.ik.branches import detect_branch_form

        return detect_branch_form(self._robot, self)

    @cached_property
    def annotation(self) -> AnnotationConstants | None:
        """The compiled annotation's constants (:func:`app.kinematics.ik.annotate.
        annotation_constants`), or None: Pinocchio labels and measures the answers."""
        from app.kinematics.ik.annotate import annotation_constants

        return annotation_constants(self._robot, self)

    @cached_property
    def query_constants(self) -> QueryConstants | None:
        """The fast path's packed constants (:func:`app.kinematics.ik.query_kernel.pack`), or
        None: no compiled search or annotation (the general path answers)."""
        from app.kinematics.ik.query_kernel import pack

        return pack(self)

    @cached_property
    def reach_parts(self) -> ReachParts | None:
        """Reach bound parts (:func:`app.kinematics.ik.failure.reach_parts_of`)."""
        from app.kinematics.ik.failure import reach_parts_of

        return reach_parts_of(self._robot, self)

    def sample_distances(self, target: pin.SE3) -> tuple[np.ndarray, float]:
        """Pose distances of the table samples to ``target``, up to the constant K_t returned
        with them (‖p − p_t‖² + c‖R − R_t‖²_F = d_i + K_t)."""
        return self.sample_distances_argmin(target)[:2]

    def sample_distances_argmin(self, target: pin.SE3) -> tuple[np.ndarray, float, int]:
        """:meth:`sample_distances` and the index of the nearest sample."""
        M, W2, MT = self.poses
        rot_weight = self.rot_weight
        pt = target.translation
        x = np.concatenate((pt, target.rotation.ravel())).astype(np.float32)
        k_t = float(pt @ pt) + 3.0 * rot_weight
        if MT is not None:
            d = np.empty(M.shape[0], dtype=np.float32)
            i = kernel.sample_distances(MT, W2, x, d)
            return d, k_t, int(i)
        d = M @ x
        d += W2
        return d, k_t, int(d.argmin())


def table_poses(robot: RobotModel, ch: IKChain) -> SamplePoses:
    """Poses of the restart table of ``ch``: M = −2·[p | c·vec(R)] (N, 12) and ‖p‖² + 3c (N,).

    With them the pose distance to a target is one matrix-vector product:
    ‖p − p_t‖² + c‖R − R_t‖²_F = (‖p‖² + 3c) − 2·[p | c·vec(R)]·[p_t; vec(R_t)] + K_t,
    K_t = ‖p_t‖² + 3c, using ‖R − R_t‖²_F = 6 − 2 vec(R)·vec(R_t) (c: ``rot_weight``). One
    FK per sample (4096 by default, tens of ms: :func:`ik_chain` runs it off any query).
    """
    rot_weight = ch.rot_weight
    model, data = robot.model, robot.model.createData()
    q = ch.mid_range.copy()
    W = np.empty((ch.restart_table.shape[0], 12))
    for i, row in enumerate(ch.restart_table):
        q[ch.active] = row
        pin.forwardKinematics(model, data, robot.to_pin(q))
        T = pin.updateFramePlacement(model, data, ch.frame_id)
        W[i, :3] = T.translation
        W[i, 3:] = rot_weight * T.rotation.ravel()
    P = W[:, :3]
    # float32: the ranking needs no more, and the product runs twice as fast.
    M = (-2.0 * W).astype(np.float32)
    W2 = (np.einsum("ij,ij->i", P, P) + 3.0 * rot_weight).astype(np.float32)
    return SamplePoses(M, W2, np.ascontiguousarray(M.T) if available() else None)


def chain_key(
    frame: str, group: Group | None = None, parameters: SolverParameters = DEFAULT_PARAMETERS
) -> LazyKey[IKChain]:
    """The model's lazy-cache key of the :class:`IKChain` of ``frame`` (and ``group``)."""
    name = None if group is None else group.name
    if parameters is DEFAULT_PARAMETERS:
        return _default_chain_key(frame, name)
    return _chain_key(frame, name, parameters)


@lru_cache(maxsize=1024)
def _default_chain_key(frame: str, group: str | None) -> LazyKey[IKChain]:
    return _chain_key(frame, group, DEFAULT_PARAMETERS)


@lru_cache(maxsize=1024)
def _chain_key(frame: str, group: str | None, parameters: SolverParameters) -> LazyKey[IKChain]:
    name = f"ik.chain:{frame}" if group is None else f"ik.chain:{frame}|group:{group}"
    if parameters != DEFAULT_PARAMETERS:
        name += f"|{parameters!r}"
    return LazyKey(name, IKChain)


def ik_chain(
    robot: RobotModel,
    frame: str,
    group: Group | None = None,
    parameters: SolverParameters = DEFAULT_PARAMETERS,
) -> IKChain:
    """The cached, prepared :class:`IKChain` of ``frame`` (raises UnknownNameError for a bad
    frame), moving only ``group``'s joints when given (InvalidInputError naming ``group``
    when none of them moves the frame)."""
    robot.frame_id(frame)
    key = chain_key(frame, group, parameters)
    if group is None:
        return robot.lazy(key, lambda r: IKChain(r, frame, None, parameters).prepare())

    def build(r: RobotModel) -> IKChain:  # checked once, with the chain (not per request)
        if r.supporting_joints(frame, group.indices).size == 0:
            raise InvalidInputError(
                f"no joint of group {group.name!r} ({', '.join(group.joints) or 'none'}) moves "
                f"frame {frame!r}",
                "group",
            )
        return IKChain(r, frame, group.indices, parameters).prepare()

    return robot.lazy(key, build)


def chain_ready(
    robot: RobotModel,
    frame: str,
    group: Group | None = None,
    parameters: SolverParameters = DEFAULT_PARAMETERS,
) -> bool:
    """Whether :func:`ik_chain` of these arguments is built already (else its first call
    computes the restart table's poses, tens of ms: a caller on an event loop runs it
    elsewhere)."""
    return robot.cached(chain_key(frame, group, parameters)) is not None


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

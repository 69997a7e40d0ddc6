"""IK solutions grouped into branches, one representative each, annotated and ranked.

With ``num_solutions`` > 1 the solver answers *distinct* solutions: one per branch.

Branches
--------
- Chains with branch flags (:mod:`.branches`: UR-type and spherical-wrist 6R arms, planar
  2-link arms): solutions with the same flags (e.g. ``shoulder_left/elbow_up/wrist_noflip``)
  are one branch, labelled by the flags.
- Other chains (redundant arms such as the Panda, other 6R arms): clusters in joint space.
  Two solutions whose largest per-joint distance (continuous joints around the circle) is at
  most :data:`CLUSTER_THRESHOLD` are linked, and a cluster is a connected component of these
  links (single linkage): any two solutions of different clusters differ by more than the
  threshold in some joint. Clusters are labelled ``cluster_<k>``, k = 0, 1, … in the order
  of their representatives' ``seed_distance`` (``cluster_0`` nearest the seed).

Each branch is answered by its solution nearest the seed (smallest ``seed_distance``, then
smallest Euclidean joint distance), annotated with

- ``seed_distance``: the largest single-joint move from the seed, max_i |q_i − s_i| (rad or
  m; continuous joints around the circle), the move the slowest joint must make, not the sum;
- ``manipulability``: Yoshikawa's w = ∏σ_i of the frame Jacobian (all six rows, world axes)
  over the joints that move the frame (√det of the smaller Gram matrix,
  :func:`app.kinematics.analysis.yoshikawa_batch`; the ``yoshikawa`` of the analysis);
- ``clearance``: with obstacles, the smallest distance (m) between the robot's collision
  geometry and the obstacles (:mod:`app.kinematics.collision`; negative: penetration), else
  None.

and ranked by ``rank_by``: ``seed_distance`` (smallest first), ``manipulability`` or
``clearance`` (largest first); ties are broken by ``seed_distance``, then by the Euclidean
joint distance, so the order is deterministic.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from operator import sub
from typing import TYPE_CHECKING

import numpy as np
import pinocchio as pin

from app.kinematics.analysis import yoshikawa_batch
from app.kinematics.collision import collision_model
from app.kinematics.errors import InvalidInputError
from app.kinematics.ik.annotate import annotate as compiled_annotation
from app.kinematics.ik.branches import branch_form, branch_label
from app.kinematics.jacobian import frame_jacobian_by_id
from app.kinematics.models import RobotModel
from app.kinematics.obstacles import Obstacle

if TYPE_CHECKING:
    from app.kinematics.ik.precompute import IKChain
    from app.kinematics.ik.search import IKSolution

#: Solutions of an unlabelled chain within this largest per-joint distance (rad or m) are
#: one cluster (single linkage).
CLUSTER_THRESHOLD = 0.5


def joint_distance(robot: RobotModel, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Per-joint |a − b| on the wire, continuous joints measured around the circle."""
    return np.abs(robot.difference(a, b))


class Grouping:
    """Branches of the solutions found so far, updated as each is added.

    Labelled chains group by :func:`~.branches.branch_label`; others by single-linkage
    clusters (union–find over the pairs within :data:`CLUSTER_THRESHOLD`).
    """

    def __init__(self, robot: RobotModel, ch: IKChain) -> None:
        self.robot, self.ch = robot, ch
        self.labelled = branch_form(robot, ch) is not None
        self.qs: list[np.ndarray] = []
        self.labels: list[str | None] = []
        self.parent: list[int] = []
        self.count = 0

    def _root(self, i: int) -> int:
        while self.parent[i] != i:
            self.parent[i] = self.parent[self.parent[i]]
            i = self.parent[i]
        return i

    def add(self, q: np.ndarray) -> None:
        """Add a solution (wire configuration)."""
        i = len(self.qs)
        self.qs.append(q)
        if self.labelled:
            label = branch_label(self.robot, self.ch, q)
            self.count += label not in self.labels
            self.labels.append(label)
            return
        self.labels.append(None)
        self.parent.append(i)
        self.count += 1
        for j in range(i):
            if joint_distance(self.robot, self.qs[j], q).max() <= CLUSTER_THRESHOLD:
                a, b = self._root(j), self._root(i)
                if a != b:
                    self.parent[max(a, b)] = min(a, b)
                    self.count -= 1

    def keys(self) -> list[str | int]:
        """The branch of each solution: its label, or its cluster's root index."""
        if self.labelled:
            return [lab or "" for lab in self.labels]
        return [self._root(i) for i in range(len(self.qs))]


def manipulability(robot: RobotModel, ch: IKChain, q: np.ndarray) -> float:
    """Yoshikawa's ∏σ_i of the frame Jacobian (6 rows, world axes) over the chain's moving
    joints at wire configuration ``q`` (as :func:`app.kinematics.analysis.manipulability_of`)."""
    J = frame_jacobian_by_id(robot, robot.to_pin(q), ch.frame_id, pin.LOCAL_WORLD_ALIGNED)
    return float(yoshikawa_batch(J[None, :, ch.active])[0])


def clearance_function(
    robot: RobotModel, obstacles: Sequence[Obstacle], mode: str = "mesh"
) -> Callable[[np.ndarray], float] | None:
    """``q ↦`` the smallest robot–obstacle distance (m) at wire configuration ``q``, or None
    without obstacles. ``mode``: the collision geometry (``mesh`` or ``convex``)."""
    if not obstacles:
        return None
    cm = collision_model(robot, mode)
    obs = tuple(obstacles)
    cm.compiled(obs)

    def clearance(q: np.ndarray) -> float:
        report = cm.check(np.asarray(q, dtype=float), obs, distances=True)
        env = [p.distance for p in report.pairs if p.kind == "environment"]
        env = [d for d in env if np.isfinite(d)]
        return float(min(env)) if env else float("inf")

    return clearance


def check_rank_by(rank_by: str, clearance: Callable[[np.ndarray], float] | None) -> None:
    """Refuse ``clearance`` without obstacles (``rank_by``; the options checked the name)."""
    if rank_by == "clearance" and clearance is None:
        raise InvalidInputError(
            "clearance ranks by the distance to obstacles: give avoid_collisions: true with "
            "obstacles or a scene",
            "rank_by",
        )


def representatives(
    robot: RobotModel,
    ch: IKChain,
    solutions: list[IKSolution],
    grouping: Grouping | None,
    seed: np.ndarray,
    *,
    rank_by: str = "seed_distance",
    clearance: Callable[[np.ndarray], float] | None = None,
    wanted: int | None = None,
    annotate: bool = True,
) -> list[IKSolution]:
    """One solution per branch (nearest the seed), annotated and ranked (module doc).

    ``grouping`` holds the branches of ``solutions`` (same order); None: rebuilt here.
    At most ``wanted`` solutions are returned (all when None). Without ``annotate``, only
    what the ranking needs is computed (always ``seed_distance``; ``branch`` when several
    solutions are wanted; ``manipulability`` when ranked by it): the core's hot path, where
    one solution nearest the seed is wanted, then pays no label nor Jacobian.
    """
    if not solutions:
        return []
    single = wanted == 1 and rank_by == "seed_distance" and clearance is None
    if single and len(solutions) == 1 and (not annotate or ch.annotation is not None):
        # the hot path: nothing to rank; the labels, if wanted, compiled (:mod:`.annotate`)
        only = solutions[0]
        if robot.has_continuous:
            only.seed_distance = float(joint_distance(robot, only.q, seed).max(initial=0.0))
        else:
            moves = map(abs, map(sub, only.q.tolist(), seed.tolist()))
            only.seed_distance = max(moves, default=0.0)
        if annotate:
            label, only.manipulability = compiled_annotation(ch, only.q[ch.active])
            only.branch = "cluster_0" if label is None else label
        return [only]
    if single and not annotate:
        best, best_order = solutions[0], (math.inf, math.inf)
        for s in solutions:
            d = joint_distance(robot, s.q, seed)
            order = (float(d.max(initial=0.0)), math.sqrt(float(d @ d)))
            if order < best_order:
                best, best_order = s, order
        best.seed_distance = best_order[0]
        return [best]
    if grouping is None or len(grouping.qs) != len(solutions):
        grouping = Grouping(robot, ch)
        for s in solutions:
            grouping.add(s.q)
    keys = grouping.keys()
    near: dict[str | int, tuple[tuple[float, float, int], IKSolution]] = {}
    for i, (s, key) in enumerate(zip(solutions, keys, strict=True)):
        moves = joint_distance(robot, s.q, seed)
        order = (float(moves.max(initial=0.0)), float(np.sqrt(moves @ moves)), i)
        if key not in near or order < near[key][0]:
            near[key] = (order, s)
    chosen = sorted(near.values(), key=lambda item: item[0])
    out = []
    for k, (order, s) in enumerate(chosen):
        s.seed_distance = order[0]
        s.branch = grouping.labels[order[2]] if grouping.labelled else f"cluster_{k}"
        if annotate or rank_by == "manipulability":
            s.manipulability = manipulability(robot, ch, s.q)
        s.clearance = None if clearance is None else clearance(s.q)
        out.append((order, s))
    if rank_by == "manipulability":
        out.sort(key=lambda item: (-(item[1].manipulability or 0.0), item[0]))
    elif rank_by == "clearance":
        out.sort(key=lambda item: (-(item[1].clearance or 0.0), item[0]))
    ranked = [s for _, s in out]
    return ranked if wanted is None else ranked[:wanted]

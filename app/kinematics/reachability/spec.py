"""What a reachability map covers: the grid, the sampling and the measure (:class:`MapSpec`).

Grid
----
A map covers an axis-aligned box of the root (world) frame, ``lower`` … ``lower + shape·s``
with cubic position voxels of edge ``s`` (m), by default :func:`default_voxel_size` (the box's
longest edge / :data:`DEFAULT_VOXELS_PER_EDGE`, coarser when needed to stay within
:data:`MAX_CELLS`): a coarse map of any arm, whatever its reach. Voxel index
i = ⌊(p − lower)/s⌋ per axis; a position outside the box belongs to no cell (not reachable).
The box defaults to a conservative reach box (:func:`default_bounds`): centred on the first
joint of the frame's chain, half-size the sum of the distances between consecutive joint
origins along the chain plus the prismatic travels plus the frame's offset. Each voxel holds
:func:`~app.kinematics.reachability.bins.orientation_bins` orientation bins.

Cells
-----
Each cell (voxel × bin) keeps the best (largest) Yoshikawa manipulability w = ∏σ_i of the
task Jacobian (:mod:`app.kinematics.analysis`; Jacobian reference ``world``, rows
``part``/``rows``, columns the joints that move the frame) over the samples that landed in
it, stored as float32; −1 marks a cell no sample reached. Reachable = w ≥ 0.

Self-collision hook
-------------------
``self_collision`` = ``mesh`` or ``convex`` drops samples in self-collision before they are
binned, using ``app.kinematics.collision.collision_model(robot, mode).collides(q)`` when that
module provides it (checked at request time; otherwise the request is refused with 422
naming ``self_collision``). Joints that do not move the frame are at their neutral values
for the check. It costs one collision query per sample (far slower than FK).
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.analysis import support_columns, task_rows
from app.kinematics.errors import InvalidInputError
from app.kinematics.mimic import follower_travel
from app.kinematics.models import RobotModel
from app.kinematics.reachability.bins import orientation_bins

#: Largest number of cells (voxels × orientation bins) of one map (float32: 4 bytes each).
MAX_CELLS = 1 << 24
MAX_SAMPLES = 1_000_000_000
MAX_ORIENTATION_DIVISIONS = 12
#: Voxels along the longest edge of the box when the request gives no voxel size.
DEFAULT_VOXELS_PER_EDGE = 24


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


#: How joint space is sampled: uniform random samples or a grid.
SAMPLINGS = ("random", "grid")
#: Self-collision filtering of samples: none, or the collision geometry of that mode.
SELF_COLLISION_MODES = ("ignore", "mesh", "convex")


def default_bounds(robot: RobotModel, frame: str) -> tuple[np.ndarray, np.ndarray]:
    """A box that contains every position of ``frame`` (module doc), in the root frame."""
    model = robot.model
    f = model.frames[robot.frame_id(frame)]
    chain = list(model.supports[f.parentJoint])[1:]
    by_pin = {j.pin_id: j for j in robot.joints}
    data = model.createData()
    neutral = robot.neutral()
    pin.forwardKinematics(model, data, robot.to_pin(neutral))
    if not chain:
        c = pin.updateFramePlacement(model, data, robot.frame_id(frame)).translation
        return c - 1e-3, c + 1e-3
    center = data.oMi[chain[0]].translation.copy()
    reach = 0.0
    for jid in chain[1:]:
        reach += float(np.linalg.norm(model.jointPlacements[jid].translation))
    mimics = {m.pin_id: m for m in robot.mimic_joints}
    for jid in chain:
        j = by_pin.get(jid)
        if j is not None and j.type == "prismatic":
            reach += max(abs(j.lower or 0.0), abs(j.upper or 0.0))
        elif jid in mimics and mimics[jid].type == "prismatic":  # travel set by its leader
            m = mimics[jid]
            lead = robot.joints[m.leader_index]
            reach += follower_travel(m, lead.lower, lead.upper, neutral[m.leader_index])
    reach += float(np.linalg.norm(f.placement.translation))
    reach = reach * (1 + 1e-6) + 1e-6
    return center - reach, center + reach


def default_voxel_size(
    lower: np.ndarray, upper: np.ndarray, bins: int, max_cells: int = MAX_CELLS
) -> float:
    """The voxel edge (m) of a request that gives none: the longest edge of the box
    ``lower``…``upper`` (m, root frame) over :data:`DEFAULT_VOXELS_PER_EDGE`, enlarged by
    steps of 5 % until the grid's voxels × ``bins`` orientation bins fit ``max_cells``
    (or the grid is one voxel)."""
    extent = np.asarray(upper, dtype=float) - np.asarray(lower, dtype=float)
    size = float(np.max(extent)) / DEFAULT_VOXELS_PER_EDGE
    while True:
        voxels = math.prod(max(1, math.ceil(e / size - 1e-9)) for e in extent)
        if voxels * bins <= max_cells or voxels == 1:  # one voxel: make_spec's check refuses
            return size
        size *= 1.05


def make_spec(
    robot: RobotModel,
    frame: str,
    *,
    voxel_size: float | None = None,
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
    """Validate a build request; every error names its request field.

    ``voxel_size`` ``None``: :func:`default_voxel_size` of the box (given or default).
    """
    ridx = task_rows(part, rows)
    cols = support_columns(robot, frame)
    if voxel_size is not None and not (math.isfinite(voxel_size) and voxel_size > 0):
        raise InvalidInputError("must be a positive number of metres", "voxel_size")
    if not 0 <= orientation_divisions <= MAX_ORIENTATION_DIVISIONS:
        raise InvalidInputError(f"must be 0 … {MAX_ORIENTATION_DIVISIONS}", "orientation_divisions")
    if not 1 <= samples <= MAX_SAMPLES:
        raise InvalidInputError(f"must be 1 … {MAX_SAMPLES}", "samples")
    if sampling not in SAMPLINGS:
        raise InvalidInputError("must be random or grid", "sampling")
    if self_collision not in SELF_COLLISION_MODES:
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
    if voxel_size is None:
        with np.errstate(over="ignore"):
            if not np.all(np.isfinite(hi - lo)):
                raise InvalidInputError("the box is too large (give smaller bounds)", "bounds")
        voxel_size = default_voxel_size(lo, hi, orientation_bins(orientation_divisions), max_cells)
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


def voxel_index(
    spec: MapSpec, lower: np.ndarray, shape: np.ndarray, P: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Flat voxel index (N,) and in-bounds mask of component-major positions P (3, N)."""
    with np.errstate(over="ignore", invalid="ignore"):  # far-off positions: out of bounds
        v = np.floor((P - lower[:, None]) / spec.voxel_size)
    ok = np.all((v >= 0) & (v < shape[:, None]), axis=0)
    v = np.where(ok, v, 0).astype(np.int64)
    return (v[0] * shape[1] + v[1]) * shape[2] + v[2], ok

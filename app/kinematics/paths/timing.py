"""Time-optimal parameterization of a joint path under joint velocity and acceleration limits.

:func:`parameterize` gives every point of a joint path (wire configurations, one row per
point) its time, joint velocities and joint accelerations, for the fastest rest-to-rest motion
along the path that keeps every joint within its limits (TOPP-RA, the ``toppra`` package):

- the geometric path is a cubic spline (not-a-knot) through the points, parameterized by the
  cumulative joint distance ``s`` (Euclidean norm of the moving joints' steps, rad or m);
  points within :data:`SAME_POINT` of walk from the previous one are the same point (same
  time);
- TOPP-RA finds the largest path speed ``ṡ(s)`` on a grid (every point of the path is a grid
  point when there are at most :data:`GRIDPOINTS`, each interval split evenly until there
  are :data:`MIN_GRIDPOINTS`; else :data:`GRIDPOINTS` even points), with ``ṡ = 0`` at both
  ends; between grid points the path acceleration ``s̈`` is constant, so ``t(s)``,
  ``q̇ = q'(s) ṡ`` and ``q̈ = q''(s) ṡ² + q'(s) s̈`` are exact everywhere on the spline;
- the limits are then **verified on the output**: at every point of the path and at
  :data:`SAMPLES_PER_INTERVAL` samples inside every grid interval and at its ends (both
  one-sided accelerations). TOPP-RA enforces the limits at grid points only, so between them
  the spline's curvature can exceed them (e.g. near a sharp corner of the joint path): the
  grid intervals exceeding a limit by more than :data:`REFINE_TOLERANCE` are split (at the
  path's points inside them, else in four) and TOPP-RA runs again (:data:`REFINE_ROUNDS`
  times, :data:`MAX_GRIDPOINTS` grid points at most); what excess remains is removed by
  slowing the whole motion uniformly in time by the smallest factor ``k ≥ 1`` that brings
  every sample within its limits (``t → k·t``, ``q̇ → q̇/k``, ``q̈ → q̈/k²``). The answer is
  always within the limits at every verified sample (to rounding); ``time_scale`` says by
  how much it was slowed (1.0 to 1.005 on smooth paths and random walks alike).

TOPP-RA's tolerances are absolute, so it runs on a unit-length path in units of a duration
bound: paths of nanometres or kilometres, limits from 1e-9 to 1e12, all give well-scaled
numbers.

Joints that move less than :data:`SAME_POINT` along the whole path are static: velocity and
acceleration 0, no limit needed. Joint paths are taken as given: a continuous joint's
wire value is one angle, so a wrap from π to −π between two points is a 2π move.

Units: seconds, rad/s and m/s, rad/s² and m/s². Accelerations at a point are those just after
it (at the last point, just before it): ``s̈`` is piecewise constant, so they can jump there.

``toppra`` is imported on first use, without Matplotlib (which toppra imports for its plots
only): the service never pays Matplotlib's import, and never needs the writable home or
temporary directory Matplotlib insists on (:func:`toppra_modules`).
"""

from __future__ import annotations

import sys
import threading
import types
from dataclasses import dataclass
from typing import Any, Unpack

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.models import RobotModel, check_joint_values
from app.kinematics.paths.limits import LimitOptions, joint_limits

#: Most points a path may have for timing (the Cartesian path's own bound).
MAX_POINTS = 100_000
#: Most TOPP-RA grid points at first (its cost is linear in them: ~60 µs each on one core).
GRIDPOINTS = 4000
#: Most TOPP-RA grid points after refinement.
MAX_GRIDPOINTS = 6000
#: Rounds of refinement: grid intervals where a verification sample exceeds a limit by more
#: than REFINE_TOLERANCE (relative) are split (:func:`_refined`) and TOPP-RA runs again.
REFINE_ROUNDS = 4
REFINE_TOLERANCE = 1e-3
#: Fewest TOPP-RA grid points: a path of few points has its intervals split evenly.
MIN_GRIDPOINTS = 500
#: Interior samples per grid interval where the limits are verified, besides its ends and
#: the path's points.
SAMPLES_PER_INTERVAL = 4
#: Points within this joint-space walk (rad or m) of the previous distinct one are the same
#: point: they share its time, velocity and acceleration. Joints whose values span less
#: along the whole path do not move.
SAME_POINT = 1e-9

_IMPORT_LOCK = threading.Lock()


@dataclass(frozen=True, slots=True)
class Timing:
    """A time parameterization of a joint path, at its points.

    Attributes
    ----------
    t : (N,) times (s) from the first point (``t[0] = 0``), non-decreasing.
    qd, qdd : (N, n) joint velocities (rad/s, m/s) and accelerations (rad/s², m/s²), in wire
        (joint) order; 0 for the joints that do not move along the path.
    velocity_limits, acceleration_limits : (n,) the limits applied (rad/s or m/s, rad/s² or
        m/s²); NaN for the joints that do not move (none applied).
    time_scale : the uniform slow-down applied after verification (1.0: TOPP-RA's motion
        already held every limit at every sample).
    """

    t: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
    velocity_limits: np.ndarray
    acceleration_limits: np.ndarray
    time_scale: float

    @property
    def duration(self) -> float:
        """Time of the last point, ``t[-1]`` (s)."""
        return float(self.t[-1])


def toppra_modules() -> tuple[Any, Any, Any]:
    """``(toppra, toppra.algorithm, toppra.constraint)``, imported on first use.

    toppra imports ``matplotlib.pyplot`` at import time for its plotting helpers, which
    Denavit never calls. Unless Matplotlib is already loaded, the import runs with empty
    stand-in ``matplotlib`` modules, removed again afterwards: Matplotlib is not imported
    (0.6 s saved per worker), and its need for a writable configuration or temporary
    directory (an ``OSError`` at import on a read-only filesystem) never arises.
    """
    with _IMPORT_LOCK:
        if "toppra" not in sys.modules and "matplotlib" not in sys.modules:
            pyplot = types.ModuleType("matplotlib.pyplot", "stand-in: toppra's plots unused")
            stubs = {"matplotlib": types.ModuleType("matplotlib"), "matplotlib.pyplot": pyplot}
            stubs["matplotlib"].pyplot = pyplot  # type: ignore[attr-defined]
            sys.modules.update(stubs)
            try:
                import toppra  # noqa: F401
            finally:
                for name, module in stubs.items():
                    if sys.modules.get(name) is module:
                        del sys.modules[name]
        import toppra
        import toppra.algorithm
        import toppra.constraint

    return toppra, toppra.algorithm, toppra.constraint


# ------------------------------------------------------------------------ the motion
def _check_points(robot: RobotModel, qs: Any, field: str) -> np.ndarray:
    arr = np.asarray(qs, dtype=float)
    if arr.ndim != 2 or arr.shape[1] != robot.n or arr.shape[0] < 1:
        raise InvalidInputError(
            f"expected (N ≥ 1, {robot.n}) joint values, got shape {arr.shape}", field
        )
    if arr.shape[0] > MAX_POINTS:
        raise InvalidInputError(f"at most {MAX_POINTS} points (got {arr.shape[0]})", field)
    check_joint_values(arr, field)  # finite, within ±MAX_JOINT_VALUE: names points.i.j
    return arr


def _distinct(walked: np.ndarray) -> np.ndarray:
    """Indices of the points kept as spline knots: the first, then each point more than
    :data:`SAME_POINT` of walk (``walked``, non-decreasing) beyond the last kept one."""
    if (np.diff(walked) > SAME_POINT).all():
        return np.arange(walked.size)
    keep = [0]
    while True:  # one step per kept point
        nxt = int(np.searchsorted(walked, walked[keep[-1]] + SAME_POINT, side="right"))
        if nxt >= walked.size:
            return np.asarray(keep)
        keep.append(nxt)


def _grid(knots: np.ndarray) -> np.ndarray:
    """TOPP-RA's first grid: the knots, each interval split evenly up to
    :data:`MIN_GRIDPOINTS` points in all; beyond :data:`GRIDPOINTS` knots, that many points
    evenly spread."""
    intervals = knots.size - 1
    if intervals + 1 > GRIDPOINTS:
        grid = np.linspace(knots[0], knots[-1], GRIDPOINTS)
    else:
        split = max(1, min(-(-(MIN_GRIDPOINTS - 1) // intervals), (GRIDPOINTS - 1) // intervals))
        steps = np.arange(split) / split
        grid = (knots[:-1, None] + np.diff(knots)[:, None] * steps).ravel()
        grid = np.append(grid, knots[-1])
    return np.unique(grid)  # strictly increasing even where rounding merged two values


class _Profile:
    """The path speed ``ṡ`` TOPP-RA found on ``grid``: piecewise-constant ``s̈``."""

    def __init__(self, grid: np.ndarray, sd: np.ndarray, field: str) -> None:
        self.grid = grid
        self.sd = np.maximum(sd, 0.0)
        self.sd[[0, -1]] = 0.0  # at rest at both ends (TOPP-RA's ends are ~1e-9 off)
        ds = np.diff(grid)
        self.sdd = (self.sd[1:] ** 2 - self.sd[:-1] ** 2) / (2.0 * ds)
        with np.errstate(divide="ignore", invalid="ignore"):
            dt = 2.0 * ds / (self.sd[:-1] + self.sd[1:])
        if not np.isfinite(dt).all():
            raise InvalidInputError(
                "the path could not be time-parameterized (zero path speed inside the path)",
                field,
            )
        self.t = np.concatenate([[0.0], np.cumsum(dt)])

    def at(self, k: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(t, ṡ, s̈) at path parameters ``s`` in grid intervals ``k``."""
        delta = s - self.grid[k]
        # ṡ² is linear in s within an interval: interpolated so that it is exact at both ends
        f = delta / (self.grid[k + 1] - self.grid[k])
        sd = np.sqrt(np.maximum((1.0 - f) * self.sd[k] ** 2 + f * self.sd[k + 1] ** 2, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            dt = np.where(delta > 0.0, 2.0 * delta / (self.sd[k] + sd), 0.0)
        return self.t[k] + dt, sd, self.sdd[k]

    def interval(self, s: np.ndarray) -> np.ndarray:
        """The grid interval each ``s`` lies in (one starting at ``s`` if it is a grid point;
        the last one for the path's end)."""
        k = np.searchsorted(self.grid, s, side="right") - 1
        return np.clip(k, 0, self.grid.size - 2)


def _motion(path: Any, profile: _Profile, k: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, ...]:
    """(t, q̇, q̈) of the moving joints at ``s`` (intervals ``k``)."""
    t, sd, sdd = profile.at(k, s)
    dq = path(s, 1).reshape(s.size, -1)
    ddq = path(s, 2).reshape(s.size, -1)
    return t, dq * sd[:, None], ddq * (sd**2)[:, None] + dq * sdd[:, None]


def _solve(path: Any, grid: np.ndarray, v: np.ndarray, a: np.ndarray, field: str) -> _Profile:
    """TOPP-RA on ``grid`` (seidel solver: deterministic), at rest at both ends."""
    _, algo, constraint = toppra_modules()
    instance = algo.TOPPRA(
        [constraint.JointVelocityConstraint(v), constraint.JointAccelerationConstraint(a)],
        path,
        gridpoints=grid,
        solver_wrapper="seidel",
    )
    _, sd, _ = instance.compute_parameterization(0.0, 0.0)
    if sd is None or not np.isfinite(sd).all():
        raise InvalidInputError(
            f"the path could not be time-parameterized ({instance.problem_data.return_code})",
            field,
        )
    return _Profile(grid, np.asarray(sd, dtype=float), field)


def _samples(grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(interval, s) of the verification samples: both ends of every grid interval and
    :data:`SAMPLES_PER_INTERVAL` evenly inside."""
    frac = np.linspace(0.0, 1.0, SAMPLES_PER_INTERVAL + 2)
    k = np.repeat(np.arange(grid.size - 1), frac.size)
    s = grid[k] + np.tile(frac, grid.size - 1) * np.diff(grid)[k]
    return k, np.minimum(s, grid[k + 1])


def _needed(qd: np.ndarray, qdd: np.ndarray, v: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Per sample, the time scale that brings every joint within its limits (≤ 1: none)."""
    return np.maximum((np.abs(qd) / v).max(axis=1), np.sqrt((np.abs(qdd) / a).max(axis=1)))


def _refined(grid: np.ndarray, bad: np.ndarray, knots: np.ndarray) -> np.ndarray:
    """``grid`` with the intervals ``bad`` (worst first) split: at the path's knots inside
    them (where the spline's curvature jumps), or in four when they hold none; as many as
    :data:`MAX_GRIDPOINTS` allows."""
    where = np.searchsorted(grid, knots, side="right") - 1
    inner = ~np.isin(knots, grid)
    counts = np.bincount(where[inner], minlength=grid.size)[bad]
    added = np.cumsum(np.where(counts > 0, counts, 3))
    bad = bad[added <= MAX_GRIDPOINTS - grid.size]
    split = bad[counts[: bad.size] == 0]
    quarters = grid[split, None] + np.diff(grid)[split, None] * np.array([0.25, 0.5, 0.75])
    inside = knots[inner & np.isin(where, bad)]
    return np.unique(np.concatenate([grid, inside, quarters.ravel()]))


def parameterize(
    robot: RobotModel,
    qs: np.ndarray,
    *,
    field: str = "timing",
    points_field: str = "points",
    **limits: Unpack[LimitOptions],
) -> Timing:
    """The time-optimal rest-to-rest timing of the joint path ``qs`` (see the module).

    Parameters
    ----------
    robot
        The robot; its description gives the default velocity limits.
    qs
        (N, n) wire configurations (rad or m), the path's points in order; at most
        :data:`MAX_POINTS`. Fewer than two distinct points: every ``t`` is 0, duration 0.
    velocity_limits, acceleration_limits
        Per joint (rad/s or m/s; rad/s² or m/s²): a list over ``joints`` (default: every
        joint, wire order) or a joint name → value map; joints not given take the defaults
        of :func:`~app.kinematics.paths.limits.joint_limits`. Every value within
        :data:`~app.kinematics.paths.limits.LIMIT_RANGE` ([1e-6, 1e9]).
    acceleration_fraction
        Instead of ``acceleration_limits``: ``a_max = fraction · v_max / (1 s)`` per joint
        (default :data:`~app.kinematics.paths.limits.DEFAULT_ACCELERATION_FRACTION`).
    velocity_scale
        In (0, 1]: every velocity limit is multiplied by it.
    joints
        Wire indices the limit lists refer to (e.g. a planning group's), in their order.
    field, points_field
        Wire names of the timing options and of the points, for errors
        (``timing.velocity_limits.<joint>``).

    Raises
    ------
    InvalidInputError
        A joint that moves has no usable velocity limit; a limit outside LIMIT_RANGE; both
        acceleration forms given; points malformed; TOPP-RA failed (not seen on paths and
        limits within range: a 422 naming ``timing``, never a 500).
    """
    arr = _check_points(robot, qs, points_field)
    n_pts = arr.shape[0]
    moving = np.flatnonzero(np.ptp(arr, axis=0) > SAME_POINT)
    v, a = joint_limits(robot, moving, field=field, **limits)
    zeros = np.zeros((n_pts, robot.n))
    # Each point's path parameter: the joint distance walked (Euclidean norm of the moving
    # joints' steps); points within SAME_POINT of walk from the last kept one merge into it.
    sub = arr[:, moving]
    walked = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(sub, axis=0), axis=1))])
    keep = _distinct(walked)
    if keep.size < 2:
        return Timing(np.zeros(n_pts), zeros, zeros.copy(), v, a, 1.0)
    knots = walked[keep]
    s_pts = knots[np.searchsorted(keep, np.arange(n_pts), side="right") - 1]

    # TOPP-RA's tolerances are absolute: it runs on a unit-length path (s/L, (q − q₀)/L) in
    # time units of T₀, a lower bound of the duration (each joint's bang-bang time over its
    # total travel), so that its numbers are of order 1 whatever the path's length and limits.
    length = float(knots[-1])
    v_m, a_m = v[moving], a[moving]
    travel = np.abs(np.diff(sub, axis=0)).sum(axis=0)
    t0 = float(np.max(np.maximum(travel / v_m, np.sqrt(travel / a_m))))
    v_n, a_n = v_m * t0 / length, a_m * t0**2 / length
    unit_knots = knots / length
    ta, _, _ = toppra_modules()
    path = ta.SplineInterpolator(unit_knots, (sub[keep] - sub[0]) / length)
    s_pts = s_pts / length
    grid = _grid(unit_knots)
    for round_ in range(REFINE_ROUNDS + 1):
        profile = _solve(path, grid, v_n, a_n, field)
        # The slow-down each grid interval needs: at its ends (one-sided accelerations), at
        # SAMPLES_PER_INTERVAL samples inside, and at the path's points in it.
        need = np.zeros(grid.size - 1)
        k_dense, s_dense = _samples(grid)
        k_pts = profile.interval(s_pts)
        for k, s in ((k_dense, s_dense), (k_pts, s_pts)):
            _, qd_s, qdd_s = _motion(path, profile, k, s)
            np.maximum.at(need, k, _needed(qd_s, qdd_s, v_n, a_n))
        bad = np.flatnonzero(need > 1.0 + REFINE_TOLERANCE)
        if bad.size == 0 or round_ == REFINE_ROUNDS:
            break
        refined = _refined(grid, bad[np.argsort(-need[bad], kind="stable")], unit_knots)
        if refined.size == grid.size:
            break  # no room left
        grid = refined

    scale = max(1.0, float(need.max()))
    t_pts, qd_m, qdd_m = _motion(path, profile, k_pts, s_pts)
    time = t0 * scale  # back to seconds, slowed down
    qd = zeros
    qdd = zeros.copy()
    qd[:, moving] = qd_m * (length / time)
    qdd[:, moving] = qdd_m * (length / time**2)
    t = t_pts * time
    return Timing(t, qd, qdd, v, a, scale)

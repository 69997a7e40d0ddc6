"""The Cartesian path: lines, arcs and explicit waypoints, their parameter and sampling.

A path starts at a pose (the frame's placement at the start configuration) and chains
segments, each ending at a given pose:

- :class:`Line` ``to``: position linear, orientation by slerp (the geodesic of SO(3));
- :class:`Arc` ``via``, ``to``: position on the circle through the start, ``via`` and ``to``
  points, at constant speed along the circle; orientation by slerp from the start to
  ``via``'s orientation while the point travels to ``via``, then from ``via`` to ``to``;
- explicit waypoints: a polyline of lines.

All poses are placements of the frame in the root (world) frame, positions in metres.

Path parameter
--------------
``s`` runs over [0, 1] along the whole path. Each segment has the length

    L = √(ℓ² + (ρ·θ)²),        ρ = :data:`ROTATION_LENGTH` = 0.1 m/rad,

where ℓ is the distance the point travels (m: the chord of a line, the arc length of an arc)
and θ the total rotation (rad: the slerp angle, for an arc the sum of its two parts). ρ is a
characteristic length: a rotation of 1 rad weighs as much as a 0.1 m translation (a tool
turning in place still advances along the path; a pure translation is not slowed by it).
``s`` is the cumulative length over the total, and within a segment grows linearly with the
segment's own parameter u ∈ [0, 1] (u drives position and orientation together). A path
whose total length is zero (every segment ends where it starts) has only its start.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from app.kinematics.errors import InvalidInputError
from app.kinematics.paths.pose_kernel import PieceArrays

#: Characteristic length weighing rotation against translation in the path length (m/rad).
ROTATION_LENGTH = 0.1
#: Most points :meth:`CartesianPath.sample` produces (beyond: InvalidInputError on max_step).
MAX_POINTS = 100_000
#: Segment length (m) below which a segment counts as zero-length (rounding of equal poses).
ZERO_LENGTH = 1e-12
#: A segment whose rotation turns less than this (rad) keeps its start's orientation
#: exactly (no slerp): the pose it gives differs from the slerp's by less than this angle.
NO_TURN = 1e-14
#: Relative size of |(via − start) × (to − start)| below which the three arc points are
#: collinear (or two coincide).
COLLINEAR = 1e-9


@dataclass(frozen=True, slots=True)
class Line:
    """A straight segment to the pose ``to`` (root frame)."""

    to: pin.SE3


@dataclass(frozen=True, slots=True)
class Arc:
    """A circular segment through the pose ``via`` to the pose ``to`` (root frame)."""

    via: pin.SE3
    to: pin.SE3


def _slerp(R0: np.ndarray, w: np.ndarray, t: float, turns: bool = True) -> np.ndarray:
    """R0·exp3(t·w): the rotation a fraction ``t`` along the geodesic R0 → R0·exp3(w)
    (R0 itself when the geodesic does not ``turns``: ‖w‖ ≤ :data:`NO_TURN`)."""
    return R0 @ pin.exp3(t * w) if turns else R0


class Target:
    """A pose of the path as arrays, its :class:`pinocchio.SE3` built on demand (the
    compiled point reads the arrays; only the fallbacks need the SE3).

    ``R`` (3, 3) and ``p`` (3,): rotation and position in the root frame (m), C-contiguous
    float64, never modified.
    """

    __slots__ = ("R", "_se3", "p")

    def __init__(self, R: np.ndarray, p: np.ndarray) -> None:
        # the compiled point reads them as C-contiguous float64 (a Fortran-ordered rotation,
        # e.g. Pinocchio's, would be read transposed)
        self.R = np.ascontiguousarray(R, dtype=np.float64)
        self.p = np.ascontiguousarray(p, dtype=np.float64)
        self._se3: pin.SE3 | None = None

    @property
    def se3(self) -> pin.SE3:
        """The pose as a :class:`pinocchio.SE3` (built once)."""
        if self._se3 is None:
            self._se3 = pin.SE3(self.R, self.p)
        return self._se3


class Samples:
    """The sampled waypoints of :meth:`CartesianPath.sample_arrays` as stacked arrays, the
    same poses and ``s`` as :meth:`CartesianPath.sample_targets`, and the segment each lies
    on (for the compiled walk, :mod:`.walk_kernel`).

    ``R`` (N, 3, 3), ``p`` (N, 3): waypoint k's rotation and position (root frame, m),
    C-contiguous float64, never modified; ``s`` (N,): its path parameter; ``runs``: per
    segment with waypoints, in order, ``(first, stop, a, b, piece)``: its waypoints are
    ``first ≤ k < stop`` (the last one its end pose exactly), it spans a < s ≤ b, and
    ``piece`` is its :meth:`_Piece.arrays`. :meth:`target` gives waypoint k as a
    :class:`Target` (built once, views of the rows).
    """

    __slots__ = ("R", "_targets", "p", "runs", "s")

    def __init__(
        self,
        R: np.ndarray,
        p: np.ndarray,
        s: np.ndarray,
        runs: list[tuple[int, int, float, float, PieceArrays]],
    ) -> None:
        self.R, self.p, self.s, self.runs = R, p, s, runs
        self._targets: list[Target | None] = [None] * len(s)

    def __len__(self) -> int:
        return len(self.s)

    def target(self, k: int) -> Target:
        """Waypoint ``k`` as a :class:`Target` (its arrays are views of ``R[k]``, ``p[k]``)."""
        t = self._targets[k]
        if t is None:
            t = self._targets[k] = Target(self.R[k], self.p[k])
        return t


def _target(T: pin.SE3) -> Target:
    """``T`` as a :class:`Target` (copies)."""
    return Target(np.array(T.rotation, order="C"), np.array(T.translation, order="C"))


class _Piece:
    """One segment, prepared: pose at its own parameter u ∈ [0, 1], lengths and rates."""

    def __init__(self, start: pin.SE3, seg: Line | Arc, field: str) -> None:
        self.start, self.end = start, seg.to
        R0 = self.R0 = start.rotation.copy()
        if isinstance(seg, Line):
            self.arc = False
            self.p0, self.dp = start.translation.copy(), seg.to.translation - start.translation
            self.w1 = pin.log3(R0.T @ seg.to.rotation)
            self.u_via = 1.0
            self.w2 = np.zeros(3)
            self.Rv = seg.to.rotation
            self.travel = float(np.linalg.norm(self.dp))
        else:
            self.arc = True
            self._circle(start.translation, seg.via.translation, seg.to.translation, field)
            self.Rv = seg.via.rotation
            self.w1 = pin.log3(R0.T @ self.Rv)
            self.w2 = pin.log3(self.Rv.T @ seg.to.rotation)
        self._arrays: PieceArrays | None = None
        self.th1 = float(np.linalg.norm(self.w1))
        self.th2 = float(np.linalg.norm(self.w2))
        self.length = math.hypot(self.travel, ROTATION_LENGTH * (self.th1 + self.th2))
        if self.length <= ZERO_LENGTH:  # the end repeats the start (up to rounding)
            self.length = 0.0

    def _circle(self, p0: np.ndarray, pv: np.ndarray, p1: np.ndarray, field: str) -> None:
        a, b = pv - p0, p1 - p0
        n = np.cross(a, b)
        nn = float(n @ n)
        scale = float(np.linalg.norm(a) * np.linalg.norm(b))
        if scale == 0.0 or math.sqrt(nn) <= COLLINEAR * max(scale, float(a @ a), float(b @ b)):
            raise InvalidInputError(
                "the arc's start, via and end points are collinear or coincide: no circle "
                "passes through them",
                f"{field}.via",
            )
        # Circumcentre of the triangle (p0, pv, p1).
        c = p0 + np.cross(float(a @ a) * b - float(b @ b) * a, n) / (2.0 * nn)
        r = float(np.linalg.norm(p0 - c))
        e1 = (p0 - c) / r
        e2 = np.cross(n / math.sqrt(nn), e1)  # p0 → pv → p1 runs counterclockwise about n

        def angle(p: np.ndarray) -> float:
            d = p - c
            return math.atan2(float(d @ e2), float(d @ e1)) % (2.0 * math.pi)

        self.c, self.r, self.e1, self.e2 = c, r, e1, e2
        self.phi = angle(p1)  # total angle swept (rad), in (0, 2π)
        self.u_via = angle(pv) / self.phi
        self.travel = r * self.phi

    def pose(self, u: float) -> pin.SE3:
        """The pose at the segment's parameter u ∈ [0, 1] (exactly the end at u = 1)."""
        if u >= 1.0:
            return self.end.copy()
        if u <= 0.0:
            return self.start.copy()
        return pin.SE3(*self._pose_arrays(u))

    def target(self, u: float) -> Target:
        """:meth:`pose` as a :class:`Target` (the same numbers, no SE3 built)."""
        if u >= 1.0 or u <= 0.0:
            T = self.end if u >= 1.0 else self.start
            return _target(T)
        return Target(*self._pose_arrays(u))

    def _pose_arrays(self, u: float) -> tuple[np.ndarray, np.ndarray]:
        """Rotation and position at 0 < u < 1 (fresh C-contiguous arrays)."""
        if self.arc:
            a = u * self.phi
            p = self.c + self.r * (math.cos(a) * self.e1 + math.sin(a) * self.e2)
        else:
            p = self.p0 + u * self.dp
        if u <= self.u_via:
            R = _slerp(self.R0, self.w1, u / self.u_via, self.th1 > NO_TURN)
        else:
            R = _slerp(self.Rv, self.w2, (u - self.u_via) / (1.0 - self.u_via), self.th2 > NO_TURN)
        return np.ascontiguousarray(R, dtype=float), p

    def arrays(self) -> PieceArrays:
        """This segment's constants for the compiled :func:`~.pose_kernel.piece_pose`
        (built once)."""
        if self._arrays is None:
            f64 = np.ascontiguousarray
            z3 = np.zeros(3)
            arc = self.arc
            self._arrays = PieceArrays(
                bool(arc), f64(z3 if arc else self.p0, dtype=float),
                f64(z3 if arc else self.dp, dtype=float), f64(self.c if arc else z3, dtype=float),
                f64(self.e1 if arc else z3, dtype=float), f64(self.e2 if arc else z3, dtype=float),
                float(self.r) if arc else 0.0, float(self.phi) if arc else 0.0,
                f64(self.R0, dtype=float), f64(self.w1, dtype=float), bool(self.th1 > NO_TURN),
                f64(self.Rv, dtype=float), f64(self.w2, dtype=float), bool(self.th2 > NO_TURN),
                float(self.u_via), f64(self.start.rotation, dtype=float),
                f64(self.start.translation, dtype=float), f64(self.end.rotation, dtype=float),
                f64(self.end.translation, dtype=float),
            )  # fmt: skip
        return self._arrays

    def steps(self, max_p: float, max_r: float) -> int:
        """Fewest equal steps of u keeping each within ``max_p`` (m, along the circle or line:
        the chord is shorter) and ``max_r`` (rad, at the faster of the two slerp rates)."""
        rate = self.th1
        if self.arc:
            rate = max(
                self.th1 / self.u_via if self.u_via > 0.0 else 0.0,
                self.th2 / (1.0 - self.u_via) if self.u_via < 1.0 else 0.0,
            )
        n = min(max(self.travel / max_p, rate / max_r), float(MAX_POINTS))  # no overflow
        return max(1, math.ceil(n * (1.0 - 1e-12))) if self.length > 0.0 else 0


class CartesianPath:
    """A chain of segments from a start pose; see the module docstring for ``s``.

    Build with :meth:`from_segments` or :meth:`from_waypoints`.
    """

    def __init__(self, start: pin.SE3, pieces: list[_Piece]) -> None:
        self.start = start.copy()
        self._pieces = pieces
        lengths = np.array([p.length for p in pieces], dtype=float)
        self.length = float(lengths.sum())
        cum = np.concatenate(([0.0], np.cumsum(lengths)))
        #: s at the end of each segment (the last exactly 1; all 0 for a zero-length path).
        self.ends = cum[1:] / self.length if self.length > 0.0 else np.zeros(len(pieces))
        if pieces and self.length > 0.0:
            self.ends[-1] = 1.0
        self._starts = np.concatenate(([0.0], self.ends[:-1]))
        self._ends, self._starts_list = self.ends.tolist(), self._starts.tolist()

    @classmethod
    def from_segments(
        cls, start: pin.SE3, segments: Sequence[Line | Arc], field: str = "segments"
    ) -> CartesianPath:
        """A path of lines and arcs from ``start``; an arc whose three points are collinear
        (or two coincide) raises InvalidInputError naming ``<field>.<i>.via``."""
        if len(segments) == 0:
            raise InvalidInputError("give at least one segment", field)
        pieces, at = [], start
        for i, seg in enumerate(segments):
            pieces.append(_Piece(at, seg, f"{field}.{i}"))
            at = seg.to
        return cls(start, pieces)

    @classmethod
    def from_waypoints(
        cls, start: pin.SE3, poses: Sequence[pin.SE3], field: str = "waypoints"
    ) -> CartesianPath:
        """The polyline of lines from ``start`` through each pose of ``poses`` in turn."""
        if len(poses) == 0:
            raise InvalidInputError("give at least one waypoint", field)
        return cls.from_segments(start, [Line(p) for p in poses], field)

    def _locate(self, s: float) -> tuple[int, float]:
        """(segment index, its parameter u) at path parameter ``s``."""
        if self.length == 0.0:
            return len(self._pieces) - 1, 1.0
        i = bisect.bisect_left(self._ends, s)  # plain floats: searchsorted's "left"
        i = min(i, len(self._pieces) - 1)
        # Skip zero-length segments sharing this s (they end where the next starts).
        while i < len(self._pieces) - 1 and self._pieces[i].length == 0.0:
            i += 1
        a, b = self._starts_list[i], self._ends[i]
        return i, (1.0 if b <= a else (s - a) / (b - a))

    def pose_at(self, s: float) -> pin.SE3:
        """The pose at path parameter ``s`` ∈ [0, 1] (clipped): the start at 0, the last
        segment's end at 1, a segment's end exactly at its ``s``."""
        s = min(max(float(s), 0.0), 1.0)
        if s == 0.0:
            return self.start.copy()
        i, u = self._locate(s)
        return self._pieces[i].pose(u)

    def target_at(self, s: float) -> Target:
        """:meth:`pose_at` as a :class:`Target`."""
        s = min(max(float(s), 0.0), 1.0)
        if s == 0.0:
            return _target(self.start)
        i, u = self._locate(s)
        return self._pieces[i].target(u)

    def sample_targets(self, max_step: tuple[float, float]) -> tuple[list[Target], np.ndarray]:
        """:meth:`sample` as :class:`Target` s (the same poses and ``s``)."""
        counts = self._counts(max_step)
        start = _target(self.start)
        poses, ss = [start], [0.0]
        for piece, n, a, b in zip(self._pieces, counts, self._starts, self.ends, strict=True):
            for k in range(1, n + 1):
                u = k / n
                poses.append(piece.target(u))
                ss.append(b if k == n else a + u * (b - a))
        return poses, np.array(ss)

    def sample_arrays(self, max_step: tuple[float, float]) -> Samples:
        """:meth:`sample_targets` as stacked arrays (:class:`Samples`): bit for bit the same
        poses and ``s``. A line that does not turn (its rotation is its start's until the
        end) is computed for all its waypoints at once, by the same elementwise operations
        (p₀ + u·Δp, u = k/n, s = a + u·(b − a)); other segments pose by pose as there."""
        counts = self._counts(max_step)
        size = 1 + sum(counts)
        R, p, ss = np.empty((size, 3, 3)), np.empty((size, 3)), np.empty(size)
        R[0], p[0], ss[0] = self.start.rotation, self.start.translation, 0.0
        runs: list[tuple[int, int, float, float, PieceArrays]] = []
        k = 1
        for piece, n, a, b in zip(self._pieces, counts, self._starts, self.ends, strict=True):
            if n == 0:
                continue
            last = k + n - 1
            u = np.arange(1, n) / n  # k / n, exactly
            if not piece.arc and not piece.th1 > NO_TURN:
                R[k:last] = piece.R0
                p[k:last] = piece.p0 + u[:, None] * piece.dp
            else:
                for i in range(1, n):
                    R[k + i - 1], p[k + i - 1] = piece._pose_arrays(i / n)
            R[last], p[last] = piece.end.rotation, piece.end.translation
            ss[k:last] = a + u * (b - a)
            ss[last] = b
            runs.append((k, last + 1, float(a), float(b), piece.arrays()))
            k = last + 1
        return Samples(R, p, ss, runs)

    def piece_at(self, s: float) -> tuple[PieceArrays, float]:
        """The segment (:meth:`_Piece.arrays`) and its parameter u whose pose is
        :meth:`pose_at` ``(s)`` (for the compiled :func:`~.pose_kernel.piece_pose`)."""
        s = min(max(float(s), 0.0), 1.0)
        if s == 0.0:
            return self._pieces[0].arrays(), 0.0
        i, u = self._locate(s)
        return self._pieces[i].arrays(), u

    def sample(self, max_step: tuple[float, float]) -> tuple[list[pin.SE3], np.ndarray]:
        """Poses along the path and their ``s``, consecutive ones within ``max_step``.

        Parameters
        ----------
        max_step
            (position m, rotation rad): the most any consecutive pair may differ in position
            and in rotation angle.

        Returns
        -------
        poses, s
            The start, then for each segment equal steps of its parameter ending exactly at
            its end pose (a zero-length segment adds nothing). At most :data:`MAX_POINTS`
            points, else InvalidInputError naming ``max_step``.
        """
        counts = self._counts(max_step)
        poses, ss = [self.start.copy()], [0.0]
        for piece, n, a, b in zip(self._pieces, counts, self._starts, self.ends, strict=True):
            for k in range(1, n + 1):
                u = k / n
                poses.append(piece.pose(u))
                ss.append(b if k == n else a + u * (b - a))
        return poses, np.array(ss)

    def count(self, max_step: tuple[float, float]) -> int:
        """How many poses :meth:`sample` gives for ``max_step`` (none built; the same
        InvalidInputError beyond :data:`MAX_POINTS`)."""
        return 1 + sum(self._counts(max_step))

    def _counts(self, max_step: tuple[float, float]) -> list[int]:
        """Steps of each segment at ``max_step``, their total checked against MAX_POINTS."""
        max_p, max_r = (float(v) for v in max_step)
        check_max_step(max_p, max_r, "max_step")
        counts = [p.steps(max_p, max_r) for p in self._pieces]
        total = 1 + sum(counts)
        if total > MAX_POINTS:
            raise InvalidInputError(
                f"these steps give {total} points along the path, more than {MAX_POINTS}: "
                "raise max_step",
                "max_step",
            )
        return counts


def check_max_step(position: float, rotation: float, field: str) -> None:
    """Both step bounds positive and finite (InvalidInputError naming ``<field>.position``
    or ``<field>.orientation``)."""
    for value, name in ((position, "position"), (rotation, "orientation")):
        if not (math.isfinite(value) and value > 0.0):
            raise InvalidInputError("must be positive and finite", f"{field}.{name}")

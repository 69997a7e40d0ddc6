"""Building a reachability map: sampling and the builder, in the calling thread.

Joint space is sampled within the limits of the joints that move the frame (the others do
not change the frame's pose and stay at their neutral values); continuous joints over
[−π, π). ``random``: uniform samples, the block of :data:`BLOCK` samples starting at sample
s drawn from ``default_rng([seed, s])``, so a map depends on the seed only, not on the
number of processes. ``grid``: g = round(samples^(1/k)) values per joint, g^k samples in
all, end points included (a range that is a full turn [−π, π] leaves out the duplicate +π).
FK and the Jacobian are vectorised over a block in NumPy
(:class:`app.kinematics.chain.SerialChain`; chains with other joint kinds fall back to
Pinocchio in a loop). Chunks of :data:`CHUNK` samples are the unit of work: with
:func:`build_map` the chunks run in the calling thread; :mod:`app.workers.map_build` runs
them over worker processes with the same :class:`MapBuilder`. Progress advances per chunk;
a cancelled build stops within a chunk.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from app.kinematics.analysis import yoshikawa_components
from app.kinematics.chain import chain_for
from app.kinematics.errors import Cancelled, InvalidInputError
from app.kinematics.models import RobotModel
from app.kinematics.reachability.bins import orientation_bin_from_rotation
from app.kinematics.reachability.spec import MapSpec, self_collision_check, voxel_index

#: Samples per chunk (one unit of work for a process; progress advances per chunk).
CHUNK = 32_768
#: Samples evaluated at once inside a chunk (small enough for the CPU caches); random
#: samples are drawn per block, so a map does not depend on CHUNK or the process count.
BLOCK = 2_048
UNREACHED = np.float32(-1.0)


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


def chunks(total: int, size: int) -> list[tuple[int, int]]:
    return [(a, min(total, a + size)) for a in range(0, total, size)]


def build_map(robot: RobotModel, spec: MapSpec, progress: Progress | None = None) -> np.ndarray:
    """The map's float32 grid (shape + (bins,)): best manipulability per cell, −1 unreached,
    built in the calling thread.

    Raises :class:`~app.kinematics.errors.Cancelled` when ``progress.cancel`` is set (checked
    after every chunk).
    """
    progress = progress or Progress(spec.samples)
    best = np.full(spec.cells, UNREACHED, dtype=np.float32)
    progress.started = time.monotonic()
    builder = MapBuilder(robot, spec)
    for a, b in chunks(spec.samples, CHUNK):
        if progress.cancel.is_set():
            raise Cancelled
        cells, vals = builder.cells(a, b)
        np.maximum.at(best, cells, vals)
        progress.done += b - a
    return best.reshape(*spec.shape, spec.bins)

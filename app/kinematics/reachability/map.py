"""A finished reachability map: its grid, metadata, bytes format and O(1) pose queries.

The bytes (:meth:`ReachabilityMap.to_bytes`) are an ``.npz`` archive: ``best``, the float32
grid (nx, ny, nz, bins), best manipulability per cell, −1 unreached; ``meta``, JSON with the
map id, creation time, the :class:`~app.kinematics.reachability.spec.MapSpec`, the sampled
joints, the build's speed, the :func:`summarize` counts and the robot's URDF fingerprint
(:func:`robot_fingerprint`) so that a map of a robot since replaced can be refused.
"""

from __future__ import annotations

import hashlib
import io
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from app.kinematics.analysis import ROW_NAMES
from app.kinematics.models import RobotModel
from app.kinematics.reachability.bins import orientation_bin
from app.kinematics.reachability.spec import MapSpec, voxel_index


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

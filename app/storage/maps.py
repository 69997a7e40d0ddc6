"""Finished reachability maps on disk: ``<data_dir>/maps/<robot_id>/<map_id>.npz``.

Each file is :meth:`app.kinematics.reachability.map.ReachabilityMap.to_bytes` (``best``: the
float32 grid; ``meta``: JSON), written atomically (:func:`app.storage.store.atomic_write_bytes`);
maps therefore survive restarts and are shared by every process on the data directory.
``meta`` holds the robot's URDF fingerprint so a map of a robot since replaced is refused.
Build jobs, which produce the maps, are :mod:`app.storage.build_jobs`.
"""

from __future__ import annotations

import hashlib
import json
import threading
from pathlib import Path
from typing import Any

import numpy as np

from app.kinematics.errors import UnknownNameError
from app.kinematics.reachability.map import ReachabilityMap
from app.storage.store import atomic_write_bytes

#: Map and build-job ids are uuid4 hex strings: 32 lowercase hex digits.
ID_LENGTH = 32


def valid_id(value: str) -> bool:
    """Whether ``value`` can be a map or job id (checked before any file or row is read)."""
    return len(value) == ID_LENGTH and all(c in "0123456789abcdef" for c in value)


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
            if not valid_id(path.stem):
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
        if not valid_id(map_id) or not path.is_file():
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

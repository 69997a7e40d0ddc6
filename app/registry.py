"""Where robots come from: the built-in catalog and the robots users add.

The registry knows every robot id without parsing any URDF (start-up stays fast); a robot's
model is built on first use and cached. Sources:

- ``example-robot-data``: the entries of ``robots/example_robot_data.yaml``; files are located
  through the installed package's metadata (6.x ships no Python loader), and the package's
  ``share`` directory is given to Pinocchio so ``package://`` mesh URIs resolve.
"""

from __future__ import annotations

import importlib.metadata
import threading
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import yaml

import robots
from app.kinematics.errors import UnknownNameError
from app.kinematics.models import RobotModel, RobotSummary


@lru_cache
def erd_share_dir() -> Path:
    """The ``share`` directory holding ``example-robot-data/robots`` (from package metadata)."""
    dist = importlib.metadata.distribution("example-robot-data")
    marker = "share/example-robot-data/robots/"
    for f in dist.files or ():
        text = str(f).replace("\\", "/")
        if marker in text:
            prefix = text[: text.index(marker) + len("share")]
            return Path(dist.locate_file(prefix)).resolve()
    raise RuntimeError("example-robot-data is installed but ships no robots directory")


@dataclass(frozen=True)
class CatalogEntry:
    """One example-robot-data robot of the catalog."""

    id: str
    name: str
    urdf: str
    joints: int
    ee_frame: str
    srdf: str | None = None
    description: str = ""

    @property
    def urdf_path(self) -> Path:
        return erd_share_dir() / "example-robot-data" / "robots" / self.urdf

    @property
    def srdf_path(self) -> Path | None:
        return erd_share_dir() / "example-robot-data" / "robots" / self.srdf if self.srdf else None

    def summary(self) -> RobotSummary:
        return RobotSummary(self.id, self.name, "example-robot-data", self.joints, self.description)

    def build(self) -> RobotModel:
        srdf = self.srdf_path
        return RobotModel(
            self.id,
            self.urdf_path.read_text(),
            name=self.name,
            source="example-robot-data",
            package_dirs=[str(erd_share_dir())],
            srdf_text=srdf.read_text() if srdf else None,
            ee_frame=self.ee_frame,
            description=self.description,
        )


def load_catalog(path: Path = robots.CATALOG_FILE) -> dict[str, CatalogEntry]:
    """The example-robot-data catalog entries by id."""
    doc = yaml.safe_load(path.read_text())
    return {e["id"]: CatalogEntry(**e) for e in doc["robots"]}


class Registry:
    """Every robot the service knows, built lazily and cached.

    Thread-safe: models are built under a lock; a built model is immutable apart from its
    per-thread Data.
    """

    def __init__(self) -> None:
        self.catalog = load_catalog()
        self._cache: dict[str, RobotModel] = {}
        self._lock = threading.Lock()

    def ids(self) -> list[str]:
        """All robot ids."""
        return list(self.catalog)

    def summaries(self) -> list[RobotSummary]:
        """What GET /robots lists (no URDF is parsed)."""
        return [e.summary() for e in self.catalog.values()]

    def is_builtin(self, robot_id: str) -> bool:
        return robot_id in self.catalog

    def cached(self, robot_id: str) -> RobotModel | None:
        """The robot's model if it is already built, else ``None`` (never blocks)."""
        return self._cache.get(robot_id)

    def get(self, robot_id: str) -> RobotModel:
        """The robot's model, built on first use; raises :class:`UnknownNameError`."""
        robot = self._cache.get(robot_id)
        if robot is not None:
            return robot
        entry = self.catalog.get(robot_id)
        if entry is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        with self._lock:
            robot = self._cache.get(robot_id)
            if robot is None:
                robot = self._cache[robot_id] = entry.build()
        return robot

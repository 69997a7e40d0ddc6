"""The built-in robots: the example-robot-data catalog and the DH tables shipped in ``robots/``.

- ``example-robot-data``: the entries of ``robots/example_robot_data.yaml``; files are located
  through the installed package's metadata (6.x ships no Python loader), and the package's
  ``share`` directory is given to Pinocchio so ``package://`` mesh URIs resolve.
- ``dh`` (built in): the tables of ``robots/dh/*.yaml``, turned into URDF by :mod:`dh2urdf`
  on first use; the default end effector is the ``tool`` frame.

Listing an entry reads no URDF (start-up stays fast); :meth:`CatalogEntry.build` and
:meth:`DHEntry.build` make the model when :class:`app.robots.registry.Registry` first needs it.
"""

from __future__ import annotations

import importlib.metadata
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Any

import yaml

import robots
from app.kinematics.models import RobotModel, RobotSummary
from dh2urdf import DHTable, to_urdf

#: Default end effector of every DH robot (the TCP frame dh2urdf generates).
DH_EE_FRAME = "tool"


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


class DHEntry:
    """One built-in DH robot (``robots/dh/<id>.yaml``).

    The summary reads the YAML only (number of rows, description); the table is validated
    and converted to URDF when the model is first needed.
    """

    def __init__(self, robot_id: str, path: Path) -> None:
        self.id = robot_id
        self.path = path

    @cached_property
    def _doc(self) -> dict[str, Any]:
        doc = yaml.safe_load(self.path.read_text(encoding="utf-8"))
        return doc if isinstance(doc, dict) else {}

    def summary(self) -> RobotSummary:
        joints = self._doc.get("joints")
        return RobotSummary(
            self.id,
            self.id,
            "dh",
            len(joints) if isinstance(joints, list) else 0,
            str(self._doc.get("description") or ""),
        )

    @cached_property
    def table(self) -> DHTable:
        return DHTable.from_file(self.path)

    def build(self) -> RobotModel:
        table = self.table
        return RobotModel(
            self.id,
            to_urdf(table),
            name=self.id,
            source="dh",
            ee_frame=DH_EE_FRAME,
            description=table.description,
        )


def load_dh_builtins(exclude: Iterable[str] = ()) -> dict[str, DHEntry]:
    """The built-in DH robots by id (file stem), skipping ids in ``exclude``."""
    taken = set(exclude)
    return {rid: DHEntry(rid, path) for rid, path in robots.dh_tables().items() if rid not in taken}

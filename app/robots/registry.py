"""Where robots come from: the built-in robots and the robots users add, by id.

The registry knows every robot id without parsing any URDF (start-up stays fast); a robot's
model is built on first use and cached. Sources:

- ``example-robot-data`` and ``dh`` (built in): the catalog and DH tables of
  :mod:`app.robots.catalog`.
- ``dh``, ``upload`` and ``package`` (user-added): robots imported from a DH table, uploaded
  as URDF text, or as a description package (an archive with meshes, whose files are stored
  with the robot under ``files/``), checked by :mod:`app.robots.documents` and kept in the
  data directory by :class:`app.storage.store.RobotStore`.

Several processes may serve the same data directory: the directory is the source of truth.
Before a cached user-added robot is served, :meth:`RobotStore.token` (one ``stat`` and one
small read) tells whether any process changed the set of robots since the last look; if
so, the directory is listed again and models whose revision changed are dropped. Built-in
robots never change and need no check.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Mapping
from pathlib import Path
from typing import Any, BinaryIO

import yaml

from app.kinematics.errors import (
    ConflictError,
    ForbiddenError,
    InvalidInputError,
    KinematicsError,
    UnknownNameError,
)
from app.kinematics.models import RobotModel, RobotSummary
from app.kinematics.text import check_text
from app.robots.catalog import DH_EE_FRAME, erd_share_dir, load_catalog, load_dh_builtins
from app.robots.documents.archive import unpack_archive
from app.robots.documents.dh import MAX_DH_JOINTS, dh_error
from app.robots.documents.limits import UploadLimits
from app.robots.documents.mesh_check import CHECKED_KEY, check_meshes, check_stored_meshes
from app.robots.documents.package import (
    CATALOG_PACKAGE,
    FILES_PREFIX,
    catalog_meshes,
    read_package,
)
from app.robots.documents.urdf import build_checked_model, check_documents
from app.storage.store import (
    PACKAGE_DIR,
    SRDF_FILE,
    TABLE_FILE,
    URDF_FILE,
    RobotStore,
    StoredRobot,
    check_robot_id,
)
from dh2urdf import DHError, DHTable, to_urdf

log = logging.getLogger("denavit.registry")

#: Ids no robot may take: /robots/dh, /robots/urdf and /robots/package are the import routes.
RESERVED_IDS = frozenset({"dh", "urdf", "package"})


def table_yaml(table: DHTable) -> bytes:
    """The stored form of a table: its SI document (``DHTable.to_dict``) as YAML."""
    return yaml.safe_dump(table.to_dict(), sort_keys=False, allow_unicode=True).encode()


# ---------------------------------------------------------------------- the registry
class Registry:
    """Every robot the service knows, built lazily and cached.

    Parameters
    ----------
    data_dir
        The data directory (``DENAVIT_DATA_DIR``); user-added robots live in
        ``<data_dir>/robots``. ``None``: built-in robots only (adding robots is refused).
        Creating a registry cleans what a crash may have left in the robots directory.
    limits
        Bounds on every upload (:class:`app.robots.documents.limits.UploadLimits`: URDF work,
        archives, xacro, meshes, the parsing child); the defaults when not given.

    A stored robot that cannot be read back (a record damaged on disk) is left out of the
    listing or answered with a 409 naming it, never a 500.

    Thread-safe: each robot is built under a lock of its own (one build per robot at a time;
    a slow build never delays another robot), and the shared dicts change under one short
    lock. A built model is immutable apart from its per-thread Data.
    """

    def __init__(
        self,
        data_dir: Path | str | None = None,
        limits: UploadLimits | None = None,
    ) -> None:
        self.limits = limits or UploadLimits()
        self.catalog = load_catalog()
        self.dh_builtin = load_dh_builtins(exclude=self.catalog)
        self.store = RobotStore(Path(data_dir) / "robots") if data_dir is not None else None
        self._cache: dict[str, RobotModel] = {}
        self._lock = threading.Lock()  # the dicts below: held for a lookup or a write only
        self._build_locks: dict[str, threading.Lock] = {}
        self._user_lock = threading.Lock()
        self._user: dict[str, StoredRobot] = {}
        self._user_models: dict[str, tuple[str, RobotModel]] = {}
        self._user_token: tuple[bytes, int] | None = None
        if self.store is not None:
            try:
                removed = self.store.recover()
            except OSError as exc:  # e.g. a read-only data directory: reads keep working
                log.error("could not clean %s: %s", self.store.root, exc)
                removed = 0
            if removed:
                log.warning("removed %d incomplete entries from %s", removed, self.store.root)

    # ------------------------------------------------------------------ user-added robots
    def _refresh(self) -> dict[str, StoredRobot]:
        """The user-added robots, re-listed from disk if any process changed them."""
        if self.store is None:
            return {}
        if self.store.token() == self._user_token:
            return self._user
        with self._user_lock:
            token = self.store.token()  # before listing: a change while listing is seen next
            if token != self._user_token:
                listing = self.store.list()
                with self._lock:
                    self._user_models = {
                        rid: entry
                        for rid, entry in self._user_models.items()
                        if rid in listing and listing[rid].revision == entry[0]
                    }
                self._user = listing
                self._user_token = token
            return self._user

    # ------------------------------------------------------------------ lookups
    def ids(self) -> list[str]:
        """All robot ids."""
        return [*self.catalog, *self.dh_builtin, *self._refresh()]

    def summaries(self) -> list[RobotSummary]:
        """What GET /robots lists (no URDF is parsed)."""
        out = [e.summary() for e in self.catalog.values()]
        out += [e.summary() for e in self.dh_builtin.values()]
        for rid, stored in self._refresh().items():
            meta = stored.meta  # validated by RobotStore.load: strings are valid text
            name, source = meta.get("name") or rid, meta.get("source") or "upload"
            joints, description = meta.get("joints") or 0, meta.get("description") or ""
            out.append(RobotSummary(rid, name, source, joints, description))
        return out

    def is_builtin(self, robot_id: str) -> bool:
        return robot_id in self.catalog or robot_id in self.dh_builtin

    def exists(self, robot_id: str) -> bool:
        """Whether ``robot_id`` names a robot (built in or user-added)."""
        return self.is_builtin(robot_id) or robot_id in self._refresh()

    def cached(self, robot_id: str) -> RobotModel | None:
        """The robot's model if it is already built and current, else ``None``.

        Never blocks on a build; for a user-added robot it costs the change check (one
        ``stat`` and one small read).
        """
        robot = self._cache.get(robot_id)
        if robot is not None:
            return robot
        entry = self._user_models.get(robot_id)
        if entry is None or self.store is None or self.store.token() != self._user_token:
            return None
        return entry[1]

    def get(self, robot_id: str) -> RobotModel:
        """The robot's model, built on first use; raises :class:`UnknownNameError`."""
        robot = self._cache.get(robot_id)
        if robot is not None:
            return robot
        entry = self.catalog.get(robot_id) or self.dh_builtin.get(robot_id)
        if entry is not None:
            with self._build_lock(robot_id):
                robot = self._cache.get(robot_id)
                if robot is None:
                    robot = self._cache[robot_id] = entry.build()
            return robot
        stored = self._refresh().get(robot_id)
        if stored is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        with self._build_lock(robot_id):
            cached = self._user_models.get(robot_id)
            if cached is not None and cached[0] == stored.revision:
                return cached[1]
            return self._stored(stored, self._build_stored(stored))

    def _build_lock(self, robot_id: str) -> threading.Lock:
        """The lock one robot's build holds (created on first use, kept for the id)."""
        with self._lock:
            return self._build_locks.setdefault(robot_id, threading.Lock())

    def _build_stored(self, stored: StoredRobot) -> RobotModel:
        """The model of a stored robot; a record that cannot be served is a 409 naming it.

        The stored URDF (and SRDF) pass the upload checks and limits again before Pinocchio
        reads them: a record written before a check existed (a namespace-hidden mesh path,
        thousands of attributes, hundreds of joints) or damaged on disk is refused, not
        served.
        """
        why = "its record is damaged"
        try:
            urdf = stored.read_text(URDF_FILE)
            if urdf is None:  # deleted by another process since the listing
                raise UnknownNameError("robot", stored.id, "robot_id", self.ids())
            srdf = stored.read_text(SRDF_FILE)
            check_documents(urdf, srdf, self.limits.urdf)
            meta = stored.meta
            dirs = [str(erd_share_dir())]
            if (stored.path / PACKAGE_DIR).is_dir():
                dirs.insert(0, str(stored.path))  # package://files/... → <robot>/files/...
            limits = self.limits
            check_stored_meshes(stored.id, urdf, meta, dirs, limits.mesh, limits.parse)
            robot = RobotModel(
                stored.id,
                urdf,
                name=meta.get("name") or stored.id,
                source=meta.get("source") or "upload",
                package_dirs=dirs,
                srdf_text=srdf,
                ee_frame=meta.get("ee_frame"),
                description=meta.get("description") or "",
            )
            robot.mesh_limits = self.limits.mesh  # checked again before a mesh is loaded
            return robot
        except UnknownNameError as exc:
            if exc.field == "robot_id":
                raise
            reason: BaseException = exc
        except InvalidInputError as exc:  # our own checks: the message holds no host detail
            reason = exc
            why = f"it fails today's checks: {exc.field}: {exc.message}"
        except (KinematicsError, OSError, ValueError, RuntimeError) as exc:
            # What a record the current code cannot read raises: the file (OSError, bytes
            # that are not UTF-8), the parser (Pinocchio's RuntimeError/ValueError), the
            # model checks (KinematicsError). Anything else is a bug: a 500 with its
            # traceback (app.middleware.guard), not "delete it and add it again".
            reason = exc
        log.error("stored robot %r cannot be loaded: %r", stored.id, reason)
        raise ConflictError(
            f"robot {stored.id!r} is stored but cannot be served ({why}); "
            "delete it and add it again",
            "robot_id",
        )

    def urdf_text(self, robot_id: str) -> str:
        """The robot's URDF (the catalog file, the generated one for DH robots)."""
        entry = self.catalog.get(robot_id)
        if entry is not None:
            return entry.urdf_path.read_text()
        return self.get(robot_id).urdf_text

    def dh_table(self, robot_id: str) -> DHTable | None:
        """The DH table a robot was built from (SI), ``None`` for URDF robots.

        Raises :class:`UnknownNameError` for an unknown id.
        """
        entry = self.dh_builtin.get(robot_id)
        if entry is not None:
            return entry.table
        if robot_id in self.catalog:
            return None
        stored = self._refresh().get(robot_id)
        if stored is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        try:
            text = stored.read_text(TABLE_FILE)
            return DHTable.from_yaml(text) if text is not None else None
        except (OSError, ValueError) as exc:  # DHError and UnicodeDecodeError included
            log.error("stored DH table of %r cannot be read: %r", robot_id, exc)
            raise ConflictError(
                f"robot {robot_id!r}: its stored DH table is damaged; delete the robot and "
                "add it again",
                "robot_id",
            ) from None

    def source(self, robot_id: str) -> str:
        """``example-robot-data``, ``dh`` or ``upload``; raises :class:`UnknownNameError`."""
        if robot_id in self.catalog:
            return "example-robot-data"
        if robot_id in self.dh_builtin:
            return "dh"
        stored = self._refresh().get(robot_id)
        if stored is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        return str(stored.meta.get("source") or "upload")

    # ------------------------------------------------------------------ writes
    def _writable(self, robot_id: str, field: str) -> RobotStore:
        if self.store is None:
            raise ForbiddenError("this service has no data directory for user robots")
        check_robot_id(robot_id, field)
        if robot_id in RESERVED_IDS:
            raise InvalidInputError(
                f"robot id {robot_id!r} is reserved (/robots/{robot_id} is an import route)", field
            )
        if self.exists(robot_id):
            kind = "a built-in robot" if self.is_builtin(robot_id) else "a robot"
            raise ConflictError(f"{kind} with id {robot_id!r} already exists", field)
        return self.store

    def _stored(self, stored: StoredRobot, robot: RobotModel) -> RobotModel:
        """Cache a user-added robot's model (copy on write: readers take no lock)."""
        with self._lock:
            self._user_models = {**self._user_models, stored.id: (stored.revision, robot)}
        return robot

    def import_dh(self, table: DHTable) -> RobotModel:
        """Add a robot from a validated DH table; its id is the table's ``name``.

        Raises :class:`ConflictError` (id taken by any robot) or :class:`InvalidInputError`.
        """
        store = self._writable(table.name, "name")
        if table.dof > MAX_DH_JOINTS:
            raise InvalidInputError(f"at most {MAX_DH_JOINTS} rows, got {table.dof}", "joints")
        try:
            urdf = to_urdf(table)
        except DHError as exc:
            raise dh_error(exc) from None
        robot = build_checked_model(
            table.name,
            urdf,
            source="dh",
            ee_frame=DH_EE_FRAME,
            description=table.description,
            urdf_field="body",
        )
        meta = {
            "name": table.name,
            "source": "dh",
            "description": table.description,
            "ee_frame": DH_EE_FRAME,
            "joints": robot.n,
        }
        files = {URDF_FILE: urdf.encode(), TABLE_FILE: table_yaml(table)}
        return self._stored(store.create(table.name, meta, files), robot)

    def add_urdf(
        self,
        robot_id: str,
        urdf: str,
        *,
        srdf: str | None = None,
        ee_frame: str | None = None,
        description: str = "",
    ) -> RobotModel:
        """Add a robot from client-supplied URDF (and SRDF) text, checked first.

        The XML is parsed with literal names as Pinocchio reads it, without DTD, entities or
        external references and within :attr:`limits`, and checked
        (:func:`app.robots.documents.urdf.check_documents`) before Pinocchio sees it.
        """
        store = self._writable(robot_id, "name")
        check_text(description, "description")
        if ee_frame is not None:
            check_text(ee_frame, "ee_frame")
        root = check_documents(urdf, srdf, self.limits.urdf)
        meshes = catalog_meshes(root, erd_share_dir(), "urdf")
        robot = build_checked_model(
            robot_id,
            urdf,
            source="upload",
            srdf=srdf,
            ee_frame=ee_frame,
            description=description,
            package_dirs=[str(erd_share_dir())],
        )
        limits = self.limits
        dirs = robot.package_dirs
        triangles = check_meshes(urdf, meshes, dirs, limits.mesh, limits.parse, "urdf")
        robot.mesh_limits = self.limits.mesh
        meta, files = _record(robot, "upload", description, triangles, urdf, srdf)
        return self._stored(store.create(robot_id, meta, files), robot)

    def add_package(
        self,
        robot_id: str,
        archive: BinaryIO,
        description_path: str,
        *,
        srdf_path: str | None = None,
        xacro_args: Mapping[str, str] | None = None,
        ee_frame: str | None = None,
        description: str = "",
        srdf_xacro_args: Mapping[str, str] | None = None,
    ) -> RobotModel:
        """Add a robot from a description package (zip or tar.gz archive with its meshes).

        The archive is unpacked within :attr:`archive_limits` into a staging directory of
        the store (:func:`app.robots.documents.archive.unpack_archive`), its description read and
        its file references resolved inside it, every mesh header checked
        (:func:`app.robots.documents.package.read_package`; xacro and MJCF in bounded children),
        the URDF checked like an uploaded one, and every mesh loaded and the collision
        geometry built in a bounded child (:func:`app.robots.documents.mesh_check.check_meshes`);
        only then is the robot stored, with the package's files. Nothing is parsed by a
        mesh loader in this process. Any refusal leaves nothing behind.
        """
        store = self._writable(robot_id, "name")
        check_text(description, "description")
        if ee_frame is not None:
            check_text(ee_frame, "ee_frame")
        with store.staging() as staging:
            files_dir = staging / PACKAGE_DIR
            files_dir.mkdir()
            unpack_archive(archive, files_dir, self.limits.archive)
            package = read_package(
                files_dir,
                description_path,
                srdf=srdf_path,
                xacro_args=xacro_args or {},
                catalog=erd_share_dir(),
                limits=self.limits,
                srdf_xacro_args=srdf_xacro_args,
            )
            check_documents(package.urdf, package.srdf, self.limits.urdf, "description")
            robot = build_checked_model(
                robot_id,
                package.urdf,
                source="package",
                srdf=package.srdf,
                ee_frame=ee_frame,
                description=description,
                package_dirs=[str(staging), str(erd_share_dir())],
                urdf_field="description",
            )
            dirs, limits = robot.package_dirs, self.limits
            triangles = check_meshes(
                package.urdf, package.meshes, dirs, limits.mesh, limits.parse, "archive"
            )
            robot.package_dirs = [str(store.root / robot_id), str(erd_share_dir())]
            robot.mesh_limits = self.limits.mesh
            meta, files = _record(
                robot, "package", description, triangles, package.urdf, package.srdf
            )
            stored = store.create(robot_id, meta, files, tree=files_dir)
        return self._stored(stored, robot)

    def files_root(self, robot_id: str) -> tuple[Path, str] | None:
        """Where the files of a robot are (GET /robots/{robot_id}/files/{path}).

        ``(directory, mesh URI prefix)``: a catalog robot's package folder of
        example-robot-data (``package://example-robot-data/robots/<folder>/``), a package
        robot's stored files (``package://files/``); ``None`` for other robots. Raises
        :class:`UnknownNameError` for an unknown id.
        """
        entry = self.catalog.get(robot_id)
        if entry is not None:
            folder = entry.urdf.split("/", 1)[0]
            prefix = f"package://{CATALOG_PACKAGE}/robots/{folder}/"
            return erd_share_dir() / CATALOG_PACKAGE / "robots" / folder, prefix
        if robot_id in self.dh_builtin:
            return None
        stored = self._refresh().get(robot_id)
        if stored is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        files = stored.path / PACKAGE_DIR
        return (files, FILES_PREFIX) if files.is_dir() else None

    def delete(self, robot_id: str) -> None:
        """Remove a user-added robot; built-in robots raise :class:`ForbiddenError`."""
        if self.is_builtin(robot_id):
            raise ForbiddenError(
                f"robot {robot_id!r} is built in and cannot be deleted", "robot_id"
            )
        if self.store is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        self.store.delete(robot_id)
        with self._lock:
            self._user_models = {k: v for k, v in self._user_models.items() if k != robot_id}


def _record(
    robot: RobotModel,
    source: str,
    description: str,
    triangles: Any,
    urdf: str,
    srdf: str | None,
) -> tuple[dict[str, Any], dict[str, bytes]]:
    """A checked, user-added robot as stored: metadata (mesh triangle counts) and documents."""
    files = {URDF_FILE: urdf} | ({} if srdf is None else {SRDF_FILE: srdf})
    return {
        "name": robot.id,
        "source": source,
        "description": description,
        "ee_frame": robot.ee_frame,
        "joints": robot.n,
        CHECKED_KEY: triangles,
    }, {name: text.encode() for name, text in files.items()}

"""Where robots come from: the built-in catalog, the built-in DH tables, the robots users add.

The registry knows every robot id without parsing any URDF (start-up stays fast); a robot's
model is built on first use and cached. Sources:

- ``example-robot-data``: the entries of ``robots/example_robot_data.yaml``; files are located
  through the installed package's metadata (6.x ships no Python loader), and the package's
  ``share`` directory is given to Pinocchio so ``package://`` mesh URIs resolve.
- ``dh`` (built in): the tables of ``robots/dh/*.yaml``, turned into URDF by :mod:`dh2urdf`
  on first use; the default end effector is the ``tool`` frame.
- ``dh`` and ``upload`` (user-added): robots imported from a DH table or uploaded as URDF,
  kept in the data directory by :class:`app.store.RobotStore`.

Several processes may serve the same data directory: the directory is the source of truth.
Before a cached user-added robot is served, :meth:`RobotStore.token` (one ``stat`` and one
small read) tells whether any process changed the set of robots since the last look; if
so, the directory is listed again and models whose revision changed are dropped. Built-in
robots never change and need no check.
"""

from __future__ import annotations

import importlib.metadata
import logging
import threading
from collections.abc import Iterable
from dataclasses import dataclass
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Any, Literal

import yaml

import robots
from app.kinematics.errors import (
    ConflictError,
    ForbiddenError,
    InvalidInputError,
    KinematicsError,
    UnknownNameError,
)
from app.kinematics.models import RobotModel, RobotSummary
from app.kinematics.text import check_text
from app.kinematics.xmldoc import parse_literal_xml
from app.store import (
    SRDF_FILE,
    TABLE_FILE,
    URDF_FILE,
    RobotStore,
    StoredRobot,
    check_robot_id,
)
from app.urdf_checks import (
    URDF_JOINT_TYPES,
    UrdfLimits,
    check_resource_uri,
    check_srdf_document,
    check_urdf_document,
)
from dh2urdf import DHError, DHTable, to_urdf

__all__ = [
    "URDF_JOINT_TYPES",
    "Registry",
    "UrdfLimits",
    "check_resource_uri",
    "check_srdf_document",
    "check_urdf_document",
    "parse_dh_document",
]

log = logging.getLogger("denavit.registry")

#: Default end effector of every DH robot (the TCP frame dh2urdf generates).
DH_EE_FRAME = "tool"
#: Ids no robot may take: /robots/dh and /robots/urdf are the import routes.
RESERVED_IDS = frozenset({"dh", "urdf"})
#: Most rows a user-supplied DH table may have.
MAX_DH_JOINTS = 64
#: Largest DH table document (bytes): tables are small, and YAML parsing is slow.
MAX_DH_DOCUMENT_BYTES = 256 * 1024
#: Deepest nesting a DH document may have (a table needs 3 levels).
MAX_DOCUMENT_DEPTH = 16
#: Most YAML parse events a DH document may have (64 rows of 10 fields need ~1,400).
MAX_YAML_EVENTS = 20_000


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


# ---------------------------------------------------------------------- DH documents
def dh_field(path: str | None, prefix: str = "") -> str:
    """A dh2urdf field path (``joints[2].lower``) in the API's dotted form (``joints.2.lower``)."""
    dotted = (path or "").replace("[", ".").replace("]", "").strip(".")
    if prefix:
        return f"{prefix}.{dotted}" if dotted else prefix
    return dotted or "body"


def dh_error(exc: DHError, prefix: str = "") -> InvalidInputError:
    """The core error (HTTP 422) for a dh2urdf validation error, naming the field."""
    return InvalidInputError(exc.reason, dh_field(exc.field, prefix))


class MalformedDocumentError(InvalidInputError):
    """The document is not JSON or YAML at all (the API answers 400)."""


def _max_bracket_depth(text: str) -> int:
    """Deepest nesting of ``[``/``{`` in ``text`` (quotes ignored: an upper bound)."""
    depth = deepest = 0
    for char in text:
        if char in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif char in "]}" and depth:
            depth -= 1
    return deepest


def _screen_yaml(text: str) -> None:
    """Cheap checks before the (pure-Python, slow) table parser sees a YAML document.

    PyYAML's scanner is quadratic in flow nesting depth and a DH table is small and
    shallow, so the document is refused when it nests deeper than
    :data:`MAX_DOCUMENT_DEPTH`, has more than :data:`MAX_YAML_EVENTS` parse events (read with
    libyaml when available), or uses aliases (``*name``, which let a small body expand
    enormously).
    """
    if _max_bracket_depth(text) > MAX_DOCUMENT_DEPTH:
        raise MalformedDocumentError(
            f"invalid YAML: nested deeper than {MAX_DOCUMENT_DEPTH} levels", "body"
        )
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    depth = events = 0
    try:
        for event in yaml.parse(text, Loader=loader):
            events += 1
            if isinstance(event, yaml.AliasEvent):
                line = event.start_mark.line + 1 if event.start_mark else "?"
                raise InvalidInputError(
                    f"YAML aliases are not accepted (alias *{event.anchor} on line {line}); "
                    "write the values out",
                    "body",
                )
            if isinstance(event, yaml.CollectionStartEvent):
                depth += 1
                if depth > MAX_DOCUMENT_DEPTH:
                    raise MalformedDocumentError(
                        f"invalid YAML: nested deeper than {MAX_DOCUMENT_DEPTH} levels", "body"
                    )
            elif isinstance(event, yaml.CollectionEndEvent):
                depth -= 1
            if events > MAX_YAML_EVENTS:
                raise InvalidInputError(
                    f"too many YAML values for a DH table (more than {MAX_YAML_EVENTS})", "body"
                )
    except yaml.YAMLError:
        return  # syntax errors are reported by the table parser, with their position
    except RecursionError:
        raise MalformedDocumentError("invalid YAML: nested too deeply", "body") from None


def parse_dh_document(text: str, fmt: Literal["json", "yaml"]) -> DHTable:
    """Validate a DH table document (JSON or YAML text) and convert it to SI.

    Raises
    ------
    MalformedDocumentError
        The text is not JSON/YAML (or uses YAML aliases, or nests absurdly deep).
    InvalidInputError
        A field is wrong; ``field`` is its dotted path (``joints.2.lower``).
    """
    if fmt == "yaml":
        _screen_yaml(text)
    try:
        table = DHTable.from_text(text, fmt)
    except DHError as exc:
        if exc.field is None and exc.reason.startswith(("invalid JSON", "invalid YAML")):
            raise MalformedDocumentError(exc.reason, "body") from None
        raise dh_error(exc) from None
    except RecursionError:
        raise MalformedDocumentError(f"invalid {fmt.upper()}: nested too deeply", "body") from None
    except (TypeError, KeyError, AttributeError) as exc:  # a value of a type dh2urdf missed
        log.warning("dh2urdf raised %r instead of DHError", exc)
        raise InvalidInputError(f"not a valid DH table ({exc})", "body") from None
    if table.dof > MAX_DH_JOINTS:
        raise InvalidInputError(f"at most {MAX_DH_JOINTS} rows, got {table.dof}", "joints")
    return table


def table_yaml(table: DHTable) -> bytes:
    """The stored form of a table: its SI document (``DHTable.to_dict``) as YAML."""
    return yaml.safe_dump(table.to_dict(), sort_keys=False, allow_unicode=True).encode()


# ---------------------------------------------------------------------- URDF uploads
def build_checked_model(
    robot_id: str,
    urdf: str,
    *,
    source: str,
    srdf: str | None = None,
    ee_frame: str | None = None,
    description: str = "",
    package_dirs: Iterable[str] = (),
    urdf_field: str = "urdf",
) -> RobotModel:
    """A :class:`RobotModel` from text a client sent; every failure is an InvalidInputError."""
    try:
        robot = RobotModel(
            robot_id,
            urdf,
            name=robot_id,
            source=source,
            package_dirs=list(package_dirs),
            srdf_text=srdf,
            ee_frame=ee_frame,
            description=description,
        )
    except UnknownNameError as exc:
        raise InvalidInputError(exc.message, "ee_frame") from None
    except (ValueError, RuntimeError, IndexError, KeyError, TypeError) as exc:
        raise InvalidInputError(f"Pinocchio rejected the URDF ({exc})", urdf_field) from None
    if robot.n == 0:
        raise InvalidInputError(
            "the URDF has no actuated joint (revolute, continuous or prismatic)", urdf_field
        )
    return robot


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
        Bounds on the work an uploaded URDF may cause (``DENAVIT_MAX_XML_*``,
        ``DENAVIT_MAX_URDF_JOINTS``, ``DENAVIT_MAX_ROBOT_DOF``); default :class:`UrdfLimits`.

    A stored robot that cannot be read back (a record damaged on disk) is left out of the
    listing or answered with a 409 naming it, never a 500.

    Thread-safe: models are built under a lock; a built model is immutable apart from its
    per-thread Data.
    """

    def __init__(
        self, data_dir: Path | str | None = None, limits: UrdfLimits | None = None
    ) -> None:
        self.limits = limits or UrdfLimits()
        self.catalog = load_catalog()
        self.dh_builtin = load_dh_builtins(exclude=self.catalog)
        self.store = RobotStore(Path(data_dir) / "robots") if data_dir is not None else None
        self._cache: dict[str, RobotModel] = {}
        self._lock = threading.Lock()
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
            out.append(
                RobotSummary(
                    rid,
                    meta.get("name") or rid,
                    meta.get("source") or "upload",
                    meta.get("joints") or 0,
                    meta.get("description") or "",
                )
            )
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
            with self._lock:
                robot = self._cache.get(robot_id)
                if robot is None:
                    robot = self._cache[robot_id] = entry.build()
            return robot
        stored = self._refresh().get(robot_id)
        if stored is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        with self._lock:
            cached = self._user_models.get(robot_id)
            if cached is not None and cached[0] == stored.revision:
                return cached[1]
            robot = self._build_stored(stored)
            self._user_models = {**self._user_models, robot_id: (stored.revision, robot)}
        return robot

    def check_documents(self, urdf: str, srdf: str | None) -> None:
        """The upload checks of a URDF (and its SRDF) within :attr:`limits`: parsed with
        literal names as Pinocchio reads them, no DTD or entities, bounded work
        (:func:`check_urdf_document`, :func:`check_srdf_document`); raises
        :class:`InvalidInputError` naming ``urdf`` or ``srdf``."""
        root = parse_literal_xml(urdf, "urdf", self.limits.xml)
        check_urdf_document(root, "urdf", self.limits)
        if srdf is not None:
            links = {link.get("name", "") for link in root.findall("link")}
            check_srdf_document(srdf, links, "srdf", self.limits.xml)

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
            self.check_documents(urdf, srdf)
            meta = stored.meta
            return RobotModel(
                stored.id,
                urdf,
                name=meta.get("name") or stored.id,
                source=meta.get("source") or "upload",
                package_dirs=[str(erd_share_dir())],
                srdf_text=srdf,
                ee_frame=meta.get("ee_frame"),
                description=meta.get("description") or "",
            )
        except UnknownNameError as exc:
            if exc.field == "robot_id":
                raise
            reason: BaseException = exc
        except InvalidInputError as exc:  # our own checks: the message holds no host detail
            reason = exc
            why = f"it fails today's checks: {exc.field}: {exc.message}"
        except (
            KinematicsError,
            OSError,
            ValueError,
            RuntimeError,
            IndexError,
            KeyError,
            TypeError,
        ) as exc:
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
        (:func:`check_urdf_document`) before Pinocchio sees it.
        """
        store = self._writable(robot_id, "name")
        check_text(description, "description")
        if ee_frame is not None:
            check_text(ee_frame, "ee_frame")
        self.check_documents(urdf, srdf)
        robot = build_checked_model(
            robot_id,
            urdf,
            source="upload",
            srdf=srdf,
            ee_frame=ee_frame,
            description=description,
            package_dirs=[str(erd_share_dir())],
        )
        meta = {
            "name": robot_id,
            "source": "upload",
            "description": description,
            "ee_frame": robot.ee_frame,
            "joints": robot.n,
        }
        files = {URDF_FILE: urdf.encode()}
        if srdf is not None:
            files[SRDF_FILE] = srdf.encode()
        return self._stored(store.create(robot_id, meta, files), robot)

    def delete(self, robot_id: str) -> None:
        """Remove a user-added robot; built-in robots raise :class:`ForbiddenError`."""
        if self.is_builtin(robot_id):
            raise ForbiddenError(
                f"robot {robot_id!r} is built in and cannot be deleted", "robot_id"
            )
        if self.store is None:
            raise UnknownNameError("robot", robot_id, "robot_id", self.ids())
        self.store.delete(robot_id)
        self._user_models = {k: v for k, v in self._user_models.items() if k != robot_id}

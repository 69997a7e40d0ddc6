"""User-added data on disk (robots, scenes, maps) under ``DENAVIT_DATA_DIR``.

Files
-----
Writes are atomic: the bytes go to a temporary file in the same directory, are fsynced,
and the file is renamed over its target (then the directory is fsynced), so a reader or a
crash sees either the old file or the new one, never half of one.

Robots
------
A user-added robot is one directory ``<root>/<id>/`` holding ``robot.json`` (metadata),
``robot.urdf`` and optionally ``robot.srdf``, ``table.yaml`` (the DH table it came from)
and ``files/`` (the unpacked description package a robot was uploaded with: its meshes).
:class:`RobotStore` makes a robot appear whole or not at all:

1. every file is written into a fresh temporary directory ``<root>/.tmp-*`` and fsynced;
   a package tree is unpacked into another locked temporary directory
   (:meth:`RobotStore.staging`), fsynced and renamed into the first one as ``files/``;
2. under the store lock (``<root>/.lock``, ``flock``), the directory is renamed to
   ``<root>/<id>`` (a single atomic ``rename``), the root is fsynced, and the generation
   counter ``<root>/.generation`` is bumped (atomically);
3. deleting renames ``<root>/<id>`` to a temporary name first (the robot disappears at
   once), bumps the generation, then removes the files.

A crash leaves at worst ``.tmp-*`` entries (staging or not yet renamed), which
:meth:`RobotStore.recover` removes at the next start, together with any robot directory
lacking its metadata or URDF.

Temporaries in use are protected by an exclusive ``flock`` held by their writer for the
whole write; the cleanup removes only temporaries it can lock itself, so a worker starting
while another one writes never deletes that write (``flock`` locks die with their process,
so a crashed writer's temporaries are always removable).

Several processes (uvicorn workers) may share the directory: the data directory is the
source of truth, and :meth:`RobotStore.token` (generation counter plus the root's
``mtime_ns``) is a cheap way for a reader to notice that something changed.
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import logging
import os
import re
import shutil
import tempfile
import uuid
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from app.kinematics.errors import ConflictError, InvalidInputError, UnknownNameError
from app.kinematics.text import SURROGATE_REASON, has_surrogate

log = logging.getLogger("denavit.store")

TMP_PREFIX = ".tmp-"

#: What a user-chosen robot id may look like (it becomes a directory name).
ID_PATTERN = re.compile(r"^[a-z0-9_-]{1,64}$")

META_FILE = "robot.json"
URDF_FILE = "robot.urdf"
SRDF_FILE = "robot.srdf"
TABLE_FILE = "table.yaml"
#: The files a robot directory may hold; ``robot.json`` is written by the store itself.
ROBOT_FILES = frozenset({URDF_FILE, SRDF_FILE, TABLE_FILE})
#: The directory of a robot's package files (the tree given to :meth:`RobotStore.create`).
PACKAGE_DIR = "files"
LOCK_FILE = ".lock"
GENERATION_FILE = ".generation"

_ATTEMPTS = 5


def _fsync_dir(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_tree(root: Path) -> None:
    """fsync every file and directory under ``root`` (a tree without links)."""
    for folder, _, names in os.walk(root):
        for name in names:
            fd = os.open(os.path.join(folder, name), os.O_RDONLY | os.O_NOFOLLOW)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
        _fsync_dir(Path(folder))


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]


def atomic_write_bytes(path: Path, data: bytes, durable: bool = True) -> None:
    """Write ``data`` to ``path`` atomically (temp file, fsync, rename, fsync dir).

    The temporary file is ``flock``-ed from creation to rename, so
    :func:`remove_stale_temporaries` running in another process never removes it.
    ``durable=False`` skips both fsyncs: readers still see the old file or the new one,
    never half of one, but a power loss may lose the write (for ephemeral status files).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    for _ in range(_ATTEMPTS):
        fd, tmp = tempfile.mkstemp(prefix=TMP_PREFIX, dir=path.parent)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX)
            if os.fstat(fd).st_nlink == 0:  # a cleanup removed it before we locked it
                continue
            _write_all(fd, data)
            if durable:
                os.fsync(fd)
            os.replace(tmp, path)
            break
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise
        finally:
            os.close(fd)
    else:  # pragma: no cover - needs a cleanup racing every attempt
        raise OSError(f"could not write {path}: temporaries removed by a concurrent cleanup")
    if durable:
        _fsync_dir(path.parent)


def _try_lock(path: Path) -> int | None:
    """An fd holding an exclusive ``flock`` on ``path``, or ``None`` if someone holds one."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW)
    except OSError:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return None
    return fd


def remove_stale_temporaries(root: Path) -> int:
    """Delete temporary files and directories a crash left behind under ``root``.

    An entry still locked by its writer (a write in progress in another process) is left
    alone. Returns how many entries were removed.
    """
    root = Path(root)
    if not root.is_dir():
        return 0
    found = sorted(root.rglob(TMP_PREFIX + "*"), key=lambda p: len(p.parts))
    removed: list[Path] = []
    for tmp in found:
        if any(tmp.is_relative_to(r) for r in removed):
            continue
        if tmp.is_symlink():
            tmp.unlink(missing_ok=True)
            removed.append(tmp)
            continue
        fd = _try_lock(tmp)
        if fd is None:
            continue
        try:
            if tmp.is_dir():
                shutil.rmtree(tmp, ignore_errors=True)
            else:
                tmp.unlink(missing_ok=True)
        finally:
            os.close(fd)
        removed.append(tmp)
    return len(removed)


def check_robot_id(robot_id: Any, field: str = "id") -> str:
    """``robot_id`` if it is a valid id (``^[a-z0-9_-]{1,64}$``), else InvalidInputError."""
    if not isinstance(robot_id, str) or not ID_PATTERN.fullmatch(robot_id):
        raise InvalidInputError(
            f"robot id {robot_id!r} is not allowed: use 1 to 64 characters among lower-case "
            "letters, digits, '_' and '-'",
            field,
        )
    return robot_id


_META_TEXT = ("name", "source", "description", "revision", "created_at")


def meta_problem(meta: Mapping[str, Any]) -> tuple[str, str] | None:
    """``(key, reason)`` for what is wrong with a robot's metadata, or ``None`` if it is fine.

    Text fields must be strings of valid Unicode (a lone surrogate cannot be encoded in a
    response), ``ee_frame`` a string or null, ``joints`` a non-negative integer.
    """
    for key in (*_META_TEXT, "ee_frame"):
        value = meta.get(key, None if key == "ee_frame" else "")
        if key == "ee_frame" and value is None:
            continue
        if not isinstance(value, str):
            return key, "must be a string"
        if has_surrogate(value):
            return key, SURROGATE_REASON
    joints = meta.get("joints", 0)
    if isinstance(joints, bool) or not isinstance(joints, int) or joints < 0:
        return "joints", "must be a non-negative integer"
    return None


@dataclass(frozen=True)
class StoredRobot:
    """A complete robot directory, as read from disk.

    ``meta`` holds ``id``, ``name``, ``source`` (``dh`` or ``upload``), ``description``,
    ``ee_frame``, ``joints`` (number of actuated joints), ``revision`` (unique per write)
    and ``created_at`` (ISO 8601, UTC).
    """

    id: str
    path: Path
    meta: dict[str, Any]

    @property
    def revision(self) -> str:
        return str(self.meta.get("revision", ""))

    def read_text(self, name: str) -> str | None:
        """A file of the robot as text, ``None`` if the robot has no such file."""
        try:
            return (self.path / name).read_text(encoding="utf-8")
        except FileNotFoundError:
            return None


class RobotStore:
    """User-added robots under ``root`` (``<data_dir>/robots``); see the module docstring."""

    def __init__(self, root: Path) -> None:
        self.root = Path(root)
        self._root_str = str(self.root)
        self._generation_str = str(self.root / GENERATION_FILE)

    # ------------------------------------------------------------------ locking
    def _ensure_root(self) -> None:
        """Create the root (and make its directory entry durable) on first use."""
        if not self.root.is_dir():
            self.root.mkdir(parents=True, exist_ok=True)
            _fsync_dir(self.root.parent)

    @contextlib.contextmanager
    def _locked(self) -> Iterator[None]:
        """Hold the store lock (exclusive ``flock`` on ``<root>/.lock``)."""
        self._ensure_root()
        fd = os.open(self.root / LOCK_FILE, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX)
            yield
        finally:
            os.close(fd)

    # ------------------------------------------------------------------ reading
    def token(self) -> tuple[bytes, int]:
        """A value that changes whenever a robot is added or removed (by any process).

        The generation counter's content plus the root directory's ``mtime_ns``: one
        ``stat`` and one small read, cheap enough to check before serving a cached model.
        """
        try:
            mtime = os.stat(self._root_str).st_mtime_ns
        except FileNotFoundError:
            return (b"", 0)
        try:
            fd = os.open(self._generation_str, os.O_RDONLY)
        except FileNotFoundError:
            return (b"", mtime)
        try:
            gen = os.read(fd, 64)
        finally:
            os.close(fd)
        return (gen, mtime)

    def load(self, robot_id: str, *, validate: bool = True) -> StoredRobot | None:
        """The complete robot ``robot_id``, or ``None`` (absent, incomplete or unreadable).

        With ``validate`` (the default), a robot whose metadata is damaged (see
        :func:`meta_problem`) is ``None`` too, with a warning in the log: one bad record on
        disk must not break listing the others. ``validate=False`` finds it anyway (so it
        can be deleted).
        """
        if not ID_PATTERN.fullmatch(robot_id):
            return None
        path = self.root / robot_id
        try:
            meta = json.loads((path / META_FILE).read_bytes())
        except FileNotFoundError:
            return None
        except (OSError, ValueError) as exc:
            log.warning("ignoring robot %r: unreadable %s (%s)", robot_id, META_FILE, exc)
            return None
        if not isinstance(meta, dict) or meta.get("id") != robot_id:
            log.warning("ignoring robot %r: %s does not describe it", robot_id, META_FILE)
            return None
        if not (path / URDF_FILE).is_file():
            return None
        problem = meta_problem(meta) if validate else None
        if problem is not None:
            log.warning("ignoring robot %r: damaged %s (%s %s)", robot_id, META_FILE, *problem)
            return None
        return StoredRobot(robot_id, path, meta)

    def list(self) -> dict[str, StoredRobot]:
        """Every complete robot, by id (sorted)."""
        try:
            names = sorted(os.listdir(self.root))
        except FileNotFoundError:
            return {}
        out: dict[str, StoredRobot] = {}
        for name in names:
            if ID_PATTERN.fullmatch(name):
                robot = self.load(name)
                if robot is not None:
                    out[name] = robot
        return out

    # ------------------------------------------------------------------ writing
    def _bump(self) -> None:
        """Increment the generation counter (call with the store lock held)."""
        try:
            current = int((self.root / GENERATION_FILE).read_bytes().split()[0])
        except (FileNotFoundError, ValueError, IndexError):
            current = 0
        atomic_write_bytes(self.root / GENERATION_FILE, f"{current + 1}\n".encode())

    def _temp_dir(self) -> tuple[Path, int]:
        """A new, locked temporary directory under the root: (path, fd holding the lock)."""
        self._ensure_root()
        for _ in range(_ATTEMPTS):
            tmp = Path(tempfile.mkdtemp(prefix=TMP_PREFIX, dir=self.root))
            fd = os.open(tmp, os.O_RDONLY | os.O_DIRECTORY)
            fcntl.flock(fd, fcntl.LOCK_EX)
            if os.fstat(fd).st_nlink > 0:
                return tmp, fd
            os.close(fd)  # removed by a concurrent cleanup before we locked it
        raise OSError("could not create a temporary directory")  # pragma: no cover

    @contextlib.contextmanager
    def staging(self) -> Iterator[Path]:
        """A new, empty, locked temporary directory under the root, removed on exit.

        For a package tree to unpack before :meth:`create` moves it into a robot (being
        under the root, the move is a ``rename``); a crash leaves it to :meth:`recover`.
        """
        tmp, fd = self._temp_dir()
        try:
            yield tmp
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
            os.close(fd)

    def create(
        self,
        robot_id: str,
        meta: Mapping[str, Any],
        files: Mapping[str, bytes],
        tree: Path | None = None,
    ) -> StoredRobot:
        """Store a new robot atomically; raises :class:`ConflictError` if the id is taken.

        Parameters
        ----------
        robot_id
            The id (``^[a-z0-9_-]{1,64}$``), also the directory name.
        meta
            Metadata (``name``, ``source``, ``description``, ``ee_frame``, ``joints``); the
            store adds ``id``, ``revision`` and ``created_at``.
        files
            File name (one of ``robot.urdf``, ``robot.srdf``, ``table.yaml``) → bytes;
            ``robot.urdf`` is required.
        tree
            A directory under the root (from :meth:`staging`) holding the robot's package
            files: fsynced, then moved (renamed) into the robot as ``files/``.
        """
        check_robot_id(robot_id)
        unknown = set(files) - ROBOT_FILES
        if unknown or URDF_FILE not in files:
            raise ValueError(f"robot files must be {sorted(ROBOT_FILES)} with {URDF_FILE}")
        full_meta = {
            **meta,
            "id": robot_id,
            "revision": uuid.uuid4().hex,
            "created_at": datetime.now(UTC).isoformat(timespec="seconds"),
        }
        problem = meta_problem(full_meta)
        if problem is not None:  # never write a record that load() would ignore
            raise InvalidInputError(problem[1], problem[0])
        payload = {**files, META_FILE: json.dumps(full_meta, indent=2).encode() + b"\n"}
        tmp, fd = self._temp_dir()
        try:
            for name, data in payload.items():
                out = os.open(tmp / name, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
                try:
                    _write_all(out, data)
                    os.fsync(out)
                finally:
                    os.close(out)
            if tree is not None:
                _fsync_tree(tree)
                os.rename(tree, tmp / PACKAGE_DIR)
            os.fsync(fd)
            target = self.root / robot_id
            with self._locked():
                if target.exists() or target.is_symlink():
                    raise ConflictError(f"a robot with id {robot_id!r} already exists", "id")
                os.rename(tmp, target)
                _fsync_dir(self.root)
                self._bump()
        except BaseException:
            shutil.rmtree(tmp, ignore_errors=True)
            raise
        finally:
            os.close(fd)
        return StoredRobot(robot_id, target, full_meta)

    def delete(self, robot_id: str) -> None:
        """Remove a robot; raises :class:`UnknownNameError` if there is none.

        The directory is renamed to a temporary name first, so the robot vanishes in one
        step; a crash before its files are removed leaves only a temporary for
        :meth:`recover`.
        """
        with self._locked():
            if self.load(robot_id, validate=False) is None:
                raise UnknownNameError("robot", robot_id, "robot_id", self.list())
            trash = self.root / f"{TMP_PREFIX}deleted-{robot_id}-{uuid.uuid4().hex[:12]}"
            os.rename(self.root / robot_id, trash)
            _fsync_dir(self.root)
            self._bump()
        shutil.rmtree(trash, ignore_errors=True)

    def recover(self) -> int:
        """Start-up cleanup: remove temporaries and incomplete robot directories.

        A robot directory is incomplete when its ``robot.json`` or ``robot.urdf`` is
        missing (the store never produces one; a hand edit or an older crash can).
        Returns how many entries were removed.
        """
        if not self.root.is_dir():
            return 0
        with self._locked():
            removed = remove_stale_temporaries(self.root)
            for entry in sorted(self.root.iterdir()):
                if not ID_PATTERN.fullmatch(entry.name) or entry.is_symlink():
                    continue
                if entry.is_dir() and not (
                    (entry / META_FILE).is_file() and (entry / URDF_FILE).is_file()
                ):
                    log.warning("removing incomplete robot directory %s", entry)
                    shutil.rmtree(entry, ignore_errors=True)
                    removed += 1
            if removed:
                _fsync_dir(self.root)
                self._bump()
        return removed

"""Scenes: named sets of obstacles, stored on disk under ``<data_dir>/scenes/<name>.json``.

A scene is ``{name, description, obstacles}`` (obstacles as in
:mod:`app.kinematics.obstacles`, in the root frame of whichever robot it is used with).
Files are written with :func:`app.storage.store.atomic_write_bytes` to a temporary name and then
hard-linked to ``<name>.json`` (``os.link`` fails if the name exists), so a crash leaves no
half-written scene, scenes survive restarts, and of two creators of one name — threads or
worker processes sharing the data directory — exactly one wins (409 for the other). Reads
go to disk when a file changed (its ``mtime_ns``/size differ from the cached copy), so
workers see each other's scenes.

Scene names are 1–64 characters of ``A–Z a–z 0–9 _ -`` (starting with a letter or digit):
they are file names.
"""

from __future__ import annotations

import os
import re
import uuid
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import orjson

from app.kinematics.errors import ConflictError, InvalidInputError, UnknownNameError
from app.kinematics.obstacles import Obstacle, parse_obstacles
from app.kinematics.text import check_text
from app.storage.store import TMP_PREFIX, atomic_write_bytes

NAME_PATTERN = r"^[A-Za-z0-9][A-Za-z0-9_-]{0,63}$"
_NAME_RE = re.compile(NAME_PATTERN)
MAX_DESCRIPTION = 1000


@dataclass(frozen=True, slots=True)
class Scene:
    """A stored scene."""

    name: str
    description: str
    obstacles: tuple[Obstacle, ...]

    def to_json(self) -> dict[str, Any]:
        """The wire (and file) form."""
        return {
            "name": self.name,
            "description": self.description,
            "obstacles": [o.to_json() for o in self.obstacles],
        }


def validate_name(name: str, field: str = "name") -> str:
    """Raise :class:`InvalidInputError` unless ``name`` is a valid scene name."""
    if not isinstance(name, str) or not _NAME_RE.match(name):
        raise InvalidInputError(
            "must be 1-64 characters of letters, digits, '_' or '-', starting with a letter "
            "or digit",
            field,
        )
    return name


def _fsync_dir(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


class SceneStore:
    """The scenes under ``root`` (``<data_dir>/scenes``)."""

    def __init__(self, root: Path) -> None:
        self.root = Path(root)
        self._cache: dict[str, tuple[tuple[int, int], Scene]] = {}

    def _path(self, name: str) -> Path:
        return self.root / f"{name}.json"

    def names(self) -> list[str]:
        """Stored scene names, sorted."""
        if not self.root.is_dir():
            return []
        return sorted(
            p.stem for p in self.root.glob("*.json") if _NAME_RE.match(p.stem) and p.is_file()
        )

    def list(self) -> list[Scene]:
        """Every stored scene (unreadable files are skipped)."""
        out = []
        for name in self.names():
            try:
                out.append(self.get(name))
            except UnknownNameError:
                continue
        return out

    def get(self, name: str, field: str = "scene") -> Scene:
        """The scene called ``name``; raises :class:`UnknownNameError` (404) if absent."""
        if not isinstance(name, str) or not _NAME_RE.match(name):
            raise UnknownNameError("scene", str(name), field, self.names())
        path = self._path(name)
        try:
            st = path.stat()
        except FileNotFoundError:
            self._cache.pop(name, None)
            raise UnknownNameError("scene", name, field, self.names()) from None
        stamp = (st.st_mtime_ns, st.st_size)
        cached = self._cache.get(name)
        if cached is not None and cached[0] == stamp:
            return cached[1]
        try:
            doc = orjson.loads(path.read_bytes())
            scene = Scene(
                name=name,
                description=str(doc.get("description", "")),
                obstacles=parse_obstacles(doc.get("obstacles", [])),
            )
        except (FileNotFoundError, orjson.JSONDecodeError, InvalidInputError, AttributeError):
            raise UnknownNameError("scene", name, field, self.names()) from None
        self._cache[name] = (stamp, scene)
        return scene

    def create(
        self, name: str, obstacles: Sequence[Mapping[str, Any]], description: str = ""
    ) -> Scene:
        """Validate and store a new scene; :class:`ConflictError` (409) if the name exists."""
        validate_name(name)
        if len(description) > MAX_DESCRIPTION:
            raise InvalidInputError(f"at most {MAX_DESCRIPTION} characters", "description")
        check_text(description, "description")
        scene = Scene(name, description, parse_obstacles(obstacles))
        data = orjson.dumps(scene.to_json(), option=orjson.OPT_INDENT_2)
        path = self._path(name)
        if path.exists():
            raise ConflictError(f"scene {name!r} already exists; delete it first", "name")
        tmp = self.root / f"{TMP_PREFIX}scene-{uuid.uuid4().hex}"
        try:
            atomic_write_bytes(tmp, data)
            try:
                os.link(tmp, path)
            except FileExistsError:
                raise ConflictError(
                    f"scene {name!r} already exists; delete it first", "name"
                ) from None
        finally:
            tmp.unlink(missing_ok=True)
        _fsync_dir(self.root)
        return scene

    def delete(self, name: str, field: str = "name") -> None:
        """Remove a scene; :class:`UnknownNameError` (404) if absent."""
        if not isinstance(name, str) or not _NAME_RE.match(name):
            raise UnknownNameError("scene", str(name), field, self.names())
        path = self._path(name)
        try:
            path.unlink()
        except FileNotFoundError:
            raise UnknownNameError("scene", name, field, self.names()) from None
        self._cache.pop(name, None)
        _fsync_dir(self.root)

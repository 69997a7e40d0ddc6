"""Reading mesh files at upload time, so that a stored robot's collisions always load.

:func:`check_mesh_files` loads every mesh a URDF names with coal's loader (assimp, the one
Pinocchio uses to build collision and visual geometry) and refuses the first one that
cannot be read, naming it by the URI the client wrote, never by its path on this host.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from pathlib import Path

import coal
import numpy as np

from app.kinematics.errors import InvalidInputError

log = logging.getLogger("denavit.meshes")

#: Mesh formats an upload may use (by file extension, lower-case): formats whose loader
#: opens only the file itself, or (OBJ) a material library the package checks.
MESH_FORMATS = frozenset({".stl", ".dae", ".obj", ".ply"})


def check_mesh_files(meshes: Mapping[str, Path], field: str) -> None:
    """Load each mesh file; the first that cannot be read is an InvalidInputError.

    Parameters
    ----------
    meshes
        The URI as written in the URDF → the file it resolves to (already known to be a
        regular file inside the package or the catalog).
    field
        Request field the error names.
    """
    for uri, path in meshes.items():
        suffix = path.suffix.lower()
        if suffix not in MESH_FORMATS:
            raise InvalidInputError(
                f"mesh {uri!r}: format {suffix or '(none)'!r} is not supported "
                f"(use {', '.join(sorted(MESH_FORMATS))})",
                field,
            )
        try:
            bvh = coal.MeshLoader().load(str(path), np.ones(3))
        except (ValueError, RuntimeError, OSError, MemoryError) as exc:
            log.info("mesh %r (%s) cannot be read: %s", uri, path, exc)
            raise InvalidInputError(
                f"mesh {uri!r} cannot be read: not a valid {suffix[1:].upper()} mesh", field
            ) from None
        if bvh.num_tris == 0:
            raise InvalidInputError(f"mesh {uri!r} has no triangles", field)

"""Every mesh of an upload read, and its collision model built, in a bounded child process.

:func:`check_meshes` runs task ``meshes`` (:func:`check_in_child`) of
:mod:`app.robots.documents.sandbox`. In the child, each mesh file the URDF names (collision and
visual) has its header checked (:func:`app.kinematics.meshes.check_header`); the robot's
collision geometry is then built exactly as a worker builds it
(:func:`app.kinematics.meshes.collision_geometry`), its triangles counted against
``DENAVIT_MAX_COLLISION_MESH_TRIANGLES`` and ``DENAVIT_MAX_COLLISION_TRIANGLES``, and the
meshes it did not read (visual ones) are loaded by coal's loader. So a 201 means every
mesh loads and collisions work, and whatever a mesh does to the loader (stall, balloon,
crash) happens in the child, bounded by ``DENAVIT_PARSE_TIMEOUT_S`` and
``DENAVIT_PARSE_MEMORY_BYTES``, never in a worker.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np

from app.kinematics.errors import InvalidInputError
from app.kinematics.meshes import (
    MeshLimits,
    check_header,
    collision_geometry,
    load_mesh,
    resolve_uri,
)
from app.kinematics.urdf_model import build_model
from app.kinematics.xmldoc import TRUSTED, parse_literal_xml
from app.robots.documents.sandbox import ChildLimits, run_child
from app.robots.documents.sandbox_child import progress
from app.robots.documents.urdf import resource_elements


def check_meshes(
    urdf: str,
    meshes: Mapping[str, Path],
    package_dirs: Sequence[str],
    limits: MeshLimits,
    child: ChildLimits,
    field: str,
) -> int:
    """Load every mesh of ``urdf`` and build its collision geometry in a bounded child; the
    number of collision triangles.

    Parameters
    ----------
    urdf
        The URDF as it will be stored (its mesh URIs resolve against ``package_dirs``).
    meshes
        Each mesh URI as the client wrote it → its file (visual and collision meshes).
    limits, child
        Bounds on the meshes; bounds on the child process.
    field
        The request field refusals name.

    Raises
    ------
    InvalidInputError
        ``field``, naming the first mesh refused (header, loader, triangles) or the limit
        the child hit.
    """
    args = {
        "urdf": urdf,
        "meshes": {uri: str(path) for uri, path in meshes.items()},
        "package_dirs": list(package_dirs),
        "limits": asdict(limits),
        "field": field,
    }
    result = run_child("meshes", args, child, field=field, what="reading the meshes")
    return int(result["collision_triangles"])


#: The key of a stored robot's record that says its meshes passed :func:`check_meshes` (the
#: number of collision triangles the loader counted).
CHECKED_KEY = "collision_triangles"


def check_stored_meshes(
    robot_id: str,
    urdf: str,
    meta: Mapping[str, Any],
    package_dirs: Sequence[str],
    limits: MeshLimits,
    child: ChildLimits,
) -> None:
    """A stored robot's meshes, checked in the child unless its record says they were.

    A robot stored before these checks existed has no :data:`CHECKED_KEY`: before a worker
    loads any of its meshes, they are read in the bounded child as at upload (the check is
    not written back: each worker does it once, on first load). Raises
    :class:`InvalidInputError` (field ``robot_id``) naming the mesh and the limit.
    """
    if isinstance(meta.get(CHECKED_KEY), int) or "<mesh" not in urdf:
        return
    meshes: dict[str, Path] = {}
    for element, uri in resource_elements(parse_literal_xml(urdf, "urdf", TRUSTED)):
        path = resolve_uri(uri, package_dirs) if element.tag == "mesh" else None
        if element.tag == "mesh" and path is None:
            raise InvalidInputError(f"robot {robot_id!r}: mesh {uri!r} is missing", "robot_id")
        if path is not None:
            meshes[uri] = path
    check_meshes(urdf, meshes, package_dirs, limits, child, "robot_id")


def check_in_child(args: dict[str, Any]) -> dict[str, int]:
    """The sandbox task (see the module docstring); runs in the child only."""
    limits = MeshLimits(**args["limits"])
    field = args["field"]
    for uri, path in args["meshes"].items():  # every header first: no loader before
        check_header(Path(path), uri, limits, field, collision=False)
    try:
        model = build_model(args["urdf"], field=field)
    except (ValueError, RuntimeError) as exc:  # pragma: no cover - checked before
        raise InvalidInputError(f"the URDF cannot be read ({type(exc).__name__})", field) from None
    gm = collision_geometry(model, args["urdf"], args["package_dirs"], limits, field, progress)
    read = {os.path.normpath(go.meshPath) for go in gm.geometryObjects if go.meshPath}
    for uri, path in args["meshes"].items():  # what the collision geometry did not read
        if os.path.normpath(path) not in read:
            progress(uri)
            load_mesh(Path(path), np.ones(3), uri, field)
    triangles = 0
    for go in gm.geometryObjects:
        n = int(getattr(go.geometry, "num_tris", 0))
        if n > limits.max_collision_mesh_triangles:
            raise InvalidInputError(
                f"the collision mesh of {go.name!r} has {n} triangles, more than "
                f"{limits.max_collision_mesh_triangles} (DENAVIT_MAX_COLLISION_MESH_TRIANGLES): "
                "give it a simpler collision mesh (its visual mesh may stay detailed)",
                field,
            )
        triangles += n
    if triangles > limits.max_collision_triangles:
        raise InvalidInputError(
            f"the collision meshes hold {triangles} triangles, more than "
            f"{limits.max_collision_triangles} (DENAVIT_MAX_COLLISION_TRIANGLES): give the "
            "links simpler collision meshes (their visual meshes may stay detailed)",
            field,
        )
    return {"collision_triangles": triangles}

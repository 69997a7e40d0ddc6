"""Loading a robot's meshes: header checks first, then coal's loader, one mesh at a time.

coal's loader (assimp, the one Pinocchio uses) holds the GIL while it reads a file and
builds its bounding-volume tree: ~5 µs per triangle of a real mesh, ~10 µs of a random
triangle soup, ~0.7 KB of memory per triangle. A worker whose GIL is held for 5 s is
killed by uvicorn's supervisor as hung. So a client's mesh never reaches the loader before
its header is read (:func:`app.kinematics.mesh_files.mesh_counts`: declared vertices and
faces against :class:`MeshLimits`), and a collision model is built mesh by mesh
(:func:`collision_geometry`): the GIL is released between two meshes, and the longest hold
is one mesh's load, at most ``max_collision_mesh_triangles`` triangles (100 000 random
triangles: ~1 s on an idle 2-core machine, ~3 s with both cores busy; a real mesh is about
2.5 times faster).

Uploads are loaded first in a bounded child process (:mod:`app.robots.documents.mesh_check`), so a
file that stalls or balloons the loader despite a valid header costs that child, not a
worker.
"""

from __future__ import annotations

import posixpath
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from xml.etree.ElementTree import Element, SubElement, tostring

import coal
import numpy as np
import pinocchio as pin

from app.kinematics.collada import UnsupportedCollada, read_collada
from app.kinematics.errors import InvalidInputError
from app.kinematics.mesh_files import MESH_FORMATS, MeshFileError, MeshTooLarge, mesh_counts
from app.kinematics.xmldoc import TRUSTED, parse_literal_xml

__all__ = ["MESH_FORMATS", "MeshLimits", "collision_geometry", "load_mesh"]


@dataclass(frozen=True, slots=True)
class MeshLimits:
    """Bounds on a client's meshes (``DENAVIT_MAX_MESH_VERTICES``,
    ``DENAVIT_MAX_COLLISION_TRIANGLES``).

    ``max_vertices`` bounds the vertices and the faces every mesh file declares;
    ``max_collision_triangles`` the triangles of a robot's collision meshes in total, and
    ``max_collision_mesh_triangles`` those of one collision mesh file (both counted by the
    loader at upload; a file's declared faces are checked again before a worker loads it).
    """

    max_vertices: int = 1_000_000
    max_collision_triangles: int = 200_000
    max_collision_mesh_triangles: int = 100_000


def check_header(path: Path, uri: str, limits: MeshLimits, field: str, collision: bool) -> None:
    """Refuse (naming ``uri``) a mesh whose header declares more than ``limits`` allow, or
    that is not a mesh of its format; a collision mesh's faces are bounded by
    ``max_collision_mesh_triangles`` too."""
    try:
        counts = mesh_counts(path, limits.max_vertices)
    except MeshTooLarge as exc:
        raise InvalidInputError(f"mesh {uri!r} {exc}", field) from None
    except MeshFileError as exc:
        raise InvalidInputError(f"mesh {uri!r} cannot be read: {exc}", field) from None
    except OSError as exc:
        raise InvalidInputError(f"mesh {uri!r} cannot be read ({exc.strerror})", field) from None
    if collision and counts.faces > limits.max_collision_mesh_triangles:
        raise InvalidInputError(
            f"mesh {uri!r} declares {counts.faces} faces, more than "
            f"{limits.max_collision_mesh_triangles} (DENAVIT_MAX_COLLISION_MESH_TRIANGLES)",
            field,
        )


def load_mesh(path: Path, scale: np.ndarray, uri: str, field: str) -> coal.BVHModelOBBRSS:
    """coal's BVH of one mesh file (the header already checked); refusals name ``uri``.

    A COLLADA file in which a node holds several meshes (a multi-material file) has its
    triangles read from the file itself (:func:`app.kinematics.collada.read_collada`:
    coal 3.0.3 joins the wrong vertices there); every other file is coal's reading."""
    suffix = path.suffix.lower()
    if suffix not in MESH_FORMATS:
        raise InvalidInputError(
            f"mesh {uri!r}: format {suffix or '(none)'!r} is not supported "
            f"(use {', '.join(sorted(MESH_FORMATS))})",
            field,
        )
    if suffix == ".dae":
        try:  # coal misreads a COLLADA node of several meshes (app.kinematics.collada)
            dae = read_collada(path)
        except UnsupportedCollada:
            dae = None  # coal's own reading, below (its loader refuses what is not COLLADA)
        if dae is not None and dae.shared_nodes:
            bvh = coal.BVHModelOBBRSS()
            bvh.beginModel(len(dae.triangles), len(dae.vertices))
            bvh.addVertices(dae.vertices * np.asarray(scale, dtype=float))
            bvh.addTriangles(dae.triangles.astype(np.int64))
            bvh.endModel()
            return bvh
    try:
        bvh = coal.MeshLoader().load(str(path), np.asarray(scale, dtype=float))
    except (ValueError, RuntimeError, OSError) as exc:
        if "bad_alloc" in str(exc):  # coal's word for assimp's std::bad_alloc: a limit
            raise MemoryError(f"mesh {uri!r}") from None
        raise InvalidInputError(
            f"mesh {uri!r} cannot be read: not a valid {suffix[1:].upper()} mesh", field
        ) from None
    if bvh.num_tris == 0:
        raise InvalidInputError(f"mesh {uri!r} has no triangles", field)
    return bvh


def resolve_uri(uri: str, package_dirs: Sequence[str]) -> Path | None:
    """The file a URDF mesh ``filename`` names, as Pinocchio resolves it: ``package://<pkg>/
    <path>`` as ``<dir>/<pkg>/<path>`` for the first package directory that has it; a
    plain or ``file://`` path as it is. ``None`` when no such file exists."""
    if uri.startswith("package://"):
        rest = posixpath.normpath(uri[len("package://") :])
        if rest.startswith(("../", "/")) or rest == "..":
            return None
        for folder in package_dirs:
            file = Path(folder) / rest
            if file.is_file():
                return file
        return None
    file = Path(uri.removeprefix("file://"))
    return file if file.is_file() else None


def _scale(mesh: Element) -> np.ndarray:
    raw = mesh.get("scale")
    return np.ones(3) if raw is None else np.array([float(v) for v in raw.split()], dtype=float)


def collision_geometry(
    model: pin.Model,
    urdf: str,
    package_dirs: Sequence[str],
    limits: MeshLimits,
    field: str = "robot_id",
    on_mesh: Callable[[str], None] | None = None,
) -> pin.GeometryModel:
    """The URDF's collision geometry as ``pin.buildGeomFromUrdfString`` builds it, each mesh
    read after its header check and loaded on its own.

    Pinocchio builds the geometry of a copy of the URDF whose ``<mesh>`` elements are unit
    boxes (same links, origins and names, ``<link>_<i>`` in order); each box of a mesh is
    then replaced by the mesh's BVH (coal's loader, with the ``<mesh scale>``), and its
    ``meshPath`` and ``meshScale`` set as Pinocchio sets them.

    ``on_mesh(uri)`` is called before each mesh file is read (a mesh used twice is read
    once and shared).

    Raises
    ------
    InvalidInputError
        ``field``, naming the mesh as the URDF writes it: missing, refused by its header
        (``limits``), or unreadable.
    """
    root = parse_literal_xml(urdf, "urdf", TRUSTED)
    meshes: dict[str, tuple[str, np.ndarray]] = {}  # geometry object name → (uri, scale)
    for link in root.iter("link"):
        for i, collision in enumerate(link.findall("collision")):
            geometry = collision.find("geometry")
            mesh = geometry.find("mesh") if geometry is not None else None
            if geometry is None or mesh is None:
                continue
            meshes[f"{link.get('name')}_{i}"] = (mesh.get("filename") or "", _scale(mesh))
            geometry.remove(mesh)
            SubElement(geometry, "box", size="1 1 1")
    gm = pin.buildGeomFromUrdfString(
        model, tostring(root, encoding="unicode"), pin.COLLISION, package_dirs=list(package_dirs)
    )
    loaded: dict[tuple[Path, tuple[float, ...]], coal.BVHModelOBBRSS] = {}
    for go in gm.geometryObjects:
        if go.name not in meshes:
            continue
        uri, scale = meshes.pop(go.name)
        path = resolve_uri(uri, package_dirs)
        if path is None:
            raise InvalidInputError(f"mesh {uri!r} is missing", field)
        key = (path, tuple(scale))
        if key not in loaded:  # a mesh used twice is loaded once and shared (immutable)
            if on_mesh is not None:
                on_mesh(uri)
            check_header(path, uri, limits, field, collision=True)
            loaded[key] = load_mesh(path, scale, uri, field)
        go.geometry = loaded[key]
        go.meshPath = str(path)
        go.meshScale = scale
    if meshes:  # pragma: no cover - Pinocchio names every collision element
        raise InvalidInputError(f"meshes {sorted(meshes)} were not placed", field)
    return gm

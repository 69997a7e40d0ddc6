"""The independent reference for the URDF/xacro corpus: the xacro CLI, yourdfpy, python-fcl.

Nothing here imports the service. A case is expanded by the real ``xacro`` command-line tool
(PyPI ``xacro``, a subprocess) with ``$(find pkg)`` resolved the way ROS 2 resolves it: the
ament index. :func:`ament_prefix` lays the case's packages out as an install prefix
(``share/<pkg>`` plus the marker ``share/ament_index/resource_index/packages/<pkg>``) and the
CLI runs with ``AMENT_PREFIX_PATH`` pointing at it. The ``ament_index_python`` module the CLI
imports for ``$(find)`` is not on PyPI, so :data:`AMENT_INDEX_SHIM` is its lookup
(``get_package_share_directory``: the first prefix of ``AMENT_PREFIX_PATH`` holding the
marker, then ``<prefix>/share/<pkg>``), written into a folder on the child's ``PYTHONPATH``.

:class:`Reference` then reads the expanded URDF with yourdfpy (mimic-aware forward
kinematics: link poses in the frame of the URDF's root link, metres) and checks
self-collisions with python-fcl on the collision meshes (trimesh) and primitives, posed by
yourdfpy's FK, on the link pairs the rules of ``app/kinematics/collision_pairs.py`` leave
(re-derived here from the URDF and SRDF, not imported).
"""

from __future__ import annotations

import io
import os
import subprocess
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from urllib.parse import unquote

import fcl
import numpy as np
import trimesh
import yourdfpy
from lxml import etree

from tests.corpus.pair_rules import bridged_adjacent

#: ``ament_index_python.packages.get_package_share_directory``, as ament_index_python
#: implements it (the package is part of ROS 2, not of PyPI).
AMENT_INDEX_SHIM = """
import os


class PackageNotFoundError(KeyError):
    pass


def get_package_prefix(package_name):
    for prefix in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep):
        marker = os.path.join(
            prefix, "share", "ament_index", "resource_index", "packages", package_name
        )
        if prefix and os.path.isfile(marker):
            return prefix
    raise PackageNotFoundError(f"package '{package_name}' not found")


def get_package_share_directory(package_name):
    return os.path.join(get_package_prefix(package_name), "share", package_name)
"""

XACRO_CLI = Path(sys.executable).parent / "xacro"


def package_folders(case: Path) -> dict[str, Path]:
    """Package name (``<name>`` of each ``package.xml``) → its folder, under ``case``."""
    found: dict[str, Path] = {}
    for manifest in sorted(case.rglob("package.xml")):
        name = etree.parse(str(manifest)).getroot().findtext("name").strip()
        found[name] = manifest.parent
    return found


def ament_prefix(case: Path, prefix: Path) -> dict[str, Path]:
    """Lay the case's packages out as the install prefix ``prefix`` (symlinks), and write
    the ``ament_index_python`` shim under ``prefix / "pylib"``.

    Returns
    -------
    dict
        Package name → its share folder (``prefix/share/<pkg>``, a link to the case folder).
    """
    shares: dict[str, Path] = {}
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True, exist_ok=True)
    for name, folder in package_folders(case).items():
        share = prefix / "share" / name
        share.symlink_to(folder.resolve(), target_is_directory=True)
        (index / name).write_text("")
        shares[name] = share
    shim = prefix / "pylib" / "ament_index_python"
    shim.mkdir(parents=True, exist_ok=True)
    (shim / "__init__.py").write_text("")
    (shim / "packages.py").write_text(AMENT_INDEX_SHIM)
    return shares


def run_xacro(
    case: Path, path: str, args: Mapping[str, str], prefix: Path
) -> tuple[str, dict[str, Path]]:
    """The xacro CLI's expansion of ``case / path`` with ``args`` (``name:=value``).

    ``path`` is read through its package's share folder (as a ROS launch file would name
    it), so ``$(find)`` and relative includes agree. Returns the document and the share
    folders (to map the absolute paths a ``file://$(find ...)`` URI holds back to the case).
    """
    if not (prefix / "share").exists():
        ament_prefix(case, prefix)
    shares = {p.name: p for p in (prefix / "share").iterdir() if p.name != "ament_index"}
    target = (case / path).resolve()
    entry = None
    for share in shares.values():
        real = share.resolve()
        if real in target.parents:
            entry = share / target.relative_to(real)
    assert entry is not None, f"{path} is in no package of the case"
    env = {
        "PATH": os.environ.get("PATH", ""),
        "HOME": str(prefix),
        "AMENT_PREFIX_PATH": str(prefix),
        "PYTHONPATH": str(prefix / "pylib"),
    }
    cmd = [str(XACRO_CLI), str(entry), *(f"{k}:={v}" for k, v in args.items())]
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, f"xacro CLI failed on {path}: {done.stderr[-2000:]}"
    return done.stdout, shares


def resolve_uri(uri: str, case: Path, shares: Mapping[str, Path], base: Path) -> Path:
    """The file of the case a mesh URI names (``package://``, ``file://`` or relative).

    ``base`` is the folder of the description (for relative paths). The answer is the
    file's path in the case folder (``case.resolve()`` / path in the archive).
    """
    packages = {name: share.resolve() for name, share in shares.items()}
    if uri.startswith("package://"):
        pkg, _, rest = uri[len("package://") :].partition("/")
        path = packages[pkg] / unquote(rest)
    elif uri.startswith("file://"):
        text = unquote(uri[len("file://") :])
        if text.startswith("/"):  # file:///abs and file:////abs (xacro's "file:///$(find)")
            raw = Path("/" + text.lstrip("/"))
            path = raw
            for share in shares.values():  # through the prefix's share links: into the case
                if share in raw.parents:
                    path = share.resolve() / raw.relative_to(share)
        else:
            path = base / text
    else:
        path = base / unquote(uri)
    # The file's path in the case (a case may link a file to a byte-identical one of
    # another case: its path stays this case's, its bytes are read through the link).
    inside = Path(os.path.normpath(path))
    assert case.resolve() in inside.parents and inside.is_file(), f"{uri} is not a case file"
    return inside


def srdf_disabled(srdf_text: str | None, links: Iterable[str]) -> set[frozenset[str]]:
    """Pairs an SRDF disables: ``disable_default_collisions`` (every pair of that link)
    unless ``enable_collisions`` restores it, and ``disable_collisions``."""
    if not srdf_text:
        return set()
    root = etree.fromstring(srdf_text.encode())
    links = list(links)
    off: set[frozenset[str]] = set()
    for el in root.iter("disable_default_collisions"):
        off.update(frozenset((el.get("link"), b)) for b in links if b != el.get("link"))
    for el in root.iter("enable_collisions"):
        off.discard(frozenset((el.get("link1"), el.get("link2"))))
    for el in root.iter("disable_collisions"):
        if el.get("link1") != el.get("link2"):
            off.add(frozenset((el.get("link1"), el.get("link2"))))
    return off


class Reference:
    """yourdfpy FK and python-fcl self-collisions of an expanded URDF.

    Parameters
    ----------
    urdf_text
        The URDF (as the xacro CLI expanded it, or the vendor's plain URDF).
    mesh_file
        Mesh URI → the case file it names (:func:`resolve_uri`).
    srdf_text
        The SRDF (expanded), or ``None``.
    """

    def __init__(self, urdf_text: str, mesh_file, srdf_text: str | None = None) -> None:
        self.urdf = yourdfpy.URDF.load(
            io.StringIO(urdf_text),
            build_scene_graph=True,
            load_meshes=False,
            build_collision_scene_graph=False,
            load_collision_meshes=False,
        )
        self.robot = self.urdf.robot
        self.root = self.urdf.base_link
        self.links = [link.name for link in self.robot.links]
        self.mesh_uris = sorted(
            {
                g.geometry.mesh.filename
                for link in self.robot.links
                for g in [*link.visuals, *link.collisions]
                if g.geometry.mesh is not None
            }
        )
        self._mesh_file = mesh_file
        self.srdf_text = srdf_text
        self._geoms = {link.name: self._link_geometry(link) for link in self.robot.links}
        self._geoms = {k: v for k, v in self._geoms.items() if v}

    # ------------------------------------------------------------------ kinematics
    @property
    def actuated(self) -> list[str]:
        """The actuated joints (mimic followers excluded)."""
        return list(self.urdf.actuated_joint_names)

    def limits(self, joint: str) -> tuple[float, float]:
        """A joint's position limits; continuous joints get [-π, π]."""
        j = self.urdf.joint_map[joint]
        if j.type == "continuous" or j.limit is None or j.limit.lower is None:
            return -np.pi, np.pi
        return float(j.limit.lower), float(j.limit.upper)

    def random_configs(self, rng: np.random.Generator, n: int) -> list[dict[str, float]]:
        """``n`` configurations (actuated joint → value) drawn uniformly within limits."""
        bounds = [self.limits(j) for j in self.actuated]
        return [
            {
                j: float(rng.uniform(lo, hi))
                for j, (lo, hi) in zip(self.actuated, bounds, strict=True)
            }
            for _ in range(n)
        ]

    def fk(self, cfg: Mapping[str, float]) -> dict[str, np.ndarray]:
        """Every link's 4×4 pose in the root link's frame at ``cfg`` (mimics followed)."""
        self.urdf.update_cfg({j: cfg[j] for j in self.actuated})
        return {name: np.array(self.urdf.get_transform(name, self.root)) for name in self.links}

    # ------------------------------------------------------------------ collisions
    def _link_geometry(self, link) -> list[tuple[object, np.ndarray]]:
        out = []
        for c in link.collisions:
            g = c.geometry
            origin = np.eye(4) if c.origin is None else np.asarray(c.origin, float)
            if g.mesh is not None:
                mesh = trimesh.load(self._mesh_file(g.mesh.filename), force="mesh")
                verts = np.asarray(mesh.vertices, float)
                if g.mesh.scale is not None:
                    verts = verts * np.asarray(g.mesh.scale, float)
                model = fcl.BVHModel()
                model.beginModel(len(verts), len(mesh.faces))
                model.addSubModel(verts, np.asarray(mesh.faces, np.int64))
                model.endModel()
                out.append((model, origin))
            elif g.box is not None:
                out.append((fcl.Box(*map(float, g.box.size)), origin))
            elif g.cylinder is not None:
                out.append(
                    (fcl.Cylinder(float(g.cylinder.radius), float(g.cylinder.length)), origin)
                )
            elif g.sphere is not None:
                out.append((fcl.Sphere(float(g.sphere.radius)), origin))
        return out

    def _bodies(self) -> tuple[dict[str, str], dict[str, str | None]]:
        """Link → its rigid body (the moving joint above it, or "" for the root's), and
        body → parent body. Fixed joints join links into one body."""
        parent_joint = {j.child: j for j in self.robot.joints}
        body: dict[str, str] = {}

        def body_of(link: str) -> str:
            if link not in body:
                j = parent_joint.get(link)
                if j is None:
                    body[link] = ""
                elif j.type == "fixed":
                    body[link] = body_of(j.parent)
                else:
                    body[link] = j.name
            return body[link]

        for link in self.links:
            body_of(link)
        up: dict[str, str | None] = {"": None}
        for j in self.robot.joints:
            if j.type != "fixed":
                up[j.name] = body[j.parent]
        return body, up

    def pairs(self) -> set[frozenset[str]]:
        """The link pairs checked for self-collision, by the documented rules: links with
        collision geometry, minus same-body pairs, adjacent bodies (bridging bodies without
        geometry) and the SRDF's disabled pairs."""
        body, up = self._bodies()
        geom_links = sorted(self._geoms)
        geom_bodies = {body[link] for link in geom_links}
        adjacent = bridged_adjacent(up, geom_bodies)
        off = srdf_disabled(self.srdf_text, geom_links)
        out: set[frozenset[str]] = set()
        for i, a in enumerate(geom_links):
            for b in geom_links[i + 1 :]:
                ba, bb = body[a], body[b]
                if ba == bb or frozenset((ba, bb)) in adjacent or frozenset((a, b)) in off:
                    continue
                out.add(frozenset((a, b)))
        return out

    def colliding(self, cfg: Mapping[str, float], pairs: Iterable[frozenset[str]]) -> set:
        """The pairs among ``pairs`` whose collision geometries intersect at ``cfg``."""
        poses = self.fk(cfg)
        objects: dict[str, list[fcl.CollisionObject]] = {}
        for link, geoms in self._geoms.items():
            objects[link] = []
            for geom, origin in geoms:
                T = poses[link] @ origin
                objects[link].append(fcl.CollisionObject(geom, fcl.Transform(T[:3, :3], T[:3, 3])))
        hit = set()
        for pair in pairs:
            a, b = sorted(pair)
            if any(
                fcl.collide(oa, ob, fcl.CollisionRequest(), fcl.CollisionResult()) > 0
                for oa in objects[a]
                for ob in objects[b]
            ):
                hit.add(pair)
        return hit
